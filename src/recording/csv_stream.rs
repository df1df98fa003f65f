//! CSV recordings: a header row of signal names with units, then one row per sample.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use anyhow::Context;

use super::partial::PartialFile;

/// A CSV file being written, row by row.
pub struct CsvRecorder {
    writer: csv::Writer<BufWriter<File>>,
    file: PartialFile,
}

impl CsvRecorder {
    /// Starts `path` with the header `names`.
    pub fn create(path: &Path, names: &[String]) -> anyhow::Result<Self> {
        let file = PartialFile::new(path);
        let mut writer = csv::WriterBuilder::new()
            .has_headers(false)
            .from_writer(file.create()?);
        writer
            .write_record(names)
            .context("writing the CSV header")?;
        Ok(Self { writer, file })
    }

    /// Appends one row (anything the csv crate serialises as a record: a slice of
    /// numbers, a struct).
    pub fn write_row<T: serde::Serialize + ?Sized>(&mut self, values: &T) -> anyhow::Result<()> {
        self.writer
            .serialize(values)
            .with_context(|| format!("writing {}", self.file.path().display()))
    }

    /// Flushes and gives the file its final name.
    pub fn finish(mut self) -> anyhow::Result<PathBuf> {
        self.writer
            .flush()
            .with_context(|| format!("writing {}", self.file.path().display()))?;
        drop(self.writer);
        self.file.commit()
    }
}
