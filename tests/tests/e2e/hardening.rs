//! What a plugin or a file does must not take the host down silently or lose a user's work:
//! panics in a plugin's `Drop` and in its state methods, a flood of events, impossible
//! input, zero quaternions, saves over what is not a plain file, screenshots the GPU cannot
//! draw, and the loader's housekeeping. Real cdylibs (`tests/fixtures/faulty`) and the
//! `onyx` binary.

use std::path::Path;
use std::process::Command;

use onyx_plugin_api::glam::Quat;
use onyx_plugin_api::{CtxError, InputEvent, Name, Plugin, Transform};
use onyx_runtime::plugins::Stage;
use onyx_runtime::{HeadlessHost, HostConfig, PluginLoadError, PluginStatus};
use onyx_tests::cli::{assert_exit, onyx, onyx_lines};
use onyx_tests::{onyx_binary, plugin_library, target_dir};

const FAULTY: &str = "fixture_faulty";

fn faulty_host(settings: &[(&str, &str)]) -> HeadlessHost {
    let mut config = HostConfig::default();
    for (key, value) in settings {
        config = config.setting(FAULTY, *key, *value);
    }
    let mut host = HeadlessHost::with_config(config);
    host.load_plugin_file(&plugin_library("fixture-faulty"))
        .expect("the fixture loads");
    host.load_plugin_file(&plugin_library("hello"))
        .expect("hello loads");
    host.step(2);
    host
}

#[test]
fn a_panic_in_a_plugins_drop_is_caught_and_named_and_the_host_goes_on() {
    // Unloaded mid-run.
    let mut host = faulty_host(&[("panic_in", "drop")]);
    assert!(host.host_mut().unload_plugin(FAULTY));
    let incidents = host.host().incidents().to_vec();
    assert_eq!(incidents.len(), 1, "{incidents:?}");
    assert!(
        incidents[0].contains(FAULTY)
            && incidents[0].contains("drop")
            && incidents[0].contains("fixture_faulty panics in drop as configured"),
        "{}",
        incidents[0]
    );
    assert_eq!(host.step(3), 3, "the host goes on");
    assert_eq!(host.plugin_status("hello"), Some(&PluginStatus::Running));

    // Replaced by a new build: the old build's drop panics, the new build runs.
    let mut host = faulty_host(&[("panic_in", "drop")]);
    host.host_mut()
        .reload_plugin(FAULTY)
        .expect("the reload itself succeeds");
    assert_eq!(host.plugin_status(FAULTY), Some(&PluginStatus::Running));
    assert!(host.host().incidents()[0].contains("previous build"));
    host.step(2);

    // At the end of a run: exit 1, one `onyx:` line naming the plugin, the dump written.
    let dir = tempfile::tempdir().unwrap();
    let dump = dir.path().join("dump.json");
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "3",
        "--plugin",
        FAULTY,
        "--set",
        "fixture_faulty.panic_in=drop",
        "--dump-state",
        dump.to_str().unwrap(),
    ]);
    assert_exit(&out, 1);
    let lines = onyx_lines(&out);
    assert!(
        lines
            .iter()
            .any(|l| l.contains("plugin `fixture_faulty` faulted in drop")),
        "{lines:?}"
    );
    assert!(dump.is_file(), "the dump is still written");
}

#[test]
fn a_panic_in_save_state_or_load_state_faults_the_plugin_keeps_the_old_build_and_exits_1() {
    for stage in [Stage::SaveState, Stage::LoadState] {
        let mut host = faulty_host(&[("panic_in", stage.as_str())]);
        let error = host.host_mut().reload_plugin(FAULTY).unwrap_err();
        assert!(error.to_string().contains(stage.as_str()), "{error}");
        match host.plugin_status(FAULTY) {
            Some(PluginStatus::Faulted { stage: s, message }) => {
                assert_eq!(*s, stage);
                assert!(message.contains("as configured"), "{message}");
            }
            other => panic!("{stage}: expected a fault, got {other:?}"),
        }
        assert_eq!(
            host.host().plugin(FAULTY).map(|p| p.reloads()),
            Some(0),
            "the old build stays in place"
        );
        assert_eq!(host.step(3), 3);
    }
    // Reached through `onyx run`: the plugin asks for its own reload.
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "5",
        "--plugin",
        FAULTY,
        "--set",
        "fixture_faulty.panic_in=save_state",
        "--set",
        "fixture_faulty.reload_self_at=2",
    ]);
    assert_exit(&out, 1);
    let lines = onyx_lines(&out);
    assert!(
        lines.iter().any(|l| l.contains("faulted in save_state")),
        "{lines:?}"
    );
}

