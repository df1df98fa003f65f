//! The physics judge of a settled motion: from the plant's own signals, whether it is
//! periodic (and with which period in revolutions), quasi-periodic, chaotic or at rest,
//! with the numbers that decide it. See `verdict.rs` for the thresholds and their reasons.

mod order_lines;
mod spread;
mod verdict;
mod zero_one;

pub use order_lines::{MAX_HEIGHT_DB, OrderSpectrum, subharmonic_height_db};
pub use spread::section_spread;
pub use verdict::{
    CHAOS_K_MIN, JudgeInput, Judgement, LINE_FRACTION_MIN, MAX_PERIOD, Motion, REST_AC_RMS_NM,
    SPREAD_MAX, SUBHARMONIC_CLEAR_DB, judge,
};
pub use zero_one::zero_one_k;
