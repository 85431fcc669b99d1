//! The host draws the world with onyx-render, on Mesa's CPU Vulkan driver: a plugin's scene
//! through its camera and lights, compared with reference images.

use onyx_runtime::{HeadlessHost, HostConfig};
use onyx_tests::{assert_golden, plugin_library};

fn repo_root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn showcase(camera: &str) -> HeadlessHost {
    let config = HostConfig::default()
        .asset_root(repo_root())
        .setting("showcase", "camera", camera);
    let mut host = HeadlessHost::with_config(config);
    host.load_plugin_file(&plugin_library("showcase")).unwrap();
    host.step(30);
    host
}

#[test]
fn the_showcase_renders_every_shading_mode_spot_and_the_grid() {
    let mut host = showcase("perspective");
    let image = host
        .screenshot(320, 200)
        .expect("renders on the CPU adapter");
    assert_golden("showcase", &image);
}

#[test]
fn the_showcase_renders_through_an_orthographic_camera() {
    let mut host = showcase("ortho");
    let image = host
        .screenshot(320, 200)
        .expect("renders on the CPU adapter");
    assert_golden("showcase-ortho", &image);
}

/// Spawns one large unlit cube in front of the default camera, and a model from a path.
struct Stage {
    model: Option<&'static str>,
}

impl onyx_plugin_api::Plugin for Stage {
    fn on_init(&mut self, ctx: &mut onyx_plugin_api::Ctx) {
        use onyx_plugin_api::*;
        let eye = glam::Vec3::new(0.0, 0.0, 5.0);
        let camera = ctx
            .spawn((Transform::from_translation(eye), Camera::perspective(0.8)))
            .unwrap();
        ctx.set_camera(camera).unwrap();
        let unlit = Material::color(1.0, 0.0, 0.0).with_shading(ShadingMode::Unlit);
        let big = Transform::IDENTITY.with_scale(glam::Vec3::splat(3.0));
        ctx.spawn((big, MeshRenderer::new(MeshId::CUBE).with_material(unlit)))
            .unwrap();
        if let Some(path) = self.model {
            let mesh = ctx.load_mesh(path).unwrap();
            let pose = Transform::from_xyz(0.0, 0.0, 3.0).with_scale(glam::Vec3::splat(0.6));
            ctx.spawn((pose, MeshRenderer::new(mesh))).unwrap();
        }
    }
}

fn centre(image: &onyx_render::image::RgbaImage) -> [u8; 4] {
    image.get_pixel(image.width() / 2, image.height() / 2).0
}

#[test]
fn editing_a_shader_recompiles_it_and_a_broken_edit_keeps_the_last_good_one() {
    let shaders = tempfile::tempdir().unwrap();
    for entry in std::fs::read_dir(repo_root().join("shaders")).unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, shaders.path().join(path.file_name().unwrap())).unwrap();
    }
    let journal = onyx_tests::journal();
    let mut host = HeadlessHost::new();
    host.set_render_settings(onyx_render::RenderSettings {
        shader_dir: Some(shaders.path().to_path_buf()),
        ..onyx_render::RenderSettings::deterministic()
    });
    host.add_plugin("witness", onyx_tests::Recorder::new("w", &journal))
        .unwrap();
    host.add_plugin("stage", Stage { model: None }).unwrap();
    host.step(1);
    let red = centre(&host.screenshot(64, 64).unwrap());
    // Pure red through the tone mapping (AgX desaturates it a little).
    assert!(
        red[0] > 180 && red[0] > red[1] + 100,
        "the unlit cube is red: {red:?}"
    );

    let unlit = shaders.path().join("unlit.wgsl");
    let source = std::fs::read_to_string(&unlit).unwrap();
    let green = source.replace(
        "vec4<f32>(base.rgb + o.emissive.rgb, alpha)",
        "vec4<f32>(0.0, 1.0, 0.0, 1.0)",
    );
    assert_ne!(
        green, source,
        "the unlit shader changed shape; update this test"
    );
    std::fs::write(&unlit, green).unwrap();
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(5);
    let mut pixel = red;
    let is_green = |p: [u8; 4]| p[1] > 150 && p[1] > p[0] + 80;
    while std::time::Instant::now() < deadline && !is_green(pixel) {
        std::thread::sleep(std::time::Duration::from_millis(20));
        host.step(1);
        pixel = centre(&host.screenshot(64, 64).unwrap());
    }
    assert!(
        is_green(pixel),
        "the edited shader never took effect: {pixel:?}"
    );

    std::fs::write(&unlit, "this is not WGSL").unwrap();
    std::thread::sleep(std::time::Duration::from_millis(200));
    for _ in 0..3 {
        host.step(1);
        pixel = centre(&host.screenshot(64, 64).unwrap());
    }
    assert!(
        is_green(pixel),
        "a broken shader replaced the last good one: {pixel:?}"
    );
    host.step(1);
    let reported = onyx_tests::entries(&journal)
        .into_iter()
        .any(|e| e.contains("Graphics(Gpu") && e.contains("unlit.wgsl"));
    assert!(
        reported,
        "no graphics event names the broken shader: {:?}",
        onyx_tests::entries(&journal)
    );
}

#[test]
fn a_missing_model_is_named_in_an_event_and_drawn_as_a_checker() {
    let journal = onyx_tests::journal();
    let mut host = HeadlessHost::with_config(HostConfig::default().asset_root(repo_root()));
    host.add_plugin("witness", onyx_tests::Recorder::new("w", &journal))
        .unwrap();
    host.add_plugin(
        "stage",
        Stage {
            model: Some("assets/models/no_such_model.obj"),
        },
    )
    .unwrap();
    host.step(1);
    let image = host.screenshot(96, 96).unwrap();
    host.step(1);
    let events: Vec<String> = onyx_tests::entries(&journal)
        .into_iter()
        .filter(|e| e.contains("AssetFailed"))
        .collect();
    assert_eq!(events.len(), 1, "{events:?}");
    assert!(events[0].contains("no_such_model.obj"), "{events:?}");
    let magenta = image
        .pixels()
        .filter(|p| p.0[0] > 150 && p.0[1] < 80 && p.0[2] > 150)
        .count();
    assert!(
        magenta > 20,
        "no magenta fallback visible ({magenta} pixels)"
    );
    // Drawing again does not report it again.
    host.screenshot(96, 96).unwrap();
    host.step(1);
    let again = onyx_tests::entries(&journal)
        .iter()
        .filter(|e| e.contains("AssetFailed"))
        .count();
    assert_eq!(again, 1);
}
