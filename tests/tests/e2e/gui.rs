//! Plugin GUIs across the boundary: real cdylib plugins draw with their own egui; the host
//! finds widgets by label, clicks them, keeps the UI's input from the scene, keeps two
//! plugins' textures apart, draws the GUI into screenshots and survives a reload.

use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::Arc;

use onyx_plugin_api::egui::{pos2, Pos2};
use onyx_plugin_api::{Ctx, Event, InputEvent, MouseButton, Plugin, Transform};
use onyx_runtime::{HeadlessHost, HostConfig};
use onyx_tests::{assert_golden, plugin_library};

fn gui_host(config: HostConfig) -> HeadlessHost {
    let mut host = HeadlessHost::with_config(config);
    host.load_plugin_file(&plugin_library("fixture-gui"))
        .expect("the GUI fixture loads");
    host.step(3);
    host
}

/// Counts the left-button presses the scene sees (as events and through `Ctx::input()`)
/// and the text events.
#[derive(Clone, Default)]
struct ScenePointer {
    events: Arc<AtomicU32>,
    polled: Arc<AtomicU32>,
    texts: Arc<AtomicU32>,
}

impl Plugin for ScenePointer {
    fn on_event(&mut self, _: &mut Ctx, event: &Event) {
        if let Event::Input(InputEvent::MouseButton {
            button: MouseButton::Left,
            pressed: true,
        }) = event
        {
            self.events.fetch_add(1, Ordering::SeqCst);
        }
        if let Event::Input(InputEvent::Text(_)) = event {
            self.texts.fetch_add(1, Ordering::SeqCst);
        }
    }

    fn on_update(&mut self, ctx: &mut Ctx, _: f32) -> onyx_plugin_api::Flow {
        if ctx.input().mouse_pressed(MouseButton::Left) {
            self.polled.fetch_add(1, Ordering::SeqCst);
        }
        onyx_plugin_api::Flow::Continue
    }
}

fn count_spawned(host: &HeadlessHost) -> usize {
    host.world()
        .query::<&onyx_plugin_api::Name>()
        .iter()
        .filter(|n| n.as_str() == "spawned")
        .count()
}

#[test]
fn clicking_the_button_found_by_its_label_runs_the_plugins_code() {
    let mut host = gui_host(HostConfig::default());
    let button = host
        .find_widget("Spawn")
        .expect("the Tools window shows Spawn");
    assert!(
        button.width() > 10.0 && button.height() > 10.0,
        "{button:?}"
    );
    assert!(
        host.find_widget("Tools").is_some(),
        "windows are found by title"
    );
    assert!(host.find_widget("No such widget").is_none());

    assert!(host.click_widget("Spawn"));
    assert_eq!(count_spawned(&host), 1);
    assert!(host.click_widget("Spawn"));
    host.step(1);
    assert_eq!(count_spawned(&host), 2);
    assert!(
        host.find_widget("Spawned: 2").is_some(),
        "the label follows the clicks"
    );
    assert!(host.find::<Transform>("spawned").is_some());
}

#[test]
fn typing_goes_to_the_focused_text_field_not_to_the_scene() {
    let mut host = gui_host(HostConfig::default());
    let pointer = ScenePointer::default();
    host.add_plugin("scene", pointer.clone()).unwrap();
    // The text field sits below the "Spawned: 0" label.
    let label = host.find_widget("Spawned: 0").expect("label");
    host.click_at(pos2(label.left() + 20.0, label.bottom() + 12.0));
    host.type_text("crate");
    host.step(2);
    assert!(
        host.find::<Transform>("typed:crate").is_some(),
        "the text field got the text"
    );
    assert_eq!(
        pointer.texts.load(Ordering::SeqCst),
        0,
        "the scene got the text too"
    );
    assert_eq!(
        pointer.events.load(Ordering::SeqCst),
        0,
        "the scene got the click"
    );
    // Click outside to drop the focus: typing reaches the scene again.
    host.click_at(pos2(900.0, 600.0));
    host.type_text("x");
    host.step(1);
    assert_eq!(pointer.texts.load(Ordering::SeqCst), 1);
}

#[test]
fn a_click_on_a_window_stays_in_the_ui_and_a_click_beside_it_reaches_the_scene() {
    let mut host = gui_host(HostConfig::default());
    let pointer = ScenePointer::default();
    host.add_plugin("scene", pointer.clone()).unwrap();
    host.step(1);

    let label = host.find_widget("Spawned: 0").expect("the label is shown");
    host.click_at(label.center());
    assert!(host.pointer_over_gui());
    assert_eq!(
        pointer.events.load(Ordering::SeqCst),
        0,
        "on_event saw the click"
    );
    assert_eq!(
        pointer.polled.load(Ordering::SeqCst),
        0,
        "Ctx::input saw the click"
    );

    host.click_at(Pos2::new(900.0, 600.0));
    assert!(!host.pointer_over_gui());
    assert_eq!(pointer.events.load(Ordering::SeqCst), 1);
    assert_eq!(pointer.polled.load(Ordering::SeqCst), 1);
    assert_eq!(count_spawned(&host), 0, "no button was under either click");
}

