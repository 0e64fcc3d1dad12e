//! The house's layout (issue 39), checked on the source tree: the folders
//! of `src/` import one another without a circle, the ground floors
//! (`number/`, `poly/`) import nothing above them, no file is named
//! `poisson.rs`, and there is one prime field.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The folders of `src/` (but `tests/`) and, for each, the other folders
/// its non-test code names as `crate::folder`.
fn imports() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let folders: BTreeSet<String> = std::fs::read_dir(&src)
        .expect("src/ is readable")
        .filter_map(|e| e.ok())
        .filter(|e| e.path().is_dir())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|f| f != "tests")
        .collect();
    let mut out = BTreeMap::new();
    for f in &folders {
        let mut uses = BTreeSet::new();
        let mut stack = vec![src.join(f)];
        while let Some(dir) = stack.pop() {
            for entry in std::fs::read_dir(&dir).expect("readable").flatten() {
                let path = entry.path();
                if path.is_dir() {
                    stack.push(path);
                    continue;
                }
                if path.extension().and_then(|e| e.to_str()) != Some("rs") {
                    continue;
                }
                let text = std::fs::read_to_string(&path).expect("readable");
                // the code before the unit tests, comments left out
                let code = text.split("#[cfg(test)]\nmod tests").next().unwrap_or("");
                for line in code.lines() {
                    let line = line.split("//").next().unwrap_or("");
                    for (i, _) in line.match_indices("crate::") {
                        let name: String = line[i + 7..]
                            .chars()
                            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                            .collect();
                        if &name != f && folders.contains(&name) {
                            uses.insert(name);
                        }
                    }
                }
            }
        }
        out.insert(f.clone(), uses);
    }
    out
}

#[test]
fn no_circle_between_folders() {
    let g = imports();
    assert!(g.len() >= 10, "the folders were found: {g:?}");
    // depth-first search for a back edge
    fn visit<'a>(
        n: &'a str,
        g: &'a BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<&'a str>,
        done: &mut BTreeSet<&'a str>,
    ) {
        if done.contains(n) {
            return;
        }
        if let Some(i) = path.iter().position(|p| *p == n) {
            panic!("a circle between folders: {:?}", &path[i..]);
        }
        path.push(n);
        for m in g.get(n).into_iter().flatten() {
            visit(m, g, path, done);
        }
        path.pop();
        done.insert(n);
    }
    let mut done = BTreeSet::new();
    for n in g.keys() {
        visit(n, &g, &mut Vec::new(), &mut done);
    }
}

#[test]
fn the_ground_floors_import_nothing_above_them() {
    let g = imports();
    let above = ["roots", "system", "elim", "geom", "tangent", "natural"];
    for floor in ["number", "poly"] {
        let bad: Vec<&String> = g[floor]
            .iter()
            .filter(|m| above.contains(&m.as_str()))
            .collect();
        assert!(bad.is_empty(), "src/{floor}/ imports {bad:?}");
    }
}

#[test]
fn files_are_named_for_what_they_compute() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut stack = vec![src];
    let mut files = 0;
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).expect("readable").flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else {
                files += 1;
                let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
                assert_ne!(name, "poisson.rs", "{}", path.display());
                // one prime field: number/prime31.rs
                assert_ne!(name, "prime62.rs", "{}", path.display());
            }
        }
    }
    assert!(files > 50);
}
