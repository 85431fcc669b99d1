//! The scene graph: parents and children through the host, physics and the renderer, with a
//! real plugin loaded from disk (`tests/fixtures/rig`) moving the scenes, and in-process
//! plugins probing the `Ctx` calls. Expected poses are computed here from the motions the
//! fixture documents, with glam matrices — not read back from the host.

use onyx_plugin_api::glam::{Affine3A, Quat, Vec3};
use onyx_plugin_api::{
    Ctx, CtxError, Entity, GlobalTransform, KeepPose, Name, Parent, ParentProblem, Plugin,
    RigidBody, Transform,
};
use onyx_runtime::{HeadlessHost, HostConfig, PluginStatus};
use onyx_tests::plugin_library;

/// Largest error allowed between a world pose and the one computed here, metres (poses are
/// f32 matrices composed over a few levels).
const POSE_TOLERANCE: f32 = 1e-5;

fn rig_host(scene: &str, settings: &[(&str, &str)]) -> HeadlessHost {
    let mut config = HostConfig::default().setting("fixture_rig", "scene", scene);
    for (key, value) in settings {
        config = config.setting("fixture_rig", *key, *value);
    }
    let mut host = HeadlessHost::with_config(config);
    host.load_plugin_file(&plugin_library("fixture-rig"))
        .expect("the rig fixture loads");
    host
}

fn entity(host: &HeadlessHost, name: &str) -> Entity {
    host.find::<Name>(name)
        .unwrap_or_else(|| panic!("no entity named {name}"))
        .0
}

fn world(host: &HeadlessHost, name: &str) -> Affine3A {
    host.host().world_pose(entity(host, name)).unwrap().affine()
}

/// Time at the end of the last fixed step after `frames` one-step frames (the fixture's `t`).
fn t_after(frames: u32) -> f32 {
    frames as f32 / 60.0
}

fn assert_pose(what: &str, actual: Affine3A, expected: Affine3A) {
    let worst = (actual.matrix3 - expected.matrix3)
        .abs()
        .to_cols_array()
        .into_iter()
        .chain((actual.translation - expected.translation).abs().to_array())
        .fold(0.0f32, f32::max);
    assert!(
        worst <= POSE_TOLERANCE,
        "{what}: world pose off by {worst}\n  measured {actual:?}\n  expected {expected:?}"
    );
}

fn trs(t: Vec3, r: Quat, s: Vec3) -> Affine3A {
    Affine3A::from_scale_rotation_translation(s, r, t)
}

