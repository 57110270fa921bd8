//! Issue 23: a corpus test must never skip while the corpus is in the tree. Corpus tests skip
//! only through `common/corpus.rs`; this checks that the helper finds the corpus whenever any
//! of it is there, and that no test looks for the corpus on its own.

#[path = "common/corpus.rs"]
mod corpus;

/// The `.m3g` files `SOURCES.md` lists (first column of its table).
fn listed_files(sources: &str) -> Vec<String> {
    sources
        .lines()
        .filter_map(|l| l.strip_prefix("| "))
        .filter_map(|l| l.split([' ', '|']).next())
        .filter(|f| f.ends_with(".m3g"))
        .map(str::to_string)
        .collect()
}

#[test]
fn the_corpus_helper_finds_the_corpus_whenever_it_is_there() {
    let path = corpus::corpus_path();
    let m3g_files = std::fs::read_dir(&path)
        .into_iter()
        .flatten()
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "m3g"))
        .count();
    if m3g_files == 0 && !path.exists() {
        // A tree without the corpus: the corpus tests skip, which is what they may do here.
        println!("no corpus at {}: nothing to guard", path.display());
        return;
    }
    let dir = corpus::m3g_corpus()
        .unwrap_or_else(|| panic!("{m3g_files} corpus files present, yet the tests skip"));
    let sources = std::fs::read_to_string(dir.join("SOURCES.md")).unwrap();
    let listed = listed_files(&sources);
    assert!(listed.len() >= 10, "SOURCES.md lists only {listed:?}");
    for f in &listed {
        assert!(
            dir.join(f).is_file(),
            "SOURCES.md lists {f}, not in {dir:?}"
        );
    }
    assert_eq!(
        m3g_files,
        listed.len(),
        "an .m3g file SOURCES.md does not list"
    );
    // Every reference image belongs to a corpus file (`<stem>_t<ms>.png`).
    for e in std::fs::read_dir(dir.join("reference")).unwrap().flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        if let Some((stem, _)) = name.rsplit_once("_t") {
            assert!(
                listed.contains(&format!("{stem}.m3g")),
                "reference image {name} without its file"
            );
        }
    }
}

/// No test builds its own corpus path (which could point elsewhere and skip) and every test
/// that can skip for want of the corpus gets it from the helper.
#[test]
fn every_corpus_test_gets_the_corpus_from_the_helper() {
    // Every crate's tests: the corpus is shared by the whole workspace.
    let root = corpus::workspace_root();
    let crates = std::fs::read_dir(root.join("crates")).unwrap().flatten();
    let test_dirs =
        std::iter::once(root.join("tests")).chain(crates.map(|c| c.path().join("tests")));
    let mut checked = 0;
    let mut wrong = Vec::new();
    for p in test_dirs.flat_map(|d| std::fs::read_dir(d).into_iter().flatten().flatten()) {
        let p = p.path();
        if p.extension().is_none_or(|x| x != "rs") {
            continue;
        }
        let text = std::fs::read_to_string(&p).unwrap();
        let code: String = text
            .lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .collect::<Vec<_>>()
            .join("\n");
        let name = p
            .strip_prefix(&root)
            .unwrap()
            .to_string_lossy()
            .into_owned();
        // This file names the path only to look for it.
        if code.contains("data/m3g") && !name.ends_with("corpus_guard.rs") {
            wrong.push(format!("{name} names the corpus directory itself"));
        }
        if code.contains("corpus::") {
            checked += 1;
        } else if code.to_lowercase().contains("corpus") && code.contains("skip") {
            wrong.push(format!("{name} skips corpus work without the helper"));
        }
    }
    assert!(wrong.is_empty(), "{wrong:#?}");
    // m3g_loader, m3g_animation, m3g_hostile, m3g_cli and this file.
    assert!(
        checked >= 5,
        "only {checked} test files use the corpus helper"
    );
}

#[test]
fn listed_files_reads_the_sources_table() {
    let table = "| file | from |\n|---|---|\n| a.m3g | x |\n| b.m3g (+ b.png) | y |\n";
    assert_eq!(listed_files(table), ["a.m3g", "b.m3g"]);
}
