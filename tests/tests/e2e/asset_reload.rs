//! Asset hot reload: a texture or model file changed under a running host is drawn anew; a
//! broken replacement keeps the last good version and raises a graphics event naming it.

use std::path::Path;
use std::time::{Duration, Instant};

use onyx_render::image::{Rgba, RgbaImage};
use onyx_runtime::HeadlessHost;

use super::asset_loading::{centre, is_green, write_png, TexturedCube};

fn is_red(p: [u8; 4]) -> bool {
    p[0] > 120 && p[0] > p[1] + 60 && p[0] > p[2] + 60
}

/// Screenshots until `wanted` holds of the centre pixel (at most 10 s), returning the last.
fn wait_for(host: &mut HeadlessHost, wanted: impl Fn([u8; 4]) -> bool) -> [u8; 4] {
    let deadline = Instant::now() + Duration::from_secs(10);
    loop {
        host.step(1);
        let pixel = centre(&host.screenshot(64, 64).unwrap());
        if wanted(pixel) || Instant::now() > deadline {
            return pixel;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Events naming `file` that say it failed.
fn failures(journal: &onyx_tests::Journal, file: &Path) -> usize {
    let name = file.file_name().unwrap().to_string_lossy().into_owned();
    onyx_tests::entries(journal)
        .iter()
        .filter(|e| e.contains("AssetFailed") && e.contains(&name))
        .count()
}

/// Writes `broken`, draws a few frames, and checks the last good image stays and one more
/// failure names `file`.
fn break_and_check(
    host: &mut HeadlessHost,
    journal: &onyx_tests::Journal,
    file: &Path,
    broken: &[u8],
) {
    let before = failures(journal, file);
    std::fs::write(file, broken).unwrap();
    let deadline = Instant::now() + Duration::from_secs(10);
    while failures(journal, file) == before && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(20));
        host.step(1);
        let pixel = centre(&host.screenshot(64, 64).unwrap());
        assert!(
            is_green(pixel),
            "a broken edit replaced the last good version: {pixel:?}"
        );
    }
    host.step(1);
    assert!(
        failures(journal, file) > before,
        "no graphics event names the broken `{}`: {:?}",
        file.display(),
        onyx_tests::entries(journal)
    );
    let pixel = centre(&host.screenshot(64, 64).unwrap());
    assert!(
        is_green(pixel),
        "a broken edit replaced the last good version: {pixel:?}"
    );
}

#[test]
fn an_edited_texture_is_drawn_anew_and_a_broken_one_keeps_the_last_good() {
    let dir = tempfile::tempdir().unwrap();
    let texture = dir.path().join("wall.png");
    write_png(
        &texture,
        &RgbaImage::from_pixel(16, 16, Rgba([220, 0, 0, 255])),
    );
    let journal = onyx_tests::journal();
    let mut host = HeadlessHost::new();
    host.add_plugin("witness", onyx_tests::Recorder::new("w", &journal))
        .unwrap();
    host.add_plugin(
        "stage",
        TexturedCube {
            texture: texture.clone(),
            model: None,
        },
    )
    .unwrap();
    let red = wait_for(&mut host, is_red);
    assert!(is_red(red), "the texture is red: {red:?}");

    write_png(
        &texture,
        &RgbaImage::from_pixel(16, 16, Rgba([0, 220, 0, 255])),
    );
    let green = wait_for(&mut host, is_green);
    assert!(
        is_green(green),
        "the edited texture never showed: {green:?}"
    );

    break_and_check(&mut host, &journal, &texture, b"this is not a PNG");
}

/// A quad facing the camera, 4 m a side, with material `paint` from `quad.mtl`.
const QUAD_OBJ: &str = "mtllib quad.mtl\nv -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0\n\
vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl paint\nf 1/1 2/2 3/3 4/4\n";

#[test]
fn an_edited_model_or_material_library_is_drawn_anew_and_a_broken_model_keeps_the_last_good() {
    let dir = tempfile::tempdir().unwrap();
    let model = dir.path().join("quad.obj");
    let mtl = dir.path().join("quad.mtl");
    let white = dir.path().join("white.png");
    write_png(&white, &RgbaImage::from_pixel(4, 4, Rgba([255; 4])));
    std::fs::write(&model, QUAD_OBJ).unwrap();
    std::fs::write(&mtl, "newmtl paint\nKd 0.9 0 0\n").unwrap();
    let journal = onyx_tests::journal();
    let mut host = HeadlessHost::new();
    host.add_plugin("witness", onyx_tests::Recorder::new("w", &journal))
        .unwrap();
    host.add_plugin(
        "stage",
        TexturedCube {
            texture: white,
            model: Some(model.clone()),
        },
    )
    .unwrap();
    let red = wait_for(&mut host, is_red);
    assert!(is_red(red), "the model's material is red: {red:?}");

    // The material library beside the model changes: the model is read again.
    std::fs::write(&mtl, "newmtl paint\nKd 0 0.9 0\n").unwrap();
    let green = wait_for(&mut host, is_green);
    assert!(
        is_green(green),
        "the edited material never showed: {green:?}"
    );

    // The model itself moves its quad away from the centre, then back.
    std::fs::write(
        &model,
        QUAD_OBJ.replace(
            "v -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0",
            "v 3 3 0\nv 4 3 0\nv 4 4 0\nv 3 4 0",
        ),
    )
    .unwrap();
    let moved = wait_for(&mut host, |p| !is_green(p));
    assert!(!is_green(moved), "the edited model never showed: {moved:?}");
    std::fs::write(&model, QUAD_OBJ).unwrap();
    let back = wait_for(&mut host, is_green);
    assert!(is_green(back), "the model never came back: {back:?}");

    break_and_check(&mut host, &journal, &model, b"v 0 0 0\n");
}
