//! The command line: the commands and their arguments (`args.rs`), and the typed values
//! of the flags that are not plain numbers or paths (`values.rs`).

pub(crate) mod args;
pub(crate) mod values;

pub use args::*;
pub use values::TrainingHalf;
