//! The testrig application's library part: what the commands share and tests use.
//!
//! ```
//! use testrig::recording::{Uff58Abscissa, Uff58Record, write_uff58};
//!
//! let record = Uff58Record {
//!     description: "strain, intermediate shaft",
//!     source: "testrig",
//!     function_type: 1,
//!     response_name: "shaft",
//!     response_node: 3,
//!     ordinate_type: 3,
//!     ordinate_unit: "strain",
//!     abscissa: Uff58Abscissa::Time { start_s: 0.0, step_s: 1.0 / 51_200.0 },
//!     values: &[1.0e-5, -2.0e-5],
//! };
//! let mut text = Vec::new();
//! write_uff58(&mut text, &record)?;
//! let text = String::from_utf8(text).expect("ASCII");
//! let lines: Vec<&str> = text.lines().collect();
//! assert_eq!(lines[0], "    -1");
//! assert!(lines[1].starts_with("    58"));
//! assert_eq!(lines[13], "   1.00000000000e-05  -2.00000000000e-05");
//! assert_eq!(lines.last(), Some(&"    -1"));
//! # Ok::<(), std::io::Error>(())
//! ```

pub mod approach_name;
pub mod calibrate;
pub mod chain;
pub mod panel;
pub mod plots;
pub mod recording;
pub mod rig_roles;
pub mod runtime;
pub mod scenario;
pub mod steady_point;
pub mod sweep;
pub mod vocabulary;
pub mod wav_input;
