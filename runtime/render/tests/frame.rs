//! Frame behaviour: instancing, culling, shader reload keeping the last good pipeline,
//! readback of odd sizes, MSAA, and GPU errors captured as events.

mod common;

use glam::{Mat4, Vec3};
use onyx_render::{
    Camera, DrawObject, GraphicsEvent, Lights, Material, OffscreenTarget, RenderScene,
    RenderSettings, ShadingMode,
};

/// `count` cubes on a grid in front of the camera, alternating two materials.
fn cubes(renderer: &onyx_render::Renderer, count: usize) -> Vec<DrawObject> {
    let cube = renderer.builtin_meshes().cube;
    let side = (count as f32).sqrt().ceil() as usize;
    (0..count)
        .map(|i| {
            let (x, z) = ((i % side) as f32, (i / side) as f32);
            let material = if i % 2 == 0 {
                Material::color(0.8, 0.2, 0.2)
            } else {
                Material::color(0.2, 0.2, 0.8).with_shading(ShadingMode::Unlit)
            };
            DrawObject::new(
                cube,
                material,
                Mat4::from_translation(Vec3::new(x - side as f32 / 2.0, 0.0, -z))
                    * Mat4::from_scale(Vec3::splat(0.5)),
            )
        })
        .collect()
}

fn overview_camera() -> Camera {
    Camera::perspective_look_at(
        Vec3::new(0.0, 40.0, 20.0),
        Vec3::new(0.0, 0.0, -15.0),
        1.2,
        0.1,
        500.0,
    )
}

#[test]
fn thousand_cubes_with_two_materials_take_two_draw_calls() {
    let mut renderer = common::renderer_with(RenderSettings {
        sky_background: false,
        ..RenderSettings::deterministic()
    });
    let objects = cubes(&renderer, 1000);
    let lights = Lights::default();
    let scene = RenderScene::new(overview_camera(), &lights).with_objects(&objects);
    let mut target = OffscreenTarget::new(renderer.gpu(), 64, 64);
    let stats = match renderer.render(&mut target, &scene) {
        Ok(stats) => stats,
        Err(error) => panic!("{error}"),
    };
    assert_eq!(stats.culled, 0, "all cubes are in view: {stats:?}");
    assert_eq!(
        (stats.instances, stats.batches, stats.draw_calls),
        (1000, 2, 2),
        "{stats:?}"
    );

    renderer
        .set_settings(RenderSettings {
            instancing: false,
            sky_background: false,
            ..RenderSettings::deterministic()
        })
        .ok();
    let stats = match renderer.render(&mut target, &scene) {
        Ok(stats) => stats,
        Err(error) => panic!("{error}"),
    };
    assert_eq!(
        stats.draw_calls, 1000,
        "without instancing each object is a draw: {stats:?}"
    );
    assert!(renderer.drain_events().is_empty());
}

#[test]
fn objects_outside_the_view_are_culled() {
    let mut renderer = common::renderer();
    let cube = renderer.builtin_meshes().cube;
    let material = Material::default();
    let camera = Camera::perspective_look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, 1.0, 0.1, 50.0);
    let objects = [
        DrawObject::new(cube, material, Mat4::IDENTITY),
        DrawObject::new(
            cube,
            material,
            Mat4::from_translation(Vec3::new(0.0, 0.0, 10.0)),
        ), // behind
        DrawObject::new(
            cube,
            material,
            Mat4::from_translation(Vec3::new(100.0, 0.0, 0.0)),
        ), // right
        DrawObject::new(
            cube,
            material,
            Mat4::from_translation(Vec3::new(0.0, 0.0, -100.0)),
        ), // past far
        // Centre outside, but scaled up so its sphere reaches into view: kept.
        DrawObject::new(
            cube,
            material,
            Mat4::from_translation(Vec3::new(6.0, 0.0, 0.0)) * Mat4::from_scale(Vec3::splat(8.0)),
        ),
    ];
    let lights = Lights::default();
    let scene = RenderScene::new(camera, &lights).with_objects(&objects);
    let mut target = OffscreenTarget::new(renderer.gpu(), 32, 32);
    let stats = renderer
        .render(&mut target, &scene)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((stats.instances, stats.culled), (2, 3), "{stats:?}");
}

