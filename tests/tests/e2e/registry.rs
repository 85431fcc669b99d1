//! The one list of built-in components, enumerated: each built-in round-trips through the
//! tool services (typed `Ctx` calls across the boundary), a scene file, the state dump and a
//! play-mode snapshot. A built-in added to the list without a sample value here fails the
//! test by name.

use std::collections::HashMap;

use onyx_plugin_api::__ffi::with_ctx;
use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::tools::ComponentValue;
use onyx_plugin_api::{
    AnimationId, Animator, BodyKind, Builtin, BuiltinFn, BuiltinId, BuiltinValue, Camera, Collider,
    Ctx, Entity, FileRefs, Joint, JointMotor, JointTarget, Light, LockedAxes, Material, MeshId,
    MeshRenderer, Name, Parent, RigidBody, ShadingMode, TextureId, Transform,
};
use onyx_runtime::HeadlessHost;

/// Runs `f` with a `Ctx` of `host`, as a plugin call would (through the boundary's bridge).
fn as_plugin<R>(host: &mut HeadlessHost, f: impl FnOnce(&mut Ctx) -> R) -> R {
    host.host_mut()
        .with_services("registry-test", |services| with_ctx(services, f))
}

/// A value of built-in `id` that differs from its default in every field that can differ.
fn sample(id: BuiltinId, ctx: &mut Ctx, parent: Entity) -> BuiltinValue {
    match id {
        BuiltinId::Name => Name::new("sample ünïcode name").into(),
        BuiltinId::Transform => Transform::from_xyz(1.5, -2.0, 3.25)
            .with_rotation(Quat::from_euler(
                onyx_plugin_api::glam::EulerRot::YXZ,
                0.3,
                -0.7,
                1.1,
            ))
            .with_scale(Vec3::new(2.0, 0.5, 1.25))
            .into(),
        BuiltinId::Parent => Parent(parent).into(),
        BuiltinId::MeshRenderer => {
            let mesh = ctx.load_mesh("models/crate.obj").unwrap();
            let texture = ctx.load_texture("textures/crate.png").unwrap();
            let material = Material::color(0.1, 0.6, 0.9)
                .with_texture(texture)
                .with_shading(ShadingMode::Wireframe)
                .with_metallic_roughness(0.75, 0.2)
                .with_emissive([0.5, 2.0, 0.0])
                .with_alpha_mode(onyx_plugin_api::AlphaMode::Mask, 0.3)
                .with_double_sided(true);
            let mut renderer = MeshRenderer::new(mesh).with_material(material);
            renderer.visible = false;
            renderer.into()
        }
        BuiltinId::Camera => {
            let mut camera = Camera::orthographic(12.0);
            camera.near = 0.5;
            camera.far = 75.0;
            camera.active = false;
            camera.into()
        }
        BuiltinId::Light => Light::Point {
            color: [1.0, 0.5, 0.25],
            intensity: 3.5,
            range: 12.0,
            shadows: true,
        }
        .into(),
        BuiltinId::RigidBody => {
            let mut body = RigidBody::kinematic()
                .with_velocity(Vec3::new(1.0, 2.0, 3.0))
                .with_mass(7.5)
                .with_ccd(true)
                .with_locked_axes(LockedAxes::ROTATION_X.union(LockedAxes::TRANSLATION_Z));
            body.kind = BodyKind::Kinematic;
            body.gravity_scale = 0.25;
            body.linear_damping = 0.1;
            body.angular_damping = 0.2;
            body.can_sleep = false;
            body.into()
        }
        // No clip: scenes name clips; a plugin has no call to register one.
        BuiltinId::Animator => Animator::new(AnimationId::NONE)
            .with_speed(-0.5)
            .with_looping(false)
            .at(1.25)
            .paused()
            .into(),
        BuiltinId::Collider => Collider::capsule(0.75, 0.3)
            .with_density(250.0)
            .with_restitution(0.4)
            .with_friction(0.8)
            .with_groups(0b101, !0b10)
            .with_sensor(true)
            .into(),
        BuiltinId::Joint => Joint::revolute(JointTarget::Body(parent), [0.0, 0.0, 1.0])
            .with_anchors([0.5, 0.0, 0.0], [-0.5, 0.25, 0.0])
            .with_limits(-0.5, 1.25)
            .with_motor(JointMotor::Velocity {
                speed: 2.0,
                max_force: 30.0,
            })
            .with_spring(0.25, 3.0, 0.5)
            .with_break(500.0, 0.0)
            .into(),
    }
}

