//! Support for the end-to-end tests: where the built plugin libraries and the `onyx` binary
//! are, and small recording plugins.
//!
//! The plugins are built as real cdylibs by `cargo build --workspace` (the README's test
//! command runs it before `cargo test`), into the same target directory as the tests: a
//! nested `cargo build` inside a test would block on cargo's target-directory lock.

pub mod cli;
pub mod fuzz;
pub mod vase;

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use onyx_plugin_api::{AttachInfo, Ctx, Event, Flow, Plugin, PluginError};

/// The target directory of this build (`target/debug`), from the running executable's path
/// (a test in `target/debug/deps`, or a binary like `onyx-fuzz` in `target/debug`).
pub fn target_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test knows its own path");
    let dir = exe
        .parent()
        .expect("executables live in target/<profile> or target/<profile>/deps");
    if dir.file_name().is_some_and(|n| n == "deps") {
        dir.parent().expect("deps has a parent").to_path_buf()
    } else {
        dir.to_path_buf()
    }
}

/// The Khronos glTF samples in `../shared/fixtures/gltf/` beside the checkout, or `None`,
/// saying so, when they are absent (the test then skips).
pub fn gltf_samples() -> Option<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/fixtures/gltf");
    if dir.is_dir() {
        Some(dir)
    } else {
        eprintln!(
            "skipped: {} is absent (../shared/fixtures not beside the checkout)",
            dir.display()
        );
        None
    }
}

/// The built library of workspace crate `crate_name` (`hello`, `fixture-faulty`, …).
///
/// Panics with the command to run when it has not been built.
pub fn plugin_library(crate_name: &str) -> PathBuf {
    let path = target_dir().join(onyx_runtime::plugins::plugin_search::library_file_name(
        crate_name,
    ));
    assert!(
        path.is_file(),
        "`{}` is missing: build the plugins first with `cargo build --workspace` \
         (the README's test command does)",
        path.display()
    );
    path
}

/// The `onyx` binary of this build.
pub fn onyx_binary() -> PathBuf {
    let path = target_dir().join(format!("onyx{}", std::env::consts::EXE_SUFFIX));
    assert!(
        path.is_file(),
        "`{}` is missing: run `cargo build --workspace` first",
        path.display()
    );
    path
}

/// `onyx` in a real window: the binary run under `xvfb-run` on a 1280×720 screen, finding
/// plugins in this build's target directory, with no Wayland display to prefer. Add `run …`.
pub fn onyx_in_xvfb() -> std::process::Command {
    let xvfb_run = std::path::Path::new("/usr/bin/xvfb-run");
    assert!(
        xvfb_run.exists(),
        "xvfb-run is missing: install the packages listed in the README (the test command does)"
    );
    let mut command = std::process::Command::new(xvfb_run);
    command
        .args(["-a", "-s", "-screen 0 1280x720x24"])
        .arg(onyx_binary())
        .env("ONYX_PLUGIN_PATH", target_dir())
        .env_remove("WAYLAND_DISPLAY");
    command
}

/// A shared, ordered log of what recording plugins saw.
pub type Journal = Arc<Mutex<Vec<String>>>;

/// A new empty journal.
pub fn journal() -> Journal {
    Arc::new(Mutex::new(Vec::new()))
}

/// The entries of `journal` so far.
pub fn entries(journal: &Journal) -> Vec<String> {
    journal.lock().expect("journal lock").clone()
}

/// An in-process plugin that writes `"<tag>.<stage>"` into a journal for every call
/// (`"<tag>.on_event:<event>"` for events), and quits after `quit_after` updates if set.
pub struct Recorder {
    /// Prefix of this recorder's entries.
    pub tag: &'static str,
    /// Where entries go.
    pub journal: Journal,
    /// Return `Flow::Quit` from this `on_update` call on (1-based).
    pub quit_after: Option<u64>,
    updates: u64,
}

impl Recorder {
    /// A recorder tagged `tag` writing to `journal`.
    pub fn new(tag: &'static str, journal: &Journal) -> Self {
        Self {
            tag,
            journal: journal.clone(),
            quit_after: None,
            updates: 0,
        }
    }

    fn note(&self, what: impl AsRef<str>) {
        self.journal
            .lock()
            .expect("journal lock")
            .push(format!("{}.{}", self.tag, what.as_ref()));
    }
}

