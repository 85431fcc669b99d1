//! The editor plugin (`plugins/editor`), loaded as a real cdylib into a headless host and
//! driven like a person: menus, inspector, undo/redo, scenes, play mode, reload, layout,
//! a golden image, and a windowed run under Xvfb.

use std::path::{Path, PathBuf};

use onyx_plugin_api::egui::{pos2, vec2, Pos2, Vec2};
use onyx_plugin_api::{Key, MeshRenderer, MouseButton, Name, PlayMode, RigidBody, Transform};
use onyx_runtime::{HeadlessHost, HostConfig};
use onyx_tests::{assert_golden, onyx_in_xvfb, plugin_library};
use serde_json::Value;

/// A host running the editor, its layout kept in `dir`.
fn editor_host(dir: &Path) -> HeadlessHost {
    editor_host_with(dir, HostConfig::default())
}

/// [`editor_host`] with more settings in `config`. The layout and the recovery copies
/// live in `dir` (the defaults, under `.onyx/` in the working directory, would be shared by
/// every test).
fn editor_host_with(dir: &Path, config: HostConfig) -> HeadlessHost {
    let config = config
        .setting(
            "editor",
            "layout",
            dir.join("layout.json").display().to_string(),
        )
        .setting(
            "editor",
            "recovery",
            dir.join("recovery").display().to_string(),
        );
    let mut host = HeadlessHost::with_config(config);
    host.load_plugin_file(&plugin_library("editor"))
        .expect("the editor loads");
    host.step(3);
    host
}

/// Clicks `label`, panicking with the label when it is not shown.
fn click(host: &mut HeadlessHost, label: &str) {
    assert!(host.click_widget(label), "no widget labelled `{label}`");
    host.step(1);
}

/// Opens menu `menu` and clicks its entry `entry`: the widget labelled `entry` that
/// appeared when the menu opened (a tab may carry the same label).
fn menu(host: &mut HeadlessHost, menu: &str, entry: &str) {
    let before = host.find_widgets(entry);
    click(host, menu);
    let shown = host.find_widgets(entry);
    let item = shown
        .iter()
        .find(|r| !before.contains(r))
        .or(shown.first())
        .unwrap_or_else(|| panic!("menu {menu} has no entry `{entry}`"));
    host.click_at(item.center());
    host.step(1);
}

/// Clicks into the text field right of the label `label` and types `text`, then Enter.
fn type_into_field_after(host: &mut HeadlessHost, label: &str, text: &str) {
    let rect = host
        .find_widget(label)
        .unwrap_or_else(|| panic!("no label `{label}`"));
    host.click_at(pos2(rect.right() + 60.0, rect.center().y));
    host.type_text(text);
    host.step(1);
    host.press_key(Key::Enter);
    host.step(2);
}

/// Opens `menu` ▸ `entry` (a file dialog), types `path` as the file name and clicks `verb`.
fn choose_file(host: &mut HeadlessHost, menu_name: &str, entry: &str, path: &Path, verb: &str) {
    menu(host, menu_name, entry);
    type_into_field_after(host, "File name", &path.display().to_string());
    click(host, verb);
}

fn names(host: &HeadlessHost) -> Vec<String> {
    let mut names: Vec<String> = host
        .world()
        .query::<&Name>()
        .iter()
        .map(|n| n.as_str().to_owned())
        .collect();
    names.sort();
    names
}

/// Asserts that an entity named `name` exists (or not), listing every name when wrong.
fn assert_entity(host: &HeadlessHost, name: &str, exists: bool) {
    assert_eq!(
        host.find::<Transform>(name).is_some(),
        exists,
        "entity `{name}` should {}exist; the world has {:?}",
        if exists { "" } else { "not " },
        names(host)
    );
}

fn create(host: &mut HeadlessHost, what: &str) {
    menu(host, "Create", what);
    host.step(1);
}

