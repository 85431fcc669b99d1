//! `spinner`: spawns a ring of entities from code and spins each about Y in fixed steps.
//!
//! Shows a plugin component (`spinner.spin`, the angular speed of each entity), the bulk
//! transform API (one call reads and writes every transform), and plugin state that survives
//! a hot reload (`save_state`/`load_state`: the number of steps spun).
//!
//! Settings: `spinner.count=N` (default 8 entities), `spinner.speed=RAD_PER_S` (default 1).

use std::collections::HashMap;

use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{
    export_plugin, state, AttachInfo, Component, Ctx, Entity, Name, Plugin, PluginError, Transform,
};
use serde::{Deserialize, Serialize};

/// Radius of the ring the entities are spawned on, metres.
const RING_RADIUS: f32 = 3.0;

/// How fast an entity spins about its Y axis.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Spin {
    /// Angular speed, radians per second.
    pub speed: f32,
}

impl Component for Spin {
    const NAME: &'static str = "spinner.spin";
}

/// The plugin's own state, carried across hot reloads.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Spinner {
    /// Fixed steps spun so far.
    pub steps: u64,
    #[serde(skip)]
    count: usize,
    #[serde(skip)]
    speed: f32,
}

impl Plugin for Spinner {
    fn on_attach(&mut self, ctx: &mut Ctx, info: &AttachInfo) -> Result<(), PluginError> {
        self.count = info.parse_setting("count")?.unwrap_or(8);
        self.speed = info.parse_setting("speed")?.unwrap_or(1.0);
        if !self.speed.is_finite() {
            return Err("spinner.speed must be a finite number".into());
        }
        if info.reload {
            ctx.info(format!("reloaded after {} steps", self.steps));
        }
        Ok(())
    }

    fn on_init(&mut self, ctx: &mut Ctx) {
        // Spawn only into a world that has no spinning entities yet (a scene may hold them).
        let existing = ctx.query::<Spin>().map(|rows| rows.len()).unwrap_or(0);
        if existing > 0 {
            ctx.info(format!("{existing} spinning entities already in the world"));
            return;
        }
        for i in 0..self.count {
            let angle = i as f32 / self.count as f32 * std::f32::consts::TAU;
            let position = Vec3::new(angle.cos(), 0.5, angle.sin()) * RING_RADIUS;
            let spin = Spin {
                speed: self.speed * (1.0 + i as f32 * 0.25),
            };
            let transform = Transform::from_translation(position);
            if let Err(error) = ctx.spawn((Name::new(format!("spinner {i}")), transform, spin)) {
                ctx.error(format!("could not spawn: {error}"));
            }
        }
        ctx.info(format!("spawned {} spinning entities", self.count));
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        let dt = ctx.time().fixed_delta;
        let speeds: HashMap<Entity, f32> = match ctx.query::<Spin>() {
            Ok(rows) => rows.into_iter().map(|(e, s)| (e, s.speed)).collect(),
            Err(error) => {
                ctx.error(format!("cannot read spin speeds: {error}"));
                return;
            }
        };
        let result = ctx.update_transforms(|items| {
            for item in items {
                if let Some(speed) = speeds.get(&item.entity) {
                    let step = Quat::from_rotation_y(speed * dt);
                    item.transform.rotation = (step * item.transform.rotation).normalize();
                }
            }
        });
        if let Err(error) = result {
            ctx.error(format!("cannot write transforms: {error}"));
        }
        self.steps += 1;
    }

    fn save_state(&self) -> Result<Vec<u8>, PluginError> {
        state::encode(self)
    }

    fn load_state(&mut self, bytes: &[u8]) -> Result<(), PluginError> {
        let saved: Spinner = state::decode(bytes)?;
        self.steps = saved.steps;
        Ok(())
    }
}

export_plugin!(Spinner);