impl Plugin for Recorder {
    fn on_attach(&mut self, _: &mut Ctx, info: &AttachInfo) -> Result<(), PluginError> {
        self.note(if info.reload {
            "on_attach(reload)"
        } else {
            "on_attach"
        });
        Ok(())
    }
    fn on_init(&mut self, _: &mut Ctx) {
        self.note("on_init");
    }
    fn on_event(&mut self, _: &mut Ctx, event: &Event) {
        self.note(format!("on_event:{event:?}"));
    }
    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        self.note(format!("on_fixed_update#{}", ctx.time().ticks));
    }
    fn on_update(&mut self, _: &mut Ctx, _dt: f32) -> Flow {
        self.updates += 1;
        self.note("on_update");
        match self.quit_after {
            Some(n) if self.updates >= n => Flow::Quit,
            _ => Flow::Continue,
        }
    }
    fn on_render(&mut self, _: &mut Ctx) {
        self.note("on_render");
    }
    fn draw_gui(&mut self, _: &mut Ctx, _: &mut onyx_plugin_api::egui::Ui) {
        self.note("draw_gui");
    }
    fn on_resize(&mut self, _: &mut Ctx, w: u32, h: u32) {
        self.note(format!("on_resize:{w}x{h}"));
    }
    fn on_detach(&mut self, _: &mut Ctx) {
        self.note("on_detach");
    }
}

/// A channel difference above this (out of 255) makes a pixel count as different.
pub const GOLDEN_CHANNEL_TOLERANCE: u8 = 12;
/// Most pixels (share of the image) that may differ from the reference.
pub const GOLDEN_MAX_DIFFERING: f64 = 0.005;

/// Compares `image` with the reference `tests/golden/<name>.png`, under
/// [`GOLDEN_CHANNEL_TOLERANCE`] and [`GOLDEN_MAX_DIFFERING`]. On failure writes
/// `<name>-actual.png` and `<name>-diff.png` into `target/golden-failures/` and panics with
/// the figures. `ONYX_UPDATE_GOLDEN=1` writes the reference instead (look at it before
/// committing it).
pub fn assert_golden(name: &str, image: &onyx_render::image::RgbaImage) {
    use onyx_render::image::{Rgba, RgbaImage};
    let reference = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("golden")
        .join(format!("{name}.png"));
    if std::env::var_os("ONYX_UPDATE_GOLDEN").is_some() {
        std::fs::create_dir_all(reference.parent().expect("has a parent")).expect("golden dir");
        image.save(&reference).expect("write golden");
        eprintln!("updated {}", reference.display());
        return;
    }
    let expected = onyx_render::image::open(&reference)
        .unwrap_or_else(|e| {
            panic!(
                "no reference {}: {e} (ONYX_UPDATE_GOLDEN=1 makes it)",
                reference.display()
            )
        })
        .to_rgba8();
    assert_eq!(
        expected.dimensions(),
        image.dimensions(),
        "{name}: size differs"
    );
    let mut diff = RgbaImage::new(image.width(), image.height());
    let mut differing = 0u64;
    for (x, y, actual) in image.enumerate_pixels() {
        let wanted = expected.get_pixel(x, y);
        let off = actual
            .0
            .iter()
            .zip(wanted.0)
            .any(|(a, b)| a.abs_diff(b) > GOLDEN_CHANNEL_TOLERANCE);
        if off {
            differing += 1;
        }
        diff.put_pixel(
            x,
            y,
            if off {
                Rgba([255, 0, 255, 255])
            } else {
                Rgba([actual.0[0] / 3, actual.0[1] / 3, actual.0[2] / 3, 255])
            },
        );
    }
    let share = differing as f64 / f64::from(image.width() * image.height());
    if share > GOLDEN_MAX_DIFFERING {
        let out = target_dir().join("golden-failures");
        std::fs::create_dir_all(&out).expect("failure dir");
        let actual_path = out.join(format!("{name}-actual.png"));
        let diff_path = out.join(format!("{name}-diff.png"));
        image.save(&actual_path).expect("write actual");
        diff.save(&diff_path).expect("write diff");
        panic!(
            "{name}: {:.2} % of pixels differ by more than {GOLDEN_CHANNEL_TOLERANCE}/255 (allowed {:.2} %); \
             see {} and {}",
            share * 100.0,
            GOLDEN_MAX_DIFFERING * 100.0,
            actual_path.display(),
            diff_path.display()
        );
    }
}
