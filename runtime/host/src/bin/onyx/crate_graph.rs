//! [`CrateSources`]: the files whose change rebuilds a plugin crate — its own sources and
//! manifests and those of every local crate it depends on (path dependencies and workspace
//! members), as `cargo metadata` resolves them.

use std::collections::{BTreeSet, HashMap, VecDeque};
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use anyhow::{anyhow, Context as _};
use serde_json::Value;

/// Where a plugin crate's inputs live: folders watched recursively and single files.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CrateSources {
    /// The local packages it is built from (itself first), by name.
    pub packages: Vec<String>,
    /// Source folders (each target's folder, e.g. `src/`), watched recursively.
    pub dirs: BTreeSet<PathBuf>,
    /// Manifests, build scripts, the lock file, and sources that sit at a package's root.
    pub files: BTreeSet<PathBuf>,
}

/// Target kinds that go into a library build (not tests, examples, benches or binaries).
const LIBRARY_KINDS: &[&str] = &[
    "lib",
    "rlib",
    "dylib",
    "cdylib",
    "staticlib",
    "proc-macro",
    "custom-build",
];

impl CrateSources {
    /// Asks `cargo metadata` for the crate at `manifest` and everything local it depends on
    /// (normal and build dependencies; dev-dependencies do not go into the library).
    pub fn of(cargo: &OsString, manifest: &Path) -> anyhow::Result<Self> {
        let output = Command::new(cargo)
            .args(["metadata", "--format-version", "1", "--manifest-path"])
            .arg(manifest)
            .stdin(Stdio::null())
            .stderr(Stdio::inherit())
            .output()
            .with_context(|| format!("cannot run `{} metadata`", cargo.to_string_lossy()))?;
        if !output.status.success() {
            return Err(anyhow!(
                "`cargo metadata` failed for `{}` ({}); its message is above",
                manifest.display(),
                output.status
            ));
        }
        let metadata: Value = serde_json::from_slice(&output.stdout)
            .context("`cargo metadata` printed something that is not its JSON")?;
        Self::from_metadata(&metadata, manifest)
    }

    /// The sources of the package whose manifest is `manifest`, read from `cargo metadata`'s
    /// JSON.
    pub fn from_metadata(metadata: &Value, manifest: &Path) -> anyhow::Result<Self> {
        let packages: HashMap<&str, &Value> = metadata["packages"]
            .as_array()
            .context("`cargo metadata` lists no packages")?
            .iter()
            .filter_map(|p| Some((p["id"].as_str()?, p)))
            .collect();
        let wanted = canonical(manifest);
        let root = packages
            .iter()
            .find(|(_, p)| {
                p["manifest_path"]
                    .as_str()
                    .is_some_and(|m| canonical(Path::new(m)) == wanted)
            })
            .map(|(id, _)| *id)
            .with_context(|| {
                format!(
                    "`cargo metadata` does not list the package of `{}`",
                    manifest.display()
                )
            })?;
        let nodes: HashMap<&str, &Value> = metadata["resolve"]["nodes"]
            .as_array()
            .map(|nodes| {
                nodes
                    .iter()
                    .filter_map(|n| Some((n["id"].as_str()?, n)))
                    .collect()
            })
            .unwrap_or_default();

        let mut sources = Self::default();
        let mut seen = BTreeSet::from([root]);
        let mut queue = VecDeque::from([root]);
        while let Some(id) = queue.pop_front() {
            let Some(package) = packages.get(id) else {
                continue;
            };
            if !package["source"].is_null() {
                continue; // from a registry or git: it does not change under us
            }
            sources.add_package(package);
            let deps = nodes.get(id).and_then(|n| n["deps"].as_array());
            for dep in deps.into_iter().flatten() {
                let builds_in = dep["dep_kinds"].as_array().is_none_or(|kinds| {
                    kinds
                        .iter()
                        .any(|k| k["kind"].is_null() || k["kind"] == "build")
                });
                if let (true, Some(dep_id)) = (builds_in, dep["pkg"].as_str()) {
                    if seen.insert(dep_id) {
                        queue.push_back(dep_id);
                    }
                }
            }
        }
        if let Some(workspace) = metadata["workspace_root"].as_str() {
            let workspace = Path::new(workspace);
            sources.files.insert(workspace.join("Cargo.toml"));
            sources.files.insert(workspace.join("Cargo.lock"));
        }
        Ok(sources)
    }

    fn add_package(&mut self, package: &Value) {
        let Some(manifest) = package["manifest_path"].as_str().map(PathBuf::from) else {
            return;
        };
        let root = manifest.parent().map(Path::to_path_buf).unwrap_or_default();
        if let Some(name) = package["name"].as_str() {
            self.packages.push(name.to_owned());
        }
        self.files.insert(manifest);
        for target in package["targets"].as_array().into_iter().flatten() {
            let builds_library = target["kind"]
                .as_array()
                .is_some_and(|kinds| kinds.iter().any(|k| LIBRARY_KINDS.iter().any(|l| k == l)));
            let Some(src) = target["src_path"].as_str().map(PathBuf::from) else {
                continue;
            };
            if !builds_library {
                continue;
            }
            match src.parent() {
                // A source at the package root (`build.rs`, `lib.rs`): that file only, not
                // the whole folder (which holds `target/`).
                Some(dir) if dir == root => {
                    self.files.insert(src);
                }
                Some(dir) => {
                    self.dirs.insert(dir.to_path_buf());
                }
                None => {}
            }
        }
    }

