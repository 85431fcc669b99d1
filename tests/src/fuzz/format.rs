//! [`Format`]: each format's corpus and how one mutated case runs through the real reader.

use std::path::{Path, PathBuf};

/// A file format Onyx reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// RON scene files, loaded into a headless host that then runs frames and saves them.
    Scene,
    /// Wavefront OBJ models (with their MTL files and textures beside them).
    Obj,
    /// MTL material libraries, loaded through an OBJ that names them.
    Mtl,
    /// PNG images, decoded as textures.
    Png,
    /// JPEG images, decoded as textures.
    Jpeg,
    /// glTF 2.0 JSON files (with their buffers and images beside them).
    Gltf,
    /// glTF 2.0 binary files.
    Glb,
    /// Plugin libraries, through the check the host runs before the system loader (and, in
    /// the long run, the loader itself).
    Library,
}

/// What a case did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// The input was read (or the library loaded).
    Read,
    /// It was refused with an error (the sentence).
    Refused(String),
}

impl Format {
    /// Every format, in report order.
    pub const ALL: [Format; 8] = [
        Format::Scene,
        Format::Obj,
        Format::Mtl,
        Format::Png,
        Format::Jpeg,
        Format::Gltf,
        Format::Glb,
        Format::Library,
    ];

    /// Its name on the command line and in recipes.
    pub fn name(self) -> &'static str {
        match self {
            Format::Scene => "scene",
            Format::Obj => "obj",
            Format::Mtl => "mtl",
            Format::Png => "png",
            Format::Jpeg => "jpeg",
            Format::Gltf => "gltf",
            Format::Glb => "glb",
            Format::Library => "library",
        }
    }

    /// The format called `name`.
    pub fn from_name(name: &str) -> Option<Format> {
        Self::ALL.into_iter().find(|f| f.name() == name)
    }

    /// Case `case` of a run with `seed`: [`mutate`](super::mutate)d, and for half of the PNG
    /// cases with the chunk checksums made right again (so the decoder gets past them).
    pub fn mutate(self, original: &[u8], seed: u64, case: u64) -> Vec<u8> {
        let mut bytes = super::mutate(original, seed, case, self.is_text());
        if self == Format::Png && case.is_multiple_of(2) {
            fix_png_checksums(&mut bytes);
        }
        bytes
    }

    /// Whether it is text (token-level mutations apply).
    pub fn is_text(self) -> bool {
        matches!(
            self,
            Format::Scene | Format::Obj | Format::Mtl | Format::Gltf
        )
    }

    /// Where its corpus lives: the repository's scenes, the shared fixtures, or this build's
    /// plugin libraries.
    pub fn root(self) -> PathBuf {
        match self {
            Format::Scene => repository().join("assets/scenes"),
            Format::Library => crate::target_dir(),
            _ => repository().join("../shared/fixtures"),
        }
    }

    /// The corpus files, relative to [`Format::root`], sorted. Empty when the root is absent
    /// (the shared fixtures on a machine without them).
    pub fn corpus(self) -> Vec<String> {
        let root = self.root();
        let mut files = Vec::new();
        match self {
            Format::Library => {
                // One plugin library is enough: they share their layout.
                let name =
                    onyx_runtime::plugins::plugin_search::library_file_name("fixture-native");
                if root.join(&name).is_file() {
                    files.push(name);
                }
            }
            _ => walk(&root, &root, &mut files),
        }
        files.retain(|f| self.wants(f));
        // Big images and models cost seconds each in a debug build and fuzz no more of the
        // reader than small ones (the headers and structure are the same).
        let cap = match self {
            Format::Png | Format::Jpeg => 256 << 10,
            Format::Library => u64::MAX,
            _ => 1 << 20,
        };
        files.retain(|f| std::fs::metadata(root.join(f)).is_ok_and(|m| m.len() <= cap));
        if self == Format::Mtl {
            files.retain(|f| !objs_naming(&root.join(f)).is_empty());
        }
        files.sort();
        files
    }

    fn wants(self, file: &str) -> bool {
        let lower = file.to_ascii_lowercase();
        match self {
            Format::Scene => lower.ends_with(".ron"),
            Format::Obj => lower.ends_with(".obj"),
            Format::Mtl => lower.ends_with(".mtl"),
            Format::Png => lower.ends_with(".png"),
            Format::Jpeg => lower.ends_with(".jpg") || lower.ends_with(".jpeg"),
            Format::Gltf => lower.ends_with(".gltf"),
            Format::Glb => lower.ends_with(".glb"),
            Format::Library => true,
        }
    }
}

fn repository() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ is inside the repository")
        .to_path_buf()
}

fn walk(root: &Path, dir: &Path, out: &mut Vec<String>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            walk(root, &path, out);
        } else if let Ok(relative) = path.strip_prefix(root) {
            out.push(relative.to_string_lossy().replace('\\', "/"));
        }
    }
}

/// The OBJ files beside `mtl` that name it in a `mtllib` line.
fn objs_naming(mtl: &Path) -> Vec<PathBuf> {
    let (Some(dir), Some(name)) = (mtl.parent(), mtl.file_name()) else {
        return Vec::new();
    };
    let name = name.to_string_lossy().into_owned();
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut objs: Vec<PathBuf> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("obj")))
        .filter(|p| {
            std::fs::read(p).is_ok_and(|bytes| {
                String::from_utf8_lossy(&bytes)
                    .lines()
                    .any(|l| l.trim_start().starts_with("mtllib") && l.contains(&name))
            })
        })
        .collect();
    objs.sort();
    objs
}