/// Entities named after the built-in they hold (the `Name` sample's entity holds only it).
fn spawn_samples(host: &mut HeadlessHost) -> (Vec<(BuiltinId, Entity, BuiltinValue)>, Entity) {
    as_plugin(host, |ctx| {
        let parent = ctx
            .spawn((Name::new("the parent"), Transform::from_xyz(0.0, 1.0, 0.0)))
            .unwrap();
        let mut samples = Vec::new();
        for &id in BuiltinId::ALL {
            let value = sample(id, ctx, parent);
            assert_eq!(value.id(), id, "the sample of {id} is another component");
            let entity = if id == BuiltinId::Name {
                ctx.spawn(()).unwrap()
            } else {
                ctx.spawn(Name::new(format!("holds {id}"))).unwrap()
            };
            ctx.set_component(entity, ComponentValue::Builtin(value.clone()))
                .unwrap_or_else(|e| panic!("{id} sample refused: {e}"));
            samples.push((id, entity, value));
        }
        (samples, parent)
    })
}

fn builtin_of(host: &mut HeadlessHost, entity: Entity, id: BuiltinId) -> Option<BuiltinValue> {
    as_plugin(host, |ctx| {
        ctx.components_of(entity)
            .ok()?
            .into_iter()
            .find_map(|c| match c {
                ComponentValue::Builtin(v) if v.id() == id => Some(v),
                _ => None,
            })
    })
}

#[test]
fn every_builtin_round_trips_through_the_tool_services() {
    let mut host = HeadlessHost::new();
    let (samples, _) = spawn_samples(&mut host);
    assert_eq!(samples.len(), BuiltinId::ALL.len());
    for (id, entity, value) in &samples {
        assert_eq!(
            builtin_of(&mut host, *entity, *id).as_ref(),
            Some(value),
            "{id}"
        );
        let typed = as_plugin(&mut host, |ctx| ctx.get_builtin(*entity, *id).unwrap());
        assert_eq!(&typed, value, "{id} through get_builtin");
        // Every built-in is removable and comes back as set.
        as_plugin(&mut host, |ctx| {
            ctx.remove_builtin(*entity, *id).unwrap();
            assert!(ctx.get_builtin(*entity, *id).is_err(), "{id} still there");
            ctx.set_builtin(*entity, value.clone()).unwrap();
        });
        assert_eq!(
            builtin_of(&mut host, *entity, *id).as_ref(),
            Some(value),
            "{id} re-set"
        );
    }
}

#[test]
fn every_builtin_round_trips_through_a_scene_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("all.ron");
    let mut first = HeadlessHost::new();
    let (samples, _) = spawn_samples(&mut first);
    first.host().save_scene(&path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    for &id in BuiltinId::ALL {
        assert!(
            text.contains(&format!("{}: Some(", id.scene_key())),
            "{id} is not in the file under `{}`:\n{text}",
            id.scene_key()
        );
    }
    let mut second = HeadlessHost::new();
    second.load_scene(&path).unwrap();
    // The same entities in the same order, with new handles: match them by position.
    let mut ids: Vec<Entity> = second
        .world()
        .iter()
        .map(|e| Entity::from_bits(e.entity().to_bits().get()))
        .collect();
    ids.sort();
    assert_eq!(ids.len(), samples.len() + 1);
    let parent = ids[0];
    for ((id, _, value), entity) in samples.iter().zip(&ids[1..]) {
        let expected = match value {
            BuiltinValue::Parent(_) => Parent(parent).into(),
            // Ids are the host's: the reloaded host registered the same files anew.
            BuiltinValue::MeshRenderer(r) => {
                let mut r = *r;
                r.mesh = second
                    .host()
                    .assets()
                    .mesh_id(std::path::Path::new("models/crate.obj"))
                    .unwrap();
                r.material.texture = second
                    .host()
                    .assets()
                    .texture_id(std::path::Path::new("textures/crate.png"))
                    .unwrap();
                r.into()
            }
            other => other.clone(),
        };
        assert_eq!(
            builtin_of(&mut second, *entity, *id),
            Some(expected),
            "{id}"
        );
    }
}