    /// Whether a change to `path` calls for a rebuild.
    pub fn contains(&self, path: &Path) -> bool {
        let hidden_or_backup = path.file_name().is_some_and(|n| {
            let n = n.to_string_lossy();
            n.starts_with('.') || n.ends_with('~') || n.ends_with(".swp") || n.ends_with(".swx")
        });
        if hidden_or_backup {
            return false;
        }
        self.files.contains(path) || self.dirs.iter().any(|dir| path.starts_with(dir))
    }

    /// The folders to watch: each source folder recursively, and the folder of each file
    /// (editors replace files rather than rewrite them), each once.
    pub fn watch_list(&self) -> Vec<(PathBuf, bool)> {
        let mut list: Vec<(PathBuf, bool)> = self.dirs.iter().map(|d| (d.clone(), true)).collect();
        for file in &self.files {
            if let Some(dir) = file.parent() {
                let covered = self.dirs.iter().any(|d| dir.starts_with(d));
                if !covered && !list.iter().any(|(d, _)| d == dir) {
                    list.push((dir.to_path_buf(), false));
                }
            }
        }
        list
    }
}

fn canonical(path: &Path) -> PathBuf {
    path.canonicalize().unwrap_or_else(|_| path.to_path_buf())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn package(id: &str, dir: &str, source: Value, targets: Value) -> Value {
        json!({
            "id": id,
            "name": id,
            "manifest_path": format!("{dir}/Cargo.toml"),
            "source": source,
            "targets": targets,
        })
    }

    fn lib(dir: &str) -> Value {
        json!([{ "kind": ["cdylib", "rlib"], "src_path": format!("{dir}/src/lib.rs") }])
    }

    /// A plugin with a path dependency (which has a build script and a dependency of its
    /// own), a registry dependency, and a dev-dependency on a local crate.
    fn metadata() -> Value {
        json!({
            "workspace_root": "/w/game",
            "packages": [
                package("game", "/w/game", Value::Null, json!([
                    { "kind": ["cdylib", "rlib"], "src_path": "/w/game/src/lib.rs" },
                    { "kind": ["test"], "src_path": "/w/game/tests/it.rs" },
                ])),
                package("logic", "/w/logic", Value::Null, json!([
                    { "kind": ["lib"], "src_path": "/w/logic/src/lib.rs" },
                    { "kind": ["custom-build"], "src_path": "/w/logic/build.rs" },
                ])),
                package("shapes", "/w/shapes", Value::Null, lib("/w/shapes")),
                package("serde", "/r/serde", json!("registry+https://example"), lib("/r/serde")),
                package("harness", "/w/harness", Value::Null, lib("/w/harness")),
            ],
            "resolve": { "nodes": [
                { "id": "game", "deps": [
                    { "pkg": "logic", "dep_kinds": [{ "kind": null }] },
                    { "pkg": "serde", "dep_kinds": [{ "kind": null }] },
                    { "pkg": "harness", "dep_kinds": [{ "kind": "dev" }] },
                ]},
                { "id": "logic", "deps": [
                    { "pkg": "shapes", "dep_kinds": [{ "kind": "build" }] },
                ]},
                { "id": "shapes", "deps": [] },
                { "id": "serde", "deps": [] },
                { "id": "harness", "deps": [] },
            ]},
        })
    }

    #[test]
    fn every_local_crate_the_library_is_built_from_is_watched() {
        let sources =
            CrateSources::from_metadata(&metadata(), Path::new("/w/game/Cargo.toml")).unwrap();
        assert_eq!(sources.packages, ["game", "logic", "shapes"]);
        for yes in [
            "/w/game/src/lib.rs",
            "/w/game/src/a/b.rs",
            "/w/game/Cargo.toml",
            "/w/game/Cargo.lock",
            "/w/logic/src/rules.rs",
            "/w/logic/Cargo.toml",
            "/w/logic/build.rs",
            "/w/shapes/src/lib.rs",
        ] {
            assert!(sources.contains(Path::new(yes)), "{yes}");
        }
        for no in [
            "/w/game/tests/it.rs",
            "/w/game/target/debug/libgame.so",
            "/w/logic/src/.rules.rs.swp",
            "/w/logic/src/rules.rs~",
            "/w/harness/src/lib.rs",
            "/r/serde/src/lib.rs",
            "/w/logic/README.md",
        ] {
            assert!(!sources.contains(Path::new(no)), "{no}");
        }
        let watched = sources.watch_list();
        for expected in [
            (PathBuf::from("/w/game/src"), true),
            (PathBuf::from("/w/logic/src"), true),
            (PathBuf::from("/w/game"), false),
            (PathBuf::from("/w/logic"), false),
        ] {
            assert!(watched.contains(&expected), "{expected:?} in {watched:?}");
        }
        assert!(!watched.iter().any(|(d, _)| d.starts_with("/r")));
    }

    #[test]
    fn a_manifest_cargo_does_not_list_is_an_error() {
        let error =
            CrateSources::from_metadata(&metadata(), Path::new("/w/other/Cargo.toml")).unwrap_err();
        assert!(error.to_string().contains("/w/other/Cargo.toml"), "{error}");
    }
}
