//! [`read_clip`]: a glTF file's node animations (one, or all of them together) as an
//! [`AnimationClip`] whose channels name their targets by the import's entity names.

use std::path::Path;

use onyx_plugin_api::glam::Vec4;
use onyx_render::SubAsset;

use super::animation_clip::{AnimationClip, Channel, Curve, Interpolation, Property};
use crate::scene::gltf_import::{GltfDocument, GltfImportError, NodeTree};

/// Why an animation could not be read.
#[derive(Debug, thiserror::Error)]
pub enum ClipError {
    /// The file could not be opened as glTF.
    #[error(transparent)]
    File(#[from] GltfImportError),
    /// Its buffers could not be read.
    #[error("`{}`: {message}", .path.display())]
    Buffers {
        /// The file.
        path: std::path::PathBuf,
        /// Which buffer, and why.
        message: String,
    },
    /// The file has no such animation.
    #[error("`{}` has {count} animation(s), so there is no animation {index}", .path.display())]
    NoSuchAnimation {
        /// The file.
        path: std::path::PathBuf,
        /// Animations it has.
        count: usize,
        /// The one asked for.
        index: usize,
    },
}

/// What [`read_clip`] gives: the clip and one sentence per channel it had to skip.
pub struct ReadClip {
    /// The playable channels.
    pub clip: AnimationClip,
    /// Channels left out (morph weights, a node outside the scene, bad keys).
    pub skipped: Vec<String>,
}

/// Reads `path`: `file.glb#animation/N` gives that animation, `file.glb` all of them.
pub fn read_clip(path: &Path) -> Result<ReadClip, ClipError> {
    // The gltf crate panics on some malformed files: the guard turns that into an error.
    onyx_render::mesh::catch_gltf_panics(path, || Ok(read(path))).unwrap_or_else(|e| {
        Err(ClipError::File(GltfImportError::Invalid {
            path: path.to_owned(),
            message: crate::scene::gltf_import::panic_message(e),
        }))
    })
}

fn read(path: &Path) -> Result<ReadClip, ClipError> {
    let (file, sub) = SubAsset::split(path);
    let opened = GltfDocument::open(&file)?;
    let document = opened.document();
    let folder = file.parent().unwrap_or(Path::new(""));
    let buffers =
        onyx_render::mesh::load_gltf_buffers(document, opened.gltf.blob.as_deref(), folder)
            .map_err(|message| ClipError::Buffers {
                path: file.clone(),
                message,
            })?;
    let animations: Vec<gltf::Animation<'_>> = match sub {
        Some(SubAsset::Animation(index)) => {
            let count = document.animations().len();
            let Some(animation) = document.animations().nth(index) else {
                return Err(ClipError::NoSuchAnimation {
                    path: file,
                    count,
                    index,
                });
            };
            vec![animation]
        }
        _ => document.animations().collect(),
    };
    let tree = NodeTree::new(document);
    let mut clip = AnimationClip::default();
    let mut skipped = Vec::new();
    for animation in animations {
        for channel in animation.channels() {
            let label = || {
                format!(
                    "animation {} channel {}",
                    animation.index(),
                    channel.index()
                )
            };
            let node = channel.target().node().index();
            let Some(target) = tree.path_of(node) else {
                skipped.push(format!("{}: node {node} is not in the scene", label()));
                continue;
            };
            let reader = channel.reader(|b| buffers.get(b.index()).map(Vec::as_slice));
            let Some(times) = reader.read_inputs() else {
                skipped.push(format!("{}: no key times", label()));
                continue;
            };
            let times: Vec<f32> = times.collect();
            use gltf::animation::util::ReadOutputs;
            let (property, values): (Property, Vec<Vec4>) = match reader.read_outputs() {
                Some(ReadOutputs::Translations(v)) => (
                    Property::Translation,
                    v.map(|[x, y, z]| Vec4::new(x, y, z, 0.0)).collect(),
                ),
                Some(ReadOutputs::Scales(v)) => (
                    Property::Scale,
                    v.map(|[x, y, z]| Vec4::new(x, y, z, 0.0)).collect(),
                ),
                Some(ReadOutputs::Rotations(v)) => {
                    (Property::Rotation, v.into_f32().map(Vec4::from).collect())
                }
                Some(ReadOutputs::MorphTargetWeights(_)) => {
                    skipped.push(format!("{}: morph target weights", label()));
                    continue;
                }
                None => {
                    skipped.push(format!("{}: no values", label()));
                    continue;
                }
            };
            let interpolation = match channel.sampler().interpolation() {
                gltf::animation::Interpolation::Step => Interpolation::Step,
                gltf::animation::Interpolation::Linear => Interpolation::Linear,
                gltf::animation::Interpolation::CubicSpline => Interpolation::CubicSpline,
            };
            match Curve::new(interpolation, times, values) {
                Ok(curve) => {
                    clip.duration = clip.duration.max(curve.end());
                    clip.channels.push(Channel {
                        target,
                        property,
                        curve,
                    });
                }
                Err(error) => skipped.push(format!("{}: {error}", label())),
            }
        }
    }
    Ok(ReadClip { clip, skipped })
}
