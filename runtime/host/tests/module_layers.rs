//! The runtime's modules form layers: no module of `runtime/host/src` imports one that
//! imports it back (directly or around a longer loop). A loop means two modules cannot be
//! understood, tested or changed one without the other; this test names the loop. Imports
//! are the `crate::…` paths in code (doc comments may link anywhere).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every `.rs` file under `dir`.
fn files_under(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            files_under(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The top-level modules of the library: `name.rs` and `name/` beside `lib.rs` (the `onyx`
/// binary under `bin/` is another crate).
fn modules() -> BTreeMap<String, Vec<PathBuf>> {
    let mut modules = BTreeMap::new();
    for entry in std::fs::read_dir(src())
        .expect("src/ is readable")
        .flatten()
    {
        let path = entry.path();
        let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else {
            continue;
        };
        if stem == "lib" || stem == "bin" {
            continue;
        }
        let mut files = Vec::new();
        if path.is_dir() {
            files_under(&path, &mut files);
        } else if path.extension().is_some_and(|e| e == "rs") {
            files.push(path.clone());
        }
        modules
            .entry(stem.to_owned())
            .or_insert_with(Vec::new)
            .extend(files);
    }
    modules
}

/// The items the crate root re-exports, by the module they come from
/// (`pub use headless_host::HeadlessHost;` → `HeadlessHost` → `headless_host`).
fn root_reexports(modules: &BTreeMap<String, Vec<PathBuf>>) -> BTreeMap<String, String> {
    let lib = std::fs::read_to_string(src().join("lib.rs")).expect("lib.rs is readable");
    let mut names = BTreeMap::new();
    for line in lib.lines() {
        let Some(rest) = line.trim().strip_prefix("pub use ") else {
            continue;
        };
        let Some((module, items)) = rest.trim_end_matches(';').split_once("::") else {
            continue;
        };
        if !modules.contains_key(module) {
            continue;
        }
        for item in items.trim_matches(|c| c == '{' || c == '}').split(',') {
            let item = item.trim();
            if !item.is_empty() {
                names.insert(item.to_owned(), module.to_owned());
            }
        }
    }
    names
}

/// The first path segments after each `crate::` in `text`, braces expanded
/// (`crate::{a::X, b}` gives `a` and `b`).
fn crate_paths(text: &str) -> Vec<String> {
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect()
    };
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(at) = rest.find("crate::") {
        let is_word = rest[..at]
            .chars()
            .next_back()
            .is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == '$');
        rest = &rest[at + "crate::".len()..];
        if is_word {
            continue;
        }
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                out.push(ident(item.trim()));
            }
        } else {
            out.push(ident(rest));
        }
    }
    out.retain(|s| !s.is_empty());
    out
}

#[test]
fn no_module_of_the_runtime_imports_one_that_imports_it_back() {
    let modules = modules();
    assert!(
        modules.len() > 10,
        "found only {modules:?} under {}",
        src().display()
    );
    let reexports = root_reexports(&modules);
    let mut edges: BTreeMap<&str, BTreeSet<String>> = BTreeMap::new();
    for (module, files) in &modules {
        let uses = edges.entry(module.as_str()).or_default();
        for file in files {
            let text = std::fs::read_to_string(file).expect("source is readable");
            // Code only: a doc link names another module without depending on it.
            let code: String = text
                .lines()
                .filter(|line| !line.trim_start().starts_with("//"))
                .collect::<Vec<_>>()
                .join("\n");
            for first in crate_paths(&code) {
                let target = if modules.contains_key(&first) {
                    first
                } else if let Some(m) = reexports.get(&first) {
                    m.clone()
                } else {
                    continue;
                };
                if target != *module {
                    uses.insert(target);
                }
            }
        }
    }
    // Depth-first search for a back edge; report the loop it closes.
    fn visit<'a>(
        at: &'a str,
        edges: &'a BTreeMap<&str, BTreeSet<String>>,
        state: &mut BTreeMap<&'a str, u8>,
        path: &mut Vec<&'a str>,
    ) -> Option<Vec<String>> {
        state.insert(at, 1);
        path.push(at);
        for next in edges.get(at).into_iter().flatten() {
            let next = next.as_str();
            match state.get(next) {
                Some(1) => {
                    let start = path.iter().position(|m| *m == next).unwrap_or(0);
                    let mut loop_: Vec<String> =
                        path[start..].iter().map(|m| m.to_string()).collect();
                    loop_.push(next.to_owned());
                    return Some(loop_);
                }
                Some(_) => {}
                None => {
                    if let Some(found) = visit(next, edges, state, path) {
                        return Some(found);
                    }
                }
            }
        }
        path.pop();
        state.insert(at, 2);
        None
    }
    let mut state = BTreeMap::new();
    for module in edges.keys() {
        if state.contains_key(module) {
            continue;
        }
        if let Some(loop_) = visit(module, &edges, &mut state, &mut Vec::new()) {
            let uses: Vec<String> = loop_
                .windows(2)
                .map(|w| format!("`{}` uses `{}`", w[0], w[1]))
                .collect();
            panic!(
                "the runtime's modules import each other in a loop: {}",
                uses.join(", ")
            );
        }
    }
}

#[test]
fn the_import_scanner_sees_plain_grouped_and_nested_paths() {
    let found = crate_paths(
        "use crate::world::WorldState;\nuse crate::{fs, scene::read_scene};\nlet x = \
         crate::render::shader_dir(); $crate::nope",
    );
    assert_eq!(found, ["world", "fs", "scene", "render"]);
}
