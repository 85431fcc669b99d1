//! glTF files as scenes: the node tree as entities under one root, for `onyx run --scene
//! model.glb` and the editor's import.
//!
//! - `gltf_document.rs`: [`GltfDocument`], the file opened and checked (required extensions
//!   refused, every feature left out named once).
//! - `gltf_node_tree.rs`: [`NodeTree`], the scene's nodes walked once, with unique names.
//! - `gltf_entities.rs`: nodes as scene entities (transform, parent, name, a mesh renderer
//!   naming `FILE#mesh/N`, camera, light) under a root whose transform is the import's
//!   scale and up axis.
//! - `gltf_default_view.rs`: a framing camera and a sun for a file with neither.
//! - `gltf_import_error.rs`: [`GltfImportError`].

mod gltf_default_view;
mod gltf_document;
mod gltf_entities;
mod gltf_import_error;
mod gltf_node_tree;

use std::path::Path;

pub use gltf_document::{GltfDocument, SUPPORTED_EXTENSIONS};
pub use gltf_entities::ONYX_PER_CANDELA;
pub use gltf_import_error::GltfImportError;
pub use gltf_node_tree::NodeTree;

use onyx_render::ImportSettings;

use super::{ImportSettingsFile, SceneFile, SCENE_FORMAT_VERSION};

/// What importing a glTF file gives: the scene and one warning per feature left out.
#[derive(Debug)]
pub struct GltfScene {
    /// The entities: the root (named after the file) first, the nodes under it.
    pub scene: SceneFile,
    /// One sentence per feature the import leaves out, each once.
    pub warnings: Vec<String>,
}

/// Whether the scene file at `path` is a glTF file (read by [`import_gltf_scene`]).
pub fn is_gltf_scene(path: &Path) -> bool {
    onyx_render::mesh::is_gltf(path)
}

/// Reads the glTF file at `path` as a scene: the root entity, then its node tree. With
/// `view`, a framing camera and a sun are added when the file has none (a file opened as the
/// whole scene); without, only the file's own nodes (an import into a scene).
///
/// `settings` bring the file in as one piece: their scale and up axis are the root's
/// transform (so node positions scale and turn with the meshes), and the scene's `imports`
/// entry for the file (written when they are not the default) carries them on, so its
/// pieces' generated normals follow `settings.normals` and a saved scene keeps them. The
/// pieces (`FILE#mesh/N`) take no scale or up axis of their own
/// ([`AssetRegistry::import_settings`](crate::assets::AssetRegistry::import_settings)).
///
/// # Errors
/// [`GltfImportError`] when the file cannot be read, is not glTF 2.0 or requires an
/// extension Onyx lacks.
pub fn import_gltf_scene(
    path: &Path,
    view: bool,
    settings: &ImportSettings,
) -> Result<GltfScene, GltfImportError> {
    // The gltf crate panics on some malformed files: the guard turns that into an error.
    onyx_render::mesh::catch_gltf_panics(path, || Ok(import(path, view, settings))).unwrap_or_else(
        |e| {
            Err(GltfImportError::Invalid {
                path: path.to_owned(),
                message: crate::scene::gltf_import::panic_message(e),
            })
        },
    )
}

/// What a panic inside the gltf crate, caught by its guard, says about the file.
pub(crate) fn panic_message(error: onyx_render::ModelLoadError) -> String {
    match error {
        onyx_render::ModelLoadError::Gltf { message, .. } => message,
        other => other.to_string(),
    }
}

fn import(
    path: &Path,
    view: bool,
    settings: &ImportSettings,
) -> Result<GltfScene, GltfImportError> {
    let file = GltfDocument::open(path)?;
    let document = file.document();
    let tree = NodeTree::new(document);
    let root = gltf_entities::root_transform(settings);
    let mut entities = gltf_entities::gltf_entities(document, &tree, path, root);
    if view {
        entities.extend(gltf_default_view::default_view(
            document,
            &tree,
            root.matrix(),
            gltf_default_view::first_free_id(document),
        ));
    }
    let mut imports = std::collections::BTreeMap::new();
    if *settings != ImportSettings::default() {
        imports.insert(
            gltf_entities::file_name(path)
                .to_string_lossy()
                .into_owned(),
            ImportSettingsFile::from_settings(settings),
        );
    }
    Ok(GltfScene {
        scene: SceneFile {
            version: SCENE_FORMAT_VERSION,
            physics: None,
            imports,
            entities,
        },
        warnings: file.warnings,
    })
}
