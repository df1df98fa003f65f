//! The physics judge of a settled motion: from the plant's own signals, whether it is
//! periodic (and with which period in revolutions), quasi-periodic, chaotic or without vibration,
//! with the numbers that decide it. See `verdict.rs` for the thresholds and their reasons.

mod order_lines;
mod spread;
mod verdict;
mod zero_one;

pub use order_lines::{MAX_HEIGHT_DB, OrderSpectrum, subharmonic_height_db, subharmonic_share};
pub use spread::section_spread;
pub use verdict::{
    CHAOS_K_MIN, JudgeInput, Judgement, LINE_FRACTION_MIN, MAX_PERIOD, Motion,
    NO_VIBRATION_AC_RMS_NM, SPREAD_MAX, SUBHARMONIC_CLEAR_DB, SUBHARMONIC_VISIBLE_SHARE, judge,
    stands_clear,
};
pub use zero_one::zero_one_k;