#[test]
fn the_editor_enters_edit_mode_and_shows_its_panels() {
    let dir = tempfile::tempdir().unwrap();
    let host = editor_host(dir.path());
    assert_eq!(host.host().play_mode(), PlayMode::Edit);
    for panel in [
        "Hierarchy",
        "Inspector",
        "Viewport",
        "Console",
        "Diagnostics",
    ] {
        assert!(host.find_widget(panel).is_some(), "panel {panel} shown");
    }
    for m in ["File", "Edit", "Create", "Plugins", "View", "Play"] {
        assert!(host.find_widget(m).is_some(), "menu {m} shown");
    }
}

#[test]
fn a_cube_created_from_the_menu_is_in_the_world() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Cube");
    let (cube, _) = host.find::<Transform>("Cube").expect("a Cube entity");
    let mesh: MeshRenderer = host.get(cube).expect("it has a mesh");
    assert_eq!(mesh.mesh, onyx_plugin_api::MeshId::CUBE);
    // The hierarchy lists it and the inspector shows its transform.
    assert!(host.find_widget("Cube").is_some());
    assert!(host.find_widget("Transform").is_some());
    assert!(host.find_widget("MeshRenderer").is_some());
}

#[test]
fn renaming_in_the_inspector_undoes_and_redoes() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Cube");
    type_into_field_after(&mut host, "Name", "2");
    assert_entity(&host, "Cube2", true);

    menu(&mut host, "Edit", "Undo");
    assert_entity(&host, "Cube", true);
    menu(&mut host, "Edit", "Redo");
    assert_entity(&host, "Cube2", true);

    // Undo the rename and the creation: the cube is gone; redo brings it back.
    menu(&mut host, "Edit", "Undo");
    menu(&mut host, "Edit", "Undo");
    assert_entity(&host, "Cube", false);
    menu(&mut host, "Edit", "Redo");
    assert_entity(&host, "Cube", true);
}

#[test]
fn deleting_and_duplicating_are_undoable() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Sphere");
    menu(&mut host, "Edit", "Duplicate");
    assert_entity(&host, "Sphere copy", true);
    menu(&mut host, "Edit", "Delete");
    assert_entity(&host, "Sphere copy", false);
    menu(&mut host, "Edit", "Undo");
    assert_entity(&host, "Sphere copy", true);
}

/// Every entity's name and components, without handles, sorted.
fn world_summary(host: &HeadlessHost) -> Vec<String> {
    let dump = host.dump_state();
    let mut rows: Vec<String> = dump["entities"]
        .as_array()
        .expect("entities")
        .iter()
        .map(|e| {
            let mut e = e.clone();
            if let Value::Object(fields) = &mut e {
                fields.remove("id");
            }
            e.to_string()
        })
        .collect();
    rows.sort();
    rows
}

#[test]
fn save_new_and_open_give_back_the_same_world() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Cube");
    create(&mut host, "Light");
    let before = world_summary(&host);
    assert!(before.len() >= 3, "{before:?}");

    let scene = dir.path().join("saved.ron");
    choose_file(&mut host, "File", "Save As…", &scene, "Save");
    assert!(scene.is_file(), "the scene was written");

    menu(&mut host, "File", "New");
    host.step(2);
    assert_entity(&host, "Cube", false);

    choose_file(&mut host, "File", "Open…", &scene, "Open");
    host.step(2);
    assert_eq!(world_summary(&host), before);
}

#[test]
fn play_lets_a_body_fall_and_stop_puts_it_back() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Cube");
    menu(&mut host, "Add Component", "RigidBody");
    let (cube, start) = host.find::<Transform>("Cube").expect("cube");
    assert!(host.get::<RigidBody>(cube).is_some(), "the body was added");

    host.step(10);
    assert_eq!(
        host.get::<Transform>(cube),
        Some(start),
        "nothing moves in Edit"
    );

    click(&mut host, "Play");
    assert_eq!(host.host().play_mode(), PlayMode::Playing);
    host.step(30);
    let fallen: Transform = host.get(cube).expect("still there");
    assert!(
        fallen.translation.y < start.translation.y - 0.1,
        "it fell: {fallen:?}"
    );

    click(&mut host, "Stop");
    host.step(1);
    assert_eq!(host.host().play_mode(), PlayMode::Edit);
    assert_eq!(host.get::<Transform>(cube), Some(start));
}

