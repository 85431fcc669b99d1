//! The editor and the scene graph: the hierarchy as a tree (collapse, filter, drag and drop
//! to re-parent and un-parent, undoably), subtree delete and duplicate, the gizmo in world
//! space on a child, the inspector's world position.

use onyx_plugin_api::egui;
use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{Entity, Key, Name, Parent, Transform};

use super::*;

/// A cart turned 90° about Y at (4, 0, 0) carrying a lamp, the lamp carrying a bulb; a loose
/// box; all in a scene file loaded into an editor host.
const CART: &str = r#"(
    version: 2,
    entities: [
        (id: Some(1), name: Some("Cart"), transform: Some((translation: (4.0, 0.0, 0.0), rotation: (0.0, 0.70710677, 0.0, 0.70710677))),
            mesh_renderer: Some((mesh: "cube"))),
        (id: Some(2), name: Some("Lamp"), parent: Some(1), transform: Some((translation: (1.0, 1.0, 0.0))),
            mesh_renderer: Some((mesh: "sphere"))),
        (name: Some("Bulb"), parent: Some(2), transform: Some((translation: (0.0, 0.5, 0.0))),
            mesh_renderer: Some((mesh: "sphere"))),
        (name: Some("Crate"), transform: Some((translation: (-3.0, 0.5, 2.0))), mesh_renderer: Some((mesh: "cube"))),
    ],
)"#;

fn cart_host(dir: &Path) -> HeadlessHost {
    let mut host = editor_host(dir);
    let scene = dir.join("cart.ron");
    std::fs::write(&scene, CART).unwrap();
    host.load_scene(&scene).unwrap();
    host.step(2);
    host
}

fn entity(host: &HeadlessHost, name: &str) -> Entity {
    host.find::<Name>(name)
        .unwrap_or_else(|| panic!("no `{name}`: {:?}", names(host)))
        .0
}

fn world_of(host: &HeadlessHost, name: &str) -> Vec3 {
    host.host()
        .world_pose(entity(host, name))
        .unwrap()
        .translation()
}

fn parent_of(host: &HeadlessHost, name: &str) -> Option<Entity> {
    host.get::<Parent>(entity(host, name)).map(|p| p.0)
}

/// The hierarchy row showing `name` (the leftmost widget so labelled: the inspector may show
/// the name too, further right).
fn row(host: &HeadlessHost, name: &str) -> egui::Rect {
    host.find_widgets(name)
        .into_iter()
        .min_by(|a, b| a.left().total_cmp(&b.left()))
        .unwrap_or_else(|| panic!("no row `{name}`"))
}

fn drag_row_onto(host: &mut HeadlessHost, name: &str, to: egui::Pos2) {
    let from = row(host, name).center();
    host.drag(from, to, 8);
    host.step(2);
}

fn near(a: Vec3, b: Vec3) -> bool {
    (a - b).length() < 1e-4
}

#[test]
fn the_hierarchy_indents_children_under_their_parents_and_collapses_them() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = cart_host(dir.path());
    let (cart, lamp, bulb) = (row(&host, "Cart"), row(&host, "Lamp"), row(&host, "Bulb"));
    assert!(
        cart.left() < lamp.left() && lamp.left() < bulb.left(),
        "each level is indented: {cart:?} {lamp:?} {bulb:?}"
    );
    assert!(
        cart.top() < lamp.top() && lamp.top() < bulb.top(),
        "children follow their parent"
    );
    click(&mut host, "Collapse Cart");
    assert!(host.find_widget("Lamp").is_none() && host.find_widget("Bulb").is_none());
    assert!(host.find_widget("Crate").is_some());
    click(&mut host, "Expand Cart");
    assert!(
        host.find_widget("Bulb").is_some(),
        "the subtree is shown again"
    );
}

#[test]
fn the_filter_keeps_the_ancestors_of_a_match_visible() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = cart_host(dir.path());
    click(&mut host, "Collapse Cart");
    type_into_field_after(&mut host, "Filter", "bul");
    for shown in ["Cart", "Lamp", "Bulb"] {
        assert!(
            host.find_widget(shown).is_some(),
            "{shown} hidden under the filter"
        );
    }
    assert!(
        host.find_widget("Crate").is_none(),
        "a row that does not match stayed"
    );
}

#[test]
fn dropping_a_row_onto_another_reparents_it_keeping_its_world_pose_and_undo_restores_it() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = cart_host(dir.path());
    let crate_world = world_of(&host, "Crate");
    let target = row(&host, "Lamp").center();
    drag_row_onto(&mut host, "Crate", target);
    assert_eq!(parent_of(&host, "Crate"), Some(entity(&host, "Lamp")));
    assert!(
        near(world_of(&host, "Crate"), crate_world),
        "it stayed where it was"
    );
    let local: Transform = host.get(entity(&host, "Crate")).unwrap();
    assert!(
        !near(local.translation, crate_world),
        "its local transform is now the lamp's frame"
    );
    assert!(
        row(&host, "Crate").left() > row(&host, "Lamp").left(),
        "shown under the lamp"
    );

    // The lamp moves: the crate goes with it.
    let lamp = hecs::Entity::from_bits(entity(&host, "Lamp").to_bits()).unwrap();
    host.host_mut()
        .world_mut()
        .get::<&mut Transform>(lamp)
        .unwrap()
        .translation
        .y += 2.0;
    host.step(1);
    assert!(near(world_of(&host, "Crate"), crate_world + Vec3::Y * 2.0));
    host.host_mut()
        .world_mut()
        .get::<&mut Transform>(lamp)
        .unwrap()
        .translation
        .y -= 2.0;
    host.step(1);

    menu(&mut host, "Edit", "Undo");
    assert_eq!(parent_of(&host, "Crate"), None);
    assert_eq!(
        host.get::<Transform>(entity(&host, "Crate"))
            .unwrap()
            .translation,
        Vec3::new(-3.0, 0.5, 2.0),
        "undo puts the old local transform back"
    );
    menu(&mut host, "Edit", "Redo");
    assert_eq!(parent_of(&host, "Crate"), Some(entity(&host, "Lamp")));
    assert!(near(world_of(&host, "Crate"), crate_world));
}