/// The dump's `GlobalTransform` of entity `name`, as a matrix.
fn dumped_world(host: &HeadlessHost, name: &str) -> Affine3A {
    let dump = host.dump_state();
    let entry = dump["entities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["name"] == name)
        .unwrap_or_else(|| panic!("{name} is not in the dump"));
    let pose: Transform = serde_json::from_value(entry["components"]["GlobalTransform"].clone())
        .unwrap_or_else(|e| panic!("{name} has no GlobalTransform in the dump: {e}"));
    pose.affine()
}

/// Where the renderer draws `name` this frame: between its last two fixed-step world poses,
/// by the clock's `alpha` (at alpha 0, the pose before the last step).
fn drawn(host: &HeadlessHost, name: &str) -> Affine3A {
    let e = entity(host, name);
    host.host()
        .drawn_poses()
        .into_iter()
        .find(|(d, _)| *d == e)
        .unwrap_or_else(|| panic!("{name} is not drawn"))
        .1
        .affine()
}

#[test]
fn a_lamp_on_a_cart_moves_with_the_cart_in_world_poses_the_dump_and_the_drawn_frame() {
    let mut host = rig_host("lamp_cart", &[]);
    host.step(30);
    let cart_x = 2.0 * t_after(30);
    let lamp = trs(
        Vec3::new(cart_x, 1.5, 0.0),
        Quat::IDENTITY,
        Vec3::splat(0.2),
    );
    assert_pose("lamp", world(&host, "lamp"), lamp);
    assert_pose("lamp in the dump", dumped_world(&host, "lamp"), lamp);
    let previous = trs(
        Vec3::new(2.0 * t_after(29), 1.5, 0.0),
        Quat::IDENTITY,
        Vec3::splat(0.2),
    );
    assert_pose("lamp as drawn at alpha 0", drawn(&host, "lamp"), previous);
    let (_, local) = host.find::<Transform>("lamp").unwrap();
    assert_eq!(
        local.translation,
        Vec3::new(0.0, 1.5, 0.0),
        "the local transform stays what the plugin wrote"
    );
    // A frame 1.5 fixed steps long: one step runs, half a step stays in the accumulator,
    // and the lamp is drawn halfway between its last two world poses (no jitter: its own
    // local transform never changed, only its parent moved).
    host.set_frame_time(1.5 / 60.0);
    host.step(1);
    assert!((host.host().time().alpha - 0.5).abs() < 1e-4);
    let halfway = 2.0 * (t_after(30) + t_after(31)) / 2.0;
    let expected = trs(
        Vec3::new(halfway, 1.5, 0.0),
        Quat::IDENTITY,
        Vec3::splat(0.2),
    );
    assert_pose("lamp drawn between steps", drawn(&host, "lamp"), expected);
}

#[test]
fn a_three_level_rig_turning_at_two_joints_puts_the_hand_where_the_matrices_say() {
    let arm_at = |t: f32| {
        trs(Vec3::ZERO, Quat::from_rotation_y(t), Vec3::ONE)
            * trs(
                Vec3::new(2.0, 0.0, 0.0),
                Quat::from_rotation_z(2.0 * t),
                Vec3::ONE,
            )
    };
    let hand_at = |t: f32| {
        arm_at(t)
            * trs(
                Vec3::new(1.0, 0.0, 0.0),
                Quat::from_rotation_x(0.3),
                Vec3::splat(0.5),
            )
    };
    let mut host = rig_host("rig", &[]);
    for frames in [1, 45, 100] {
        host.step(frames - host.host().time().ticks as u32);
        let t = t_after(frames);
        assert_pose(&format!("arm at t = {t}"), world(&host, "arm"), arm_at(t));
        assert_pose(
            &format!("hand at t = {t}"),
            world(&host, "hand"),
            hand_at(t),
        );
        assert_pose(
            &format!("hand dumped at t = {t}"),
            dumped_world(&host, "hand"),
            hand_at(t),
        );
        assert_pose(
            &format!("hand drawn at t = {t} (alpha 0: the step before)"),
            drawn(&host, "hand"),
            hand_at(t_after(frames - 1)),
        );
    }
}

#[test]
fn a_dynamic_box_rides_a_kinematic_platform_whose_parent_carries_it() {
    let mut host = rig_host("platform", &[]);
    host.step(180);
    let carrier_x = t_after(180);
    let platform = world(&host, "platform");
    assert_pose(
        "platform (kinematic, under the carrier)",
        platform,
        trs(Vec3::new(carrier_x, 1.0, 0.0), Quat::IDENTITY, Vec3::ONE),
    );
    let (_, local) = host.find::<Transform>("platform").unwrap();
    assert_eq!(
        local,
        Transform::from_xyz(0.0, 1.0, 0.0),
        "physics never rewrites a kinematic child that went where its parent put it"
    );
    let (_, b) = host.find::<Transform>("box").unwrap();
    let (_, body) = host.find::<RigidBody>("box").unwrap();
    let top = 1.0 + 0.1 + 0.25;
    assert!(
        (b.translation.y - top).abs() < 0.01,
        "the box rests on the platform: y = {} (expected {top})",
        b.translation.y
    );
    assert!(
        (body.linear_velocity.x - 1.0).abs() < 0.02,
        "the box moves with the platform at 1 m/s: {}",
        body.linear_velocity.x
    );
    assert!(
        (b.translation.x - carrier_x).abs() < 1.0 && b.translation.x > 2.0,
        "the box was carried along and is still on the platform: x = {} (platform at {carrier_x})",
        b.translation.x
    );
}

#[test]
fn re_parenting_a_subtree_mid_run_keeps_its_world_pose_then_follows_the_new_parent() {
    let b_at = |frames: u32| {
        trs(
            Vec3::new(10.0, 0.0, t_after(frames)),
            Quat::from_rotation_y(std::f32::consts::FRAC_PI_2),
            Vec3::ONE,
        )
    };
    let mut host = rig_host("reparent", &[("reparent_at", "30")]);
    host.step(30);
    let before = trs(Vec3::new(1.0, 1.0, 0.0), Quat::IDENTITY, Vec3::ONE);
    assert_pose("box before", world(&host, "box"), before);
    host.step(1); // tick 30: `middle` moves under `b`, world pose kept
    assert_eq!(
        host.get::<Parent>(entity(&host, "middle")),
        Some(Parent(entity(&host, "b")))
    );
    assert_pose("box right after the re-parent", world(&host, "box"), before);
    host.step(30);
    // From now on it follows b, which moved 0.5 m along +Z.
    let moved = b_at(61) * b_at(31).inverse() * before;
    assert_pose(
        "box following its new grandparent",
        world(&host, "box"),
        moved,
    );
    let previous = b_at(60) * b_at(31).inverse() * before;
    assert_pose("box as drawn", drawn(&host, "box"), previous);

    let mut host = rig_host("reparent", &[("reparent_at", "30"), ("keep", "local")]);
    host.step(31);
    // Local pose kept: middle at (1, 0, 0) in b's frame, the box 1 m above it.
    let expected = b_at(31) * trs(Vec3::new(1.0, 1.0, 0.0), Quat::IDENTITY, Vec3::ONE);
    assert_pose(
        "box re-parented keeping its local pose",
        world(&host, "box"),
        expected,
    );
}

/// Runs `probe` once, as a plugin's `on_init`, in a fresh headless host.
fn probe<F: FnMut(&mut Ctx) + Send + 'static>(probe: F) -> HeadlessHost {
    struct Probe<F>(F);
    impl<F: FnMut(&mut Ctx) + Send + 'static> Plugin for Probe<F> {
        fn on_init(&mut self, ctx: &mut Ctx) {
            (self.0)(ctx)
        }
    }
    let mut host = HeadlessHost::new();
    host.add_plugin("probe", Probe(probe)).unwrap();
    host.step(1);
    // An assertion failing inside the plugin faults it (the host catches the panic).
    if let Some(PluginStatus::Faulted { message, .. }) = host.plugin_status("probe") {
        panic!("{message}");
    }
    host
}

