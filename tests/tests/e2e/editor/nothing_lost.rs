//! Nothing lost: Quit, the window's close button, New and Open ask "Save changes?" while the
//! scene has unsaved edits, and those edits are autosaved to a recovery copy that the next
//! start offers back — after a real `SIGKILL` of the process that made them.

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use onyx_plugin_api::WindowEvent;

use super::*;

/// An editor autosaving every 0.2 s into `dir/recovery`, on a copy of the tour scene in
/// `dir` when `on_tour`.
fn editor_autosaving(dir: &Path, on_tour: bool) -> (HeadlessHost, PathBuf) {
    let config = HostConfig::default().setting("editor", "autosave", "0.2");
    let mut host = editor_host_with(dir, config);
    let scene = dir.join("tour.ron");
    if on_tour {
        if !scene.is_file() {
            std::fs::copy(repo_file("assets/scenes/editor_tour.ron"), &scene).unwrap();
        }
        host.load_scene(&scene).expect("the copy loads");
        host.step(2);
    }
    (host, scene)
}

/// Creates a cube and renames it `Cube kept`: an edit that only this test makes.
fn make_an_edit(host: &mut HeadlessHost) {
    create(host, "Cube");
    type_into_field_after(host, "Name", " kept");
    assert_entity(host, "Cube kept", true);
}

fn asking(host: &HeadlessHost) -> bool {
    host.find_widget("Save changes?").is_some()
}

fn recovery_files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir.join("recovery"))
        .map(|entries| {
            entries
                .flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}

/// File ▸ New threw unsaved edits away without a word.
#[test]
fn new_asks_before_throwing_unsaved_edits_away() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    menu(&mut host, "File", "New");
    assert!(!asking(&host), "nothing to lose: no question");

    make_an_edit(&mut host);
    menu(&mut host, "File", "New");
    assert!(asking(&host), "unsaved edits: it asks");
    assert_entity(&host, "Cube kept", true);
    click(&mut host, "Cancel");
    assert!(!asking(&host));
    assert_entity(&host, "Cube kept", true);

    menu(&mut host, "File", "New");
    click(&mut host, "Don't Save");
    host.step(1);
    assert!(!asking(&host));
    assert_entity(&host, "Cube kept", false);
}

/// File ▸ Quit ended the run with edits unsaved.
#[test]
fn quit_with_unsaved_edits_saves_them_first_when_told_to() {
    let dir = tempfile::tempdir().unwrap();
    let (mut host, scene) = editor_autosaving(dir.path(), true);
    make_an_edit(&mut host);
    menu(&mut host, "File", "Quit");
    assert!(asking(&host));
    assert!(!host.quit_requested(), "it waits for the answer");
    click(&mut host, "Save");
    assert!(host.quit_requested(), "saved, then quit");
    let text = std::fs::read_to_string(&scene).unwrap();
    assert!(text.contains("Cube kept"), "the edit was saved:\n{text}");
    host.shutdown();
    assert!(
        recovery_files(dir.path()).is_empty(),
        "saved: no recovery copy left {:?}",
        recovery_files(dir.path())
    );
}

/// The window's close button ended the run with edits unsaved.
#[test]
fn closing_the_window_with_unsaved_edits_asks_and_keeps_it_open() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    make_an_edit(&mut host);
    host.host_mut().push_event(WindowEvent::CloseRequested);
    host.step(2);
    assert!(!host.quit_requested(), "kept open to ask");
    assert!(asking(&host));
    click(&mut host, "Don't Save");
    assert!(
        host.quit_requested(),
        "told to throw the edits away: it closes"
    );

    // Nothing unsaved: the close button closes at once.
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    host.host_mut().push_event(WindowEvent::CloseRequested);
    host.step(1);
    assert!(host.quit_requested());
}

/// Save in "Save changes?" on an untitled scene goes through Save As, then does what was
/// asked (here: opening another scene).
#[test]
fn an_untitled_scene_is_saved_through_save_as_before_another_opens() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = editor_host(dir.path());
    make_an_edit(&mut host);
    let tour = dir.path().join("tour.ron");
    std::fs::copy(repo_file("assets/scenes/editor_tour.ron"), &tour).unwrap();
    choose_file(&mut host, "File", "Open…", &tour, "Open");
    assert!(asking(&host));
    assert_entity(&host, "Cube kept", true);
    click(&mut host, "Save");
    let saved = dir.path().join("mine.ron");
    type_into_field_after(&mut host, "File name", &saved.display().to_string());
    click(&mut host, "Save");
    host.step(2);
    let text = std::fs::read_to_string(&saved).unwrap();
    assert!(text.contains("Cube kept"), "saved first:\n{text}");
    assert_entity(&host, "Cube kept", false);
    assert!(title(&host, "tour.ron"), "then the other scene opened");
}

/// Autosave writes a copy of the edits (never the scene's file), and Save takes it away.
#[test]
fn unsaved_edits_are_autosaved_and_the_copy_goes_once_they_are_saved() {
    let dir = tempfile::tempdir().unwrap();
    let (mut host, scene) = editor_autosaving(dir.path(), true);
    let original = std::fs::read_to_string(&scene).unwrap();
    run_for(&mut host, Duration::from_millis(600));
    assert!(
        recovery_files(dir.path()).is_empty(),
        "no edits: nothing autosaved {:?}",
        recovery_files(dir.path())
    );
    make_an_edit(&mut host);
    run_for(&mut host, Duration::from_millis(600));
    let pid = std::process::id();
    assert_eq!(
        recovery_files(dir.path()),
        [format!("about-{pid}.json"), format!("scene-{pid}.ron")]
    );
    let copy =
        std::fs::read_to_string(dir.path().join(format!("recovery/scene-{pid}.ron"))).unwrap();
    assert!(copy.contains("Cube kept"), "{copy}");
    assert_eq!(
        std::fs::read_to_string(&scene).unwrap(),
        original,
        "an autosave never writes the scene's own file"
    );
    assert!(title(&host, "tour.ron *"), "still the tour, still modified");

    menu(&mut host, "File", "Save");
    assert!(
        recovery_files(dir.path()).is_empty(),
        "saved: the copy went"
    );
}

