//! Shared helpers of the integration tests: pin the CPU adapter, create renderers, paths to
//! assets and fixtures, and golden-image comparison.

#![allow(dead_code)] // each test binary uses a different subset

mod lavapipe_env;

use std::path::PathBuf;
use std::sync::Once;

use image::RgbaImage;
use onyx_render::{OffscreenTarget, RenderScene, RenderSettings, Renderer};

/// A channel differing by more than this (0..255) marks the pixel as different.
pub const PIXEL_TOLERANCE: u8 = 12;
/// Largest share of different pixels a golden comparison accepts (0.5 %).
pub const MAX_DIFF_SHARE: f64 = 0.005;

/// Pins wgpu to lavapipe (Vulkan, CPU) unless the caller already chose an adapter, and gives
/// Mesa a runtime dir. Runs once per test binary, before any test touches wgpu.
pub fn setup() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        lavapipe_env::pin_lavapipe();
        let _ = tracing_subscriber::fmt()
            .with_env_filter(tracing_subscriber::EnvFilter::from_default_env())
            .with_test_writer()
            .try_init();
    });
}

/// A renderer with deterministic settings (MSAA off).
pub fn renderer() -> Renderer {
    renderer_with(RenderSettings::deterministic())
}

pub fn renderer_with(settings: RenderSettings) -> Renderer {
    setup();
    match Renderer::new_headless(settings) {
        Ok(renderer) => renderer,
        Err(error) => {
            panic!("no renderer on this machine (is mesa-vulkan-drivers installed?): {error}")
        }
    }
}

/// The workspace `assets/` folder.
pub fn assets() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets")
}

/// The workspace `shaders/` folder.
pub fn shaders() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shaders")
}

/// Real-world fixtures shared between projects.
pub fn fixtures() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/fixtures")
}

/// `relative` under the shared fixtures (`gltf`, `obj/x.obj`), or `None` when it is absent
/// (the test then skips, saying so).
pub fn fixture(relative: &str) -> Option<PathBuf> {
    let path = fixtures().join(relative);
    if path.exists() {
        Some(path)
    } else {
        eprintln!(
            "skipped: {} is absent (../shared/fixtures not beside the checkout)",
            path.display()
        );
        None
    }
}

/// Renders `scene` offscreen and reads it back.
pub fn render_image(
    renderer: &mut Renderer,
    width: u32,
    height: u32,
    scene: &RenderScene<'_>,
) -> RgbaImage {
    let mut target = OffscreenTarget::new(renderer.gpu(), width, height);
    if let Err(error) = renderer.render(&mut target, scene) {
        panic!("render failed: {error}");
    }
    let events = renderer.drain_events();
    assert!(events.is_empty(), "the frame raised GPU events: {events:?}");
    match target.read_image(renderer.gpu()) {
        Ok(image) => image,
        Err(error) => panic!("readback failed: {error}"),
    }
}

/// Compares `actual` with `tests/golden/<name>.png`.
///
/// With `ONYX_UPDATE_GOLDEN=1` the reference is (re)written instead. On failure the actual
/// image and a diff (differing pixels red over a dimmed copy) are written to
/// `$CARGO_TARGET_TMPDIR/golden/<name>-actual.png` and `<name>-diff.png`.
pub fn check_golden(name: &str, actual: &RgbaImage) {
    let reference_path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(format!("{name}.png"));
    if std::env::var("ONYX_UPDATE_GOLDEN").is_ok_and(|v| v == "1") {
        if let Err(error) = actual.save(&reference_path) {
            panic!("could not write {}: {error}", reference_path.display());
        }
        eprintln!("golden image written: {}", reference_path.display());
        return;
    }
    let reference = match image::open(&reference_path) {
        Ok(image) => image.to_rgba8(),
        Err(error) => panic!(
            "no reference image {} ({error}); run with ONYX_UPDATE_GOLDEN=1 to create it, then look at it",
            reference_path.display()
        ),
    };
    let out_dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("golden");
    if reference.dimensions() != actual.dimensions() {
        save_failure(&out_dir, name, actual, None);
        panic!(
            "{name}: size {:?}, reference {:?}",
            actual.dimensions(),
            reference.dimensions()
        );
    }
    let mut diff = RgbaImage::new(actual.width(), actual.height());
    let mut differing = 0usize;
    let mut worst = 0u8;
    for ((a, r), d) in actual
        .pixels()
        .zip(reference.pixels())
        .zip(diff.pixels_mut())
    {
        let delta =
            a.0.iter()
                .zip(r.0.iter())
                .map(|(x, y)| x.abs_diff(*y))
                .max()
                .unwrap_or(0);
        worst = worst.max(delta);
        if delta > PIXEL_TOLERANCE {
            differing += 1;
            *d = image::Rgba([255, 0, 0, 255]);
        } else {
            let grey = (u16::from(a.0[0]) + u16::from(a.0[1]) + u16::from(a.0[2])) / 12;
            *d = image::Rgba([grey as u8; 4]);
            d.0[3] = 255;
        }
    }
    let share = differing as f64 / f64::from(actual.width() * actual.height());
    if share > MAX_DIFF_SHARE {
        save_failure(&out_dir, name, actual, Some(&diff));
        panic!(
            "{name}: {differing} pixels ({:.3} %) differ by more than {PIXEL_TOLERANCE}/255 (allowed {:.3} %, worst \
             channel difference {worst}); actual and diff written to {}",
            share * 100.0,
            MAX_DIFF_SHARE * 100.0,
            out_dir.display()
        );
    }
}

fn save_failure(dir: &std::path::Path, name: &str, actual: &RgbaImage, diff: Option<&RgbaImage>) {
    let _ = std::fs::create_dir_all(dir);
    let _ = actual.save(dir.join(format!("{name}-actual.png")));
    if let Some(diff) = diff {
        let _ = diff.save(dir.join(format!("{name}-diff.png")));
    }
}

/// Share of pixels whose channels differ by more than [`PIXEL_TOLERANCE`] between two
/// images of the same size.
pub fn differing_share(a: &RgbaImage, b: &RgbaImage) -> f64 {
    assert_eq!(a.dimensions(), b.dimensions(), "images of different sizes");
    let differing = a
        .pixels()
        .zip(b.pixels())
        .filter(|(p, q)| {
            p.0.iter()
                .zip(q.0.iter())
                .any(|(x, y)| x.abs_diff(*y) > PIXEL_TOLERANCE)
        })
        .count();
    differing as f64 / f64::from(a.width() * a.height())
}
