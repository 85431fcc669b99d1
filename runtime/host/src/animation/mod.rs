//! Node animation: clips of translation, rotation and scale keys (read from glTF files),
//! played by [`Animator`](onyx_plugin_api::Animator) components.
//!
//! - `animation_clip.rs`: [`AnimationClip`], [`Channel`], [`Curve`]: keys and their sampling
//!   (step, linear/slerp, cubic spline).
//! - `clip_reader.rs`: [`read_clip`], a glTF file's animations as a clip.
//! - `animation_system.rs`: [`AnimationSystem`], each frame's advance and posing.

mod animation_clip;
mod animation_system;
mod clip_reader;

pub use animation_clip::{AnimationClip, Channel, Curve, CurveError, Interpolation, Property};
pub use animation_system::AnimationSystem;
pub use clip_reader::{read_clip, ClipError, ReadClip};