fn copy_shaders(dir: &std::path::Path) {
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    for entry in std::fs::read_dir(common::shaders())
        .unwrap_or_else(|e| panic!("shaders/: {e}"))
        .flatten()
    {
        std::fs::copy(entry.path(), dir.join(entry.file_name())).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn shader_compile_error_keeps_the_last_good_pipeline() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("reload-shaders");
    copy_shaders(&dir);
    let mut renderer = common::renderer_with(RenderSettings::deterministic().with_shader_dir(&dir));
    let sphere = renderer.builtin_meshes().sphere;
    let objects = [DrawObject::new(
        sphere,
        Material::color(0.2, 0.8, 0.3).with_shading(ShadingMode::Unlit),
        Mat4::IDENTITY,
    )];
    let lights = Lights::default();
    let camera = Camera::perspective_look_at(Vec3::new(0.0, 0.0, 2.0), Vec3::ZERO, 1.0, 0.1, 10.0);
    let scene = RenderScene::new(camera, &lights).with_objects(&objects);
    let before = common::render_image(&mut renderer, 32, 32, &scene);

    // Break unlit.wgsl: the reload reports it, the previous pipeline keeps drawing.
    std::fs::write(
        dir.join("unlit.wgsl"),
        "@fragment fn fs_main() -> @location(0) vec4<f32> { return oops; }",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let error = match renderer.reload_shaders() {
        Err(error) => error,
        Ok(()) => panic!("a broken shader must be reported"),
    };
    assert_eq!(error.failures.len(), 1, "{error}");
    assert!(error.to_string().contains("unlit.wgsl"), "{error}");
    let events = renderer.drain_events();
    assert!(
        matches!(events.as_slice(), [GraphicsEvent::ShaderCompileFailed { shader, .. }] if shader == "unlit.wgsl"),
        "{events:?}"
    );
    let after_error = common::render_image(&mut renderer, 32, 32, &scene);
    assert_eq!(
        before, after_error,
        "the last good pipeline must stay in use"
    );

    // A good edit is picked up: unlit now ignores the colour and draws white.
    let fixed = std::fs::read_to_string(common::shaders().join("unlit.wgsl"))
        .unwrap_or_else(|e| panic!("{e}"))
        .replace(
            "vec4<f32>(base.rgb + o.emissive.rgb, alpha)",
            // Alpha 0: shown as it is, without tone mapping.
            "vec4<f32>(1.0, 1.0, 1.0, 0.0)",
        );
    std::fs::write(dir.join("unlit.wgsl"), fixed).unwrap_or_else(|e| panic!("{e}"));
    renderer.reload_shaders().unwrap_or_else(|e| panic!("{e}"));
    let after_fix = common::render_image(&mut renderer, 32, 32, &scene);
    assert_eq!(
        after_fix.get_pixel(16, 16).0,
        [255, 255, 255, 255],
        "the reloaded shader must be used"
    );
}

#[test]
fn broken_shader_folder_at_start_falls_back_to_embedded_shaders() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("broken-start-shaders");
    copy_shaders(&dir);
    std::fs::write(dir.join("lit_low.wgsl"), "this is not wgsl").unwrap_or_else(|e| panic!("{e}"));
    let mut renderer = common::renderer_with(RenderSettings::deterministic().with_shader_dir(&dir));
    let events = renderer.drain_events();
    assert!(
        matches!(
            events.as_slice(),
            [GraphicsEvent::ShaderCompileFailed { .. }]
        ),
        "{events:?}"
    );
    let cube = renderer.builtin_meshes().cube;
    let objects = [DrawObject::new(cube, Material::default(), Mat4::IDENTITY)];
    let lights = Lights::default();
    let scene = RenderScene::new(Camera::default(), &lights).with_objects(&objects);
    let image = common::render_image(&mut renderer, 32, 32, &scene);
    let centre = image.get_pixel(16, 16).0;
    assert!(
        centre[0] > 80,
        "the embedded lit_low shader must draw the cube: {centre:?}"
    );
}

#[test]
fn readback_handles_sizes_that_need_row_padding() {
    let mut renderer = common::renderer_with(RenderSettings {
        sky_background: false,
        ..RenderSettings::deterministic()
    });
    let lights = Lights::default();
    let scene = RenderScene::new(Camera::default(), &lights);
    let image = common::render_image(&mut renderer, 33, 17, &scene);
    assert_eq!(image.dimensions(), (33, 17));
    // The clear colour, sRGB-encoded, everywhere (no padding bytes leaked in).
    let first = *image.get_pixel(0, 0);
    assert!(
        image.pixels().all(|p| *p == first),
        "every pixel must be the clear colour"
    );
}

#[test]
fn msaa_renders_without_gpu_errors() {
    let mut renderer = common::renderer_with(RenderSettings::default().with_msaa(4));
    let objects = cubes(&renderer, 16);
    let lights = Lights::default();
    let scene = RenderScene::new(overview_camera(), &lights)
        .with_objects(&objects)
        .with_grid(true);
    let image = common::render_image(&mut renderer, 64, 48, &scene);
    assert_eq!(image.dimensions(), (64, 48));
    // Two batches, the sky and the grid.
    assert_eq!(renderer.stats().draw_calls, 4);
}

#[test]
fn gpu_validation_errors_become_events_not_panics() {
    let renderer = common::renderer();
    // MAP_READ with VERTEX is invalid without MAPPABLE_PRIMARY_BUFFERS.
    let _buffer = renderer
        .gpu()
        .device()
        .create_buffer(&onyx_render::wgpu::BufferDescriptor {
            label: Some("deliberately invalid"),
            size: 16,
            usage: onyx_render::wgpu::BufferUsages::MAP_READ
                | onyx_render::wgpu::BufferUsages::VERTEX,
            mapped_at_creation: false,
        });
    let events = renderer.drain_events();
    assert!(
        matches!(events.as_slice(), [GraphicsEvent::Validation { .. }]),
        "{events:?}"
    );
}

#[test]
fn device_loss_is_reported_and_rendering_does_not_panic() {
    let mut renderer = common::renderer();
    renderer.gpu().device().destroy();
    let _ = renderer.gpu().wait_idle();
    let lights = Lights::default();
    let objects = cubes(&renderer, 4);
    let scene = RenderScene::new(overview_camera(), &lights).with_objects(&objects);
    let mut target = OffscreenTarget::new(renderer.gpu(), 16, 16);
    let _ = renderer.render(&mut target, &scene);
    let _ = target.read_image(renderer.gpu());
    let events = renderer.drain_events();
    assert!(
        events
            .iter()
            .any(|e| matches!(e, GraphicsEvent::DeviceLost { .. })),
        "{events:?}"
    );
}
