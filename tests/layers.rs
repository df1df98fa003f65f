//! The application's folders form layers (ARCHITECTURE.md): each module of `src/` imports
//! only modules of lower layers, never one above it or beside it. Checked from the
//! source: every `crate::…` path outside comments, in every file of a module's folder, is
//! an import of that top module.

use std::collections::BTreeSet;
use std::path::Path;

#[path = "../rig/tests/support/import_graph.rs"]
mod import_graph;

use import_graph::{Graph, cycle, referenced};

/// The layers, lowest first; a module may import those of lower layers only.
const LAYERS: &[&[&str]] = &[
    &["vocabulary"],
    &["approach_name"],
    &["recording", "wav_input"],
    &["plots"],
    &["chain"],
    &["steady_point"],
    &["rig_roles"],
    &["scenario"],
    &["runtime"],
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

/// The graph of the files directly in `dir` (each sub-folder one node), whose module path
/// is `module` (`crate::sweep::`; `crate::` for a crate's root): an edge for every
/// `super::x` and every `module` + `x`.
fn folder_graph(dir: &Path, module: &str) -> Graph {
    let prefixes = ["super::", module];
    let mut graph = Graph::new();
    for entry in std::fs::read_dir(dir).expect("folder") {
        let path = entry.expect("entry").path();
        let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else {
            continue;
        };
        let (node, code) = if path.is_dir() {
            let code: String = sources(&path).into_iter().map(|(_, t)| t).collect();
            (stem.to_string(), code)
        } else if path.extension().is_some_and(|e| e == "rs")
            && !["mod", "lib", "main"].contains(&stem)
        {
            (
                stem.to_string(),
                std::fs::read_to_string(&path).expect("read"),
            )
        } else {
            continue;
        };
        let mut edges = referenced(&code, &prefixes);
        edges.remove(&node);
        graph.entry(node).or_default().extend(edges);
    }
    graph
}

/// Every folder of the application's modules (and of the Python extension's crate), with
/// its module path.
fn folders() -> Vec<(std::path::PathBuf, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out = vec![(root.join("python/src"), "crate::".to_string())];
    let mut stack = vec![(root.join("src"), "crate::".to_string())];
    while let Some((dir, module)) = stack.pop() {
        for entry in std::fs::read_dir(&dir).expect("folder") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                let name = path.file_name().and_then(|n| n.to_str()).expect("name");
                let inner = format!("{module}{name}::");
                out.push((path.clone(), inner.clone()));
                stack.push((path, inner));
            }
        }
    }
    out
}

#[test]
fn the_circle_finder_sees_each_form_of_path_and_a_circle() {
    let code =
        "use super::a::B;\nuse crate::sweep::{b::C, c};\nlet x = super::e::f(); // super::g::h\n";
    let prefixes = ["super::", "crate::sweep::"];
    let found: Vec<String> = referenced(code, &prefixes).into_iter().collect();
    assert_eq!(found, ["a", "b", "e"]);
    let mut looped = Graph::new();
    looped.insert("x".into(), ["y".into()].into());
    looped.insert("y".into(), ["z".into()].into());
    looped.insert("z".into(), ["x".into()].into());
    assert_eq!(
        cycle(&looped),
        Some(vec!["x".into(), "y".into(), "z".into(), "x".into()])
    );
}

#[test]
fn no_file_of_a_folder_imports_one_that_imports_it() {
    let folders = folders();
    let graph_of = |tail: &str| {
        let (dir, module) = folders
            .iter()
            .find(|(dir, _)| dir.ends_with(tail))
            .expect("folder");
        folder_graph(dir, module)
    };
    // The graphs are read: edges known to be there are found.
    assert!(graph_of("src/sweep")["knocked"].contains("series"));
    assert!(graph_of("src/commands")["simulate"].contains("signal_writer"));
    assert!(graph_of("python/src")["simulate"].contains("argument_names"));
    assert!(graph_of("src/runtime")["threaded_run"].contains("sinks"));
    let circles: Vec<String> = folders
        .iter()
        .filter_map(|(dir, module)| {
            cycle(&folder_graph(dir, module))
                .map(|c| format!("{}: {}", dir.display(), c.join(" → ")))
        })
        .collect();
    assert!(
        circles.is_empty(),
        "files that import, directly or through others, a file that imports them:\n{}",
        circles.join("\n")
    );
}
