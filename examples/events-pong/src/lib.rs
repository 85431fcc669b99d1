//! # Lesson 4: plugin-to-plugin custom events (the answering side)
//!
//! The other half of `examples/events-ping` (read that one first). `events_pong` listens for
//! [`Ping`] events in `on_event`, answers each with a [`Pong`] carrying the same number,
//! counts them on its ball ([`PongTally`]) and bounces the ball.
//!
//! It declares its own `Ping` and `Pong`: what makes them the same messages as the other
//! plugin's is the `NAME` and the JSON fields, not the Rust type.
//!
//! ```sh
//! cargo build --workspace
//! target/debug/onyx run --plugin events_ping --plugin events_pong
//! ```

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{
    export_plugin, Component, Ctx, Entity, Event, Material, MeshId, MeshRenderer, Message, Name,
    Plugin, Transform,
};
use serde::{Deserialize, Serialize};

/// What `events_ping` sends (the same name and fields as there).
#[derive(Debug, Serialize, Deserialize)]
pub struct Ping {
    /// Which ping.
    pub n: u32,
}

impl Message for Ping {
    const NAME: &'static str = "examples.ping";
}

/// The answer.
#[derive(Debug, Serialize, Deserialize)]
pub struct Pong {
    /// The ping answered.
    pub n: u32,
}

impl Message for Pong {
    const NAME: &'static str = "examples.pong";
}

/// What `events_pong` counted, kept on its ball.
#[derive(Debug, Default, Serialize, Deserialize)]
pub struct PongTally {
    /// Pings heard (and answered).
    pub heard: u32,
    /// The sender of the last ping.
    pub from: String,
}

impl Component for PongTally {
    const NAME: &'static str = "events_pong.tally";
}

/// The plugin.
#[derive(Default)]
pub struct EventsPong {
    ball: Option<Entity>,
    heard: u32,
    /// Metres above its rest height, falling back each fixed step.
    hop: f32,
}

impl Plugin for EventsPong {
    fn on_init(&mut self, ctx: &mut Ctx) {
        let ball = (
            Name::new("pong ball"),
            Transform::from_xyz(1.0, 0.5, 0.0),
            MeshRenderer::new(MeshId::SPHERE).with_material(Material::color(0.2, 0.5, 0.9)),
            PongTally::default(),
        );
        match ctx.spawn(ball) {
            Ok(ball) => self.ball = Some(ball),
            Err(error) => ctx.error(format!("could not spawn the ball: {error}")),
        }
    }

    fn on_event(&mut self, ctx: &mut Ctx, event: &Event) {
        let Event::Custom(custom) = event else { return };
        if !custom.is::<Ping>() {
            return;
        }
        let ping = match custom.decode::<Ping>() {
            Ok(ping) => ping,
            Err(error) => {
                ctx.warn(format!("a ping we cannot read: {error}"));
                return;
            }
        };
        self.heard += 1;
        self.hop = 0.5;
        if let Err(error) = ctx.send(&Pong { n: ping.n }) {
            ctx.error(format!("could not answer: {error}"));
        }
        if let Some(ball) = self.ball {
            let tally = PongTally {
                heard: self.heard,
                from: custom.sender.clone(),
            };
            ctx.set(ball, tally).ok();
        }
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        let Some(ball) = self.ball else { return };
        self.hop = (self.hop - ctx.time().fixed_delta).max(0.0);
        let at = Vec3::new(1.0, 0.5 + self.hop, 0.0);
        ctx.set(ball, Transform::from_translation(at)).ok();
    }
}

export_plugin!(EventsPong);
