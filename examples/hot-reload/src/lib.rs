//! # Lesson 8: hot reload with `onyx dev`
//!
//! `onyx dev --plugin-crate DIR` builds a plugin crate, runs it, and rebuilds it whenever a
//! file under `src/` changes; the host swaps the new build in while it runs. The world is
//! never touched by a swap. The plugin object is: the old one is dropped and a new one made
//! from the new library, so whatever the plugin wants to keep it hands over in
//! [`Plugin::save_state`] and takes back in [`Plugin::load_state`] (here the whole struct, as
//! JSON, through `onyx_plugin_api::state`).
//!
//! Walkthrough (from the repository root, with a display or under `xvfb-run`):
//!
//! ```sh
//! cargo build --workspace
//! target/debug/onyx dev --plugin-crate examples/hot-reload
//! ```
//!
//! 1. A cube turns. Edit [`COLOUR`] below to `[0.2, 0.8, 0.3]` and save: within a few seconds
//!    the log says `reloaded after … turns` and the cube is green — still at the angle it had
//!    (`angle` came through `save_state`/`load_state`), the turn count going on.
//! 2. Change [`TURN_SPEED`] to `3.0`: the same cube turns faster.
//! 3. Break the code (delete a `;`) and save: the compiler's errors are printed, the old build
//!    keeps running. Fix it and the next save swaps again.
//! 4. Add a field to [`HotReload`] with `#[serde(default)]`: the new build still reads the
//!    old build's state.
//!
//! What does not survive: anything that points into the old library (closures, trait
//! objects, `TypeId`s) — build those again in `on_attach`, which is told `info.reload`.
//!
//! Checked by `tests/tests/e2e/examples.rs`: a reload of the built library keeps the angle
//! and the turn count.

use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{
    export_plugin, state, AttachInfo, Camera, Ctx, Entity, Light, Material, MeshId, MeshRenderer,
    Name, Plugin, PluginError, Transform,
};
use serde::{Deserialize, Serialize};

/// The cube's colour (linear RGB): edit it while `onyx dev` runs.
pub const COLOUR: [f32; 3] = [0.9, 0.4, 0.1];
/// How fast the cube turns, radians per second: edit it too.
pub const TURN_SPEED: f32 = 1.0;

/// The plugin. Everything here is kept across a reload by `save_state`/`load_state`.
#[derive(Debug, Default, Serialize, Deserialize)]
pub struct HotReload {
    /// The cube (entities live in the host's world, so the handle stays good).
    pub cube: Option<Entity>,
    /// How far it has turned, radians.
    pub angle: f32,
    /// Whole turns so far.
    pub turns: u32,
    /// How many times this plugin was swapped for a new build.
    pub reloads: u32,
}

impl Plugin for HotReload {
    fn on_attach(&mut self, ctx: &mut Ctx, info: &AttachInfo) -> Result<(), PluginError> {
        if info.reload {
            // `load_state` has already run: the old build's fields are back.
            self.reloads += 1;
            ctx.info(format!(
                "reloaded after {} turns (reload {}); colour {COLOUR:?}, speed {TURN_SPEED}",
                self.turns, self.reloads
            ));
        }
        Ok(())
    }

    fn on_init(&mut self, ctx: &mut Ctx) {
        let cube = ctx.spawn((
            Name::new("cube"),
            Transform::from_xyz(0.0, 0.5, 0.0),
            MeshRenderer::new(MeshId::CUBE),
        ));
        self.cube = cube.ok();
        let camera = ctx.spawn((
            Name::new("camera"),
            Transform::from_xyz(0.0, 2.0, 4.0).with_rotation(Quat::from_rotation_x(-0.4)),
            Camera::perspective(50f32.to_radians()),
        ));
        if let Ok(camera) = camera {
            ctx.set_camera(camera).ok();
        }
        let sun = Transform::IDENTITY.with_rotation(Quat::from_rotation_x(-0.9));
        ctx.spawn((Name::new("sun"), sun, Light::sun())).ok();
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        let Some(cube) = self.cube else { return };
        self.angle += TURN_SPEED * ctx.time().fixed_delta;
        if self.angle >= std::f32::consts::TAU {
            self.angle -= std::f32::consts::TAU;
            self.turns += 1;
        }
        let [r, g, b] = COLOUR;
        let pose = Transform::from_translation(Vec3::new(0.0, 0.5, 0.0))
            .with_rotation(Quat::from_rotation_y(self.angle));
        ctx.set(cube, pose).ok();
        // Written every step, so an edited colour shows as soon as the new build runs.
        let look = MeshRenderer::new(MeshId::CUBE).with_material(Material::color(r, g, b));
        ctx.set(cube, look).ok();
    }

    fn save_state(&self) -> Result<Vec<u8>, PluginError> {
        state::encode(self)
    }

    fn load_state(&mut self, bytes: &[u8]) -> Result<(), PluginError> {
        *self = state::decode(bytes)?;
        Ok(())
    }
}

export_plugin!(HotReload);
