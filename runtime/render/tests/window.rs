//! A real window through winit (X11; run the suite under `xvfb-run -a` on a machine without
//! a display): the surface path draws the same pixels as an offscreen target, skips frames
//! while minimised (0×0), and survives a vsync toggle. Without `DISPLAY` it fails with a
//! note saying how to run it (`scripts/test.sh` runs the suite under Xvfb).

mod common;

use std::sync::Arc;
use std::time::Duration;

use glam::{Mat4, Vec3};
use onyx_render::{
    Camera, DrawObject, GpuContext, Lights, Material, RenderScene, RenderSettings, Renderer,
    ShadingMode, SurfaceTarget,
};
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::platform::pump_events::EventLoopExtPumpEvents;
use winit::platform::x11::EventLoopBuilderExtX11;
use winit::window::{Window, WindowId};

const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;
/// Event-loop turns to wait for the window to appear.
const MAX_PUMPS: usize = 200;

#[derive(Default)]
struct Probe {
    window: Option<Arc<Window>>,
    error: Option<String>,
}

impl ApplicationHandler for Probe {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.window.is_some() {
            return;
        }
        let attributes = Window::default_attributes()
            .with_title("onyx-render window test")
            .with_inner_size(PhysicalSize::new(WIDTH, HEIGHT))
            .with_resizable(false);
        match event_loop.create_window(attributes) {
            Ok(window) => self.window = Some(Arc::new(window)),
            Err(error) => self.error = Some(error.to_string()),
        }
    }

    fn window_event(&mut self, _: &ActiveEventLoop, _: WindowId, _: WindowEvent) {}
}

#[test]
fn window_surface_draws_like_offscreen_and_handles_minimise_and_vsync() {
    common::setup();
    assert!(
        std::env::var_os("DISPLAY").is_some(),
        "no DISPLAY: run the tests under `xvfb-run -a` (scripts/test.sh does)"
    );
    let mut event_loop = match EventLoop::builder().with_any_thread(true).build() {
        Ok(event_loop) => event_loop,
        Err(error) => panic!("no X11 event loop (X libraries installed?): {error}"),
    };
    let mut probe = Probe::default();
    for _ in 0..MAX_PUMPS {
        let _ = event_loop.pump_app_events(Some(Duration::from_millis(5)), &mut probe);
        if probe.window.is_some() || probe.error.is_some() {
            break;
        }
    }
    let Some(window) = probe.window.clone() else {
        panic!("no window: {:?}", probe.error)
    };

    let instance = GpuContext::create_instance();
    let surface = instance
        .create_surface(window.clone())
        .unwrap_or_else(|e| panic!("{e}"));
    let gpu = GpuContext::from_instance(instance, Some(&surface)).unwrap_or_else(|e| panic!("{e}"));
    let mut renderer =
        Renderer::new(gpu, RenderSettings::deterministic()).unwrap_or_else(|e| panic!("{e}"));
    let size = window.inner_size();
    let mut target = SurfaceTarget::new(renderer.gpu(), surface, size.width, size.height, true)
        .unwrap_or_else(|e| panic!("{e}"));

    let meshes = *renderer.builtin_meshes();
    let objects = [
        DrawObject::new(
            meshes.cube,
            Material::color(0.9, 0.4, 0.2),
            Mat4::from_rotation_y(0.5),
        ),
        DrawObject::new(
            meshes.sphere,
            Material::color(0.2, 0.5, 0.9).with_shading(ShadingMode::Normal),
            Mat4::from_translation(Vec3::new(1.2, 0.0, 0.0)),
        ),
    ];
    let lights = Lights::default();
    let camera = Camera::perspective_look_at(Vec3::new(0.0, 1.5, 3.5), Vec3::ZERO, 1.0, 0.1, 100.0);
    let scene = RenderScene::new(camera, &lights)
        .with_objects(&objects)
        .with_grid(true);

    // A normal frame.
    let stats = renderer
        .render(&mut target, &scene)
        .unwrap_or_else(|e| panic!("{e}"));
    // Two objects, the sky and the grid.
    assert!(!stats.skipped && stats.draw_calls == 4, "{stats:?}");

    // Minimised: nothing drawn, no error.
    target.resize(renderer.gpu(), 0, 0);
    assert!(target.is_minimized());
    let stats = renderer
        .render(&mut target, &scene)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(stats.skipped, "{stats:?}");

    // Restored with vsync off, and captured.
    target.resize(renderer.gpu(), size.width, size.height);
    target.set_vsync(renderer.gpu(), false);
    assert!(!target.vsync());
    target.request_screenshot();
    let stats = renderer
        .render(&mut target, &scene)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(!stats.skipped, "{stats:?}");
    let _ = event_loop.pump_app_events(Some(Duration::ZERO), &mut probe);
    let shot = match target.take_screenshot() {
        Some(Ok(image)) => image,
        Some(Err(error)) => panic!("screenshot failed: {error}"),
        None => panic!("no screenshot was taken"),
    };

    // Kept for a person to look at: $CARGO_TARGET_TMPDIR/window/screenshot.png.
    let shot_dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("window");
    let _ = std::fs::create_dir_all(&shot_dir);
    let _ = shot.save(shot_dir.join("screenshot.png"));

    let offscreen = common::render_image(&mut renderer, size.width, size.height, &scene);
    let share = common::differing_share(&shot, &offscreen);
    if share > common::MAX_DIFF_SHARE {
        let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("golden");
        let _ = std::fs::create_dir_all(&dir);
        let _ = shot.save(dir.join("window-actual.png"));
        let _ = offscreen.save(dir.join("window-offscreen.png"));
        panic!(
            "window and offscreen differ on {:.2} % of pixels; images in {}",
            share * 100.0,
            dir.display()
        );
    }
    let events = renderer.drain_events();
    assert!(events.is_empty(), "{events:?}");
}
