//! An equirectangular HDR sky: read from a Radiance `.hdr` file, it lights the scene
//! (prefiltered specular and irradiance) and is drawn behind it; a file that cannot be read
//! keeps the procedural sky. The test writes its own small sky file.

mod common;

use std::path::{Path, PathBuf};

use glam::{Mat4, Vec3};
use image::Rgb;
use onyx_render::{
    Camera, DrawObject, Lights, Material, RenderScene, RenderSettings, Renderer, Sky,
};

const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;

const ORANGE: [f32; 3] = [2.0, 0.8, 0.2];
const MAGENTA: [f32; 3] = [1.5, 0.1, 1.5];
const GROUND: [f32; 3] = [0.05, 0.35, 0.05];

/// A 64×32 equirectangular sky: an orange upper half with a magenta band straight ahead
/// (−Z, the image's middle column), a green lower half.
fn write_sky(name: &str) -> PathBuf {
    let (w, h) = (64usize, 32usize);
    let pixels: Vec<Rgb<f32>> = (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let u = (x as f32 + 0.5) / w as f32;
            if y >= h / 2 {
                Rgb(GROUND)
            } else if (u - 0.5).abs() < 0.06 {
                Rgb(MAGENTA)
            } else {
                Rgb(ORANGE)
            }
        })
        .collect();
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let file = std::fs::File::create(&path).expect("create the sky file");
    image::codecs::hdr::HdrEncoder::new(std::io::BufWriter::new(file))
        .encode(&pixels, w, h)
        .expect("write the sky file");
    path
}

/// A rough white sphere and a mirror sphere, seen from slightly above, looking down −Z.
fn spheres(renderer: &Renderer) -> Vec<DrawObject> {
    let sphere = renderer.builtin_meshes().sphere;
    vec![
        DrawObject::new(
            sphere,
            Material::color(0.9, 0.9, 0.9).with_metallic_roughness(0.0, 0.9),
            Mat4::from_translation(Vec3::new(-0.6, 0.0, 0.0)),
        ),
        DrawObject::new(
            sphere,
            Material::color(0.95, 0.95, 0.95).with_metallic_roughness(1.0, 0.05),
            Mat4::from_translation(Vec3::new(0.6, 0.0, 0.0)),
        ),
    ]
}

fn render(sky: Sky) -> image::RgbaImage {
    let mut renderer = common::renderer_with(RenderSettings::deterministic().with_sky(sky));
    let objects = spheres(&renderer);
    // Sky light only: no sun, so what lights the spheres is the image.
    let lights = Lights {
        ambient: Vec3::ONE,
        sun: None,
        ..Lights::default()
    };
    let camera = Camera::perspective_look_at(
        Vec3::new(0.0, 0.3, 3.0),
        Vec3::new(0.0, 0.1, 0.0),
        0.9,
        0.1,
        100.0,
    );
    let scene = RenderScene::new(camera, &lights).with_objects(&objects);
    common::render_image(&mut renderer, WIDTH, HEIGHT, &scene)
}

fn pixel(image: &image::RgbaImage, x: u32, y: u32) -> [i32; 3] {
    let p = image.get_pixel(x, y).0;
    [i32::from(p[0]), i32::from(p[1]), i32::from(p[2])]
}

#[test]
fn an_hdr_file_lights_the_scene_and_is_drawn_behind_it() {
    let path = write_sky("sky_image_test.hdr");
    let image = render(Sky::image(&path));
    common::check_golden("sky_image", &image);

    // Background: magenta straight ahead at the top, orange to the sides, green below.
    let ahead = pixel(&image, WIDTH / 2, 4);
    let side = pixel(&image, 4, 4);
    assert!(
        ahead[2] > ahead[1] + 60 && ahead[0] > ahead[1] + 60,
        "ahead of the camera the sky is not magenta: {ahead:?}"
    );
    assert!(
        side[0] > side[2] + 60,
        "to the side the sky is not orange: {side:?}"
    );
    let below = pixel(&image, 4, HEIGHT - 4);
    assert!(
        below[1] > below[0] && below[1] > below[2],
        "below the horizon the sky is not green: {below:?}"
    );
    // The rough sphere's top is lit by the orange sky; its bottom sees the green ground too
    // (the bright sky still dominates), so it is greener than the top.
    let top = pixel(&image, WIDTH / 2 - 30, HEIGHT / 2 - 12);
    let bottom = pixel(&image, WIDTH / 2 - 30, HEIGHT / 2 + 16);
    assert!(
        top[0] > top[2] + 40,
        "the top of the sphere is not orange-lit: {top:?}"
    );
    assert!(
        bottom[1] - bottom[0] > top[1] - top[0] + 20,
        "the bottom of the sphere ({bottom:?}) is not greener than its top ({top:?})"
    );

    let procedural = render(Sky::default());
    let share = common::differing_share(&image, &procedural);
    assert!(
        share > 0.5,
        "the image sky looks like the procedural one ({share})"
    );
}

#[test]
fn a_missing_or_broken_sky_file_keeps_the_procedural_sky() {
    let procedural = render(Sky::default());
    let missing = render(Sky::image(
        Path::new(env!("CARGO_TARGET_TMPDIR")).join("no_such_sky.hdr"),
    ));
    assert_eq!(
        common::differing_share(&procedural, &missing),
        0.0,
        "a missing sky file changed the image"
    );
    let broken = Path::new(env!("CARGO_TARGET_TMPDIR")).join("broken_sky.hdr");
    std::fs::write(&broken, b"#?RADIANCE\nnot really\n").expect("write the broken file");
    let broken = render(Sky::image(broken));
    assert_eq!(
        common::differing_share(&procedural, &broken),
        0.0,
        "a broken sky file changed the image"
    );
}
