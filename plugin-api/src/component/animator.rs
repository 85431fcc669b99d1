//! [`Animator`] and [`AnimationId`]: an entity playing a node animation (a glTF file's
//! translation, rotation and scale channels) on the entities below it.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{Builtin, InvalidValue};

/// An animation the host can play: `file.glb#animation/N` (one of the file's animations) or
/// `file.glb` (all of them together), registered when a scene names it. Valid for the life of
/// the host.
#[repr(transparent)]
#[derive(
    StableAbi,
    Clone,
    Copy,
    Debug,
    Default,
    PartialEq,
    Eq,
    Hash,
    PartialOrd,
    Ord,
    Serialize,
    Deserialize,
)]
#[serde(transparent)]
pub struct AnimationId(pub u32);

impl AnimationId {
    /// No animation: the animator does nothing.
    pub const NONE: Self = Self(0);
}

/// Plays an animation on the entities below this one: each channel finds its entity by the
/// path of [`Name`](crate::Name)s from this entity down (as a glTF import names them) and
/// writes its [`Transform`](crate::Transform)'s translation, rotation or scale each frame.
///
/// Control it as any component, through `Ctx`:
/// ```no_run
/// # use onyx_plugin_api::*;
/// # fn demo(ctx: &mut Ctx, model: Entity) -> Result<(), CtxError> {
/// let animator: Animator = ctx.get(model)?;
/// ctx.set(model, animator.paused())?; // hold the pose
/// ctx.set(model, animator.playing().with_speed(2.0).with_looping(false))?;
/// ctx.set(model, animator.at(0.5))?; // jump to 0.5 s
/// # Ok(()) }
/// ```
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Animator {
    /// What it plays.
    pub clip: AnimationId,
    /// Where it is in the clip, seconds (the host advances it while playing).
    pub time: f32,
    /// Seconds of clip per second of (scaled) frame time; negative plays backwards.
    pub speed: f32,
    /// Whether time advances.
    pub playing: bool,
    /// At the end, start again (else stop at the last pose and stop playing).
    pub looping: bool,
}

impl Animator {
    /// Plays `clip` from its start, looping, at normal speed.
    pub const fn new(clip: AnimationId) -> Self {
        Self {
            clip,
            time: 0.0,
            speed: 1.0,
            playing: true,
            looping: true,
        }
    }

    /// Returns it playing.
    #[must_use]
    pub const fn playing(mut self) -> Self {
        self.playing = true;
        self
    }

    /// Returns it paused (the pose held).
    #[must_use]
    pub const fn paused(mut self) -> Self {
        self.playing = false;
        self
    }

    /// Returns it at `speed` (clip seconds per frame second).
    #[must_use]
    pub const fn with_speed(mut self, speed: f32) -> Self {
        self.speed = speed;
        self
    }

    /// Returns it looping or not.
    #[must_use]
    pub const fn with_looping(mut self, looping: bool) -> Self {
        self.looping = looping;
        self
    }

    /// Returns it at `time` seconds into the clip.
    #[must_use]
    pub const fn at(mut self, time: f32) -> Self {
        self.time = time;
        self
    }
}

/// An [`Animator`] as scene files and state dumps write it: the clip by file path.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnimatorFile {
    /// `file.glb#animation/N`, or `file.glb` for all of the file's animations (empty: none).
    #[serde(default)]
    pub clip: String,
    /// Seconds into the clip.
    #[serde(default)]
    pub time: f32,
    /// Clip seconds per frame second.
    #[serde(default = "one")]
    pub speed: f32,
    /// Whether it plays.
    #[serde(default = "yes")]
    pub playing: bool,
    /// Whether it loops.
    #[serde(default = "yes")]
    pub looping: bool,
}

fn one() -> f32 {
    1.0
}

fn yes() -> bool {
    true
}

impl Builtin for Animator {
    const NAME: &'static str = "Animator";
    type File = AnimatorFile;

    fn tool_default() -> Option<Self> {
        // Nothing to play until a clip is chosen.
        Some(Animator::new(AnimationId::NONE))
    }

    fn validate(&self, refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        finite("time", &[self.time])?;
        finite("speed", &[self.speed])?;
        if !refs.knows_animation(self.clip) {
            return Err(InvalidValue::invalid(
                "clip",
                format!(
                    "is animation id {}, which this host did not give",
                    self.clip.0
                ),
            ));
        }
        Ok(())
    }

    fn to_file(&self, refs: &dyn HostRefs) -> AnimatorFile {
        AnimatorFile {
            clip: refs.animation_file(self.clip).unwrap_or_default(),
            time: self.time,
            speed: self.speed,
            playing: self.playing,
            looping: self.looping,
        }
    }

    fn from_file(file: AnimatorFile, refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        // An empty clip is an animator with nothing to play yet.
        let clip = if file.clip.is_empty() {
            AnimationId::NONE
        } else {
            refs.animation(&file.clip)
        };
        Ok(Animator {
            clip,
            time: file.time,
            speed: file.speed,
            playing: file.playing,
            looping: file.looping,
        })
    }
}
