//! The core's modules import one another one way (issue 21 item 6): each stage imports the
//! stages before it and the descriptions it reads, never a later stage, so the pipeline
//! order can be read from the module graph. This test reads the sources, builds the graph
//! of the crate's `src/` (a module is a top-level file with its folder; test modules and
//! comments left out; the root `lib.rs`, which drives the stages, is not a node) and fails
//! with the cycle it finds.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// The sibling modules a module's source refers to.
fn references(source: &str, modules: &BTreeSet<String>, own: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in source.lines() {
        let code = line.split("//").next().unwrap_or("");
        for prefix in ["crate::", "super::super::", "super::"] {
            let mut rest = code;
            while let Some(at) = rest.find(prefix) {
                rest = &rest[at + prefix.len()..];
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                if modules.contains(&name) && name != own {
                    out.insert(name);
                }
            }
        }
    }
    out
}

/// The source without its `#[cfg(test)]` modules (everything from the attribute on).
fn without_tests(source: &str) -> &str {
    source
        .find("#[cfg(test)]\nmod ")
        .map_or(source, |at| &source[..at])
}

fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let core = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let modules: BTreeSet<String> = fs::read_dir(&core)
        .unwrap()
        .filter_map(|e| {
            let p = e.unwrap().path();
            (p.extension()? == "rs").then(|| p.file_stem().unwrap().to_string_lossy().into())
        })
        .filter(|m: &String| m != "tests" && m != "lib")
        .collect();
    let mut graph = BTreeMap::new();
    for m in &modules {
        let mut files = vec![core.join(format!("{m}.rs"))];
        if let Ok(dir) = fs::read_dir(core.join(m)) {
            files.extend(dir.map(|e| e.unwrap().path()));
        }
        let mut refs = BTreeSet::new();
        for f in files
            .iter()
            .filter(|f| f.extension().is_some_and(|e| e == "rs"))
        {
            // A child's `super::` is its parent, itself: only `super::super::` and
            // `crate::` leave the module there.
            let source = fs::read_to_string(f).unwrap();
            let source = without_tests(&source);
            let source = if f.parent() == Some(&core) {
                source.to_string()
            } else {
                source
                    .replace("super::super::", "crate::")
                    .replace("super::", "")
            };
            refs.extend(references(&source, &modules, m));
        }
        graph.insert(m.clone(), refs);
    }
    graph
}

/// A cycle of `graph`, if it has one.
fn cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        m: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = path.iter().position(|p| p == m) {
            let mut c = path[at..].to_vec();
            c.push(m.to_string());
            return Some(c);
        }
        if done.contains(m) {
            return None;
        }
        path.push(m.to_string());
        for next in &graph[m] {
            if let Some(c) = visit(next, graph, path, done) {
                return Some(c);
            }
        }
        path.pop();
        done.insert(m.to_string());
        None
    }
    let mut done = BTreeSet::new();
    graph
        .keys()
        .find_map(|m| visit(m, graph, &mut Vec::new(), &mut done))
}

#[test]
fn core_modules_import_one_way() {
    let g = graph();
    // The reader sees real edges: the graph is not empty by accident.
    assert!(g["clip"].contains("vertex"), "{g:?}");
    assert!(g["fragment"].contains("raster"), "{g:?}");
    if let Some(c) = cycle(&g) {
        panic!("the core's modules import in a circle: {}", c.join(" -> "));
    }
    // The stages in pipeline order: none imports a later one.
    let order = ["vertex", "clip", "setup", "raster", "fragment"];
    for (i, m) in order.iter().enumerate() {
        for later in &order[i + 1..] {
            assert!(
                !g[*m].contains(*later),
                "{m} imports the later stage {later}"
            );
        }
    }
}

#[test]
fn the_cycle_finder_finds_cycles() {
    let edge = |a: &str, b: &[&str]| (a.to_string(), b.iter().map(|s| s.to_string()).collect());
    let g: BTreeMap<String, BTreeSet<String>> = [
        edge("a", &["b"]),
        edge("b", &["c"]),
        edge("c", &["a"]),
        edge("d", &[]),
    ]
    .into();
    assert_eq!(cycle(&g).unwrap(), ["a", "b", "c", "a"]);
    let g: BTreeMap<String, BTreeSet<String>> =
        [edge("a", &["b", "c"]), edge("b", &["c"]), edge("c", &[])].into();
    assert_eq!(cycle(&g), None);
}
