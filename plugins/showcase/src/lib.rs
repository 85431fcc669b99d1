//! `showcase`: what the renderer can draw, in one scene.
//!
//! A row of five spheres, one per shading mode (unlit, lit-low, lit, normals, wireframe); a
//! row of cubes spinning in fixed steps (drawn at interpolated poses), one textured; the vase
//! from `assets/models/vase/` (OBJ + MTL + its own texture); an ambient light, a sun and two
//! coloured point lights; a perspective camera; the editor grid on Y = 0, which is also the
//! ground that a few physics bodies fall onto.
//!
//! Asset paths are relative to the host's asset root (the working directory for `onyx run`;
//! run from the repository root). Setting `showcase.camera=ortho` uses an orthographic camera.

use onyx_plugin_api::glam::{Mat3, Quat, Vec3};
use onyx_plugin_api::{
    export_plugin, AttachInfo, Camera, Collider, Ctx, DebugLine, Entity, Light, Material, MeshId,
    MeshRenderer, Name, Plugin, PluginError, RigidBody, ShadingMode, Transform,
};

/// Where the camera looks from and at.
const EYE: Vec3 = Vec3::new(0.0, 4.0, 10.5);
const TARGET: Vec3 = Vec3::new(0.0, 0.6, 0.0);
/// Radians per second the cubes turn.
const SPIN_SPEED: f32 = 0.8;

/// The plugin.
#[derive(Default)]
pub struct Showcase {
    orthographic: bool,
    spinning: Vec<Entity>,
}

/// The rotation that makes an entity at `eye` look at `target` (local -Z forward, Y up).
fn look_at(eye: Vec3, target: Vec3) -> Quat {
    let back = (eye - target).normalize();
    let right = Vec3::Y.cross(back).normalize();
    let up = back.cross(right);
    Quat::from_mat3(&Mat3::from_cols(right, up, back))
}

impl Showcase {
    fn spawn_all(&mut self, ctx: &mut Ctx) -> Result<(), onyx_plugin_api::CtxError> {
        let camera = if self.orthographic {
            Camera::orthographic(7.0)
        } else {
            Camera::perspective(45f32.to_radians())
        };
        let pose = Transform::from_translation(EYE).with_rotation(look_at(EYE, TARGET));
        let camera = ctx.spawn((Name::new("camera"), pose, camera))?;
        ctx.set_camera(camera)?;

        let ambient = Light::Ambient {
            color: [1.0, 1.0, 1.0],
            intensity: 0.15,
        };
        ctx.spawn((Name::new("ambient"), Transform::IDENTITY, ambient))?;
        let sun = Transform::IDENTITY.with_rotation(look_at(Vec3::new(-3.0, 6.0, 4.0), Vec3::ZERO));
        ctx.spawn((
            Name::new("sun"),
            sun,
            Light::Directional {
                color: [1.0, 0.96, 0.9],
                intensity: 0.8,
                shadows: true,
            },
        ))?;
        let red = Light::Point {
            color: [1.0, 0.2, 0.1],
            intensity: 2.0,
            range: 5.0,
            shadows: false,
        };
        let blue = Light::Point {
            color: [0.1, 0.3, 1.0],
            intensity: 2.0,
            range: 5.0,
            shadows: false,
        };
        ctx.spawn((
            Name::new("red light"),
            Transform::from_xyz(-3.0, 1.5, 1.5),
            red,
        ))?;
        ctx.spawn((
            Name::new("blue light"),
            Transform::from_xyz(3.0, 1.5, 1.5),
            blue,
        ))?;

        let modes = [
            ShadingMode::Unlit,
            ShadingMode::LitLow,
            ShadingMode::Lit,
            ShadingMode::Normal,
            ShadingMode::Wireframe,
        ];
        for (i, mode) in modes.into_iter().enumerate() {
            let x = -4.0 + 2.0 * i as f32;
            let material = Material::color(0.9, 0.55, 0.2).with_shading(mode);
            let look = MeshRenderer::new(MeshId::SPHERE).with_material(material);
            ctx.spawn((
                Name::new(format!("{mode:?} sphere")),
                Transform::from_xyz(x, 0.6, 1.5),
                look,
            ))?;
        }

        let grid_texture = ctx.load_texture("assets/textures/uv_grid.png")?;
        for i in 0..3 {
            let x = -2.0 + 2.0 * i as f32;
            let mut material = Material::color(0.3, 0.7, 0.9);
            if i == 1 {
                material = Material::color(1.0, 1.0, 1.0).with_texture(grid_texture);
            }
            let look = MeshRenderer::new(MeshId::CUBE).with_material(material);
            let cube = ctx.spawn((
                Name::new(format!("cube {i}")),
                Transform::from_xyz(x, 0.5, -1.0),
                look,
            ))?;
            self.spinning.push(cube);
        }

        // Physics: the grid's plane is the ground; a few bodies fall onto it and on each other.
        ctx.spawn((Name::new("ground"), Transform::IDENTITY, Collider::plane()))?;
        for i in 0..4 {
            let x = 3.2 + 0.3 * i as f32;
            let y = 1.0 + 1.3 * i as f32;
            let (mesh, collider) = if i % 2 == 0 {
                (MeshId::CUBE, Collider::cuboid(0.5, 0.5, 0.5))
            } else {
                (MeshId::SPHERE, Collider::sphere(0.5).with_restitution(0.4))
            };
            let look = MeshRenderer::new(mesh).with_material(Material::color(0.4, 0.8, 0.4));
            let pose = Transform::from_xyz(x, y, -1.5)
                .with_rotation(Quat::from_rotation_z(0.3 * i as f32));
            ctx.spawn((
                Name::new(format!("falling {i}")),
                pose,
                look,
                RigidBody::dynamic(),
                collider,
            ))?;
        }

        let vase = ctx.load_mesh("assets/models/vase/vase.obj")?;
        let pose = Transform::from_xyz(-4.0, 0.0, -2.2)
            .with_rotation(Quat::from_rotation_y(2.2))
            .with_scale(Vec3::splat(2.0));
        let look = MeshRenderer::new(vase).with_material(Material::color(1.0, 1.0, 1.0));
        ctx.spawn((Name::new("vase"), pose, look))?;
        Ok(())
    }
}

impl Plugin for Showcase {
    fn on_attach(&mut self, _ctx: &mut Ctx, info: &AttachInfo) -> Result<(), PluginError> {
        self.orthographic = info.setting("camera") == Some("ortho");
        Ok(())
    }

    fn on_init(&mut self, ctx: &mut Ctx) {
        if let Err(error) = self.spawn_all(ctx) {
            ctx.error(format!("could not build the showcase: {error}"));
        }
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        let step = Quat::from_rotation_y(SPIN_SPEED * ctx.time().fixed_delta);
        for &cube in &self.spinning {
            if let Ok(mut t) = ctx.get::<Transform>(cube) {
                t.rotation = (step * t.rotation).normalize();
                ctx.set(cube, t).ok();
            }
        }
    }

    fn on_render(&mut self, ctx: &mut Ctx) {
        // Debug drawing: the world axes at the origin, one metre long.
        let o = Vec3::new(0.0, 0.01, 0.0);
        ctx.draw_debug_lines(&[
            DebugLine::new(o, o + Vec3::X, [1.0, 0.2, 0.2, 1.0]),
            DebugLine::new(o, o + Vec3::Y, [0.2, 1.0, 0.2, 1.0]),
            DebugLine::new(o, o + Vec3::Z, [0.2, 0.4, 1.0, 1.0]),
        ]);
    }
}

export_plugin!(Showcase);
