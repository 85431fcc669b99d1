//! Node animation played by the `Animator` a glTF scene's root gets, checked against the
//! Khronos samples' own keys (InterpolationTest: step, linear, cubic spline on translation,
//! rotation and scale; BoxAnimated: a chain under a moving parent) at chosen times, and
//! controlled (pause, speed, loop) from a plugin through `Ctx`. Skips, saying so, when the
//! samples are absent.

mod common;

use std::sync::{Arc, Mutex};

use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{Animator, Ctx, Entity, Flow, Name, Plugin, Transform};
use onyx_runtime::HeadlessHost;

fn open(file: &str) -> Option<HeadlessHost> {
    let dir = common::gltf_samples()?;
    let mut host = HeadlessHost::new();
    if let Err(error) = host.load_scene(&dir.join(file)) {
        panic!("{file}: {error}");
    }
    Some(host)
}

/// Holds the root's animator at `time` and runs a frame: the pose of that instant.
fn pose_at(host: &mut HeadlessHost, root: &str, time: f32) {
    let (entity, animator) = host
        .find::<Animator>(root)
        .unwrap_or_else(|| panic!("{root} has no animator"));
    let Some(e) = hecs::Entity::from_bits(entity.to_bits()) else {
        panic!("{root}: {entity} is no hecs entity")
    };
    if let Ok(mut stored) = host.host_mut().world_mut().get::<&mut Animator>(e) {
        *stored = animator.paused().at(time);
    }
    host.step(1);
}

fn transform(host: &HeadlessHost, name: &str) -> Transform {
    host.find::<Transform>(name)
        .unwrap_or_else(|| panic!("no {name}"))
        .1
}

/// The midpoint of two key times of InterpolationTest, and the point a quarter in.
fn between(t0: f32, t1: f32, s: f32) -> f32 {
    t0 + (t1 - t0) * s
}

fn smoothstep(s: f32) -> f32 {
    3.0 * s * s - 2.0 * s * s * s
}

const T1: f32 = 0.416_666_66;
const T2: f32 = 0.875;
const T2_TRANSLATION: f32 = 0.833_333_3;

#[test]
fn interpolation_test_scales_follow_step_linear_and_cubic_spline_keys() {
    let Some(mut host) = open("InterpolationTest/glTF-Binary/InterpolationTest.glb") else {
        return;
    };
    // Keys of all three: scale 0.5 at T1, 1.0 at T2; cubic-spline tangents are zero.
    for s in [0.25f32, 0.5, 0.75] {
        pose_at(&mut host, "InterpolationTest", between(T1, T2, s));
        let step = transform(&host, "Cube").scale;
        let linear = transform(&host, "Cube.001").scale;
        let cubic = transform(&host, "Cube.002").scale;
        let expected_linear = 0.5 + 0.5 * s;
        let expected_cubic = 0.5 + 0.5 * smoothstep(s);
        assert!(
            step.abs_diff_eq(Vec3::splat(0.5), 1e-5),
            "s={s}: step {step}"
        );
        assert!(
            linear.abs_diff_eq(Vec3::splat(expected_linear), 1e-4),
            "s={s}: linear {linear}, expected {expected_linear}"
        );
        assert!(
            cubic.abs_diff_eq(Vec3::splat(expected_cubic), 1e-4),
            "s={s}: cubic {cubic}, expected {expected_cubic}"
        );
    }
}

#[test]
fn interpolation_test_translations_and_rotations_follow_their_keys() {
    let Some(mut host) = open("InterpolationTest/glTF/InterpolationTest.gltf") else {
        return;
    };
    // Translations: y 10 at T1, 6 at T2_TRANSLATION (step's keys are at 0.458 and 0.833).
    let s = 0.25;
    pose_at(
        &mut host,
        "InterpolationTest",
        between(T1, T2_TRANSLATION, s),
    );
    let linear = transform(&host, "Cube.009").translation.y;
    let cubic = transform(&host, "Cube.008").translation.y;
    let step = transform(&host, "Cube.006").translation.y;
    assert!(
        (linear - (10.0 - 4.0 * s)).abs() < 1e-4,
        "linear y {linear}"
    );
    assert!(
        (cubic - (10.0 - 4.0 * smoothstep(s))).abs() < 1e-4,
        "cubic y {cubic}"
    );
    // At 0.52 s the step key of 0.458 s (y 10) holds; at 0.4 s the first (y 6.665).
    assert!(
        (step - 10.0).abs() < 1e-4,
        "step y {step} after its 0.458 s key"
    );
    pose_at(&mut host, "InterpolationTest", 0.4);
    let step = transform(&host, "Cube.006").translation.y;
    assert!(
        (step - 6.665).abs() < 1e-3,
        "step y {step} before its 0.458 s key"
    );
    // Rotations about -Z: 0° at 0 s, 45° at T1. Linear is a slerp: 22.5° half-way.
    pose_at(&mut host, "InterpolationTest", T1 * 0.5);
    let linear = transform(&host, "Cube.005").rotation;
    let expected = Quat::from_rotation_z(-std::f32::consts::FRAC_PI_8);
    assert!(linear.abs_diff_eq(expected, 1e-4), "{linear} != {expected}");
    let step = transform(&host, "Cube.003").rotation;
    assert!(step.abs_diff_eq(Quat::IDENTITY, 1e-4), "step {step}");
    // At a key every interpolation gives the key: 90° at 0.875 s.
    pose_at(&mut host, "InterpolationTest", T2);
    let key = Quat::from_rotation_z(-std::f32::consts::FRAC_PI_2);
    for name in ["Cube.003", "Cube.004", "Cube.005"] {
        let r = transform(&host, name).rotation;
        assert!(r.abs_diff_eq(key, 1e-4), "{name}: {r} != {key}");
    }
}

