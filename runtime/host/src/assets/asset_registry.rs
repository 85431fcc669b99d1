//! [`AssetRegistry`]: which file each mesh and texture id stands for.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use onyx_plugin_api::{AnimationId, MeshId, TextureId};
use onyx_render::{ImportSettings, SubAsset};

/// Ids for model and texture files, one per path, valid for the life of the host. It holds
/// no GPU data: a host without a renderer still hands out ids (so plugins and scenes behave
/// the same headless), and the renderer loads each file the first time it is drawn.
#[derive(Debug, Default)]
pub struct AssetRegistry {
    root: PathBuf,
    meshes: Vec<PathBuf>,
    mesh_ids: HashMap<PathBuf, MeshId>,
    textures: Vec<PathBuf>,
    texture_ids: HashMap<PathBuf, TextureId>,
    animations: Vec<PathBuf>,
    animation_ids: HashMap<PathBuf, AnimationId>,
    import_settings: HashMap<PathBuf, ImportSettings>,
}

impl AssetRegistry {
    /// A registry resolving relative paths against `root` (the asset root).
    pub fn new(root: PathBuf) -> Self {
        Self {
            root,
            ..Self::default()
        }
    }

    /// Where the file named `path` is: relative paths are taken from the asset root. Paths are
    /// registered as written, so scene files keep them portable.
    pub fn resolve(&self, path: &Path) -> PathBuf {
        self.root.join(path)
    }

    /// The path a file named `written` inside a file in `folder` (a scene) is registered
    /// under: a relative path is looked for beside that file first, then as the host always
    /// read it (from the asset root: the working directory by default), then beside each
    /// folder above that file (a scene in `assets/scenes/` naming `assets/models/x.obj`), so
    /// the same scene shows the same models from any working directory. Found nowhere, it is
    /// kept as written (the load error then names it). A piece of a model file
    /// (`city.glb#mesh/3`, [`SubAsset`]) is found by its file and keeps its piece.
    pub fn find_beside(&self, folder: &Path, written: &Path) -> PathBuf {
        if let (file, Some(sub)) = SubAsset::split(written) {
            return sub.path_in(&self.find_file_beside(folder, &file));
        }
        self.find_file_beside(folder, written)
    }

    fn find_file_beside(&self, folder: &Path, written: &Path) -> PathBuf {
        if written.is_absolute() || written.as_os_str().is_empty() {
            return written.to_path_buf();
        }
        let beside = folder.join(written);
        if beside.is_file() {
            return beside;
        }
        if self.resolve(written).is_file() {
            return written.to_path_buf();
        }
        folder
            .ancestors()
            .skip(1)
            .map(|up| up.join(written))
            .find(|candidate| candidate.is_file())
            .unwrap_or_else(|| written.to_path_buf())
    }

    /// The id of the model at `path`, registering it if new.
    pub fn mesh(&mut self, path: &Path) -> MeshId {
        if let Some(id) = self.mesh_ids.get(path) {
            return *id;
        }
        let id = MeshId(MeshId::FIRST_LOADED + self.meshes.len() as u32);
        self.meshes.push(path.to_path_buf());
        self.mesh_ids.insert(path.to_path_buf(), id);
        id
    }

    /// The id of the image at `path`, registering it if new.
    pub fn texture(&mut self, path: &Path) -> TextureId {
        if let Some(id) = self.texture_ids.get(path) {
            return *id;
        }
        let id = TextureId(1 + self.textures.len() as u32);
        self.textures.push(path.to_path_buf());
        self.texture_ids.insert(path.to_path_buf(), id);
        id
    }

    /// Brings the model file at `path` (as registered) in with `settings` from now on; the
    /// default settings forget any given before.
    pub fn set_import_settings(&mut self, path: &Path, settings: ImportSettings) {
        let (file, _) = SubAsset::split(path);
        if settings == ImportSettings::default() {
            self.import_settings.remove(&file);
        } else {
            self.import_settings.insert(file, settings);
        }
    }

    /// How the model at `path` is imported: the settings given for its file, else the
    /// default. A piece of a file (`file.glb#mesh/2`, drawn by a node of its imported node
    /// tree) takes only its file's normals: it sits in the file's node space, so the file's
    /// scale and up axis apply once, at the imported root's transform
    /// ([`import_gltf_scene`](crate::scene::import_gltf_scene)), not again to each piece.
    pub fn import_settings(&self, path: &Path) -> ImportSettings {
        let (file, piece) = SubAsset::split(path);
        let settings = self.import_settings.get(&file).copied().unwrap_or_default();
        match piece {
            Some(_) => ImportSettings {
                normals: settings.normals,
                ..ImportSettings::default()
            },
            None => settings,
        }
    }

    /// The settings given for the model file at `path` itself (a piece's path names its
    /// file), else the default: what a glTF node tree is imported with.
    pub fn file_import_settings(&self, path: &Path) -> ImportSettings {
        let (file, _) = SubAsset::split(path);
        self.import_settings.get(&file).copied().unwrap_or_default()
    }

