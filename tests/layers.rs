//! The application's folders form layers (ARCHITECTURE.md): each module of `src/` imports
//! only modules of lower layers, never one above it or beside it. Checked from the
//! source: every `crate::…` path outside comments, in every file of a module's folder, is
//! an import of that top module.

use std::collections::BTreeSet;
use std::path::Path;

/// The layers, lowest first; a module may import those of lower layers only.
const LAYERS: &[&[&str]] = &[
    &["vocabulary"],
    &["recording", "wav_input"],
    &["plots"],
    &["chain"],
    &["rig_point"],
    &["rig_roles"],
    &["scenario"],
    &["runtime"],
    &["steady_point"],
    &["panel", "sweep"],
    &["calibrate"],
];

fn layer_of(module: &str) -> Option<usize> {
    LAYERS.iter().position(|layer| layer.contains(&module))
}

/// Top modules named after `crate::` in `code`, comments left out.
fn imports(code: &str) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    for line in code.lines() {
        let line = line.split("//").next().unwrap_or("");
        let mut rest = line;
        while let Some(at) = rest.find("crate::") {
            rest = &rest[at + "crate::".len()..];
            let groups: Vec<&str> = match rest.strip_prefix('{') {
                Some(inner) => inner.split('}').next().unwrap_or("").split(',').collect(),
                None => vec![rest],
            };
            for group in groups {
                let name: String = group
                    .trim()
                    .chars()
                    .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '_')
                    .collect();
                if !name.is_empty() {
                    names.insert(name);
                }
            }
        }
    }
    names
}

/// Every `.rs` file below `path` (or `path` itself), with its text.
fn sources(path: &Path) -> Vec<(String, String)> {
    if path.is_file() {
        let text = std::fs::read_to_string(path).expect("read");
        return vec![(path.display().to_string(), text)];
    }
    let mut out = Vec::new();
    for entry in std::fs::read_dir(path).expect("folder") {
        let p = entry.expect("entry").path();
        if p.is_dir() || p.extension().is_some_and(|e| e == "rs") {
            out.extend(sources(&p));
        }
    }
    out
}

#[test]
fn each_module_of_the_application_imports_only_lower_layers() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let lib = std::fs::read_to_string(src.join("lib.rs")).expect("lib.rs");
    let modules: Vec<String> = lib
        .lines()
        .filter_map(|l| l.trim().strip_prefix("pub mod "))
        .map(|l| l.trim_end_matches(';').to_string())
        .collect();
    assert!(modules.len() >= 10, "{modules:?}");
    let mut wrong = Vec::new();
    for module in &modules {
        let layer = layer_of(module).unwrap_or_else(|| {
            panic!("`{module}` is in no layer of this test and ARCHITECTURE.md")
        });
        let folder = src.join(module);
        let path = if folder.is_dir() {
            folder
        } else {
            src.join(format!("{module}.rs"))
        };
        for (file, text) in sources(&path) {
            for imported in imports(&text) {
                if &imported == module {
                    continue;
                }
                let Some(target) = layer_of(&imported) else {
                    continue;
                };
                if target >= layer {
                    wrong.push(format!(
                        "{file} (layer {layer}) imports crate::{imported} (layer {target})"
                    ));
                }
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "imports upward or sideways:\n{}",
        wrong.join("\n")
    );
}
