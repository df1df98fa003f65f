//! Files written under `NAME.partial` and given their final name only when complete, so
//! no half-written file ever carries a final name.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use anyhow::Context;

use super::journal::note_finished;

/// A file on its way to `path`.
#[derive(Clone, Debug)]
pub struct PartialFile {
    path: PathBuf,
    partial: PathBuf,
}

impl PartialFile {
    /// A file that will be `path`, written meanwhile as `path` + `.partial`.
    pub fn new(path: &Path) -> Self {
        let mut partial = path.as_os_str().to_owned();
        partial.push(".partial");
        Self {
            path: path.to_path_buf(),
            partial: partial.into(),
        }
    }

    /// The name it is written under.
    pub fn partial_path(&self) -> &Path {
        &self.partial
    }

    /// The final name.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Creates the partial file for buffered writing.
    pub fn create(&self) -> anyhow::Result<BufWriter<File>> {
        let file = File::create(&self.partial)
            .with_context(|| format!("cannot write {}", self.partial.display()))?;
        Ok(BufWriter::new(file))
    }

    /// Writes the whole of `contents` to `path` by way of its partial name.
    pub fn write_whole(path: &Path, contents: impl AsRef<[u8]>) -> anyhow::Result<PathBuf> {
        let file = Self::new(path);
        std::fs::write(&file.partial, contents)
            .with_context(|| format!("cannot write {}", file.partial.display()))?;
        file.commit()
    }

    /// Gives the finished file its final name, and notes it in its folder's journal of
    /// finished files where a run keeps one (`super::journal`).
    pub fn commit(&self) -> anyhow::Result<PathBuf> {
        std::fs::rename(&self.partial, &self.path)
            .with_context(|| format!("cannot name {}", self.path.display()))?;
        note_finished(&self.path);
        Ok(self.path.clone())
    }
}
