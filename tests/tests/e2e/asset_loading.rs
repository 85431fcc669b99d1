//! Models and textures load off the frame thread: a frame asking for a large texture returns
//! while it is still being decoded, drawing the missing-texture checker, and a later frame
//! shows it; a screenshot waits for it, so images compared with references show final assets.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use onyx_plugin_api::{
    glam, Camera, Ctx, Material, MeshId, MeshRenderer, Plugin, ShadingMode, Transform,
};
use onyx_render::image::{Rgba, RgbaImage};
use onyx_render::OffscreenTarget;
use onyx_runtime::render::RenderSystem;
use onyx_runtime::HeadlessHost;

/// A camera looking at one large unlit cube textured with the image at `texture`.
pub(crate) struct TexturedCube {
    pub(crate) texture: PathBuf,
    pub(crate) model: Option<PathBuf>,
}

impl Plugin for TexturedCube {
    fn on_init(&mut self, ctx: &mut Ctx) {
        let eye = glam::Vec3::new(0.0, 0.0, 5.0);
        let camera = ctx
            .spawn((Transform::from_translation(eye), Camera::perspective(0.8)))
            .unwrap();
        ctx.set_camera(camera).unwrap();
        let texture = ctx
            .load_texture(&self.texture.display().to_string())
            .unwrap();
        let unlit = Material::color(1.0, 1.0, 1.0)
            .with_shading(ShadingMode::Unlit)
            .with_texture(texture);
        let mesh = match &self.model {
            Some(path) => ctx.load_mesh(&path.display().to_string()).unwrap(),
            None => MeshId::CUBE,
        };
        let big = Transform::IDENTITY.with_scale(glam::Vec3::splat(3.0));
        ctx.spawn((big, MeshRenderer::new(mesh).with_material(unlit)))
            .unwrap();
    }
}

pub(crate) fn centre(image: &RgbaImage) -> [u8; 4] {
    image.get_pixel(image.width() / 2, image.height() / 2).0
}

pub(crate) fn is_green(p: [u8; 4]) -> bool {
    p[1] > 120 && p[1] > p[0] + 60 && p[1] > p[2] + 60
}

pub(crate) fn write_png(path: &Path, image: &RgbaImage) {
    image
        .save_with_format(path, onyx_render::image::ImageFormat::Png)
        .unwrap();
}

#[test]
fn a_large_texture_is_decoded_off_the_frame_and_shows_on_a_later_frame() {
    let dir = tempfile::tempdir().unwrap();
    let texture = dir.path().join("large.png");
    // 4096 × 4096 (64 MiB decoded, 85 MiB with mips), green with a little noise so the
    // PNG is not trivially compressible.
    let image = RgbaImage::from_fn(4096, 4096, |x, y| {
        Rgba([0, 200, ((x * 7 + y * 13) % 32) as u8, 255])
    });
    write_png(&texture, &image);
    drop(image);

    let mut host = HeadlessHost::new();
    host.add_plugin(
        "stage",
        TexturedCube {
            texture: texture.clone(),
            model: None,
        },
    )
    .unwrap();
    host.step(1);
    let Ok(mut system) = RenderSystem::new_headless(RenderSystem::offscreen_settings()) else {
        eprintln!("skipped: no adapter to render with");
        return;
    };
    let mut target = OffscreenTarget::new(system.renderer().gpu(), 64, 64);

    let started = Instant::now();
    host.host_mut().render(&mut system, &mut target).unwrap();
    let first_frame = started.elapsed();
    let first = centre(&target.read_image(system.renderer().gpu()).unwrap());
    assert_eq!(
        system.pending_loads(),
        1,
        "the frame returned with the texture decoded: it waited for it"
    );
    assert!(
        !is_green(first),
        "the first frame shows the texture it could not have yet: {first:?}"
    );

    let mut frames = 1;
    let mut pixel = first;
    while !is_green(pixel) && started.elapsed() < Duration::from_secs(120) {
        std::thread::sleep(Duration::from_millis(10));
        host.step(1);
        host.host_mut().render(&mut system, &mut target).unwrap();
        frames += 1;
        pixel = centre(&target.read_image(system.renderer().gpu()).unwrap());
    }
    println!(
        "first frame {first_frame:?} while a 4096² texture decoded; it showed on frame \
         {frames}, {:?} after the first",
        started.elapsed()
    );
    assert!(is_green(pixel), "the texture never appeared: {pixel:?}");
    assert_eq!(system.pending_loads(), 0);
}

#[test]
fn a_screenshot_waits_for_the_textures_it_draws() {
    let dir = tempfile::tempdir().unwrap();
    let texture = dir.path().join("green.png");
    write_png(
        &texture,
        &RgbaImage::from_pixel(1024, 1024, Rgba([0, 200, 0, 255])),
    );
    let mut host = HeadlessHost::new();
    host.add_plugin(
        "stage",
        TexturedCube {
            texture,
            model: None,
        },
    )
    .unwrap();
    host.step(1);
    // The very first image: the texture was never asked for before it.
    let pixel = centre(&host.screenshot(64, 64).unwrap());
    assert!(
        is_green(pixel),
        "the screenshot shows a placeholder: {pixel:?}"
    );
}
