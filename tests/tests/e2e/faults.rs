//! A plugin that panics in any lifecycle method is faulted, reported and never called again;
//! the host and the other plugins go on. Tested with a real cdylib, so the panic really is
//! caught inside the plugin's own image.

use onyx_plugin_api::{
    Ctx, CtxError, Entity, EntityTransform, Name, Plugin, Transform, WindowEvent,
};
use onyx_runtime::plugins::Stage;
use onyx_runtime::{HeadlessHost, HostConfig, PluginLoadError, PluginStatus};
use onyx_tests::{entries, journal, plugin_library, Recorder};

const FAULTY: &str = "fixture_faulty";

fn host_with_faulty(panic_in: &str) -> (HeadlessHost, onyx_tests::Journal) {
    let config = HostConfig::default().setting(FAULTY, "panic_in", panic_in);
    let mut host = HeadlessHost::with_config(config);
    let journal = journal();
    host.add_plugin("witness", Recorder::new("witness", &journal))
        .unwrap();
    host.load_plugin_file(&plugin_library("fixture-faulty"))
        .unwrap();
    (host, journal)
}

fn faulty_updates(host: &HeadlessHost) -> u32 {
    let Some((e, _)) = host.find::<Name>("faulty") else {
        return 0;
    };
    host.get::<onyx_runtime::world::PluginComponents>(e)
        .and_then(|p| p.0.get("fixture_faulty.updates").cloned())
        .map(|b| u32::from_le_bytes(b.bytes.try_into().unwrap()))
        .unwrap_or(0)
}

fn assert_faulted_in(host: &HeadlessHost, journal: &onyx_tests::Journal, stage: Stage) {
    match host.plugin_status(FAULTY) {
        Some(PluginStatus::Faulted { stage: s, message }) => {
            assert_eq!(*s, stage);
            assert!(
                message.contains(&format!("fixture_faulty panics in {stage} as configured")),
                "{message}"
            );
            assert!(
                message.contains("src/lib.rs"),
                "the panic location is reported: {message}"
            );
        }
        other => panic!("expected a fault in {stage}, got {other:?}"),
    }
    // The other plugin heard about it through the dispatcher.
    let heard = entries(journal).iter().any(|e| {
        e.starts_with("witness.on_event:Platform(PluginFaulted")
            && e.contains(FAULTY)
            && e.contains(stage.as_str())
    });
    assert!(
        heard,
        "no PluginFaulted event reached the other plugin: {:?}",
        entries(journal)
    );
}

/// Runs frames after the fault: the frame loop and the witness go on; the faulty plugin is
/// never called again.
fn assert_host_goes_on(host: &mut HeadlessHost, journal: &onyx_tests::Journal) {
    let updates_before = faulty_updates(host);
    let witness_before = entries(journal)
        .iter()
        .filter(|e| *e == "witness.on_update")
        .count();
    assert_eq!(host.step(5), 5);
    let witness_after = entries(journal)
        .iter()
        .filter(|e| *e == "witness.on_update")
        .count();
    assert_eq!(witness_after, witness_before + 5);
    assert_eq!(
        faulty_updates(host),
        updates_before,
        "a faulted plugin was called again"
    );
}

#[test]
fn a_panic_in_on_init_faults_the_plugin() {
    let (mut host, journal) = host_with_faulty("on_init");
    host.step(2);
    assert_faulted_in(&host, &journal, Stage::Init);
    assert_host_goes_on(&mut host, &journal);
}

#[test]
fn a_panic_in_on_event_faults_the_plugin() {
    let (mut host, journal) = host_with_faulty("on_event");
    host.step(3);
    assert_faulted_in(&host, &journal, Stage::Event);
    assert_host_goes_on(&mut host, &journal);
}

#[test]
fn a_panic_in_on_fixed_update_faults_the_plugin() {
    let (mut host, journal) = host_with_faulty("on_fixed_update");
    host.step(2);
    assert_faulted_in(&host, &journal, Stage::FixedUpdate);
    assert_host_goes_on(&mut host, &journal);
}

#[test]
fn a_panic_in_on_update_faults_the_plugin() {
    let (mut host, journal) = host_with_faulty("on_update");
    host.step(2);
    assert_faulted_in(&host, &journal, Stage::Update);
    assert_eq!(faulty_updates(&host), 0);
    assert_host_goes_on(&mut host, &journal);
}

#[test]
fn a_panic_in_on_render_faults_the_plugin() {
    let (mut host, journal) = host_with_faulty("on_render");
    host.step(2);
    assert_faulted_in(&host, &journal, Stage::Render);
    assert_host_goes_on(&mut host, &journal);
}

#[test]
fn a_panic_in_draw_gui_faults_the_plugin() {
    let (mut host, journal) = host_with_faulty("draw_gui");
    host.step(2);
    assert_faulted_in(&host, &journal, Stage::DrawGui);
    assert_host_goes_on(&mut host, &journal);
}

