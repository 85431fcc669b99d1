//! # Lesson 4: plugin-to-plugin custom events (the sending side)
//!
//! Plugins never call each other: they send events through the host. A [`Message`] is a
//! serde type with a stable [`Message::NAME`]; `ctx.send(&message)` delivers it to every
//! plugin's `on_event` at the start of the next frame as [`Event::Custom`], with the sender's
//! name, and `event.decode::<M>()` reads it back. The name is the contract: two plugins built
//! separately agree on it (and on the fields), not on a Rust type — in a real project put the
//! message types in a small crate both depend on.
//!
//! `events_ping` sends a [`Ping`] once a second and counts the [`Pong`]s that come back;
//! `events_pong` (the other half, `examples/events-pong`) answers each ping. Each bounces a
//! ball when it hears from the other, and keeps its counts in a component on its ball
//! ([`PingTally`]), so the editor's inspector (or a test) can read them.
//!
//! ```sh
//! cargo build --workspace
//! target/debug/onyx run --plugin events_ping --plugin events_pong
//! ```
//!
//! Checked by `tests/tests/e2e/examples.rs`: with both loaded, pings are answered; with
//! `events_ping` alone, nothing comes back.

use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{
    export_plugin, Camera, Component, Ctx, CtxError, Entity, Event, Light, Material, MeshId,
    MeshRenderer, Message, Name, Plugin, Transform,
};
use serde::{Deserialize, Serialize};

/// Sent by `events_ping` once a second.
#[derive(Debug, Serialize, Deserialize)]
pub struct Ping {
    /// 1 for the first ping, then 2, 3, …
    pub n: u32,
}

impl Message for Ping {
    const NAME: &'static str = "examples.ping";
}

/// Sent back by `events_pong` for each ping (the same `NAME` and fields in both crates).
#[derive(Debug, Serialize, Deserialize)]
pub struct Pong {
    /// The ping answered.
    pub n: u32,
}

impl Message for Pong {
    const NAME: &'static str = "examples.pong";
}

/// What `events_ping` counted, kept on its ball.
#[derive(Debug, Default, Serialize, Deserialize)]
pub struct PingTally {
    /// Pings sent.
    pub sent: u32,
    /// Pongs received.
    pub answered: u32,
}

impl Component for PingTally {
    const NAME: &'static str = "events_ping.tally";
}

/// Fixed steps between pings (one second at the default 60 Hz).
const STEPS_PER_PING: u64 = 60;

/// The plugin.
#[derive(Default)]
pub struct EventsPing {
    ball: Option<Entity>,
    tally: PingTally,
    steps: u64,
}

impl EventsPing {
    fn build_scene(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        let camera = ctx.spawn((
            Name::new("camera"),
            Transform::from_xyz(0.0, 1.0, 6.0).with_rotation(Quat::from_rotation_x(-0.1)),
            Camera::perspective(50f32.to_radians()),
        ))?;
        ctx.set_camera(camera)?;
        ctx.spawn((
            Name::new("sun"),
            Transform::IDENTITY.with_rotation(Quat::from_rotation_x(-0.8)),
            Light::sun(),
        ))?;
        let ball = ctx.spawn((
            Name::new("ping ball"),
            Transform::from_xyz(-1.0, 0.5, 0.0),
            MeshRenderer::new(MeshId::SPHERE).with_material(Material::color(0.9, 0.3, 0.2)),
            PingTally::default(),
        ))?;
        self.ball = Some(ball);
        Ok(())
    }

    /// Puts the counts on the ball and lifts it by `hop` metres.
    fn show(&mut self, ctx: &mut Ctx, hop: f32) {
        let Some(ball) = self.ball else { return };
        let tally = PingTally {
            sent: self.tally.sent,
            answered: self.tally.answered,
        };
        ctx.set(ball, tally).ok();
        ctx.set(
            ball,
            Transform::from_translation(Vec3::new(-1.0, 0.5 + hop, 0.0)),
        )
        .ok();
    }
}

impl Plugin for EventsPing {
    fn on_init(&mut self, ctx: &mut Ctx) {
        if let Err(error) = self.build_scene(ctx) {
            ctx.error(format!("could not build the scene: {error}"));
        }
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        self.steps += 1;
        if self.steps.is_multiple_of(STEPS_PER_PING) {
            self.tally.sent += 1;
            if let Err(error) = ctx.send(&Ping { n: self.tally.sent }) {
                ctx.error(format!("could not send ping: {error}"));
            }
        }
        // The ball falls back after a hop.
        let since = (self.steps % STEPS_PER_PING) as f32 / STEPS_PER_PING as f32;
        self.show(ctx, (0.5 - since).max(0.0));
    }

    fn on_event(&mut self, ctx: &mut Ctx, event: &Event) {
        let Event::Custom(custom) = event else { return };
        if !custom.is::<Pong>() {
            return; // our own pings come back to us too: every plugin gets every event
        }
        match custom.decode::<Pong>() {
            Ok(pong) => {
                self.tally.answered += 1;
                ctx.info(format!("pong {} from `{}`", pong.n, custom.sender));
                self.show(ctx, 0.5);
            }
            Err(error) => ctx.warn(format!("a pong we cannot read: {error}")),
        }
    }
}

export_plugin!(EventsPing);
