//! A window rendered with onyx-render through winit: a spinning lit cube, a textured Spot
//! cow and the editor grid.
//!
//! `cargo run --example window` — close the window to quit.
//! `cargo run --example window -- --frames 120` — exits after 120 frames, exercising a
//! minimise (0×0 resize) and a vsync toggle on the way; exit code 1 if a GPU event occurred.
//! Headless: `xvfb-run -a -s "-screen 0 1280x720x24" cargo run --example window -- --frames 60`.

use std::sync::Arc;
use std::time::Instant;

use glam::{Mat4, Quat, Vec3};
use onyx_render::{
    Camera, DrawObject, GpuContext, Lights, Material, PointLight, RenderError, RenderScene,
    RenderSettings, Renderer, SurfaceTarget,
};
use winit::application::ApplicationHandler;
use winit::dpi::LogicalSize;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::window::{Window, WindowId};

struct Running {
    window: Arc<Window>,
    renderer: Renderer,
    target: SurfaceTarget,
    cow: Vec<DrawObject>,
}

#[derive(Default)]
struct App {
    running: Option<Running>,
    frame: u32,
    max_frames: Option<u32>,
    start: Option<Instant>,
    gpu_events: usize,
    error: Option<String>,
}

impl App {
    fn start(
        &mut self,
        event_loop: &ActiveEventLoop,
    ) -> Result<Running, Box<dyn std::error::Error>> {
        let attributes = Window::default_attributes()
            .with_title("onyx-render")
            .with_inner_size(LogicalSize::new(800, 600));
        let window = Arc::new(event_loop.create_window(attributes)?);
        let instance = GpuContext::create_instance();
        let surface = instance.create_surface(window.clone())?;
        let gpu = GpuContext::from_instance(instance, Some(&surface))?;
        let shader_dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shaders");
        let mut renderer =
            Renderer::new(gpu, RenderSettings::default().with_shader_dir(shader_dir))?;
        let size = window.inner_size();
        let target = SurfaceTarget::new(renderer.gpu(), surface, size.width, size.height, true)?;
        let spot = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../../shared/fixtures/spot/spot_triangulated.obj");
        let (model, problems) = renderer.load_model_or_fallback(spot);
        for problem in problems {
            eprintln!("warning: {problem}");
        }
        let cow = model
            .draw_objects(Mat4::from_translation(Vec3::new(1.2, 0.7, 0.0)))
            .collect();
        Ok(Running {
            window,
            renderer,
            target,
            cow,
        })
    }
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.running.is_some() {
            return;
        }
        match self.start(event_loop) {
            Ok(running) => {
                let info = running.renderer.gpu().adapter_info();
                println!("adapter: {} ({:?})", info.name, info.backend);
                self.running = Some(running);
                self.start = Some(Instant::now());
            }
            Err(error) => {
                self.error = Some(error.to_string());
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let Some(running) = self.running.as_mut() else {
            return;
        };
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) => {
                running
                    .target
                    .resize(running.renderer.gpu(), size.width, size.height)
            }
            WindowEvent::RedrawRequested => {
                let t = self.start.map_or(0.0, |s| s.elapsed().as_secs_f32());
                let cube = running.renderer.builtin_meshes().cube;
                let mut objects = vec![DrawObject::new(
                    cube,
                    Material::color(0.9, 0.4, 0.2),
                    Mat4::from_rotation_translation(
                        Quat::from_rotation_y(t),
                        Vec3::new(-1.2, 0.5, 0.0),
                    ),
                )];
                objects.extend(running.cow.iter().copied());
                let lights = Lights {
                    points: vec![PointLight::new(Vec3::new(0.0, 1.5, 1.5))
                        .with_color(Vec3::new(0.4, 0.6, 1.0))],
                    ..Lights::default()
                };
                let camera = Camera::perspective_look_at(
                    Vec3::new(0.0, 2.0, 4.5),
                    Vec3::new(0.0, 0.4, 0.0),
                    0.9,
                    0.1,
                    200.0,
                );
                let scene = RenderScene::new(camera, &lights)
                    .with_objects(&objects)
                    .with_grid(true);
                match running.renderer.render(&mut running.target, &scene) {
                    Ok(_) => {}
                    Err(RenderError::SurfaceLost) => {
                        self.error = Some("surface lost".to_owned());
                        event_loop.exit();
                    }
                    Err(error) => eprintln!("frame failed: {error}"),
                }
                for event in running.renderer.drain_events() {
                    eprintln!("graphics event: {event}");
                    self.gpu_events += 1;
                }
                self.frame += 1;
                if let Some(max) = self.max_frames {
                    // Exercise the window paths a host meets: minimise and vsync off.
                    let gpu = running.renderer.gpu();
                    if self.frame == max / 3 {
                        running.target.resize(gpu, 0, 0);
                    } else if self.frame == max / 3 + 5 {
                        let size = running.window.inner_size();
                        running.target.resize(gpu, size.width, size.height);
                        running.target.set_vsync(gpu, false);
                    }
                    if self.frame >= max {
                        let stats = running.renderer.stats();
                        println!("{} frames, last frame: {stats:?}", self.frame);
                        event_loop.exit();
                    }
                }
            }
            _ => {}
        }
    }

    fn about_to_wait(&mut self, _event_loop: &ActiveEventLoop) {
        if let Some(running) = &self.running {
            running.window.request_redraw();
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut app = App::default();
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        if arg == "--frames" {
            app.max_frames = args.next().and_then(|n| n.parse().ok());
        }
    }
    let event_loop = EventLoop::new()?;
    event_loop.set_control_flow(ControlFlow::Poll);
    event_loop.run_app(&mut app)?;
    if let Some(error) = app.error {
        return Err(error.into());
    }
    if app.gpu_events > 0 {
        return Err(format!("{} graphics events", app.gpu_events).into());
    }
    Ok(())
}
