//! # Lesson 3: spawning from a GUI window
//!
//! [`Plugin::draw_gui`] gets the window's root [`egui::Ui`] once a frame: draw windows,
//! panels and widgets with [egui](https://docs.rs/egui/0.36), and act on what was clicked
//! right there, with the same `ctx` as every other call. A click the UI takes does not reach
//! the scene (`on_event` and `ctx.input()` do not see it).
//!
//! This plugin shows a "Spawner" window: pick a shape and a colour, press **Spawn** and a
//! body drops onto the ground; **Clear** removes what it spawned. The window also says how
//! many bodies there are.
//!
//! ```sh
//! cargo build --workspace
//! target/debug/onyx run --plugin gui_spawner
//! ```
//!
//! Checked by `tests/tests/e2e/examples.rs`, which clicks the buttons like a person would
//! (by label, through egui's AccessKit tree) in a headless host.

use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{
    egui, export_plugin, Camera, Collider, Ctx, CtxError, Entity, Light, Material, MeshId,
    MeshRenderer, Name, Plugin, RigidBody, Transform,
};

/// What Spawn makes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum Shape {
    #[default]
    Cube,
    Ball,
}

/// The plugin: what the window's widgets hold, and the bodies it spawned.
#[derive(Default)]
pub struct GuiSpawner {
    shape: Shape,
    color: [f32; 3],
    spawned: Vec<Entity>,
}

impl GuiSpawner {
    fn build_scene(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        self.color = [0.2, 0.6, 1.0];
        let camera = ctx.spawn((
            Name::new("camera"),
            Transform::from_xyz(0.0, 3.0, 9.0).with_rotation(Quat::from_rotation_x(-0.3)),
            Camera::perspective(55f32.to_radians()),
        ))?;
        ctx.set_camera(camera)?;
        ctx.spawn((
            Name::new("sun"),
            Transform::IDENTITY.with_rotation(Quat::from_rotation_x(-1.0)),
            Light::sun(),
        ))?;
        ctx.spawn((
            Name::new("ground"),
            Transform::IDENTITY.with_scale(Vec3::new(12.0, 1.0, 12.0)),
            MeshRenderer::new(MeshId::PLANE).with_material(Material::color(0.5, 0.5, 0.45)),
            Collider::plane(),
        ))?;
        Ok(())
    }

    fn spawn_one(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        // Spread them out a little so they land side by side.
        let n = self.spawned.len() as f32;
        let at = Transform::from_xyz((n * 0.7).sin() * 2.0, 4.0, (n * 1.3).cos());
        let [r, g, b] = self.color;
        let (mesh, collider) = match self.shape {
            Shape::Cube => (MeshId::CUBE, Collider::cuboid(0.5, 0.5, 0.5)),
            Shape::Ball => (MeshId::SPHERE, Collider::sphere(0.5).with_restitution(0.5)),
        };
        let body = ctx.spawn((
            Name::new(format!("{:?} {}", self.shape, self.spawned.len() + 1)),
            at,
            MeshRenderer::new(mesh).with_material(Material::color(r, g, b)),
            RigidBody::dynamic(),
            collider,
        ))?;
        self.spawned.push(body);
        Ok(())
    }
}

impl Plugin for GuiSpawner {
    fn on_init(&mut self, ctx: &mut Ctx) {
        if let Err(error) = self.build_scene(ctx) {
            ctx.error(format!("could not build the scene: {error}"));
        }
    }

    fn draw_gui(&mut self, ctx: &mut Ctx, ui: &mut egui::Ui) {
        egui::Window::new("Spawner")
            .default_pos([16.0, 16.0])
            .resizable(false)
            .show(ui.ctx(), |ui| {
                ui.horizontal(|ui| {
                    ui.selectable_value(&mut self.shape, Shape::Cube, "Cube");
                    ui.selectable_value(&mut self.shape, Shape::Ball, "Ball");
                });
                ui.horizontal(|ui| {
                    ui.label("Colour");
                    ui.color_edit_button_rgb(&mut self.color);
                });
                ui.horizontal(|ui| {
                    if ui.button("Spawn").clicked() {
                        if let Err(error) = self.spawn_one(ctx) {
                            ctx.error(format!("could not spawn: {error}"));
                        }
                    }
                    if ui.button("Clear").clicked() {
                        for body in self.spawned.drain(..) {
                            ctx.despawn(body).ok();
                        }
                    }
                });
                ui.label(format!("{} bodies", self.spawned.len()));
            });
    }
}

export_plugin!(GuiSpawner);