#[test]
fn a_plugin_that_floods_the_event_queue_is_faulted_and_the_queue_stays_bounded() {
    let mut host = faulty_host(&[("flood", "1")]);
    host.step(30);
    match host.plugin_status(FAULTY) {
        Some(PluginStatus::Faulted { message, .. }) => assert!(
            message.contains("custom events in one frame")
                && message.contains("max_events_per_frame"),
            "{message}"
        ),
        other => panic!("the flooding plugin should be faulted, got {other:?}"),
    }
    assert_eq!(host.plugin_status("hello"), Some(&PluginStatus::Running));
    assert_eq!(host.step(5), 5, "the host goes on");
}

#[test]
fn a_zero_quaternion_is_refused_like_nan_from_a_plugin_and_from_a_scene_file() {
    struct Zero(std::sync::Arc<std::sync::Mutex<Option<Result<(), CtxError>>>>);
    impl Plugin for Zero {
        fn on_init(&mut self, ctx: &mut onyx_plugin_api::Ctx) {
            let zero = Transform::IDENTITY.with_rotation(Quat::from_xyzw(0.0, 0.0, 0.0, 0.0));
            let answer = ctx.spawn((Name::new("zero"), zero)).map(|_| ());
            *self.0.lock().unwrap() = Some(answer);
        }
    }
    let answer = std::sync::Arc::new(std::sync::Mutex::new(None));
    let mut host = HeadlessHost::new();
    host.add_plugin("zero", Zero(answer.clone())).unwrap();
    host.step(1);
    let answer = answer.lock().unwrap().clone().expect("on_init ran");
    match answer {
        Err(CtxError::InvalidValue {
            component, field, ..
        }) => {
            assert_eq!(
                (component.as_str(), field.as_str()),
                ("Transform", "rotation")
            );
        }
        other => panic!("expected the rotation refused, got {other:?}"),
    }
    assert!(host.find::<Name>("zero").is_none());

    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("zero.ron");
    std::fs::write(
        &path,
        "(version: 2, entities: [(name: Some(\"spinner\"), transform: Some((rotation: (0.0, 0.0, 0.0, 0.0))))])",
    )
    .unwrap();
    let error = HeadlessHost::new()
        .load_scene(&path)
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("entity #0 (\"spinner\")") && error.contains("`rotation`"),
        "{error}"
    );
}

#[test]
fn saving_follows_a_symlink_keeps_a_files_mode_and_refuses_read_only_files_and_devices() {
    use std::os::unix::fs::PermissionsExt as _;
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real.ron");
    std::fs::write(&real, "old").unwrap();
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o640)).unwrap();
    let link = dir.path().join("link.ron");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "1",
        "--save-scene",
        link.to_str().unwrap(),
    ]);
    assert_exit(&out, 0);
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::read_to_string(&real).unwrap().contains("version"));
    assert_eq!(
        std::fs::metadata(&real).unwrap().permissions().mode() & 0o777,
        0o640
    );

    let locked = dir.path().join("locked.json");
    std::fs::write(&locked, "keep").unwrap();
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o444)).unwrap();
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "1",
        "--dump-state",
        locked.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        onyx_lines(&out).iter().any(|l| l.contains("read-only")),
        "{:?}",
        onyx_lines(&out)
    );
    assert_eq!(std::fs::read_to_string(&locked).unwrap(), "keep");

    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "1",
        "--save-scene",
        "/dev/null",
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        onyx_lines(&out).iter().any(|l| l.contains("a device")),
        "{:?}",
        onyx_lines(&out)
    );
    assert!(
        std::fs::metadata("/dev/null").unwrap().permissions().mode() & 0o666 == 0o666,
        "/dev/null is still the device"
    );
}