#[test]
fn dropping_onto_the_root_area_unparents_and_a_drop_that_would_make_a_cycle_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = cart_host(dir.path());
    let bulb_world = world_of(&host, "Bulb");
    let root_area = host
        .find_widget("Drop here to make it a root")
        .expect("the root area is shown");
    drag_row_onto(&mut host, "Bulb", root_area.center());
    assert_eq!(parent_of(&host, "Bulb"), None, "the bulb is a root");
    assert!(near(world_of(&host, "Bulb"), bulb_world));

    // The cart onto its own lamp: refused, nothing changes, the status line says why.
    let lamp = row(&host, "Lamp").center();
    drag_row_onto(&mut host, "Cart", lamp);
    assert_eq!(parent_of(&host, "Cart"), None);
    assert_eq!(parent_of(&host, "Lamp"), Some(entity(&host, "Cart")));
    assert!(
        host.find_widget_containing("cycle").is_some(),
        "the refusal is shown"
    );
}

#[test]
fn deleting_a_parent_deletes_its_subtree_and_undo_brings_the_whole_tree_back() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = cart_host(dir.path());
    let bulb_world = world_of(&host, "Bulb");
    click(&mut host, "Cart");
    host.press_key(Key::Delete);
    host.step(2);
    for gone in ["Cart", "Lamp", "Bulb"] {
        assert_entity(&host, gone, false);
    }
    assert_entity(&host, "Crate", true);
    menu(&mut host, "Edit", "Undo");
    assert_eq!(parent_of(&host, "Lamp"), Some(entity(&host, "Cart")));
    assert_eq!(parent_of(&host, "Bulb"), Some(entity(&host, "Lamp")));
    assert!(
        near(world_of(&host, "Bulb"), bulb_world),
        "the tree is back where it was"
    );
    menu(&mut host, "Edit", "Redo");
    assert_entity(&host, "Bulb", false);
}

#[test]
fn duplicating_a_parent_copies_its_subtree_under_the_copy() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = cart_host(dir.path());
    click(&mut host, "Cart");
    menu(&mut host, "Edit", "Duplicate");
    let copy = entity(&host, "Cart copy");
    let lamps: Vec<Entity> = host
        .world()
        .query::<(hecs::Entity, &Name)>()
        .iter()
        .filter(|(_, n)| n.as_str() == "Lamp")
        .map(|(e, _)| Entity::from_bits(e.to_bits().get()))
        .collect();
    assert_eq!(lamps.len(), 2, "the lamp was copied");
    let copied_lamp = lamps
        .iter()
        .find(|l| host.get::<Parent>(**l).map(|p| p.0) == Some(copy))
        .expect("one lamp hangs under the copy");
    let bulbs = host
        .world()
        .query::<(hecs::Entity, &Name, &Parent)>()
        .iter()
        .filter(|(_, n, p)| n.as_str() == "Bulb" && p.0 == *copied_lamp)
        .count();
    assert_eq!(bulbs, 1, "and the bulb under the copied lamp");
    assert!(near(
        host.host().world_pose(copy).unwrap().translation(),
        world_of(&host, "Cart")
    ));
    menu(&mut host, "Edit", "Undo");
    assert!(host.find::<Name>("Cart copy").is_none());
    assert_eq!(
        host.world()
            .query::<&Name>()
            .iter()
            .filter(|n| n.as_str() == "Lamp")
            .count(),
        1
    );
}

#[test]
fn the_gizmo_moves_a_child_in_world_space_and_writes_its_local_transform() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = cart_host(dir.path());
    click(&mut host, "Lamp");
    let lamp = entity(&host, "Lamp");
    let before = world_of(&host, "Lamp");
    let local_before: Transform = host.get(lamp).unwrap();
    // The gizmo sits on the lamp's world position; in World space its X handle is world X,
    // which the editor camera (looking along -Z) shows pointing right.
    drag_handle(&mut host, "Gizmo X", egui::vec2(40.0, 0.0));
    let after = world_of(&host, "Lamp");
    let moved = after - before;
    assert!(moved.x > 0.05, "moved along world +X: {moved}");
    assert!(
        moved.y.abs() < 1e-3 && moved.z.abs() < 1e-3,
        "and only along it: {moved}"
    );
    let local: Transform = host.get(lamp).unwrap();
    // Under the cart (turned 90° about Y) world +X is local +Z.
    let local_moved = local.translation - local_before.translation;
    assert!(
        local_moved.z < -0.05 || local_moved.z > 0.05,
        "the local transform changed along its Z: {local_moved}"
    );
    assert!(local_moved.x.abs() < 1e-3, "{local_moved}");
    assert_eq!(parent_of(&host, "Lamp"), Some(entity(&host, "Cart")));
}

#[test]
fn the_inspector_shows_the_local_transform_and_the_world_position_read_only() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = cart_host(dir.path());
    click(&mut host, "Bulb");
    assert!(host.find_widget("World position").is_some());
    let world = world_of(&host, "Bulb");
    let shown = format!("X {:.3}  Y {:.3}  Z {:.3}", world.x, world.y, world.z);
    assert!(
        host.find_widget_containing(&shown).is_some(),
        "the world position {shown} is shown"
    );
    assert!(host.find_widget("Parent").is_some(), "the parent is shown");
}