    /// Every model given settings other than the default, by path.
    pub fn all_import_settings(&self) -> impl Iterator<Item = (&Path, &ImportSettings)> {
        self.import_settings.iter().map(|(p, s)| (p.as_path(), s))
    }

    /// The id of the animation at `path` (`file.glb#animation/N`, or `file.glb` for all of
    /// the file's animations), registering it if new.
    pub fn animation(&mut self, path: &Path) -> AnimationId {
        if let Some(id) = self.animation_ids.get(path) {
            return *id;
        }
        let id = AnimationId(1 + self.animations.len() as u32);
        self.animations.push(path.to_path_buf());
        self.animation_ids.insert(path.to_path_buf(), id);
        id
    }

    /// The id of the animation at `path`, if it was registered.
    pub fn animation_id(&self, path: &Path) -> Option<AnimationId> {
        self.animation_ids.get(path).copied()
    }

    /// The file (and piece) of an animation id.
    pub fn animation_path(&self, id: AnimationId) -> Option<&Path> {
        let index = id.0.checked_sub(1)?;
        self.animations.get(index as usize).map(PathBuf::as_path)
    }

    /// Whether `id` is none or a registered animation.
    pub fn knows_animation(&self, id: AnimationId) -> bool {
        id == AnimationId::NONE || self.animation_path(id).is_some()
    }

    /// The id of the model at `path`, if it was registered.
    pub fn mesh_id(&self, path: &Path) -> Option<MeshId> {
        self.mesh_ids.get(path).copied()
    }

    /// The id of the image at `path`, if it was registered.
    pub fn texture_id(&self, path: &Path) -> Option<TextureId> {
        self.texture_ids.get(path).copied()
    }

    /// The file of a loaded-model id (`None` for built-in shapes and unknown ids).
    pub fn mesh_path(&self, id: MeshId) -> Option<&Path> {
        let index = id.0.checked_sub(MeshId::FIRST_LOADED)?;
        self.meshes.get(index as usize).map(PathBuf::as_path)
    }

    /// The file of a texture id.
    pub fn texture_path(&self, id: TextureId) -> Option<&Path> {
        let index = id.0.checked_sub(1)?;
        self.textures.get(index as usize).map(PathBuf::as_path)
    }

    /// Whether `id` is a built-in shape or a registered model.
    pub fn knows_mesh(&self, id: MeshId) -> bool {
        MeshId::BUILTIN.iter().any(|(b, _)| *b == id) || self.mesh_path(id).is_some()
    }

    /// Whether `id` is none or a registered texture.
    pub fn knows_texture(&self, id: TextureId) -> bool {
        id == TextureId::NONE || self.texture_path(id).is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scene_paths_are_found_beside_the_scene_then_above_it() {
        //! A scene's models were looked for in the working directory only: the same scene
        //! run from elsewhere showed checker cubes.
        let root = std::env::temp_dir().join(format!("onyx-beside-{}", std::process::id()));
        let scenes = root.join("assets/scenes");
        let _ = std::fs::create_dir_all(&scenes);
        let _ = std::fs::create_dir_all(root.join("assets/models"));
        std::fs::write(scenes.join("near.obj"), "v 0 0 0").unwrap_or_else(|e| panic!("{e}"));
        std::fs::write(root.join("assets/models/far.obj"), "v 0 0 0")
            .unwrap_or_else(|e| panic!("{e}"));
        let registry = AssetRegistry::new(std::env::temp_dir().join("onyx-no-such-root"));
        assert_eq!(
            registry.find_beside(&scenes, Path::new("near.obj")),
            scenes.join("near.obj")
        );
        assert_eq!(
            registry.find_beside(&scenes, Path::new("assets/models/far.obj")),
            root.join("assets/models/far.obj")
        );
        assert_eq!(
            registry.find_beside(&scenes, Path::new("gone.obj")),
            Path::new("gone.obj")
        );
        // One mesh of a glTF file: found by its file, the piece kept.
        std::fs::write(scenes.join("city.glb"), "glTF").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            registry.find_beside(&scenes, Path::new("city.glb#mesh/3")),
            PathBuf::from(format!("{}#mesh/3", scenes.join("city.glb").display()))
        );
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn one_id_per_path_and_back() {
        let mut r = AssetRegistry::default();
        let a = r.mesh(Path::new("a.obj"));
        assert_eq!(r.mesh(Path::new("a.obj")), a);
        let b = r.mesh(Path::new("b.obj"));
        assert_ne!(a, b);
        assert_eq!(r.mesh_path(b), Some(Path::new("b.obj")));
        assert_eq!(r.mesh_path(MeshId::CUBE), None);
        assert!(r.knows_mesh(MeshId::SPHERE) && r.knows_mesh(a) && !r.knows_mesh(MeshId(999)));
        let t = r.texture(Path::new("t.png"));
        assert_ne!(t, TextureId::NONE);
        assert_eq!(r.texture_path(t), Some(Path::new("t.png")));
        assert!(r.knows_texture(TextureId::NONE) && !r.knows_texture(TextureId(77)));
    }
}
