//! The editor's viewport as a newcomer meets it: the camera keys after File ▸ New and Open,
//! clicks that pick the shape under the pointer, the gizmo moving a whole selection, the
//! selection outline and the frame shown while playing.

use onyx_plugin_api::glam::camera::rh::proj::directx::perspective;
use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{Camera, Entity, Projection};

use super::*;

/// The tour scene (a floor, lights, boxes, a ball, a pillar) loaded into an editor host.
fn tour_host(dir: &Path) -> HeadlessHost {
    let mut host = editor_host(dir);
    host.load_scene(&repo_file("assets/scenes/editor_tour.ron"))
        .expect("the tour scene loads");
    host.step(2);
    host
}

fn entity(host: &HeadlessHost, name: &str) -> Entity {
    host.find::<Name>(name)
        .unwrap_or_else(|| panic!("no `{name}`: {:?}", names(host)))
        .0
}

/// Where the world point `point` shows in the viewport, seen through the editor camera.
fn on_screen(host: &HeadlessHost, point: Vec3) -> Pos2 {
    let rect = host
        .host()
        .gui()
        .frame()
        .viewport
        .expect("the viewport is shown");
    let (camera, pose) = host
        .find::<Transform>("Editor Camera")
        .expect("the editor's camera entity");
    let lens: Camera = host.get(camera).expect("it is a camera");
    let Projection::Perspective { fov_y } = lens.projection else {
        panic!("the editor camera is a perspective one: {lens:?}");
    };
    let aspect = rect.width() / rect.height();
    let projection = perspective(fov_y, aspect, lens.near, lens.far);
    let clip = projection * pose.matrix().inverse() * point.extend(1.0);
    let ndc = clip.truncate() / clip.w;
    pos2(
        rect.min.x + (ndc.x + 1.0) * 0.5 * rect.width(),
        rect.min.y + (1.0 - ndc.y) * 0.5 * rect.height(),
    )
}

/// The world position of entity `name`.
fn world_position(host: &HeadlessHost, name: &str) -> Vec3 {
    host.host()
        .world_pose(entity(host, name))
        .expect("a world pose")
        .translation()
}

/// Whether the inspector shows `name`: its hierarchy row and the inspector's name field
/// both carry it.
fn inspected(host: &HeadlessHost, name: &str) -> bool {
    host.find_widgets(name).len() >= 2
}

/// A point over the viewport, away from any gizmo handle: its lower left.
fn over_viewport(host: &HeadlessHost) -> Pos2 {
    let rect = host.host().gui().frame().viewport.expect("viewport shown");
    rect.left_bottom() + vec2(20.0, -20.0)
}

/// After File ▸ New then Open, F and the fly camera wrote the camera's pose into the Sun:
/// the editor's camera handle from the empty scene named the opened scene's first entity.
#[test]
fn after_new_then_open_the_camera_keys_move_the_view_and_not_the_sun() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    menu(&mut host, "File", "New");
    host.step(2);
    let tour = repo_file("assets/scenes/editor_tour.ron");
    choose_file(&mut host, "File", "Open…", &tour, "Open");
    host.step(2);
    let (sun, sun_before) = host.find::<Transform>("Sun").expect("the tour's sun");

    click(&mut host, "Box 1");
    host.pointer_move(over_viewport(&host));
    host.step(2);
    let view_before = editor_camera(&host);
    host.press_key(Key::F);
    host.step(3);
    assert_eq!(
        host.get::<Transform>(sun),
        Some(sun_before),
        "F moved the Sun"
    );
    let framed = editor_camera(&host);
    assert_ne!(framed, view_before, "F did not move the view");
    let to_box = world_position(&host, "Box 1") - framed.translation;
    let view = framed.rotation * Vec3::NEG_Z;
    assert!(to_box.normalize().dot(view) > 0.99, "F frames Box 1");

    host.hold_button(MouseButton::Right, true);
    host.hold_key(Key::W, true);
    host.step(10);
    host.hold_key(Key::W, false);
    host.hold_button(MouseButton::Right, false);
    host.step(2);
    assert_eq!(
        host.get::<Transform>(sun),
        Some(sun_before),
        "flying moved the Sun"
    );
    assert_ne!(editor_camera(&host), framed, "flying did not move the view");
    let cameras = host.world().query::<&Camera>().iter().count();
    assert_eq!(cameras, 1, "one editor camera, names: {:?}", names(&host));
}

/// Clicks picked by bounding spheres, nearest centre first: the 12 m floor's 9 m sphere took
/// clicks meant for Box 0 and the Pillar, and clicks on the empty sky.
#[test]
fn a_click_picks_the_nearest_shape_under_the_pointer_and_the_sky_picks_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = tour_host(dir.path());
    for name in ["Box 0", "Pillar", "Ball", "Floor"] {
        // The floor is clicked well in front of everything standing on it.
        let aim = if name == "Floor" {
            Vec3::new(0.0, 0.0, 4.0)
        } else {
            world_position(&host, name)
        };
        host.click_at(on_screen(&host, aim));
        host.step(1);
        assert!(
            inspected(&host, name),
            "a click on {name} selects it; the world has {:?}",
            names(&host)
        );
    }
    // The top edge of the view looks above the horizon.
    let rect = host.host().gui().frame().viewport.expect("viewport shown");
    host.click_at(pos2(rect.center().x, rect.top() + 4.0));
    host.step(1);
    assert!(
        host.find_widget("Nothing selected").is_some(),
        "a click on the sky selects nothing"
    );
}