#[test]
fn a_reloaded_editor_keeps_drawing_and_reacting() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Cube");
    host.host_mut().reload_plugin("editor").expect("reloads");
    host.step(3);
    assert_eq!(host.host().plugin("editor").map(|p| p.reloads()), Some(1));
    assert!(host.find_widget("Hierarchy").is_some());
    // The selection survived: the inspector still shows the cube.
    assert!(host.find_widget("MeshRenderer").is_some());
    create(&mut host, "Sphere");
    assert_entity(&host, "Sphere", true);
    assert_eq!(
        host.host().play_mode(),
        PlayMode::Edit,
        "a reload does not stop/start"
    );
}

/// The editor's move snap with Ctrl held, metres (`editor::viewport::SNAP_METRES`).
const SNAP_METRES: f32 = 0.5;

/// A cube made from the menu, selected, its gizmo shown; and its transform.
fn selected_cube(host: &mut HeadlessHost) -> (onyx_plugin_api::Entity, Transform) {
    create(host, "Cube");
    host.find::<Transform>("Cube").expect("a Cube entity")
}

/// Drags gizmo handle `handle` ("Gizmo X", …) by `by` points.
fn drag_handle(host: &mut HeadlessHost, handle: &str, by: Vec2) {
    let at = host
        .find_widget(handle)
        .unwrap_or_else(|| panic!("no {handle} handle shown"))
        .center();
    host.drag(at, at + by, 6);
    host.step(1);
}

#[test]
fn dragging_the_gizmo_moves_the_cube_along_one_axis_and_undo_puts_it_back() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    let (cube, start) = selected_cube(&mut host);

    drag_handle(&mut host, "Gizmo X", vec2(60.0, 0.0));
    let moved: Transform = host.get(cube).unwrap();
    assert!(moved.translation.x > start.translation.x + 0.2, "{moved:?}");
    assert_eq!(moved.translation.y, start.translation.y, "only along X");
    assert_eq!(moved.translation.z, start.translation.z, "only along X");
    assert_eq!((moved.rotation, moved.scale), (start.rotation, start.scale));

    // One drag is one edit.
    menu(&mut host, "Edit", "Undo");
    assert_eq!(host.get::<Transform>(cube), Some(start));
    menu(&mut host, "Edit", "Redo");
    assert_eq!(host.get::<Transform>(cube), Some(moved));

    // With Ctrl held the move snaps to whole steps.
    host.hold_key(Key::ControlLeft, true);
    drag_handle(&mut host, "Gizmo Y", vec2(0.0, -45.0));
    host.hold_key(Key::ControlLeft, false);
    let snapped: Transform = host.get(cube).unwrap();
    let rise = snapped.translation.y - start.translation.y;
    assert!(rise >= SNAP_METRES - 1e-4, "moved up: {snapped:?}");
    let steps = rise / SNAP_METRES;
    assert!(
        (steps - steps.round()).abs() < 1e-3,
        "{rise} m is whole snap steps"
    );
}

#[test]
fn r_and_e_switch_the_gizmo_to_scale_and_rotate() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    let (cube, start) = selected_cube(&mut host);
    let x_handle = host.find_widget("Gizmo X").unwrap().center();

    // Keys go to the viewport while the pointer is over it.
    host.pointer_move(x_handle + vec2(0.0, 40.0));
    host.step(1);
    host.press_key(Key::R);
    host.step(2);
    drag_handle(&mut host, "Gizmo X", vec2(40.0, 0.0));
    let scaled: Transform = host.get(cube).unwrap();
    assert!(scaled.scale.x > 1.2, "{scaled:?}");
    assert_eq!((scaled.scale.y, scaled.scale.z), (1.0, 1.0));
    assert_eq!(scaled.translation, start.translation);

    host.press_key(Key::E);
    host.step(2);
    drag_handle(&mut host, "Gizmo Y", vec2(40.0, 0.0));
    let turned: Transform = host.get(cube).unwrap();
    let (axis, angle) = turned.rotation.to_axis_angle();
    assert!(angle > 0.1, "it turned: {turned:?}");
    assert!(axis.y.abs() > 0.999, "about Y only: {axis:?}");
    assert_eq!(turned.translation, start.translation);
}