#[test]
fn a_parent_that_is_the_entity_a_descendant_or_gone_is_refused_and_nothing_changes() {
    probe(|ctx| {
        let a = ctx.spawn((Name::new("a"), Transform::IDENTITY)).unwrap();
        let b = ctx.spawn((Transform::IDENTITY, Parent(a))).unwrap();
        let c = ctx.spawn((Transform::IDENTITY, Parent(b))).unwrap();
        let gone = ctx.spawn(Transform::IDENTITY).unwrap();
        ctx.despawn(gone).unwrap();
        let problem = |r: Result<(), CtxError>| match r {
            Err(CtxError::InvalidParent { problem, .. }) => Some(problem),
            other => panic!("expected InvalidParent, got {other:?}"),
        };
        assert_eq!(
            problem(ctx.set_parent(a, a, KeepPose::World)),
            Some(ParentProblem::Itself)
        );
        assert_eq!(
            problem(ctx.set_parent(a, c, KeepPose::World)),
            Some(ParentProblem::Descendant)
        );
        assert_eq!(
            problem(ctx.set(a, Parent(c))),
            Some(ParentProblem::Descendant)
        );
        assert_eq!(
            problem(ctx.set_parent(b, gone, KeepPose::Local)),
            Some(ParentProblem::Missing)
        );
        assert_eq!(
            problem(ctx.set_parent(b, Entity::from_bits(0xdead_0000_beef), KeepPose::Local)),
            Some(ParentProblem::Missing)
        );
        let message = ctx
            .set_parent(a, c, KeepPose::World)
            .unwrap_err()
            .to_string();
        assert!(message.contains("cycle"), "{message}");
        assert_eq!(
            ctx.parent(a).unwrap(),
            None,
            "a refused parent changed nothing"
        );
        assert_eq!(ctx.parent(b).unwrap(), Some(a));
        assert_eq!(ctx.children(a).unwrap(), vec![b]);
        // Spawning under a parent that is gone is refused too, and spawns nothing.
        let before = ctx.entities().len();
        assert!(ctx.spawn((Transform::IDENTITY, Parent(gone))).is_err());
        assert_eq!(ctx.entities().len(), before);
    });
}