/// One corpus file made ready to be mutated: a private copy of its folder (models read their
/// materials, buffers and images from beside them), its original bytes, and where a mutated
/// version goes.
pub struct Case {
    format: Format,
    /// The file as it is in the corpus.
    pub original: Vec<u8>,
    _dir: tempfile::TempDir,
    /// Where the mutated bytes are written.
    target: PathBuf,
    /// The file the reader opens (for MTL: the OBJs naming it).
    entries: Vec<PathBuf>,
}

impl Case {
    /// Prepares `source` (relative to the format's root).
    pub fn prepare(format: Format, source: &str) -> std::io::Result<Case> {
        let root = format.root();
        let path = root.join(source);
        let original = std::fs::read(&path)?;
        let dir = tempfile::tempdir()?;
        let folder = path.parent().unwrap_or(&root);
        let file_name = path
            .file_name()
            .map(|n| n.to_os_string())
            .unwrap_or_default();
        let copy = dir.path().join("case");
        match format {
            Format::Obj | Format::Mtl | Format::Gltf | Format::Glb => {
                copy_dir(folder, &copy)?;
            }
            _ => std::fs::create_dir_all(&copy)?,
        }
        let target = copy.join(&file_name);
        let entries = match format {
            Format::Mtl => objs_naming(&path)
                .into_iter()
                .filter_map(|obj| obj.file_name().map(|n| copy.join(n)))
                .collect(),
            _ => vec![target.clone()],
        };
        Ok(Case {
            format,
            original,
            _dir: dir,
            target,
            entries,
        })
    }

    /// Runs `bytes` through the format's reader. `deep`: also open a library that passes the
    /// check with the system loader (only in a child process: a damaged library can crash
    /// it, and each opened library stays mapped).
    pub fn run(&self, bytes: &[u8], deep: bool) -> Outcome {
        match self.format {
            Format::Library => return run_library(bytes, &self.target, deep),
            Format::Png | Format::Jpeg => {
                return match onyx_render::texture::decode_texture_bytes(
                    bytes,
                    Path::new("fuzz-case"),
                    4096,
                ) {
                    Ok(_) => Outcome::Read,
                    Err(e) => Outcome::Refused(e.to_string()),
                };
            }
            _ => {}
        }
        if let Err(e) = std::fs::write(&self.target, bytes) {
            return Outcome::Refused(format!("cannot write the case: {e}"));
        }
        let outcome = match self.format {
            Format::Scene => run_scene(&self.target),
            _ => run_models(&self.entries),
        };
        // Put the original back for the next case's siblings (an MTL case's OBJ, etc.).
        let _ = std::fs::write(&self.target, &self.original);
        outcome
    }
}

fn copy_dir(from: &Path, to: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(to)?;
    for entry in std::fs::read_dir(from)?.flatten() {
        let path = entry.path();
        let dest = to.join(entry.file_name());
        if path.is_dir() {
            copy_dir(&path, &dest)?;
        } else {
            std::fs::copy(&path, &dest)?;
        }
    }
    Ok(())
}

fn run_models(entries: &[PathBuf]) -> Outcome {
    let settings = onyx_render::ImportSettings::default();
    let mut outcome = Outcome::Read;
    for entry in entries {
        if let Err(e) = onyx_render::mesh::ModelSource::load(entry, &settings, 4096) {
            outcome = Outcome::Refused(e.to_string());
        }
        // A glTF file is also read as a scene (node tree, cameras, lights, animations).
        if onyx_render::mesh::is_gltf(entry) {
            if let Err(e) = onyx_runtime::scene::gltf_import::import_gltf_scene(
                entry,
                true,
                &Default::default(),
            ) {
                outcome = Outcome::Refused(e.to_string());
            }
        }
    }
    outcome
}

/// Loads the scene into a fresh headless host, runs frames (physics and the scene graph see
/// whatever values were accepted) and saves it again.
fn run_scene(path: &Path) -> Outcome {
    let mut host = onyx_runtime::HeadlessHost::new();
    if let Err(e) = host.load_scene(path) {
        return Outcome::Refused(e.to_string());
    }
    host.step(3);
    let saved = path.with_extension("saved.ron");
    match host.host().save_scene(&saved) {
        Ok(()) => Outcome::Read,
        Err(e) => Outcome::Refused(format!("loaded, but saving it again failed: {e}")),
    }
}

fn run_library(bytes: &[u8], target: &Path, deep: bool) -> Outcome {
    if let Err(problem) = onyx_runtime::plugins::library_check::check_library(bytes) {
        return Outcome::Refused(problem.to_string());
    }
    if !deep {
        return Outcome::Read;
    }
    if let Err(e) = std::fs::write(target, bytes) {
        return Outcome::Refused(format!("cannot write the case: {e}"));
    }
    match onyx_runtime::plugins::open_library(target) {
        Ok(_) => Outcome::Read,
        Err(e) => Outcome::Refused(e.to_string()),
    }
}

/// Recomputes the CRC of every complete PNG chunk.
fn fix_png_checksums(bytes: &mut [u8]) {
    let mut at = 8;
    while at + 12 <= bytes.len() {
        let len = u32::from_be_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
        let Some(end) = (at + 8).checked_add(len as usize) else {
            return;
        };
        if end + 4 > bytes.len() {
            return;
        }
        let crc = crc32fast::hash(&bytes[at + 4..end]);
        bytes[end..end + 4].copy_from_slice(&crc.to_be_bytes());
        at = end + 4;
    }
}