#[test]
fn showing_an_entity_in_the_inspector_changes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    host.load_scene(&repo_file("assets/scenes/editor_tour.ron"))
        .expect("the tour scene loads");
    host.step(2);
    let before = world_summary(&host);
    for name in ["Ball", "Sun", "Lamp", "Floor", "Pillar"] {
        click(&mut host, name);
        host.step(2);
    }
    let after = world_summary(&host);
    let changed: Vec<_> = after.iter().filter(|row| !before.contains(row)).collect();
    assert!(changed.is_empty(), "changed by being shown: {changed:#?}");
}

#[test]
fn the_layout_is_saved_at_detach_and_restored_at_attach() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    menu(&mut host, "View", "Console");
    host.step(1);
    assert!(host.find_widget("Console").is_none(), "hidden");
    drop(host);
    let layout = dir.path().join("layout.json");
    assert!(layout.is_file(), "written at detach");

    let mut host = editor_host(dir.path());
    assert!(host.find_widget("Console").is_none(), "still hidden");
    menu(&mut host, "View", "Reset layout");
    host.step(1);
    assert!(host.find_widget("Console").is_some(), "back after a reset");
}

#[test]
fn a_corrupt_layout_file_gives_the_default_layout() {
    let dir = tempfile::tempdir().unwrap();
    let layout = dir.path().join("layout.json");
    std::fs::write(&layout, "{ not a layout").unwrap();
    let host = editor_host(dir.path());
    for panel in ["Hierarchy", "Inspector", "Viewport", "Console"] {
        assert!(host.find_widget(panel).is_some(), "panel {panel} shown");
    }
    // The console says why.
    assert!(
        host.find_widget_containing("ignored, using the default layout")
            .is_some(),
        "the warning is in the console"
    );
    drop(host);
    let text = std::fs::read_to_string(&layout).unwrap();
    assert!(
        serde_json::from_str::<Value>(&text).is_ok(),
        "replaced by a good layout"
    );
}

#[test]
fn clicking_an_object_in_the_viewport_selects_it() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Cube");
    let (cube, _) = host.find::<Transform>("Cube").expect("cube");
    create(&mut host, "Empty");
    // The cube sits 5 m in front of the camera: the middle of the viewport image shows it.
    let viewport = host.find_widget("Viewport").expect("viewport tab");
    let toolbar = host.find_widget("Grid").expect("viewport toolbar");
    let inspector = host.find_widget("Inspector").expect("inspector tab");
    let console = host.find_widget("Console").expect("console tab");
    let centre = pos2(
        (viewport.left() + inspector.left()) / 2.0,
        (toolbar.bottom() + console.top()) / 2.0,
    );
    host.click_at(centre);
    host.step(1);
    assert!(
        host.find_widget("MeshRenderer").is_some(),
        "the cube is inspected"
    );
    let _ = cube;
}

/// The repository's copy of `path`.
fn repo_file(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(path)
}

#[test]
fn the_editor_matches_its_golden_image() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    host.load_scene(&repo_file("assets/scenes/editor_tour.ron"))
        .expect("the tour scene loads");
    host.step(2);
    click(&mut host, "Ball");
    // Log lines hold paths and timings: filter them all out.
    type_into_field_after(&mut host, "Search", "no line says this");
    host.pointer_move(Pos2::new(1.0, 700.0));
    host.step(3);
    let image = host.screenshot(1280, 720).expect("lavapipe renders");
    assert_golden("editor", &image);
}

/// Writes the README's Play-mode image, `docs/images/editor-play.png`: the tour scene played
/// for a second, paused, the Diagnostics panel open. Not a golden (the panel shows this
/// machine's timings): run it on purpose after a change the image shows, look at it, commit it:
/// `cargo test -p onyx-tests --test e2e -- --ignored the_readme_play_mode_image`.
#[test]
#[ignore = "writes docs/images/editor-play.png; run on purpose"]
fn the_readme_play_mode_image() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    host.load_scene(&repo_file("assets/scenes/editor_tour.ron"))
        .expect("the tour scene loads");
    host.step(2);
    click(&mut host, "Play");
    host.step(60);
    click(&mut host, "Pause");
    assert_eq!(host.host().play_mode(), PlayMode::Paused);
    click(&mut host, "Diagnostics");
    host.pointer_move(Pos2::new(1.0, 700.0));
    host.step(3);
    let image = host.screenshot(1280, 720).expect("lavapipe renders");
    let path = repo_file("docs/images/editor-play.png");
    image.save(&path).expect("write the image");
    eprintln!("wrote {}", path.display());
}