/// Reads a dumped component back through its file form.
struct DumpRefs<'a> {
    host: &'a HeadlessHost,
}

impl FileRefs for DumpRefs<'_> {
    fn mesh(&mut self, path: &str) -> MeshId {
        self.host
            .host()
            .assets()
            .mesh_id(std::path::Path::new(path))
            .unwrap_or(MeshId(0))
    }
    fn texture(&mut self, path: &str) -> TextureId {
        self.host
            .host()
            .assets()
            .texture_id(std::path::Path::new(path))
            .unwrap_or(TextureId::NONE)
    }
    fn animation(&mut self, path: &str) -> onyx_plugin_api::AnimationId {
        self.host
            .host()
            .assets()
            .animation_id(std::path::Path::new(path))
            .unwrap_or(onyx_plugin_api::AnimationId::NONE)
    }
    fn entity(&self, file_id: u64) -> Option<Entity> {
        Some(Entity::from_bits(file_id))
    }
}

#[test]
fn every_builtin_round_trips_through_the_state_dump() {
    let mut host = HeadlessHost::new();
    let (samples, _) = spawn_samples(&mut host);
    let dump = host.dump_state();
    let by_id: HashMap<u64, &serde_json::Value> = dump["entities"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| (e["id"].as_u64().unwrap(), &e["components"]))
        .collect();
    struct Read<'a> {
        json: serde_json::Value,
        refs: DumpRefs<'a>,
    }
    impl BuiltinFn for Read<'_> {
        type Output = BuiltinValue;
        fn call<T: Builtin>(&mut self) -> BuiltinValue {
            let file: T::File = serde_json::from_value(self.json.take())
                .unwrap_or_else(|e| panic!("{} in the dump does not read back: {e}", T::NAME));
            T::from_file(file, &mut self.refs).unwrap().into_value()
        }
    }
    for (id, entity, value) in &samples {
        let json = by_id[&entity.to_bits()][id.name()].clone();
        assert!(!json.is_null(), "{id} is not in the dump");
        let read = id.dispatch(&mut Read {
            json,
            refs: DumpRefs { host: &host },
        });
        assert_eq!(&read, value, "{id}");
    }
}

#[test]
fn every_builtin_round_trips_through_a_play_mode_snapshot() {
    let mut host = HeadlessHost::new();
    let (samples, parent) = spawn_samples(&mut host);
    as_plugin(&mut host, |ctx| ctx.stop()); // a host starts playing; Play snapshots from Edit
    host.step(1);
    as_plugin(&mut host, |ctx| {
        ctx.play();
        let other = ctx.spawn(Name::new("other")).unwrap();
        for (id, entity, _) in &samples {
            let changed = match id {
                BuiltinId::Parent => Parent(other).into(),
                BuiltinId::Name => Name::new("changed").into(),
                BuiltinId::Joint => Joint::spherical(JointTarget::Body(other)).into(),
                _ => id.tool_default().unwrap(),
            };
            ctx.set_builtin(*entity, changed).unwrap();
        }
        ctx.despawn(parent).unwrap();
        ctx.stop();
    });
    host.step(1);
    for (id, entity, value) in &samples {
        assert_eq!(
            builtin_of(&mut host, *entity, *id).as_ref(),
            Some(value),
            "{id}"
        );
    }
}
