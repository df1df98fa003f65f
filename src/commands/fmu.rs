//! `testrig fmu --rig FILE|--preset NAME --out FILE.fmu`: a rig file's plant as an FMI 3.0
//! co-simulation FMU. The zip holds `modelDescription.xml` (written by `testrig_fmu`),
//! the shared library built beside this binary (`libtestrig_fmu.so`, there or in its
//! `deps/` folder, or the file `TESTRIG_FMU_LIBRARY` names) as
//! `binaries/x86_64-linux/<modelIdentifier>.so`, the checked rig as `resources/rig.json` and `documentation/index.html`. Entries carry a
//! fixed date, so the same rig and library give the same bytes.

use std::io::Write;
use std::path::PathBuf;

use anyhow::Context;
use rig::RigTopology;
use testrig::recording::PartialFile;
use testrig::scenario::{preset_rig_with_overrides, rig_with_overrides};
use testrig_fmu::{Causality, RIG_RESOURCE, model_description, model_identifier, variables};
use zip::write::SimpleFileOptions;

use crate::cli::FmuArgs;

/// The shared library's file name as cargo builds it.
const LIBRARY: &str = "libtestrig_fmu.so";

pub fn run(args: &FmuArgs) -> anyhow::Result<()> {
    if !cfg!(all(target_os = "linux", target_arch = "x86_64")) {
        anyhow::bail!("testrig fmu packs an x86_64-linux binary: run it on x86_64 Linux");
    }
    let rig = match (&args.rig_file, &args.preset) {
        (Some(path), _) => rig_with_overrides(path, &args.overrides)?,
        (None, Some(name)) => preset_rig_with_overrides(name, &args.overrides)?,
        (None, None) => anyhow::bail!("--rig FILE or --preset NAME"),
    };
    let library_path = library()?;
    let library = std::fs::read(&library_path)
        .with_context(|| format!("cannot read the FMU's library {}", library_path.display()))?;
    let rig_json = serde_json::to_string_pretty(&rig)?;
    let tool = format!("testrig {}", env!("CARGO_PKG_VERSION"));
    let xml = model_description(&rig, &rig_json, &tool)?;
    let identifier = model_identifier(&rig);
    let docs = documentation(&rig);
    let entries: [(String, &[u8], u32); 4] = [
        ("modelDescription.xml".into(), xml.as_bytes(), 0o644),
        (
            format!("binaries/x86_64-linux/{identifier}.so"),
            &library,
            0o755,
        ),
        (
            format!("resources/{RIG_RESOURCE}"),
            rig_json.as_bytes(),
            0o644,
        ),
        ("documentation/index.html".into(), docs.as_bytes(), 0o644),
    ];
    let bytes = zip_of(&entries)?;
    PartialFile::write_whole(&args.out, &bytes)?;
    let count = variables(&rig).len();
    eprintln!(
        "testrig: {} ({:.1} MB): FMI 3.0 co-simulation FMU `{identifier}` of rig `{}`, {count} variables (docs/fmu.md)",
        args.out.display(),
        bytes.len() as f64 / 1e6,
        rig.name
    );
    Ok(())
}

/// The FMU's shared library: `TESTRIG_FMU_LIBRARY`, else the one built beside this binary,
/// else the one in the folder this binary was built in (`cargo install --path .` builds
/// in the workspace's `target/release` and copies only the binary).
fn library() -> anyhow::Result<PathBuf> {
    if let Some(path) = std::env::var_os("TESTRIG_FMU_LIBRARY") {
        return Ok(PathBuf::from(path));
    }
    let exe = std::env::current_exe().context("cannot find this program's own path")?;
    let dir = exe.parent().map(PathBuf::from).unwrap_or_default();
    let built = PathBuf::from(env!("TESTRIG_BUILD_PROFILE_DIR"));
    let beside = dir.join(LIBRARY);
    // `cargo build` puts the library beside the binary; `cargo test` leaves it in deps/.
    let candidates = [
        beside.clone(),
        dir.join("deps").join(LIBRARY),
        built.join(LIBRARY),
        built.join("deps").join(LIBRARY),
    ];
    if let Some(found) = candidates.iter().find(|c| c.is_file()) {
        return Ok(found.clone());
    }
    anyhow::bail!(
        "the FMU's library {} is not there, nor in {} where this testrig was built: build it with `cargo build --release` (the workspace builds it beside testrig), or name it with TESTRIG_FMU_LIBRARY",
        beside.display(),
        built.display()
    )
}

/// A zip of `(name, bytes, unix mode)` entries, deflated, dated 1980-01-01.
fn zip_of(entries: &[(String, &[u8], u32)]) -> anyhow::Result<Vec<u8>> {
    let mut zip = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    for (name, bytes, mode) in entries {
        let options = SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Deflated)
            .last_modified_time(zip::DateTime::default())
            .unix_permissions(*mode);
        zip.start_file(name.as_str(), options)?;
        zip.write_all(bytes)?;
    }
    Ok(zip.finish()?.into_inner())
}

/// `documentation/index.html`: what the FMU is and its variables.
fn documentation(rig: &RigTopology) -> String {
    let mut rows = String::new();
    for v in variables(rig) {
        let causality = match v.causality {
            Causality::Independent => "independent",
            Causality::Parameter => "parameter",
            Causality::Input => "input",
            Causality::Output => "output",
        };
        let start = v.start.map_or(String::new(), |s| s.to_string());
        rows.push_str(&format!(
            "<tr><td>{}</td><td>{}</td><td>{causality}</td><td>{}</td><td>{start}</td><td>{}</td></tr>\n",
            v.value_reference,
            html(&v.name),
            html(v.unit),
            html(&v.description)
        ));
    }
    format!(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{name}</title></head><body>\n\
         <h1>{name}: a testrig rig as an FMU</h1>\n\
         <p>FMI 3.0 co-simulation. The plant is exact between contact switches and finds every \
         switch on the exact solution; each communication step (a whole number of 0.1 ms \
         samples) is advanced with the inputs held. It starts at rest. Model exchange, event \
         mode and serialized states are not offered. See docs/fmu.md in testrig.</p>\n\
         <table border=\"1\"><tr><th>value reference</th><th>name</th><th>causality</th>\
         <th>unit</th><th>start</th><th>description</th></tr>\n{rows}</table>\n</body></html>\n",
        name = html(&rig.name)
    )
}

fn html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