/// The Console of a fresh editor opened on a yellow egui-wgpu warning about an sRGB
/// framebuffer: a clean start must log no warning at all.
#[test]
fn a_windowed_editor_starts_without_a_warning_and_saves_a_screenshot() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("editor.png");
    let layout: PathBuf = dir.path().join("layout.json");
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let out = onyx_in_xvfb()
        .args([
            "run",
            "--plugin",
            "editor",
            "--scene",
            "assets/scenes/demo.ron",
        ])
        .args(["--frames", "20", "--size", "640x360", "--screenshot"])
        .arg(&png)
        .arg("--set")
        .arg(format!("editor.layout={}", layout.display()))
        .current_dir(repo)
        .env("RUST_LOG", "warn")
        .output()
        .expect("onyx runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    // `tracing`'s warnings (Mesa's own lines start `WARNING:` and are not ours).
    let warnings: Vec<&str> = err
        .lines()
        .filter(|l| l.contains("WARN") && !l.contains("WARNING"))
        .collect();
    assert!(warnings.is_empty(), "a clean start warned: {warnings:#?}");
    let image = onyx_render::image::open(&png).unwrap().to_rgba8();
    assert_eq!(image.dimensions(), (640, 360));
    let first = image.get_pixel(0, 0);
    assert!(image.pixels().any(|p| p != first), "not a blank image");
    assert!(
        layout.is_file(),
        "the layout was saved when the editor detached"
    );
}

#[test]
fn the_console_shows_host_and_plugin_lines_and_filters_them_by_level_and_text() {
    let dir = tempfile::tempdir().unwrap();
    let layout = dir.path().join("layout.json");
    std::fs::write(&layout, "{ not a layout").unwrap();
    let mut host = editor_host(dir.path());
    let warning = "ignored, using the default layout";
    let line = host
        .find_widget_containing(warning)
        .expect("the editor's warning");
    // Time, level, source.
    let text_of_line = |host: &HeadlessHost| host.find_widget_containing(warning).is_some();
    assert!(line.width() > 0.0 && text_of_line(&host));
    assert!(
        host.find_widget_containing("WARN  editor: editor layout")
            .is_some(),
        "level and source are shown"
    );

    // Only errors: the warning goes.
    click(&mut host, "TRACE");
    let error_entry = *host.find_widgets("ERROR").last().expect("level list open");
    host.click_at(error_entry.center());
    host.step(2);
    assert!(!text_of_line(&host), "hidden below ERROR");

    // Back to every level, then a text filter that matches nothing.
    click(&mut host, "ERROR");
    let trace_entry = *host.find_widgets("TRACE").last().expect("level list open");
    host.click_at(trace_entry.center());
    host.step(2);
    assert!(text_of_line(&host), "shown again");
    type_into_field_after(&mut host, "Search", "no line says this");
    assert!(!text_of_line(&host), "filtered out by text");
}

#[test]
fn the_diagnostics_panel_shows_frame_physics_render_and_per_plugin_figures() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    click(&mut host, "Diagnostics");
    host.step(3);
    for row in [
        "fixed steps",
        "physics",
        "contacts",
        "bodies awake / asleep",
        "draw calls",
        "triangles",
    ] {
        assert!(host.find_widget(row).is_some(), "row {row}");
    }
    assert!(
        host.find_widget_containing(" fps").is_some(),
        "frame time and fps"
    );
    // The editor's own time, per lifecycle stage.
    assert!(host.find_widget("draw_gui").is_some(), "per-stage rows");
}

