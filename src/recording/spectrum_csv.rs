//! A displayed spectrum as CSV: `# key: value` metadata lines, the header
//! `frequency_hz,power,alias_of_hz`, one row per line (the format `testrig analyse` writes).

use std::io::Write;
use std::path::Path;

use anyhow::Context;
use instruments::Line;

use super::partial::PartialFile;

/// What the `alias_of_hz` column holds, for the metadata of every spectrum CSV.
pub const ALIAS_COLUMN: &str = "true frequency of a component aliased onto the line; empty for a real component or one below the ADC's quantisation noise per line";

/// Metadata lines written as `# key: value` before the header.
pub type Metadata = Vec<(&'static str, String)>;

/// Writes `path` with metadata, a header `frequency_hz,power,alias_of_hz` and one row per line.
pub fn write_spectrum_csv(
    path: &Path,
    metadata: &Metadata,
    lines: &[Line],
    alias_of: &[Option<f64>],
) -> anyhow::Result<()> {
    let target = PartialFile::new(path);
    let mut file = target.create()?;
    for (key, value) in metadata {
        writeln!(file, "# {key}: {value}")?;
    }
    let mut csv = csv::Writer::from_writer(file);
    csv.write_record(["frequency_hz", "power", "alias_of_hz"])?;
    for (line, alias) in lines.iter().zip(alias_of) {
        let alias = alias.map_or(String::new(), |f| format!("{f}"));
        csv.write_record([
            format!("{}", line.frequency_hz),
            format!("{:e}", line.value),
            alias,
        ])?;
    }
    csv.flush()
        .with_context(|| format!("writing {}", path.display()))?;
    drop(csv);
    target.commit()?;
    Ok(())
}
