//! `signals.csv` of `testrig simulate`, streamed under a temporary name until finished.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use anyhow::Context;

use testrig::recording::{PartialFile, start_journal};
use testrig::runtime::clear_previous_run;

/// Streams the true signals to `signals.csv`, under a temporary name until finished.
pub(crate) struct SignalWriter {
    csv: csv::Writer<BufWriter<File>>,
    file: PartialFile,
}

impl SignalWriter {
    /// Prepares `dir` as simulate's output folder (an earlier simulate's files removed;
    /// another run's refused unless `replace`; a journal of finished files started) and
    /// opens `signals.csv` in it.
    pub(crate) fn create<S: AsRef<[u8]>>(
        dir: &Path,
        replace: bool,
        header: impl IntoIterator<Item = S>,
    ) -> anyhow::Result<Self> {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("--out {}: cannot create the folder", dir.display()))?;
        clear_previous_run(dir, "simulate", replace)?;
        start_journal(dir, "simulate")?;
        let file = PartialFile::new(&dir.join("signals.csv"));
        let mut csv = csv::Writer::from_writer(file.create()?);
        csv.write_record(header)?;
        Ok(Self { csv, file })
    }

    /// Writes one row of numbers.
    pub(crate) fn write_row(&mut self, row: &[f64]) -> anyhow::Result<()> {
        self.csv.serialize(row).context("writing signals.csv")
    }

    pub(crate) fn finish(mut self) -> anyhow::Result<PathBuf> {
        self.csv.flush().context("writing signals.csv")?;
        drop(self.csv);
        self.file.commit()
    }
}
