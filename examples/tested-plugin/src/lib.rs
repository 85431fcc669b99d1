//! # Lesson 7: a plugin tested without a window
//!
//! `onyx_runtime::HeadlessHost` is the whole host — world, fixed steps, physics, events,
//! plugin calls through the same ABI adapter a loaded library goes through — without a window
//! or a GPU. A plugin's tests add it in-process (`host.add_plugin`), run frames
//! (`host.step(n)`: each frame 1/60 s with one fixed step), feed it input
//! (`host.hold_key`, `host.click_at`, `host.inject`) and look at the world
//! (`host.find::<Transform>(name)`, `host.get`). Depend on `onyx-runtime` as a
//! dev-dependency only: the plugin library itself never links the host.
//!
//! The plugin: a guard walks back and forth between two posts at [`DEFAULT_SPEED`] (or the
//! `tested_plugin.speed` setting, metres per second); `P` pauses it. The tests below check
//! the arrival time, the turn at each post, the setting, a bad setting refused with a
//! sentence, and the pause key.
//!
//! ```sh
//! cargo test -p tested-plugin          # the lesson
//! target/debug/onyx run --plugin tested_plugin --set tested_plugin.speed=3
//! ```

use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{
    export_plugin, AttachInfo, Camera, Ctx, Entity, Key, Light, Material, MeshId, MeshRenderer,
    Name, Plugin, PluginError, Transform,
};

/// Walking speed without a `speed` setting, metres per second.
pub const DEFAULT_SPEED: f32 = 1.5;
/// The two posts the guard walks between (x, metres).
pub const POSTS: [f32; 2] = [-3.0, 3.0];

/// The plugin.
#[derive(Debug, Default)]
pub struct TestedPlugin {
    speed: f32,
    guard: Option<Entity>,
    /// Which post the guard walks to (an index into [`POSTS`]).
    heading_to: usize,
    paused: bool,
}

impl Plugin for TestedPlugin {
    fn on_attach(&mut self, _ctx: &mut Ctx, info: &AttachInfo) -> Result<(), PluginError> {
        let speed = info.parse_setting::<f32>("speed")?.unwrap_or(DEFAULT_SPEED);
        if !(speed.is_finite() && speed > 0.0) {
            return Err(format!("setting `speed` must be a positive number, not {speed}").into());
        }
        self.speed = speed;
        self.heading_to = 1;
        Ok(())
    }

    fn on_init(&mut self, ctx: &mut Ctx) {
        let guard = ctx.spawn((
            Name::new("guard"),
            Transform::from_xyz(POSTS[0], 0.5, 0.0),
            MeshRenderer::new(MeshId::CAPSULE).with_material(Material::color(0.3, 0.3, 0.8)),
        ));
        self.guard = guard.ok();
        let camera = ctx.spawn((
            Name::new("camera"),
            Transform::from_xyz(0.0, 3.0, 8.0).with_rotation(Quat::from_rotation_x(-0.35)),
            Camera::perspective(50f32.to_radians()),
        ));
        if let Ok(camera) = camera {
            ctx.set_camera(camera).ok();
        }
        let sun = Transform::IDENTITY.with_rotation(Quat::from_rotation_x(-0.8));
        ctx.spawn((Name::new("sun"), sun, Light::sun())).ok();
    }

    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> onyx_plugin_api::Flow {
        if ctx.input().key_pressed(Key::P) {
            self.paused = !self.paused;
        }
        onyx_plugin_api::Flow::Continue
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        let Some(guard) = self.guard else { return };
        if self.paused {
            return;
        }
        let Ok(mut at) = ctx.get::<Transform>(guard) else {
            return;
        };
        let target = POSTS[self.heading_to];
        let step = self.speed * ctx.time().fixed_delta;
        let to_go = target - at.translation.x;
        if to_go.abs() <= step {
            at.translation.x = target;
            self.heading_to = 1 - self.heading_to;
        } else {
            at.translation.x += step * to_go.signum();
        }
        let facing = if self.heading_to == 1 { -1.0 } else { 1.0 };
        at.rotation = Quat::from_rotation_y(facing * std::f32::consts::FRAC_PI_2);
        at.translation = Vec3::new(at.translation.x, 0.5, 0.0);
        ctx.set(guard, at).ok();
    }
}

export_plugin!(TestedPlugin);

#[cfg(test)]
mod tests {
    use super::*;
    use onyx_runtime::{HeadlessHost, HostConfig};

    /// A host running the plugin with `config`.
    fn host_with(config: HostConfig) -> HeadlessHost {
        let mut host = HeadlessHost::with_config(config);
        host.add_plugin("tested_plugin", TestedPlugin::default())
            .expect("the plugin attaches");
        host
    }

    fn guard_x(host: &HeadlessHost) -> f32 {
        let (_, at) = host.find::<Transform>("guard").expect("the guard exists");
        at.translation.x
    }

    #[test]
    fn the_guard_reaches_the_far_post_in_distance_over_speed() {
        let mut host = host_with(HostConfig::default());
        let seconds = (POSTS[1] - POSTS[0]) / DEFAULT_SPEED; // 4 s
        host.step((seconds * 60.0) as u32 - 6);
        assert!(guard_x(&host) < POSTS[1], "not there 0.1 s early");
        host.step(6);
        assert!(
            (guard_x(&host) - POSTS[1]).abs() < 1e-4,
            "{}",
            guard_x(&host)
        );
    }

    #[test]
    fn at_a_post_the_guard_turns_back() {
        let mut host = host_with(HostConfig::default());
        host.step(4 * 60 + 30); // half a second past the far post
        let x = guard_x(&host);
        let back = POSTS[1] - 0.5 * DEFAULT_SPEED;
        assert!(
            (x - back).abs() < 0.03,
            "walking back: x = {x}, expected {back}"
        );
    }

    #[test]
    fn the_speed_setting_is_read_at_attach() {
        let config = HostConfig::default().setting("tested_plugin", "speed", "3");
        let mut host = host_with(config);
        host.step(60);
        let walked = guard_x(&host) - POSTS[0];
        assert!(
            (walked - 3.0).abs() < 0.06,
            "3 m in a second: walked {walked} m"
        );
    }

    #[test]
    fn a_bad_speed_is_refused_with_a_sentence() {
        let config = HostConfig::default().setting("tested_plugin", "speed", "fast");
        let mut host = HeadlessHost::with_config(config);
        let error = host
            .add_plugin("tested_plugin", TestedPlugin::default())
            .expect_err("refused at attach");
        let text = error.to_string();
        assert!(text.contains("`speed` = `fast` is not valid"), "{text}");
    }

    #[test]
    fn p_pauses_and_resumes_the_guard() {
        let mut host = host_with(HostConfig::default());
        host.step(30);
        host.press_key(Key::P);
        host.step(1);
        let stopped_at = guard_x(&host);
        host.step(60);
        assert_eq!(guard_x(&host), stopped_at, "paused");
        host.press_key(Key::P);
        host.step(60);
        assert!(guard_x(&host) > stopped_at + 1.0, "walking again");
    }
}