/// A child is picked where it is drawn: at its world pose, under a moved and turned parent
/// (turned 45° about Z, the arm holds its hand up and to the left, at about (-4.1, 3.1, 0)).
#[test]
fn a_click_picks_a_child_at_its_world_pose() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("rig.ron");
    std::fs::write(
        &scene,
        r#"(
    version: 2,
    entities: [
        (id: Some(1), name: Some("Arm"), transform: Some((translation: (-2.0, 1.0, 0.0),
            rotation: (0.0, 0.0, 0.38268343, 0.9238795))), mesh_renderer: Some((mesh: "cube"))),
        (name: Some("Hand"), parent: Some(1), transform: Some((translation: (0.0, 3.0, 0.0),
            scale: (0.5, 0.5, 0.5))), mesh_renderer: Some((mesh: "sphere"))),
    ],
)"#,
    )
    .unwrap();
    let mut host = editor_host(dir.path());
    host.load_scene(&scene).unwrap();
    host.step(2);
    host.click_at(on_screen(&host, world_position(&host, "Hand")));
    host.step(1);
    assert!(inspected(&host, "Hand"), "the child is picked");
    // Where the hand would be without its parent there is nothing.
    host.click_at(on_screen(&host, Vec3::new(0.0, 3.0, 0.0)));
    host.step(1);
    assert!(host.find_widget("Nothing selected").is_some());
}

/// With two entities selected the gizmo moved only the last one.
#[test]
fn the_gizmo_moves_every_selected_entity_together_and_undo_puts_them_all_back() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = tour_host(dir.path());
    let moved_names = ["Box 0", "Pillar"];
    let before: Vec<Transform> = moved_names
        .iter()
        .map(|n| host.find::<Transform>(n).expect("in the tour").1)
        .collect();
    click(&mut host, "Box 0");
    host.hold_key(Key::ControlLeft, true);
    click(&mut host, "Pillar");
    host.hold_key(Key::ControlLeft, false);
    host.step(1);
    assert!(host.find_widget_containing("2 selected").is_some());

    let x_handle = host.find_widget("Gizmo X").expect("the gizmo").center();
    host.drag(x_handle, x_handle + vec2(60.0, 0.0), 6);
    host.step(1);
    let after: Vec<Transform> = moved_names
        .iter()
        .map(|n| host.find::<Transform>(n).unwrap().1)
        .collect();
    let shift = after[1].translation - before[1].translation;
    assert!(shift.x > 0.2, "the primary moved along X: {shift:?}");
    assert!(shift.y.abs() < 1e-5 && shift.z.abs() < 1e-5, "{shift:?}");
    let other = after[0].translation - before[0].translation;
    assert!(
        (other - shift).length() < 1e-4,
        "Box 0 moved with the Pillar: {other:?} vs {shift:?}"
    );

    menu(&mut host, "Edit", "Undo");
    for (name, was) in moved_names.iter().zip(&before) {
        assert_eq!(
            host.find::<Transform>(name).unwrap().1,
            *was,
            "one undo puts {name} back"
        );
    }
}

/// The accessible name of the selection outline of `name`.
fn outline_label(name: &str) -> String {
    format!("Selection outline: {name}")
}

#[test]
fn the_selection_is_outlined_in_the_viewport() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = tour_host(dir.path());
    assert!(host.find_widget(&outline_label("Box 0")).is_none());
    click(&mut host, "Box 0");
    host.step(1);
    let outline = host
        .find_widget(&outline_label("Box 0"))
        .expect("Box 0 is outlined");
    let centre = on_screen(&host, world_position(&host, "Box 0"));
    assert!(outline.contains(centre), "{outline:?} around {centre:?}");
    // The outline is drawn: its colour is on the screen inside that rectangle.
    let image = host.screenshot(1280, 720).expect("lavapipe renders");
    let outlined = (outline.left() as u32..outline.right() as u32)
        .flat_map(|x| (outline.top() as u32..outline.bottom() as u32).map(move |y| (x, y)))
        .filter(|&(x, y)| {
            let [r, g, b, _] = image.get_pixel(x, y).0;
            r > 230 && (150..=200).contains(&g) && b < 60
        })
        .count();
    assert!(outlined > 20, "{outlined} outline pixels");
}

#[test]
fn the_viewport_is_framed_in_orange_while_playing() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = tour_host(dir.path());
    let rect = host.host().gui().frame().viewport.expect("viewport shown");
    let edge = (rect.left() as u32 + 1, rect.center().y as u32);
    let colour_at_edge = |host: &mut HeadlessHost| {
        let image = host.screenshot(1280, 720).expect("lavapipe renders");
        image.get_pixel(edge.0, edge.1).0
    };
    let playing = |[r, g, b, _]: [u8; 4]| r > 200 && (90..=170).contains(&g) && b < 60;
    let editing = colour_at_edge(&mut host);
    assert!(!playing(editing), "no frame in Edit: {editing:?}");
    click(&mut host, "Play");
    host.step(2);
    let framed = colour_at_edge(&mut host);
    assert!(playing(framed), "framed while playing: {framed:?}");
    assert!(
        host.find_widget("Playing: Stop puts the scene back")
            .is_some(),
        "the viewport says so"
    );
    click(&mut host, "Stop");
    host.step(2);
    let stopped = colour_at_edge(&mut host);
    assert!(!playing(stopped), "no frame after Stop: {stopped:?}");
}
