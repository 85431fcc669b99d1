//! `hello`: the smallest useful Onyx plugin.
//!
//! It logs each lifecycle stage the first time it runs, counts every call in a `hello.stats`
//! component on an entity named "hello" (visible in `--dump-state` and scene files), and
//! quits after N frames when given `--set hello.quit_after=N`.

use onyx_plugin_api::{
    export_plugin, AttachInfo, Component, Ctx, Entity, Event, Flow, Name, Plugin, PluginError,
};
use serde::{Deserialize, Serialize};

/// How many times each lifecycle method ran.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Stats {
    /// `on_attach` calls.
    pub attach: u32,
    /// `on_init` calls.
    pub init: u32,
    /// `on_event` calls.
    pub events: u32,
    /// `on_fixed_update` calls.
    pub fixed_updates: u64,
    /// `on_update` calls.
    pub updates: u64,
    /// `on_render` calls.
    pub renders: u64,
    /// `draw_gui` calls.
    pub gui: u64,
    /// `on_resize` calls.
    pub resizes: u32,
}

impl Component for Stats {
    const NAME: &'static str = "hello.stats";
}

/// The plugin.
#[derive(Default)]
pub struct Hello {
    stats: Stats,
    entity: Option<Entity>,
    quit_after: Option<u64>,
}

impl Hello {
    fn first(ctx: &mut Ctx, count: u64, stage: &str) {
        if count == 1 {
            ctx.info(format!("hello from {stage}"));
        }
    }

    fn publish(&mut self, ctx: &mut Ctx) {
        if let Some(entity) = self.entity {
            if let Err(error) = ctx.set(entity, self.stats.clone()) {
                ctx.warn(format!("could not store stats: {error}"));
            }
        }
    }
}

impl Plugin for Hello {
    fn on_attach(&mut self, ctx: &mut Ctx, info: &AttachInfo) -> Result<(), PluginError> {
        self.quit_after = info.parse_setting("quit_after")?;
        self.stats.attach += 1;
        Self::first(ctx, 1, "on_attach");
        Ok(())
    }

    fn on_init(&mut self, ctx: &mut Ctx) {
        self.stats.init += 1;
        Self::first(ctx, 1, "on_init");
        self.entity = ctx.spawn((Name::new("hello"), self.stats.clone())).ok();
    }

    fn on_event(&mut self, ctx: &mut Ctx, event: &Event) {
        self.stats.events += 1;
        if self.stats.events == 1 {
            ctx.info(format!("hello from on_event: {event:?}"));
        }
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        self.stats.fixed_updates += 1;
        Self::first(ctx, self.stats.fixed_updates, "on_fixed_update");
    }

    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> Flow {
        self.stats.updates += 1;
        Self::first(ctx, self.stats.updates, "on_update");
        match self.quit_after {
            Some(n) if self.stats.updates >= n => {
                ctx.info(format!("quitting after {n} frames, as asked"));
                self.publish(ctx);
                Flow::Quit
            }
            _ => Flow::Continue,
        }
    }

    fn on_render(&mut self, ctx: &mut Ctx) {
        self.stats.renders += 1;
        Self::first(ctx, self.stats.renders, "on_render");
    }

    fn draw_gui(&mut self, ctx: &mut Ctx, _ui: &mut onyx_plugin_api::egui::Ui) {
        self.stats.gui += 1;
        Self::first(ctx, self.stats.gui, "draw_gui");
        self.publish(ctx);
    }

    fn on_resize(&mut self, ctx: &mut Ctx, width: u32, height: u32) {
        self.stats.resizes += 1;
        ctx.info(format!("hello from on_resize: {width}x{height}"));
    }

    fn on_detach(&mut self, ctx: &mut Ctx) {
        ctx.info(format!(
            "goodbye after {} frames and {} fixed steps",
            self.stats.updates, self.stats.fixed_updates
        ));
    }
}

export_plugin!(Hello);