const CHILD: &str = "ONYX_TEST_EDITOR_TO_KILL";
const AUTOSAVED: &str = "onyx-test: autosaved";

/// The editor is killed (SIGKILL: no detach, no atexit) with unsaved edits; the next start
/// offers them back, and Recover gives the same world named after the same file.
#[test]
fn a_killed_editor_s_unsaved_edits_are_offered_back_at_the_next_start() {
    if let Some(dir) = std::env::var_os(CHILD) {
        // The process to kill: edit, wait for the autosave, say so, wait for the end.
        let dir = PathBuf::from(dir);
        let (mut host, _) = editor_autosaving(&dir, true);
        make_an_edit(&mut host);
        let pid = std::process::id();
        let copy = dir.join(format!("recovery/scene-{pid}.ron"));
        for _ in 0..400 {
            run_for(&mut host, Duration::from_millis(50));
            if std::fs::read_to_string(&copy).is_ok_and(|t| t.contains("Cube kept")) {
                println!("{AUTOSAVED}");
                loop {
                    std::thread::sleep(Duration::from_secs(1));
                }
            }
        }
        panic!("never autosaved to {}", copy.display());
    }

    let dir = tempfile::tempdir().unwrap();
    let mut child = Command::new(std::env::current_exe().unwrap())
        .args([
            "editor::nothing_lost::a_killed_editor_s_unsaved_edits_are_offered_back_at_the_next_start",
            "--exact",
            "--nocapture",
            "--test-threads",
            "1",
        ])
        .env(CHILD, dir.path())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let stdout = child.stdout.take().unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            if line.contains(AUTOSAVED) {
                let _ = tx.send(());
            }
        }
    });
    let started = Instant::now();
    let autosaved = rx.recv_timeout(Duration::from_secs(240));
    if autosaved.is_err() {
        let _ = child.kill();
        panic!(
            "the child never autosaved in {:?}: {:?}",
            started.elapsed(),
            child.wait()
        );
    }

    // While it runs, its copy is its own: another editor neither offers nor deletes it.
    {
        let other_dir = dir.path().join("other");
        std::fs::create_dir_all(&other_dir).unwrap();
        let mut other = HeadlessHost::with_config(
            HostConfig::default()
                .setting(
                    "editor",
                    "layout",
                    other_dir.join("l.json").display().to_string(),
                )
                .setting(
                    "editor",
                    "recovery",
                    dir.path().join("recovery").display().to_string(),
                ),
        );
        other
            .load_plugin_file(&plugin_library("editor"))
            .expect("the editor loads");
        other.step(3);
        assert!(other.find_widget("Recover unsaved changes?").is_none());
        other.shutdown();
        assert_eq!(
            recovery_files(dir.path()).len(),
            2,
            "the running editor's copy stays"
        );
    }

    child.kill().unwrap();
    let status = child.wait().unwrap();
    assert!(!status.success(), "killed: {status:?}");
    let scene = dir.path().join("tour.ron");
    let on_disk = std::fs::read_to_string(&scene).unwrap();
    assert!(!on_disk.contains("Cube kept"), "the edit was never saved");

    let (mut host, _) = editor_autosaving(dir.path(), false);
    assert!(
        host.find_widget("Recover unsaved changes?").is_some(),
        "the next start offers the copy"
    );
    assert!(
        host.find_widget_containing("tour.ron").is_some(),
        "naming the scene it is a copy of"
    );
    click(&mut host, "Recover");
    host.step(2);
    assert_entity(&host, "Cube kept", true);
    assert!(title(&host, "tour.ron *"), "named after its file, modified");
    let pid = std::process::id();
    assert_eq!(
        recovery_files(dir.path()),
        [format!("about-{pid}.json"), format!("scene-{pid}.ron")],
        "the copy is this editor's now"
    );

    menu(&mut host, "File", "Save");
    let saved = std::fs::read_to_string(&scene).unwrap();
    assert!(
        saved.contains("Cube kept"),
        "Save wrote the recovered edits to tour.ron"
    );
    assert!(recovery_files(dir.path()).is_empty());
}

/// The editor's title reads `text` (the scene's file name, ` *` when modified).
fn title(host: &HeadlessHost, text: &str) -> bool {
    host.find_widget(text).is_some()
}

/// Runs frames for `time` of wall time (autosave keeps the user's time, not the world's).
fn run_for(host: &mut HeadlessHost, time: Duration) {
    let start = Instant::now();
    while start.elapsed() < time {
        host.step(1);
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// A hot reload of the editor forgot that the scene had unsaved edits: Quit then quit
/// without asking.
#[test]
fn unsaved_edits_are_still_unsaved_after_the_editor_is_reloaded() {
    let dir = tempfile::tempdir().unwrap();
    let (mut host, _) = editor_autosaving(dir.path(), true);
    make_an_edit(&mut host);
    host.host_mut().reload_plugin("editor").expect("reloads");
    host.step(3);
    assert!(title(&host, "tour.ron *"), "still modified");
    menu(&mut host, "File", "Quit");
    assert!(asking(&host), "so Quit still asks");
    assert!(!host.quit_requested());
}