#[test]
fn set_parent_keeps_the_world_pose_or_the_local_one_and_world_pose_is_exact_at_once() {
    probe(|ctx| {
        let parent_pose = Transform::from_xyz(5.0, 0.0, 0.0)
            .with_rotation(Quat::from_rotation_y(1.0))
            .with_scale(Vec3::splat(2.0));
        let parent = ctx.spawn(parent_pose).unwrap();
        let child_pose =
            Transform::from_xyz(1.0, 2.0, 3.0).with_rotation(Quat::from_rotation_x(0.5));
        let child = ctx.spawn(child_pose).unwrap();
        ctx.set_parent(child, parent, KeepPose::World).unwrap();
        let world = ctx.world_pose(child).unwrap();
        assert_pose("kept world pose", world.affine(), child_pose.affine());
        let local: Transform = ctx.get(child).unwrap();
        assert_pose(
            "the local transform that keeps it",
            parent_pose.affine() * local.affine(),
            child_pose.affine(),
        );
        ctx.clear_parent(child, KeepPose::Local).unwrap();
        assert_pose(
            "a root keeping its local transform is at it",
            ctx.world_pose(child).unwrap().affine(),
            local.affine(),
        );
        ctx.set_parent(child, parent, KeepPose::Local).unwrap();
        assert_pose(
            "keeping the local transform moves it with the parent",
            ctx.world_pose(child).unwrap().affine(),
            parent_pose.affine() * local.affine(),
        );
        // Written and read back in the same call: no frame in between.
        ctx.set(parent, Transform::from_xyz(-3.0, 0.0, 0.0))
            .unwrap();
        assert_pose(
            "world pose right after the parent moved",
            ctx.world_pose(child).unwrap().affine(),
            Transform::from_xyz(-3.0, 0.0, 0.0).affine() * local.affine(),
        );
        // set_world_pose writes the local transform that puts it there.
        let target = Transform::from_xyz(0.0, 7.0, 0.0);
        ctx.set_world_pose(child, target).unwrap();
        assert_pose(
            "set_world_pose",
            ctx.world_pose(child).unwrap().affine(),
            target.affine(),
        );
    });
}

#[test]
fn a_non_uniform_scale_under_a_rotated_parent_shears_the_child_and_the_matrix_holds_it() {
    let host = probe(|ctx| {
        let parent = ctx
            .spawn((
                Name::new("squashed"),
                Transform::IDENTITY.with_scale(Vec3::new(3.0, 1.0, 1.0)),
            ))
            .unwrap();
        let child = ctx
            .spawn((
                Name::new("turned"),
                Transform::from_xyz(1.0, 0.0, 0.0).with_rotation(Quat::from_rotation_z(0.7)),
                Parent(parent),
            ))
            .unwrap();
        let expected = Transform::IDENTITY
            .with_scale(Vec3::new(3.0, 1.0, 1.0))
            .affine()
            * Transform::from_xyz(1.0, 0.0, 0.0)
                .with_rotation(Quat::from_rotation_z(0.7))
                .affine();
        let world = ctx.world_pose(child).unwrap();
        assert_pose("sheared child", world.affine(), expected);
        // No translation/rotation/scale triple holds it: the matrix's axes are not
        // perpendicular.
        let m = world.affine().matrix3;
        assert!(m.x_axis.dot(m.y_axis).abs() > 0.1, "{m:?}");
    });
    let expected = Vec3::new(3.0, 0.0, 0.0);
    assert!(
        Vec3::from(world(&host, "turned").translation).abs_diff_eq(expected, POSE_TOLERANCE),
        "the propagated pose matches too"
    );
}