#[test]
fn a_panic_in_on_resize_faults_the_plugin() {
    let (mut host, journal) = host_with_faulty("on_resize");
    host.step(2);
    assert_eq!(host.plugin_status(FAULTY), Some(&PluginStatus::Running));
    host.inject(WindowEvent::Resized {
        width: 640,
        height: 480,
    });
    host.step(2);
    assert_faulted_in(&host, &journal, Stage::Resize);
    assert_host_goes_on(&mut host, &journal);
}

#[test]
fn a_panic_in_on_detach_faults_the_plugin_and_others_still_detach() {
    let (mut host, journal) = host_with_faulty("on_detach");
    host.step(2);
    host.shutdown();
    assert!(matches!(
        host.plugin_status(FAULTY),
        Some(PluginStatus::Faulted {
            stage: Stage::Detach,
            ..
        })
    ));
    assert!(entries(&journal).contains(&"witness.on_detach".to_owned()));
}

#[test]
fn a_panic_in_on_attach_refuses_the_plugin_and_the_host_goes_on() {
    let config = HostConfig::default().setting(FAULTY, "panic_in", "on_attach");
    let mut host = HeadlessHost::with_config(config);
    let error = host
        .load_plugin_file(&plugin_library("fixture-faulty"))
        .unwrap_err();
    assert!(
        matches!(error, PluginLoadError::AttachFailed { .. }),
        "{error:?}"
    );
    let message = error.to_string();
    assert!(
        message.contains("fixture_faulty") && message.contains("panics in on_attach"),
        "{message}"
    );
    assert!(host.plugin_status(FAULTY).is_none());
    host.load_plugin_file(&plugin_library("hello")).unwrap();
    assert_eq!(host.step(3), 3);
}

#[test]
fn an_error_from_on_attach_refuses_the_plugin_with_its_message() {
    let config = HostConfig::default().setting(FAULTY, "fail_attach", "1");
    let mut host = HeadlessHost::with_config(config);
    let error = host
        .load_plugin_file(&plugin_library("fixture-faulty"))
        .unwrap_err();
    assert!(
        error
            .to_string()
            .contains("refusing to attach, as configured"),
        "{error}"
    );
}

#[test]
fn a_bad_setting_is_reported_by_the_plugin_that_reads_it() {
    let config = HostConfig::default().setting("hello", "quit_after", "soon");
    let mut host = HeadlessHost::with_config(config);
    let error = host.load_plugin_file(&plugin_library("hello")).unwrap_err();
    assert!(
        error
            .to_string()
            .contains("setting `quit_after` = `soon` is not valid"),
        "{error}"
    );
}

/// A plugin that tries to write NaN and infinity in every way the API allows, and records
/// what the host answered.
#[derive(Default)]
struct NanWriter {
    answers: std::sync::Arc<std::sync::Mutex<Vec<Result<(), CtxError>>>>,
    good: Option<Entity>,
}

impl Plugin for NanWriter {
    fn on_init(&mut self, ctx: &mut Ctx) {
        self.good = ctx
            .spawn((Name::new("good"), Transform::from_xyz(1.0, 2.0, 3.0)))
            .ok();
    }
    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> onyx_plugin_api::Flow {
        let e = self.good.unwrap();
        let nan = Transform::from_xyz(f32::NAN, 0.0, 0.0);
        let inf = Transform::IDENTITY.with_scale(onyx_plugin_api::glam::Vec3::INFINITY);
        let mut answers = vec![
            ctx.set(e, nan),
            ctx.set(e, inf),
            ctx.spawn((Name::new("bad"), nan)).map(|_| ()),
            ctx.set_transforms(&[
                EntityTransform {
                    entity: e,
                    transform: Transform::from_xyz(9.0, 9.0, 9.0),
                },
                EntityTransform {
                    entity: e,
                    transform: nan,
                },
            ]),
        ];
        answers.push(ctx.update_transforms(|items| {
            for item in items {
                item.transform.translation.x = f32::INFINITY;
            }
        }));
        *self.answers.lock().unwrap() = answers;
        onyx_plugin_api::Flow::Continue
    }
}

#[test]
fn non_finite_transforms_are_rejected_with_an_error_and_nothing_is_written() {
    let plugin = NanWriter::default();
    let answers = plugin.answers.clone();
    let mut host = HeadlessHost::new();
    host.add_plugin("nan_writer", plugin).unwrap();
    host.step(1);
    let answers = answers.lock().unwrap().clone();
    assert_eq!(answers.len(), 5);
    for (i, answer) in answers.iter().enumerate() {
        assert!(
            matches!(answer, Err(CtxError::NonFinite { component, .. }) if component == "Transform"),
            "write #{i} answered {answer:?}"
        );
    }
    let (_, t) = host.find::<Transform>("good").unwrap();
    assert_eq!(
        t,
        Transform::from_xyz(1.0, 2.0, 3.0),
        "a rejected write changed the world"
    );
    assert!(
        host.find::<Name>("bad").is_none(),
        "a rejected spawn left an entity"
    );
    assert_eq!(
        host.plugin_status("nan_writer"),
        Some(&PluginStatus::Running)
    );
}