#[test]
fn a_screenshot_larger_than_the_gpu_can_draw_is_refused_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("huge.png");
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "1",
        "--size",
        "40000x40000",
        "--screenshot",
        png.to_str().unwrap(),
    ]);
    assert_exit(&out, 2);
    let lines = onyx_lines(&out);
    assert!(
        lines.iter().any(|l| l.contains("larger than this GPU")),
        "{lines:?}"
    );
    assert!(!png.exists(), "no empty image was written");
}

#[test]
fn a_scroll_of_minus_f32_max_does_not_reach_a_plugins_ui() {
    let dir = tempfile::tempdir().unwrap();
    let config = HostConfig::default().setting(
        "editor",
        "layout",
        dir.path().join("layout.json").display().to_string(),
    );
    let mut host = HeadlessHost::with_config(config);
    host.load_plugin_file(&plugin_library("editor")).unwrap();
    host.step(3);
    host.pointer_move(onyx_plugin_api::egui::pos2(600.0, 300.0));
    for event in [
        InputEvent::Scroll {
            dx: 0.0,
            dy: -f32::MAX,
        },
        InputEvent::Scroll {
            dx: f32::NAN,
            dy: 1.0,
        },
        InputEvent::CursorMoved {
            x: f32::INFINITY,
            y: 0.0,
        },
        InputEvent::MouseMotion {
            dx: f32::MAX,
            dy: -f32::MAX,
        },
    ] {
        host.inject(event);
        host.step(2);
    }
    assert_eq!(host.plugin_status("editor"), Some(&PluginStatus::Running));
}

#[test]
fn a_directory_given_as_a_plugin_is_named_as_one_and_copies_are_not_left_behind() {
    let dir = tempfile::tempdir().unwrap();
    let mut host = HeadlessHost::new();
    let error = host.load_plugin_file(dir.path()).unwrap_err();
    assert!(
        matches!(error, PluginLoadError::NotAFile { .. }),
        "{error:?}"
    );
    assert!(error.to_string().contains("is a directory"), "{error}");

    // A copy folder of a process that is gone is removed by the next process that loads, and
    // that process leaves none of its own.
    let stale = std::env::temp_dir().join(format!("onyx-plugins-{}", u32::MAX - 7));
    std::fs::create_dir_all(&stale).unwrap();
    std::fs::write(stale.join("0-libold.so"), b"old").unwrap();
    let child = Command::new(onyx_binary())
        .args(["run", "--headless", "--frames", "1", "--plugin", "hello"])
        .env("ONYX_PLUGIN_PATH", target_dir())
        .env("RUST_LOG", "warn")
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("onyx runs");
    let pid = child.id();
    let out = child.wait_with_output().unwrap();
    assert_exit(&out, 0);
    assert!(
        !Path::new(&stale).exists(),
        "the stale folder is still there"
    );
    let own = std::env::temp_dir().join(format!("onyx-plugins-{pid}"));
    assert!(!own.exists(), "{} is left behind", own.display());
}

#[test]
fn the_library_check_passes_every_real_library_it_is_shown() {
    use onyx_runtime::plugins::library_check::check_library;
    // Every plugin cdylib of this build, and the system's shared libraries (built by other
    // toolchains and linkers: the check must not refuse what the loader handles).
    let mut files: Vec<std::path::PathBuf> = std::fs::read_dir(target_dir())
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| {
            p.extension()
                .is_some_and(|e| e == std::env::consts::DLL_EXTENSION)
        })
        .collect();
    for dir in [
        "/usr/lib/x86_64-linux-gnu",
        "/usr/lib/aarch64-linux-gnu",
        "/lib64",
    ] {
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        files.extend(
            entries
                .flatten()
                .map(|e| e.path())
                .filter(|p| {
                    p.file_name()
                        .is_some_and(|n| n.to_string_lossy().contains(".so"))
                })
                .filter(|p| std::fs::metadata(p).is_ok_and(|m| m.is_file() && m.len() < 64 << 20)),
        );
    }
    assert!(files.len() > 5, "{files:?}");
    let mut refused = Vec::new();
    for file in &files {
        let bytes = std::fs::read(file).unwrap();
        if let Err(problem) = check_library(&bytes) {
            refused.push(format!("{}: {problem}", file.display()));
        }
    }
    eprintln!("{} libraries checked", files.len());
    assert!(
        refused.is_empty(),
        "{} of {} refused:\n{}",
        refused.len(),
        files.len(),
        refused.join("\n")
    );
}