#[test]
fn box_animated_moves_its_chain_and_turns_the_inner_box() {
    let Some(mut host) = open("BoxAnimated/glTF-Binary/BoxAnimated.glb") else {
        return;
    };
    // Node 0's translation: y 0 at 0 s, 2.52 at 1.25 s; linear.
    pose_at(&mut host, "BoxAnimated", 0.625);
    let y = transform(&host, "node 0").translation.y;
    assert!((y - 1.26).abs() < 1e-4, "y {y}");
    // Node 2 (two levels down) follows in the world.
    let (inner, _) = host
        .find::<Transform>("node 2")
        .unwrap_or_else(|| panic!("no node 2"));
    let world = host
        .host()
        .world_pose(inner)
        .map_or(Vec3::NAN, |p| Vec3::from(p.0.translation));
    assert!((world.y - 1.26).abs() < 1e-4, "world {world}");
    // Node 2's rotation: identity at 1.25 s to 180° about X at 2.5 s: 90° half-way.
    pose_at(&mut host, "BoxAnimated", 1.875);
    let r = transform(&host, "node 2").rotation;
    let angle = r.angle_between(Quat::IDENTITY);
    assert!(
        (angle - std::f32::consts::FRAC_PI_2).abs() < 1e-4 && r.x.abs() > 0.707,
        "rotation {r}: {angle} rad"
    );
}

#[test]
fn a_paused_animator_leaves_the_entities_below_it_alone() {
    let Some(mut host) = open("BoxAnimated/glTF-Binary/BoxAnimated.glb") else {
        return;
    };
    pose_at(&mut host, "BoxAnimated", 0.625);
    // A tool moves the animated node while the animation is paused: it stays moved.
    let (node, _) = host
        .find::<Transform>("node 0")
        .unwrap_or_else(|| panic!("no node 0"));
    let Some(e) = hecs::Entity::from_bits(node.to_bits()) else {
        panic!("{node} is no hecs entity")
    };
    let moved = Transform::from_xyz(5.0, 6.0, 7.0);
    if let Ok(mut stored) = host.host_mut().world_mut().get::<&mut Transform>(e) {
        *stored = moved;
    }
    host.step(3);
    assert_eq!(
        transform(&host, "node 0").translation,
        moved.translation,
        "a paused animator rewrote its entities"
    );
    // Seeking poses it again.
    pose_at(&mut host, "BoxAnimated", 0.625 / 2.0);
    let y = transform(&host, "node 0").translation.y;
    assert!((y - 0.63).abs() < 1e-4, "y {y}");
}

/// Drives the root's animator through `Ctx` as a game would: pauses it at frame 10, plays
/// it at double speed from frame 20, then once without looping from frame 30.
struct Remote {
    root: Option<Entity>,
    frame: u32,
    seen: Arc<Mutex<Vec<(u32, f32, bool)>>>,
}

impl Plugin for Remote {
    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> Flow {
        self.frame += 1;
        if self.root.is_none() {
            let all = ctx.entities().to_vec();
            self.root = all.into_iter().find(|&e| {
                ctx.get::<Name>(e)
                    .is_ok_and(|n| n.as_str() == "BoxAnimated")
            });
        }
        let Some(root) = self.root else {
            return Flow::Continue;
        };
        let Ok(animator) = ctx.get::<Animator>(root) else {
            return Flow::Continue;
        };
        if let Ok(mut seen) = self.seen.lock() {
            seen.push((self.frame, animator.time, animator.playing));
        }
        let changed = match self.frame {
            10 => Some(animator.paused()),
            20 => Some(animator.playing().with_speed(2.0)),
            30 => Some(animator.at(3.0).with_speed(1.0).with_looping(false)),
            _ => None,
        };
        if let Some(animator) = changed {
            let _ = ctx.set(root, animator);
        }
        Flow::Continue
    }
}

#[test]
fn a_plugin_pauses_speeds_up_and_plays_once_through_ctx() {
    let Some(mut host) = open("BoxAnimated/glTF/BoxAnimated.gltf") else {
        return;
    };
    let seen = Arc::new(Mutex::new(Vec::new()));
    let remote = Remote {
        root: None,
        frame: 0,
        seen: Arc::clone(&seen),
    };
    host.add_plugin("remote", remote)
        .unwrap_or_else(|e| panic!("{e}"));
    host.set_frame_time(0.05);
    host.step(50);
    let (_, animator) = host
        .find::<Animator>("BoxAnimated")
        .unwrap_or_else(|| panic!("no animator"));
    // Frames 1..9 at 0.05 s, paused 10..19, 2× from 20 to 29: 9·0.05 + 10·0.1 = 1.45 s before
    // the seek; then from 3.0 s once through to the 3.708 s end, where it stops.
    assert!(!animator.playing, "{animator:?}");
    assert!((animator.time - 3.708_33).abs() < 1e-3, "{animator:?}");
    // The plugin's own view (each frame's animator as on_update sees it, after the host
    // advanced it): 0.05 s a frame, held while paused, 0.1 s a frame at double speed.
    let seen = seen.lock().map(|s| s.clone()).unwrap_or_default();
    let time_at = |frame: u32| {
        seen.iter()
            .find(|(f, _, _)| *f == frame)
            .map_or(f32::NAN, |(_, t, _)| *t)
    };
    assert!((time_at(9) - time_at(8) - 0.05).abs() < 1e-5, "{seen:?}");
    assert_eq!(time_at(12), time_at(18), "paused: {seen:?}");
    assert!((time_at(25) - time_at(24) - 0.1).abs() < 1e-5, "{seen:?}");
}
