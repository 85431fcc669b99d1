//! Lifecycle order, fixed-step counts, quit, pause and single step.

use onyx_plugin_api::{Ctx, Flow, InputEvent, Key, Plugin, WindowEvent};
use onyx_runtime::clock::ClockSettings;
use onyx_runtime::{HeadlessHost, HostConfig};
use onyx_tests::{entries, journal, Recorder};

#[test]
fn lifecycle_calls_follow_the_documented_order() {
    let journal = journal();
    let mut host = HeadlessHost::new();
    host.add_plugin("a", Recorder::new("a", &journal)).unwrap();
    host.add_plugin("b", Recorder::new("b", &journal)).unwrap();
    host.inject(WindowEvent::Resized {
        width: 800,
        height: 600,
    });
    host.step(1);
    host.shutdown();
    let expected = [
        "a.on_attach",
        "b.on_attach",
        "a.on_init",
        "b.on_init",
        // Events first: the platform events of both loads, then the resize (on_event to all,
        // then on_resize to all).
        "a.on_event:Platform(PluginLoaded { plugin: \"a\" })",
        "b.on_event:Platform(PluginLoaded { plugin: \"a\" })",
        "a.on_event:Platform(PluginLoaded { plugin: \"b\" })",
        "b.on_event:Platform(PluginLoaded { plugin: \"b\" })",
        "a.on_event:Window(Resized { width: 800, height: 600 })",
        "b.on_event:Window(Resized { width: 800, height: 600 })",
        "a.on_resize:800x600",
        "b.on_resize:800x600",
        "a.on_fixed_update#0",
        "b.on_fixed_update#0",
        "a.on_update",
        "b.on_update",
        "a.on_render",
        "b.on_render",
        "a.draw_gui",
        "b.draw_gui",
        // Detach in reverse load order.
        "b.on_detach",
        "a.on_detach",
    ];
    assert_eq!(entries(&journal), expected);
}

#[test]
fn a_plugin_added_after_start_is_initialised_at_once() {
    let journal = journal();
    let mut host = HeadlessHost::new();
    host.add_plugin("a", Recorder::new("a", &journal)).unwrap();
    host.step(1);
    host.add_plugin("late", Recorder::new("late", &journal))
        .unwrap();
    let log = entries(&journal);
    assert_eq!(&log[log.len() - 2..], ["late.on_attach", "late.on_init"]);
}

fn fixed_steps_per_frame(frame_time: f64, frames: usize, settings: ClockSettings) -> Vec<usize> {
    let journal = journal();
    let mut host = HeadlessHost::with_config(HostConfig {
        clock: settings,
        ..Default::default()
    });
    host.set_frame_time(frame_time);
    host.add_plugin("r", Recorder::new("r", &journal)).unwrap();
    let mut counts = Vec::new();
    for _ in 0..frames {
        let before = entries(&journal)
            .iter()
            .filter(|e| e.starts_with("r.on_fixed_update"))
            .count();
        host.step(1);
        let after = entries(&journal)
            .iter()
            .filter(|e| e.starts_with("r.on_fixed_update"))
            .count();
        counts.push(after - before);
    }
    counts
}

#[test]
fn fixed_steps_match_the_frame_time() {
    let default = ClockSettings::default;
    assert_eq!(fixed_steps_per_frame(1.0 / 60.0, 6, default()), [1; 6]);
    assert_eq!(fixed_steps_per_frame(1.0 / 30.0, 6, default()), [2; 6]);
    assert_eq!(
        fixed_steps_per_frame(1.0 / 120.0, 6, default()),
        [0, 1, 0, 1, 0, 1]
    );
    assert_eq!(fixed_steps_per_frame(0.1, 3, default()), [6; 3]);
    // 240 Hz stepping at 60 fps frames: four per frame.
    let hz240 = ClockSettings {
        fixed_hz: 240.0,
        ..default()
    };
    assert_eq!(fixed_steps_per_frame(1.0 / 60.0, 3, hz240), [4; 3]);
    // The cap: a 1 s frame at 60 Hz would be 60 steps; the default cap is 8.
    assert_eq!(fixed_steps_per_frame(0.2, 2, default()), [8, 8]);
}

#[test]
fn fixed_steps_see_consecutive_ticks() {
    let journal = journal();
    let mut host = HeadlessHost::new();
    host.set_frame_time(1.0 / 20.0);
    host.add_plugin("r", Recorder::new("r", &journal)).unwrap();
    host.step(2);
    let ticks: Vec<String> = entries(&journal)
        .into_iter()
        .filter_map(|e| e.strip_prefix("r.on_fixed_update#").map(str::to_owned))
        .collect();
    assert_eq!(ticks, ["0", "1", "2", "3", "4", "5"]);
    assert_eq!(host.host().time().ticks, 6);
    assert_eq!(host.host().time().frame, 2);
}

#[test]
fn flow_quit_stops_the_run_after_that_frame() {
    let journal = journal();
    let mut host = HeadlessHost::new();
    let mut quitter = Recorder::new("q", &journal);
    quitter.quit_after = Some(3);
    host.add_plugin("q", quitter).unwrap();
    host.add_plugin("other", Recorder::new("o", &journal))
        .unwrap();
    assert_eq!(host.step(100), 3);
    assert!(host.quit_requested());
    // The frame finished: the other plugin got its update, render and gui for frame 3.
    let log = entries(&journal);
    assert_eq!(log.iter().filter(|e| *e == "o.draw_gui").count(), 3);
}

#[test]
fn close_requested_quits_after_the_frame() {
    let mut host = HeadlessHost::new();
    host.step(1);
    host.inject(WindowEvent::CloseRequested);
    assert_eq!(host.step(10), 1);
}

/// Pauses on P, steps once on N, reads the clock.
#[derive(Default)]
struct Controller;

impl Plugin for Controller {
    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> Flow {
        let input = ctx.input();
        if input.key_pressed(Key::P) {
            let paused = ctx.time().paused;
            ctx.set_paused(!paused);
        }
        if input.key_pressed(Key::N) {
            ctx.step_once();
        }
        Flow::Continue
    }
}

fn press(host: &mut HeadlessHost, key: Key) {
    host.inject(InputEvent::Key {
        key,
        pressed: true,
        repeat: false,
    });
    host.inject(InputEvent::Key {
        key,
        pressed: false,
        repeat: false,
    });
}

#[test]
fn a_plugin_can_pause_and_single_step_the_simulation() {
    let mut host = HeadlessHost::new();
    host.add_plugin("controller", Controller).unwrap();
    host.step(3);
    assert_eq!(host.host().time().ticks, 3);
    press(&mut host, Key::P);
    host.step(1); // frame 4 runs its step, then pauses
    host.step(5);
    assert_eq!(host.host().time().ticks, 4, "no steps while paused");
    assert!(host.host().time().paused);
    press(&mut host, Key::N);
    host.step(1); // the request lands in this frame's update
    host.step(3); // exactly one step runs next frame
    assert_eq!(host.host().time().ticks, 5);
    press(&mut host, Key::P);
    host.step(1);
    host.step(2);
    assert_eq!(host.host().time().ticks, 7);
}