#[test]
fn import_obj_makes_an_entity_showing_the_model() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    let model = repo_file("assets/models/two_materials.obj");
    choose_file(&mut host, "Create", "Import OBJ…", &model, "Import");
    host.step(2);
    let (entity, _) = host
        .find::<Transform>("two_materials")
        .expect("an entity named after the file");
    let mesh: MeshRenderer = host.get(entity).expect("it shows a mesh");
    assert!(
        onyx_plugin_api::MeshId::BUILTIN
            .iter()
            .all(|(id, _)| *id != mesh.mesh),
        "the imported model, not a built-in shape"
    );
    // Undoable like any creation.
    menu(&mut host, "Edit", "Undo");
    assert_entity(&host, "two_materials", false);
}

#[test]
fn import_gltf_brings_the_node_tree_under_one_new_entity_and_undoes_in_one_step() {
    let Some(samples) = onyx_tests::gltf_samples() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    let before = host.world().len();
    let model = samples.join("BoxAnimated/glTF-Binary/BoxAnimated.glb");
    choose_file(&mut host, "Create", "Import glTF…", &model, "Import");
    host.step(2);
    // The root and the file's four nodes: node 3 and node 0 → node 1 → node 2.
    assert_eq!(host.world().len(), before + 5, "{:?}", names(&host));
    let (root, _) = host
        .find::<Transform>("BoxAnimated")
        .expect("a root named after the file");
    let (chain, parent) = host
        .find::<onyx_plugin_api::Parent>("node 0")
        .expect("node 0 under the root");
    assert_eq!(parent.0, root);
    let (_, parent) = host
        .find::<onyx_plugin_api::Parent>("node 1")
        .expect("node 1 under node 0");
    assert_eq!(parent.0, chain);
    let (inner, _) = host.find::<Transform>("node 2").expect("node 2");
    assert!(
        host.get::<MeshRenderer>(inner).is_some(),
        "node 2 shows its mesh"
    );
    assert!(
        host.get::<onyx_plugin_api::Animator>(root).is_some(),
        "the root plays the file's animation"
    );
    // One undo takes the whole tree away.
    menu(&mut host, "Edit", "Undo");
    host.step(1);
    assert_eq!(host.world().len(), before, "{:?}", names(&host));
}

#[test]
fn plugins_menu_loads_a_library_and_lists_it_running() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    let library = plugin_library("fixture-gui");
    choose_file(&mut host, "Plugins", "Load…", &library, "Load");
    host.step(3);
    assert!(
        host.host().plugin("fixture_gui").is_some(),
        "the library was loaded"
    );
    click(&mut host, "Plugins");
    assert!(
        host.find_widget_containing("fixture_gui (running)")
            .is_some(),
        "listed with its status"
    );
}

#[test]
fn the_plugins_menu_shows_a_faulted_plugin_with_its_error() {
    let dir = tempfile::tempdir().unwrap();
    let config = HostConfig::default().setting("fixture_faulty", "panic_in", "on_update");
    let mut host = editor_host_with(dir.path(), config);
    host.load_plugin_file(&plugin_library("fixture-faulty"))
        .expect("loads");
    host.step(3);
    click(&mut host, "Plugins");
    assert!(
        host.find_widget_containing("fixture_faulty (faulted in on_update: ")
            .is_some(),
        "the fault is listed with its stage and message"
    );
    // The editor itself keeps running.
    create(&mut host, "Cube");
    assert_entity(&host, "Cube", true);
}

#[test]
fn ctrl_click_in_the_hierarchy_selects_several_and_delete_removes_them() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Cube");
    create(&mut host, "Sphere");
    create(&mut host, "Capsule");

    click(&mut host, "Cube");
    host.hold_key(Key::ControlLeft, true);
    click(&mut host, "Capsule");
    host.hold_key(Key::ControlLeft, false);
    host.step(1);
    menu(&mut host, "Edit", "Delete");
    assert_entity(&host, "Cube", false);
    assert_entity(&host, "Capsule", false);
    assert_entity(&host, "Sphere", true);
}

