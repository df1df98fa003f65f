//! Recorders: streams of samples to files that other tools read, each written under a
//! `.partial` name until complete.
//!
//! Files: `partial.rs` (written as `NAME.partial`, renamed when complete, and then named in
//! the folder's `journal.rs`: `files.journal`, so that a killed run's files are known),
//! `cleanup.rs`, `frame_writer.rs` (the face of every recording), `wav.rs` (float32/int24 +
//! JSON sidecar), `csv_stream.rs`, `impact_log.rs` (`impacts.csv` of either plant), `uff58.rs`/`uff58_stream.rs` (numbers in
//! Fortran's E format by `fortran_e.rs`), `spectrum_csv.rs`.

pub(crate) mod cleanup;
pub(crate) mod csv_stream;
pub(crate) mod fortran_e;
pub(crate) mod frame_writer;
pub(crate) mod impact_log;
pub(crate) mod journal;
pub(crate) mod partial;
pub(crate) mod spectrum_csv;
pub(crate) mod uff58;
pub(crate) mod uff58_stream;
pub(crate) mod wav;

pub use cleanup::{remove_files_with_extension, remove_partial_files};
pub use csv_stream::CsvRecorder;
pub use frame_writer::{CsvFrames, FrameWriter, Written};
pub use impact_log::ImpactLog;
pub use journal::{
    JOURNAL_NAME, end_journal, journaled_files, journaled_scenario, note_finished, start_journal,
};
pub use partial::PartialFile;
pub use spectrum_csv::{ALIAS_COLUMN, Metadata, write_spectrum_csv};
pub use uff58::{
    Uff58Abscissa, Uff58Record, write_uff58, write_uff58_header, write_uff58_trailer,
    write_uff58_values,
};
pub use uff58_stream::{Uff58Channel, Uff58Recorder};
pub use wav::{ChannelInfo, WavRecorder, WavSamples};
