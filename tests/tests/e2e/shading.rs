//! The renderer through `onyx run --headless --scene F --screenshot S`, as a user checks it:
//! a box lit from above shadows the floor under it, the sky light works without a
//! `Transform`, and the same scene 100 km from the origin screenshots the same image.

use std::path::{Path, PathBuf};
use std::process::Command;

use onyx_render::image::RgbaImage;
use onyx_tests::{onyx_binary, target_dir};

const SIZE: (u32, u32) = (160, 120);

fn repo_file(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(path)
}

fn screenshot(scene: &str, dir: &Path) -> RgbaImage {
    let png = dir.join(format!("{scene}.png"));
    let out = Command::new(onyx_binary())
        .args(["run", "--headless", "--frames", "2", "--size"])
        .arg(format!("{}x{}", SIZE.0, SIZE.1))
        .arg("--scene")
        .arg(repo_file(&format!("assets/scenes/{scene}.ron")))
        .arg("--screenshot")
        .arg(&png)
        .env("ONYX_PLUGIN_PATH", target_dir())
        .env("RUST_LOG", "warn")
        .output()
        .expect("onyx runs");
    assert!(
        out.status.success(),
        "onyx failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    match onyx_render::image::open(&png) {
        Ok(image) => image.to_rgba8(),
        Err(error) => panic!("no screenshot {}: {error}", png.display()),
    }
}

/// Mean luminance (0..255) of a 5 × 5 block centred on (x, y).
fn brightness(image: &RgbaImage, x: u32, y: u32) -> f32 {
    let mut sum = 0.0;
    for py in y - 2..=y + 2 {
        for px in x - 2..=x + 2 {
            let [r, g, b, _] = image.get_pixel(px, py).0;
            sum += 0.2126 * f32::from(r) + 0.7152 * f32::from(g) + 0.0722 * f32::from(b);
        }
    }
    sum / 25.0
}

/// The pixel of a point on the floor seen by the scene's camera (at (0, 3, 6), pitched down
/// 30°, 0.9 rad vertical field of view).
fn floor_pixel(x: f32, z: f32) -> (u32, u32) {
    let eye = [0.0f32, 3.0, 6.0];
    let pitch = 30f32.to_radians();
    let d = [x - eye[0], -eye[1], z - eye[2]];
    // Camera space: rotate by +pitch about X (undo the camera's -30° tilt).
    let (s, c) = pitch.sin_cos();
    let cy = d[1] * c - d[2] * s;
    let cz = d[1] * s + d[2] * c;
    let f = 1.0 / (0.45f32).tan();
    let aspect = SIZE.0 as f32 / SIZE.1 as f32;
    let ndc_x = d[0] * f / aspect / -cz;
    let ndc_y = cy * f / -cz;
    let px = (ndc_x * 0.5 + 0.5) * SIZE.0 as f32;
    let py = (0.5 - ndc_y * 0.5) * SIZE.1 as f32;
    (px as u32, py as u32)
}

#[test]
fn a_box_lit_from_above_shadows_the_floor_and_the_sky_light_needs_no_transform() {
    let dir = tempfile::tempdir().expect("temp dir");
    let image = screenshot("shadow_box", dir.path());
    onyx_tests::assert_golden("shadow_box", &image);
    let (ux, uy) = floor_pixel(0.0, 0.0);
    let (ax, ay) = floor_pixel(-3.0, 0.0);
    let (under, beside) = (brightness(&image, ux, uy), brightness(&image, ax, ay));
    assert!(
        under < 0.6 * beside,
        "the floor under the box ({under:.1}) is not in its shadow (beside it {beside:.1})"
    );
    // The shadowed floor is lit by the sky alone: not black.
    assert!(
        under > 15.0,
        "the shadowed floor is black ({under:.1}): the Transform-less sky light was ignored"
    );
}

#[test]
fn a_scene_100_km_from_the_origin_screenshots_like_at_the_origin() {
    let dir = tempfile::tempdir().expect("temp dir");
    let near = screenshot("shadow_box", dir.path());
    let far = screenshot("far_origin", dir.path());
    // What differs (0.44 % at 160 × 120) is the editor grid's world axes: the blue Z axis
    // through the middle of the origin's image and the red X axis across its shadow, which
    // 100 km out are not there to draw. Shading, shadows and grid lines match.
    let differing = near
        .pixels()
        .zip(far.pixels())
        .filter(|(a, b)| a.0.iter().zip(b.0.iter()).any(|(x, y)| x.abs_diff(*y) > 12))
        .count();
    let share = differing as f64 / f64::from(SIZE.0 * SIZE.1);
    eprintln!("100 km out: {:.3} % of pixels differ", share * 100.0);
    assert!(
        share < 0.005,
        "{:.3} % of pixels differ between the scene at the origin and 100 km out",
        share * 100.0
    );
}
