//! The editor and scene files as a newcomer meets them: a scene given with `--scene` named in
//! the title, Save writing back to it, the file dialog starting beside it, a modified marker,
//! and renaming in the hierarchy.

use super::*;

/// A copy of the tour scene in `dir`, loaded into an editor host as `--scene` does.
fn host_on_a_copy_of_the_tour(dir: &Path) -> (HeadlessHost, PathBuf) {
    let scenes = dir.join("my scenes");
    std::fs::create_dir_all(&scenes).unwrap();
    let scene = scenes.join("tour.ron");
    std::fs::copy(repo_file("assets/scenes/editor_tour.ron"), &scene).unwrap();
    let mut host = editor_host(dir);
    host.load_scene(&scene).expect("the copy loads");
    host.step(2);
    (host, scene)
}

/// The editor's title: the scene's file name, `*` when it has unsaved edits.
fn title(host: &HeadlessHost, text: &str) -> bool {
    host.find_widget(text).is_some()
}

/// A scene opened with `--scene` showed as "untitled".
#[test]
fn a_scene_given_on_the_command_line_is_named_in_the_title() {
    let dir = tempfile::tempdir().unwrap();
    let (host, _) = host_on_a_copy_of_the_tour(dir.path());
    assert!(title(&host, "tour.ron"), "the title names the file");
    assert!(!title(&host, "untitled"), "not untitled");
}

/// Save acted as Save As for a scene opened with `--scene`.
#[test]
fn save_writes_back_to_the_scene_given_on_the_command_line() {
    let dir = tempfile::tempdir().unwrap();
    let (mut host, scene) = host_on_a_copy_of_the_tour(dir.path());
    create(&mut host, "Cube");
    menu(&mut host, "File", "Save");
    host.step(1);
    assert!(
        host.find_widget("Save scene as").is_none(),
        "Save asked for a file name"
    );
    let text = std::fs::read_to_string(&scene).unwrap();
    assert!(text.contains("\"Cube\""), "the cube was saved:\n{text}");
}

/// The file dialog always opened in `assets/scenes`.
#[test]
fn the_file_dialog_opens_in_the_folder_of_the_current_scene() {
    let dir = tempfile::tempdir().unwrap();
    let (mut host, scene) = host_on_a_copy_of_the_tour(dir.path());
    menu(&mut host, "File", "Open…");
    host.step(1);
    let folder = scene.parent().unwrap().display().to_string();
    assert!(
        host.find_widget_containing(&folder).is_some(),
        "the dialog lists {folder}"
    );
    assert!(
        host.find_widget("tour.ron").is_some(),
        "and the scene in it"
    );
}

#[test]
fn the_title_marks_unsaved_edits_until_they_are_saved_or_undone() {
    let dir = tempfile::tempdir().unwrap();
    let (mut host, _) = host_on_a_copy_of_the_tour(dir.path());
    assert!(title(&host, "tour.ron"), "unmodified at first");
    create(&mut host, "Cube");
    assert!(title(&host, "tour.ron *"), "modified after an edit");
    menu(&mut host, "Edit", "Undo");
    assert!(title(&host, "tour.ron"), "back to the saved scene");
    menu(&mut host, "Edit", "Redo");
    assert!(title(&host, "tour.ron *"));
    host.pointer_move(pos2(1.0, 700.0));
    host.hold_key(Key::ControlLeft, true);
    host.step(1);
    host.press_key(Key::S);
    host.step(1);
    host.hold_key(Key::ControlLeft, false);
    host.step(1);
    assert!(title(&host, "tour.ron"), "saved with Ctrl+S");
    assert!(!title(&host, "tour.ron *"));

    menu(&mut host, "File", "New");
    assert!(title(&host, "untitled"), "a new scene is untitled");
    create(&mut host, "Sphere");
    assert!(title(&host, "untitled *"));
}

/// Double-click rename appended to the old name ("Cube copyCrate").
#[test]
fn renaming_a_duplicate_in_the_hierarchy_replaces_its_whole_name() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    create(&mut host, "Cube");
    menu(&mut host, "Edit", "Duplicate");
    assert_entity(&host, "Cube copy", true);
    let row = host
        .find_widgets("Cube copy")
        .into_iter()
        .min_by(|a, b| a.left().total_cmp(&b.left()))
        .expect("its row");
    host.click_at(row.center());
    host.click_at(row.center());
    host.step(1);
    host.type_text("Crate");
    host.step(1);
    host.press_key(Key::Enter);
    host.step(2);
    assert_entity(&host, "Crate", true);
    assert_entity(&host, "Cube copyCrate", false);
    assert_entity(&host, "Cube copy", false);
}