/// A plugin library with one field changed the way the fuzzer found crashes the system loader
/// (each of these ended the process with a segfault or an `ld.so` assertion before the host
/// checked libraries): the host refuses each with exit 2 and one sentence, and nothing crashes.
#[test]
fn damaged_libraries_are_refused_before_the_system_loader_sees_them() {
    use object::elf;
    use object::read::elf::{Dyn as _, FileHeader as _, ProgramHeader as _};
    use object::Endianness;

    let original = std::fs::read(plugin_library("fixture-native")).unwrap();
    let header = elf::FileHeader64::<Endianness>::parse(&*original).unwrap();
    let endian = header.endian().unwrap();
    let headers = header.program_headers(endian, &*original).unwrap();
    let phoff = header.e_phoff(endian) as usize;
    let phdr_at = |i: usize| phoff + i * 56;
    let loads: Vec<(u64, u64, u64)> = headers
        .iter()
        .filter(|p| p.p_type(endian) == elf::PT_LOAD)
        .map(|p| (p.p_vaddr(endian), p.p_offset(endian), p.p_filesz(endian)))
        .collect();
    let offset_of = |addr: u64| {
        loads
            .iter()
            .find(|(v, _, n)| *v <= addr && addr < v + n)
            .map(|(v, o, _)| (o + (addr - v)) as usize)
            .expect("address in a segment")
    };
    let dynamic_index = headers
        .iter()
        .position(|p| p.p_type(endian) == elf::PT_DYNAMIC)
        .unwrap();
    let dynamic_at = headers[dynamic_index].p_offset(endian) as usize;
    let entries = headers[dynamic_index]
        .dynamic(endian, &*original)
        .unwrap()
        .unwrap();
    let entry = |tag: u32| {
        let i = entries
            .iter()
            .position(|d| d.d_tag(endian) == u64::from(tag))
            .unwrap_or_else(|| panic!("the fixture has dynamic tag {tag:#x}"));
        (dynamic_at + i * 16, entries[i].d_val(endian))
    };
    let put_u64 = |bytes: &mut Vec<u8>, at: usize, value: u64| {
        bytes[at..at + 8].copy_from_slice(&value.to_le_bytes())
    };
    let get_u64 =
        |bytes: &[u8], at: usize| u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap());
    let first_load = headers
        .iter()
        .position(|p| p.p_type(endian) == elf::PT_LOAD)
        .unwrap();
    let second_load = headers
        .iter()
        .enumerate()
        .filter(|(_, p)| p.p_type(endian) == elf::PT_LOAD)
        .nth(1)
        .unwrap()
        .0;

    type Patch = Box<dyn Fn(&mut Vec<u8>)>;
    let patches: Vec<(&str, Patch)> = vec![
        ("symbol versions lost", {
            let (at, _) = entry(elf::DT_VERSYM);
            Box::new(move |b| put_u64(b, at, 0x6f27_fff0))
        }),
        ("relocation entry size lost", {
            let (at, _) = entry(elf::DT_RELAENT);
            Box::new(move |b| put_u64(b, at, 0x4000_0009))
        }),
        ("relocation table lost", {
            let (at, _) = entry(elf::DT_RELA);
            Box::new(move |b| put_u64(b, at, 0x807))
        }),
        ("initialiser array overrun", {
            let (at, size) = entry(elf::DT_INIT_ARRAYSZ);
            Box::new(move |b| put_u64(b, at + 8, size + 0x8000))
        }),
        ("needed-versions count", {
            let (at, count) = entry(elf::DT_VERNEEDNUM);
            Box::new(move |b| put_u64(b, at + 8, count + (1 << 40)))
        }),
        ("dynamic section moved", {
            let at = phdr_at(dynamic_index) + 16;
            Box::new(move |b| {
                let v = get_u64(b, at);
                put_u64(b, at, v + 6)
            })
        }),
        ("segment unreadable", {
            let at = phdr_at(first_load) + 4;
            Box::new(move |b| b[at..at + 4].copy_from_slice(&0u32.to_le_bytes()))
        }),
        ("segment maps the wrong file bytes", {
            let at = phdr_at(second_load) + 8;
            Box::new(move |b| {
                let v = get_u64(b, at);
                put_u64(b, at, v + 0x1_0000)
            })
        }),
        ("PLT slot moved", {
            let (_, jmprel) = entry(elf::DT_JMPREL);
            let at = offset_of(jmprel);
            Box::new(move |b| {
                let v = get_u64(b, at);
                put_u64(b, at, v + 8)
            })
        }),
        ("pointer far outside", {
            let (_, rela) = entry(elf::DT_RELA);
            let at = offset_of(rela) + 16;
            Box::new(move |b| {
                let v = get_u64(b, at);
                put_u64(b, at, v + 0x7c00_0000_0000)
            })
        }),
        ("needed versions from an unknown library", {
            let (_, verneed) = entry(elf::DT_VERNEED);
            let at = offset_of(verneed) + 4;
            Box::new(move |b| {
                let v = u32::from_le_bytes(b[at..at + 4].try_into().unwrap());
                b[at..at + 4].copy_from_slice(&(v + 1).to_le_bytes())
            })
        }),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (what, patch) in &patches {
        let mut bytes = original.clone();
        patch(&mut bytes);
        assert_ne!(bytes, original, "{what}: the patch changed something");
        let path = dir.path().join("libdamaged.so");
        std::fs::write(&path, &bytes).unwrap();
        let out = onyx(&[
            "run",
            "--headless",
            "--frames",
            "1",
            "--plugin",
            path.to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{what}: {err}");
        let lines = onyx_lines(&out);
        assert_eq!(lines.len(), 1, "{what}: {err}");
        assert!(lines[0].contains("is damaged"), "{what}: {}", lines[0]);
        assert!(!err.contains("native crash"), "{what}: {err}");
    }
}

/// Keeps the window open while it has "unsaved work", then quits when told it was saved.
#[derive(Default)]
struct Careful {
    unsaved: bool,
}

impl Plugin for Careful {
    fn on_event(&mut self, ctx: &mut onyx_plugin_api::Ctx, event: &onyx_plugin_api::Event) {
        use onyx_plugin_api::{Event, WindowEvent};
        if matches!(event, Event::Window(WindowEvent::CloseRequested)) && self.unsaved {
            ctx.prevent_close();
            // "Saved": the next close goes through.
            self.unsaved = false;
        }
    }
}

#[test]
fn a_plugin_with_unsaved_work_keeps_the_window_open_to_ask() {
    use onyx_plugin_api::WindowEvent;
    let mut host = HeadlessHost::new();
    host.host_mut()
        .add_plugin("careful", Careful { unsaved: true })
        .unwrap();
    host.step(1);
    host.host_mut().push_event(WindowEvent::CloseRequested);
    assert!(!host.host_mut().frame(1.0 / 60.0).quit, "kept open to ask");
    host.host_mut().push_event(WindowEvent::CloseRequested);
    assert!(
        host.host_mut().frame(1.0 / 60.0).quit,
        "nothing left to ask: it closes"
    );

    // Without such a plugin a close request ends the run after its frame, as before.
    let mut host = HeadlessHost::new();
    host.step(1);
    host.host_mut().push_event(WindowEvent::CloseRequested);
    assert!(host.host_mut().frame(1.0 / 60.0).quit);
}
