//! How the Python functions' arguments are named in messages.

use testrig::vocabulary::InputNames;

/// The Python arguments' names, for messages.
pub(crate) const ARGUMENT_NAMES: InputNames = InputNames {
    rpm: "rpm",
    load: "load_nm",
    settle: "settle_s",
    duration: "duration_s",
    rate: "rate_hz",
};
