//! UFF dataset 58 time histories streamed to disk: each channel's values go to a body file
//! as they come; finishing writes the datasets (header with the final count, values,
//! trailer) into one `.uff` file, so memory stays flat however long the run.

use std::fs::File;
use std::io::{BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};

use anyhow::Context;

use super::fortran_e::FortranE;
use super::frame_writer::{FrameWriter, Written};
use super::partial::PartialFile;
use super::uff58::{Uff58Abscissa, Uff58Record, write_uff58_header, write_uff58_trailer};

/// What identifies one channel's dataset.
#[derive(Clone, Debug, PartialEq)]
pub struct Uff58Channel {
    /// ID line 1.
    pub description: String,
    /// Response entity name.
    pub response_name: String,
    /// Response node.
    pub response_node: u32,
    /// Ordinate specific data type (3 strain, 19 rpm, 0 unknown).
    pub ordinate_type: u32,
    /// Ordinate unit label.
    pub ordinate_unit: String,
}

struct Body {
    channel: Uff58Channel,
    path: PathBuf,
    writer: BufWriter<File>,
    pending: Vec<f64>,
    text: FortranE,
    count: usize,
}

/// Time histories of several channels on one time base, being written.
pub struct Uff58Recorder {
    file: PartialFile,
    source: String,
    start_s: f64,
    step_s: f64,
    bodies: Vec<Body>,
}

impl Uff58Recorder {
    /// Starts `path` for `channels` sampled every `step_s` from `start_s`; `source` is ID line 2.
    pub fn create(
        path: &Path,
        channels: Vec<Uff58Channel>,
        source: &str,
        start_s: f64,
        step_s: f64,
    ) -> anyhow::Result<Self> {
        let file = PartialFile::new(path);
        let bodies = channels
            .into_iter()
            .enumerate()
            .map(|(i, channel)| {
                let body = PathBuf::from(format!("{}.{i}", file.partial_path().display()));
                let writer = File::create(&body)
                    .with_context(|| format!("cannot write {}", body.display()))?;
                Ok(Body {
                    channel,
                    path: body,
                    writer: BufWriter::new(writer),
                    pending: Vec::with_capacity(4),
                    text: FortranE::default(),
                    count: 0,
                })
            })
            .collect::<anyhow::Result<_>>()?;
        Ok(Self {
            file,
            source: source.to_string(),
            start_s,
            step_s,
            bodies,
        })
    }

    /// Appends one frame: a value per channel, in channel order.
    pub fn write_frame(&mut self, values: &[f64]) -> anyhow::Result<()> {
        for (body, &v) in self.bodies.iter_mut().zip(values) {
            body.pending.push(v);
            body.count += 1;
            if body.pending.len() == 4 {
                body.text
                    .write_values(&mut body.writer, &body.pending)
                    .with_context(|| format!("writing {}", body.path.display()))?;
                body.pending.clear();
            }
        }
        Ok(())
    }

    /// Writes the datasets into the final file and removes the bodies.
    pub fn finish(self) -> anyhow::Result<PathBuf> {
        let mut out = self.file.create()?;
        for mut body in self.bodies {
            body.text.write_values(&mut body.writer, &body.pending)?;
            body.writer.flush()?;
            drop(body.writer);
            let c = &body.channel;
            let header = Uff58Record {
                description: &c.description,
                source: &self.source,
                function_type: 1,
                response_name: &c.response_name,
                response_node: c.response_node,
                ordinate_type: c.ordinate_type,
                ordinate_unit: &c.ordinate_unit,
                abscissa: Uff58Abscissa::Time {
                    start_s: self.start_s,
                    step_s: self.step_s,
                },
                values: &[],
            };
            write_uff58_header(&mut out, &header, body.count)?;
            let mut reader = BufReader::new(File::open(&body.path)?);
            std::io::copy(&mut reader, &mut out)
                .with_context(|| format!("assembling {}", self.file.partial_path().display()))?;
            write_uff58_trailer(&mut out)?;
            std::fs::remove_file(&body.path).ok();
        }
        out.flush()
            .with_context(|| format!("writing {}", self.file.partial_path().display()))?;
        drop(out);
        self.file.commit()
    }
}

impl FrameWriter for Uff58Recorder {
    fn write_frame(&mut self, _time_s: f64, values: &[f64]) -> anyhow::Result<()> {
        Uff58Recorder::write_frame(self, values)
    }

    fn finish(self: Box<Self>) -> anyhow::Result<Written> {
        Ok(Written {
            files: vec![Uff58Recorder::finish(*self)?],
            facts: Vec::new(),
        })
    }
}
