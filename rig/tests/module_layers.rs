//! The plant's modules form layers: no file imports, directly or through others, a file
//! that imports it. Checked from the source: every `crate::…` and `super::…` path outside
//! comments is an edge, at two levels (the crate's modules, each folder as one; and the
//! files inside each folder: `topology/`, `plant/`, `judge/`).

use std::collections::BTreeMap;
use std::path::Path;

#[path = "support/import_graph.rs"]
mod import_graph;

use import_graph::{Graph, cycle, referenced};

fn files(dir: &Path) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = std::fs::read_dir(dir)
        .expect("source folder")
        .filter_map(|e| {
            let path = e.expect("entry").path();
            let stem = path.file_stem()?.to_str()?.to_string();
            (path.extension()? == "rs")
                .then(|| (stem, std::fs::read_to_string(&path).expect("read")))
        })
        .collect();
    out.sort();
    out
}

/// The sub-folders of the crate's source, each a module of files.
const FOLDERS: [&str; 3] = ["judge", "plant", "topology"];

/// The crate-level graph (each folder one node) and each folder's graph of its files.
fn graphs() -> (Graph, BTreeMap<&'static str, Graph>) {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut crate_level = Graph::new();
    for (name, code) in files(&src) {
        if name != "lib" {
            let edges = referenced(&code, &["crate::"]);
            crate_level.entry(name).or_default().extend(edges);
        }
    }
    let mut folders = BTreeMap::new();
    for folder in FOLDERS {
        let mut inside = Graph::new();
        for (name, code) in files(&src.join(folder)) {
            let mut outward = referenced(&code, &["crate::"]);
            outward.remove(folder);
            crate_level
                .entry(folder.into())
                .or_default()
                .extend(outward);
            if name != "mod" {
                inside.insert(name, referenced(&code, &["super::"]));
            }
        }
        for (name, edges) in inside.iter_mut() {
            edges.remove(name);
        }
        folders.insert(folder, inside);
    }
    for (name, edges) in crate_level.iter_mut() {
        edges.remove(name);
    }
    (crate_level, folders)
}

#[test]
fn the_reference_finder_sees_each_form_of_path() {
    let code =
        "use crate::a::B;\nuse crate::{b::C, c::d};\nlet x = crate::e::f(); // crate::g::h\n";
    let found: Vec<String> = referenced(code, &["crate::"]).into_iter().collect();
    assert_eq!(found, ["a", "b", "c", "e"]);
    let mut looped = Graph::new();
    looped.insert("x".into(), ["y".into()].into());
    looped.insert("y".into(), ["x".into()].into());
    assert!(cycle(&looped).is_some());
}

#[test]
fn the_plant_has_no_import_cycles() {
    let (crate_level, folders) = graphs();
    assert!(
        crate_level["plant"].contains("stride"),
        "graph read: {crate_level:?}"
    );
    assert!(
        folders["plant"]["stepping"].contains("network_plant"),
        "graph read: {folders:?}"
    );
    assert_eq!(cycle(&crate_level), None, "modules of rig");
    for (folder, graph) in &folders {
        assert_eq!(cycle(graph), None, "files of rig/src/{folder}");
    }
}
