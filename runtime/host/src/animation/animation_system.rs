//! [`AnimationSystem`]: advances every [`Animator`] by the frame's time and writes the poses
//! of its clip into the entities below it.

use std::collections::HashMap;
use std::sync::Arc;

use onyx_plugin_api::{AnimationId, Animator, Name, Transform};

use super::animation_clip::{AnimationClip, Property};
use super::clip_reader::read_clip;
use crate::world::WorldState;

/// The clips read so far (each once; a file that fails is reported once and plays nothing),
/// and the clip and time each animator last posed its entities at.
#[derive(Debug, Default)]
pub struct AnimationSystem {
    clips: HashMap<AnimationId, Option<Arc<AnimationClip>>>,
    posed: HashMap<hecs::Entity, (AnimationId, u32)>,
}

impl AnimationSystem {
    /// Advances each playing animator by `dt` seconds × its speed (looping, or stopping at an
    /// end), then poses the entities its channels name when its clip or time changed since
    /// it last did (a paused animator writes nothing, so the entities below it are left
    /// alone; setting its time seeks).
    pub fn advance(&mut self, world: &mut WorldState, dt: f32) {
        let animators: Vec<(hecs::Entity, Animator)> = world
            .ecs
            .query::<(hecs::Entity, &Animator)>()
            .iter()
            .map(|(e, a)| (e, *a))
            .collect();
        let mut last = std::mem::take(&mut self.posed);
        for (entity, mut animator) in animators {
            let Some(clip) = self.clip(animator.clip, world) else {
                continue;
            };
            let before = animator;
            step(&mut animator, clip.duration, dt);
            if animator != before {
                if let Ok(mut stored) = world.ecs.get::<&mut Animator>(entity) {
                    *stored = animator;
                }
            }
            let at = (animator.clip, animator.time.to_bits());
            if last.remove(&entity) != Some(at) {
                pose(world, entity, &clip, animator.time);
            }
            self.posed.insert(entity, at);
        }
    }

    /// The clip of `id`, read the first time it is asked for.
    fn clip(&mut self, id: AnimationId, world: &WorldState) -> Option<Arc<AnimationClip>> {
        if let Some(clip) = self.clips.get(&id) {
            return clip.clone();
        }
        let path = world
            .assets
            .animation_path(id)
            .map(|p| world.assets.resolve(p));
        let clip = match path.as_deref().map(read_clip) {
            None => None,
            Some(Ok(read)) => {
                for skipped in &read.skipped {
                    tracing::warn!(clip = %path.as_deref().unwrap_or_else(|| std::path::Path::new("")).display(), "channel not played: {skipped}");
                }
                Some(Arc::new(read.clip))
            }
            Some(Err(error)) => {
                tracing::error!("animation not played: {error}");
                None
            }
        };
        self.clips.insert(id, clip.clone());
        clip
    }
}

/// Moves `animator`'s time on by `dt` × speed: wrapped into `[0, duration)` when looping,
/// else held at the end it reached (and no longer playing).
fn step(animator: &mut Animator, duration: f32, dt: f32) {
    if !animator.playing {
        return;
    }
    let time = animator.time + dt * animator.speed;
    if !time.is_finite() {
        return;
    }
    if duration <= 0.0 {
        animator.time = 0.0;
    } else if animator.looping {
        animator.time = time.rem_euclid(duration);
    } else if time >= duration || time <= 0.0 {
        animator.time = time.clamp(0.0, duration);
        animator.playing = false;
    } else {
        animator.time = time;
    }
}

/// Writes every channel of `clip` at `time` into the entity its names lead to from `root`.
fn pose(world: &mut WorldState, root: hecs::Entity, clip: &AnimationClip, time: f32) {
    for channel in &clip.channels {
        let Some(target) = find_below(world, root, &channel.target) else {
            continue;
        };
        let Ok(mut transform) = world.ecs.get::<&mut Transform>(target) else {
            continue;
        };
        match channel.property {
            Property::Translation => transform.translation = channel.vec3_at(time),
            Property::Scale => transform.scale = channel.vec3_at(time),
            Property::Rotation => transform.rotation = channel.rotation_at(time),
        }
        drop(transform);
        world.moved(target);
    }
}

/// The entity reached from `root` by following children named `path`, one name a level.
fn find_below(world: &mut WorldState, root: hecs::Entity, path: &[String]) -> Option<hecs::Entity> {
    let mut at = root;
    for name in path {
        at = world.children(at).into_iter().find(|child| {
            world
                .ecs
                .get::<&Name>(*child)
                .is_ok_and(|n| n.as_str() == name)
        })?;
    }
    Some(at)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn looping_wraps_and_a_single_play_stops_at_the_end() {
        let mut looping = Animator::new(AnimationId(1));
        step(&mut looping, 2.0, 2.5);
        assert!((looping.time - 0.5).abs() < 1e-6 && looping.playing);
        let mut once = Animator::new(AnimationId(1)).with_looping(false);
        step(&mut once, 2.0, 2.5);
        assert_eq!((once.time, once.playing), (2.0, false));
        let mut backwards = Animator::new(AnimationId(1)).with_speed(-1.0).at(0.5);
        step(&mut backwards, 2.0, 1.0);
        assert!((backwards.time - 1.5).abs() < 1e-6);
        let mut paused = Animator::new(AnimationId(1)).paused().at(0.3);
        step(&mut paused, 2.0, 1.0);
        assert_eq!(paused.time, 0.3);
    }
}
