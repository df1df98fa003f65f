//! The graph of which source file imports which, read from the text, and its circles:
//! shared by the layer tests of `rig` (`module_layers.rs`) and of the application
//! (`tests/layers.rs`, which includes this file by path).

use std::collections::{BTreeMap, BTreeSet};

/// Each node's names it refers to.
pub type Graph = BTreeMap<String, BTreeSet<String>>;

/// Module names a piece of code refers to after any of `prefixes` (`crate::`, `super::`,
/// `crate::sweep::`), followed by `::`; comments left out.
pub fn referenced(code: &str, prefixes: &[&str]) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    for line in code.lines() {
        let line = line.split("//").next().unwrap_or("");
        for prefix in prefixes {
            let mut rest = line;
            while let Some(at) = rest.find(prefix) {
                rest = &rest[at + prefix.len()..];
                let groups: Vec<&str> = match rest.strip_prefix('{') {
                    Some(inner) => inner.split('}').next().unwrap_or("").split(',').collect(),
                    None => vec![rest],
                };
                for group in groups {
                    let group = group.trim();
                    let name: String = group
                        .chars()
                        .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '_')
                        .collect();
                    if !name.is_empty() && group[name.len()..].starts_with("::") {
                        names.insert(name);
                    }
                }
            }
        }
    }
    names
}

/// A cycle of `graph`, if there is one, as the names along it (the first repeated last).
pub fn cycle(graph: &Graph) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &Graph,
        done: &mut BTreeSet<String>,
        path: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = path.iter().position(|n| n == node) {
            let mut found = path[at..].to_vec();
            found.push(node.to_string());
            return Some(found);
        }
        if done.contains(node) {
            return None;
        }
        path.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            if let Some(found) = visit(next, graph, done, path) {
                return Some(found);
            }
        }
        path.pop();
        done.insert(node.to_string());
        None
    }
    let mut done = BTreeSet::new();
    graph
        .keys()
        .find_map(|n| visit(n, graph, &mut done, &mut Vec::new()))
}