fn count_pixels(image: &onyx_render::image::RgbaImage, rgb: [u8; 3]) -> usize {
    image
        .pixels()
        .filter(|p| p.0[..3].iter().zip(rgb).all(|(a, b)| a.abs_diff(b) <= 8))
        .count()
}

#[test]
fn two_plugins_with_the_same_texture_ids_both_show_their_own_texture() {
    let mut host = gui_host(HostConfig::default());
    host.load_plugin_file(&plugin_library("fixture-gui-swatch"))
        .expect("the second GUI fixture loads");
    host.set_window_size(640, 240);
    // Windows fade in over their first frames.
    host.step(30);
    let image = host
        .screenshot(640, 240)
        .expect("renders on the CPU adapter");
    let red = count_pixels(&image, [255, 0, 0]);
    let blue = count_pixels(&image, [0, 0, 255]);
    // Each swatch is 32 × 32 texels of one colour.
    assert!(red >= 900, "red swatch pixels: {red}");
    assert!(blue >= 900, "blue swatch pixels: {blue}");
}

#[test]
fn the_tools_window_matches_its_reference_image() {
    let mut host = gui_host(HostConfig::default());
    host.set_window_size(320, 200);
    host.step(30);
    let image = host
        .screenshot(320, 200)
        .expect("renders on the CPU adapter");
    assert_golden("gui-tools", &image);
}

#[test]
fn a_reloaded_gui_plugin_keeps_drawing_and_reacting() {
    let dir = tempfile::tempdir().unwrap();
    let library = dir.path().join(
        plugin_library("fixture-gui")
            .file_name()
            .expect("a file name"),
    );
    std::fs::copy(plugin_library("fixture-gui"), &library).unwrap();
    let mut host = HeadlessHost::new();
    let name = host.load_plugin_file(&library).unwrap();
    host.set_window_size(320, 200);
    host.step(3);
    assert!(host.click_widget("Spawn"));
    assert_eq!(count_spawned(&host), 1);

    host.host_mut().reload_plugin(&name).expect("reloads");
    host.step(3);
    assert_eq!(host.host().plugin(&name).map(|p| p.reloads()), Some(1));
    assert!(host.click_widget("Spawn"), "the new build shows its window");
    assert_eq!(count_spawned(&host), 2);
    host.step(30);
    let image = host.screenshot(320, 200).expect("renders");
    let red = count_pixels(&image, [255, 0, 0]);
    assert!(
        red >= 900,
        "the new build's swatch texture is drawn: {red} red pixels"
    );
}

#[test]
fn a_plugin_showing_the_viewport_gets_the_scene_in_it_and_its_pointer_input() {
    let config = HostConfig::default().setting("fixture_gui", "viewport", "1");
    let mut host = gui_host(config);
    let pointer = ScenePointer::default();
    host.add_plugin("scene", pointer.clone()).unwrap();
    host.set_window_size(320, 200);
    host.step(3);
    let frame = host.host().gui().frame();
    assert_eq!(
        frame.viewport_pixels(),
        Some((200, 200)),
        "the viewport fills what the 120-point panel leaves"
    );

    host.click_at(pos2(60.0, 100.0));
    assert_eq!(
        pointer.events.load(Ordering::SeqCst),
        0,
        "the panel took the click"
    );
    host.click_at(pos2(220.0, 100.0));
    assert_eq!(
        pointer.events.load(Ordering::SeqCst),
        1,
        "a click on the viewport reaches the scene"
    );

    host.step(30);
    let image = host.screenshot(320, 200).expect("renders");
    image.save("/tmp/gui_viewport.png").ok();
    let full_scene = {
        let mut plain = HeadlessHost::new();
        plain.screenshot(200, 200).expect("renders")
    };
    // The right part of the window is the scene at the viewport's size.
    let mut off = 0u64;
    for y in 0..200 {
        for x in 0..200 {
            let a = image.get_pixel(120 + x, y).0;
            let b = full_scene.get_pixel(x, y).0;
            off += a
                .iter()
                .zip(b)
                .map(|(p, q)| u64::from(p.abs_diff(q)))
                .sum::<u64>();
        }
    }
    let mean = off as f64 / (200.0 * 200.0 * 4.0);
    assert!(
        mean < 3.0,
        "the viewport differs from the scene by {mean:.2}/255"
    );
}

/// A real window under Xvfb: the GUI plugin runs with egui-winit's input and is drawn over
/// the window's frames; the run's screenshot (the window's renderer) shows its window.
#[test]
fn a_windowed_run_draws_the_plugin_gui_under_xvfb() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("gui-window.png");
    let out = onyx_tests::onyx_in_xvfb()
        .args([
            "run",
            "--plugin",
            "fixture_gui",
            "--frames",
            "40",
            "--size",
            "320x200",
            "--no-vsync",
            "--screenshot",
        ])
        .arg(&png)
        .env("RUST_LOG", "warn")
        .output()
        .expect("xvfb-run runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "exit {:?}: {err}", out.status);
    assert!(!err.contains("faulted"), "{err}");
    let image = onyx_render::image::open(&png).unwrap().to_rgba8();
    let red = count_pixels(&image, [255, 0, 0]);
    assert!(red >= 900, "the window's GUI swatch: {red} red pixels");
}