#[test]
fn double_clicking_a_hierarchy_row_renames_in_place_and_undo_restores_the_name() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Cube");
    create(&mut host, "Sphere");
    let row = host
        .find_widgets("Sphere")
        .first()
        .copied()
        .expect("its row");
    host.click_at(row.center());
    host.click_at(row.center());
    host.step(1);
    // The field opens with the old name selected: typing replaces it.
    host.type_text("Ball");
    host.step(1);
    host.press_key(Key::Enter);
    host.step(2);
    assert_entity(&host, "Ball", true);
    menu(&mut host, "Edit", "Undo");
    assert_entity(&host, "Sphere", true);
}

#[test]
fn a_script_picked_in_the_inspector_runs_in_play_and_stop_undoes_its_work() {
    let dir = tempfile::tempdir().unwrap();
    // With a plugin that registers the "Rotator" behaviour.
    let config =
        HostConfig::default().setting("fixture_services", "dir", dir.path().display().to_string());
    let mut host = editor_host_with(dir.path(), config);
    host.load_plugin_file(&plugin_library("fixture-services"))
        .expect("services fixture loads");
    host.step(2);
    let (cube, start) = selected_cube(&mut host);
    // A new Script names the first registered behaviour; the dropdown lists them all.
    menu(&mut host, "Add Component", "onyx.Script");
    click(&mut host, "Rotator");
    let listed = host.find_widgets("Rotator");
    assert_eq!(listed.len(), 2, "the dropdown and its one entry");
    host.click_at(listed[1].center());
    host.step(2);
    let dump = host.dump_state();
    let cube_dump = dump["entities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["name"] == "Cube")
        .expect("the cube in the dump");
    assert_eq!(cube_dump["components"]["onyx.Script"]["name"], "Rotator");
    assert_eq!(
        host.get::<Transform>(cube),
        Some(start),
        "scripts wait for Play"
    );

    click(&mut host, "Play");
    host.step(30);
    let turned: Transform = host.get(cube).unwrap();
    assert!(
        turned.rotation.angle_between(start.rotation) > 0.05,
        "{turned:?}"
    );
    click(&mut host, "Stop");
    host.step(1);
    assert_eq!(host.get::<Transform>(cube), Some(start));
}

/// The editor camera's pose.
fn editor_camera(host: &HeadlessHost) -> Transform {
    host.find::<Transform>("Editor Camera")
        .expect("the editor's camera entity")
        .1
}

#[test]
fn the_viewport_camera_flies_zooms_and_frames_the_selection() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    let (_, cube) = selected_cube(&mut host);
    let over_viewport = host.find_widget("Gizmo X").unwrap().center() + vec2(0.0, 80.0);
    host.pointer_move(over_viewport);
    host.step(2);
    let start = editor_camera(&host);
    let forward = start.rotation * onyx_plugin_api::glam::Vec3::NEG_Z;

    // The wheel moves along the view direction.
    host.scroll(2.0);
    host.step(3);
    let zoomed = editor_camera(&host);
    let moved = zoomed.translation - start.translation;
    assert!(moved.dot(forward) > 0.1, "moved forward: {moved:?}");
    assert!(
        moved.cross(forward).length() < 1e-3,
        "only forward: {moved:?}"
    );

    // Right button + W flies forward for as long as they are held.
    host.hold_button(MouseButton::Right, true);
    host.hold_key(Key::W, true);
    host.step(30);
    host.hold_key(Key::W, false);
    host.hold_button(MouseButton::Right, false);
    host.step(2);
    let flown = editor_camera(&host);
    let travelled = (flown.translation - zoomed.translation).dot(forward);
    assert!(travelled > 1.0, "flew {travelled} m forward");

    // F frames the selection: the cube ahead, at a few metres.
    host.press_key(Key::F);
    host.step(3);
    let framed = editor_camera(&host);
    let to_cube = cube.translation - framed.translation;
    let view = framed.rotation * onyx_plugin_api::glam::Vec3::NEG_Z;
    assert!(to_cube.normalize().dot(view) > 0.99, "looking at the cube");
    assert!(
        (2.0..10.0).contains(&to_cube.length()),
        "{} m away",
        to_cube.length()
    );
}

mod files;
mod nothing_lost;
mod scene_graph;
mod viewport;