#[test]
fn despawning_a_parent_leaves_its_children_where_they_are_and_despawn_recursive_takes_them() {
    let host = probe(|ctx| {
        let parent = ctx
            .spawn(Transform::from_xyz(10.0, 0.0, 0.0).with_rotation(Quat::from_rotation_y(0.5)))
            .unwrap();
        let child = ctx
            .spawn((
                Name::new("orphan"),
                Transform::from_xyz(0.0, 0.0, 2.0),
                Parent(parent),
            ))
            .unwrap();
        let grandchild = ctx
            .spawn((
                Name::new("grandchild"),
                Transform::from_xyz(0.0, 1.0, 0.0),
                Parent(child),
            ))
            .unwrap();
        let before = ctx.world_pose(child).unwrap();
        let grand_before = ctx.world_pose(grandchild).unwrap();
        ctx.despawn(parent).unwrap();
        assert_eq!(ctx.parent(child).unwrap(), None, "the child became a root");
        assert_pose(
            "the child stayed put",
            ctx.world_pose(child).unwrap().affine(),
            before.affine(),
        );
        assert_pose(
            "and so did its own child",
            ctx.world_pose(grandchild).unwrap().affine(),
            grand_before.affine(),
        );
        assert_eq!(ctx.children(child).unwrap(), vec![grandchild]);

        let root = ctx.spawn(Transform::IDENTITY).unwrap();
        let mut subtree = vec![root];
        for i in 0..3 {
            let e = ctx
                .spawn((Transform::IDENTITY, Parent(subtree[i])))
                .unwrap();
            subtree.push(e);
        }
        let sibling = ctx
            .spawn((Transform::IDENTITY, Parent(subtree[1])))
            .unwrap();
        ctx.despawn_recursive(subtree[1]).unwrap();
        assert!(ctx.contains(root));
        for e in subtree.iter().skip(1).chain([&sibling]) {
            assert!(!ctx.contains(*e), "{e} survived despawn_recursive");
        }
        assert!(ctx.children(root).unwrap().is_empty());
    });
    assert!(host.find::<Name>("orphan").is_some() && host.find::<Name>("grandchild").is_some());
}

#[test]
fn children_keep_their_attach_order_and_the_entity_list_names_each_parent() {
    probe(|ctx| {
        let root = ctx.spawn(Name::new("root")).unwrap();
        let kids: Vec<Entity> = (0..5)
            .map(|i| {
                ctx.spawn((Name::new(format!("kid {i}")), Parent(root)))
                    .unwrap()
            })
            .collect();
        ctx.clear_parent(kids[1], KeepPose::Local).unwrap();
        ctx.set(kids[1], Parent(root)).unwrap();
        let order = [kids[0], kids[2], kids[3], kids[4], kids[1]];
        assert_eq!(ctx.children(root).unwrap(), order);
        let list = ctx.entity_list();
        let root_row = list.entities().iter().position(|e| *e == root).unwrap();
        for kid in kids {
            let row = list.entities().iter().position(|e| *e == kid).unwrap();
            assert_eq!(list.parent(row), Some(root_row));
        }
        assert_eq!(list.parent(root_row), None);
    });
}

#[test]
fn a_world_pose_of_an_entity_without_a_transform_passes_its_parent_through() {
    let host = probe(|ctx| {
        let top = ctx.spawn(Transform::from_xyz(0.0, 3.0, 0.0)).unwrap();
        let group = ctx.spawn((Name::new("group"), Parent(top))).unwrap();
        let leaf = ctx
            .spawn((
                Name::new("leaf"),
                Transform::from_xyz(1.0, 0.0, 0.0),
                Parent(group),
            ))
            .unwrap();
        assert_eq!(
            ctx.world_pose(leaf).unwrap(),
            GlobalTransform::from(Transform::from_xyz(1.0, 3.0, 0.0))
        );
    });
    let dump = host.dump_state();
    let group = dump["entities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["name"] == "group")
        .unwrap();
    assert!(
        group["components"].get("GlobalTransform").is_none(),
        "only entities with a Transform show a world pose"
    );
    assert!(group["components"]["Parent"].is_u64());
}
