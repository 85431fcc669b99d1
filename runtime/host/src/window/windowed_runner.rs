//! [`run_windowed`]: drives a [`Host`] from a winit window.

use std::sync::Arc;
use std::time::{Duration, Instant};

use onyx_render::{GpuContext, RenderSettings, Renderer, SurfaceTarget};

use onyx_plugin_api::{InputEvent, WindowEvent as OnyxWindowEvent};
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{DeviceEvent, DeviceId, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{KeyCode, PhysicalKey};
use winit::window::{Window, WindowId};

use super::winit_input::{key_event, map_button, scroll_event};
use super::WindowError;
use crate::render::RenderSystem;
use crate::Host;

/// How the window is opened and how long it runs.
#[derive(Clone, Debug)]
pub struct WindowOptions {
    /// Title bar text.
    pub title: String,
    /// Initial inner size in physical pixels.
    pub size: (u32, u32),
    /// Stop after this many frames (`None`: until closed or a plugin quits).
    pub frames: Option<u64>,
    /// Frames per second the loop aims for (on top of vsync, and without a renderer).
    pub target_fps: f64,
    /// Wait for the display's refresh before presenting.
    pub vsync: bool,
    /// MSAA samples per pixel of the window's scene: 1 (off) or 4. Default 4 (the renderer
    /// falls back to 1, with a warning, where the adapter cannot).
    pub msaa_samples: u32,
    /// The sky (procedural by default, or an HDR image).
    pub sky: onyx_render::Sky,
}

impl Default for WindowOptions {
    fn default() -> Self {
        Self {
            title: "Onyx".into(),
            size: (1280, 720),
            frames: None,
            target_fps: 60.0,
            vsync: true,
            msaa_samples: 4,
            sky: onyx_render::Sky::default(),
        }
    }
}

/// What a windowed run did.
#[derive(Debug, Default)]
pub struct WindowedSummary {
    /// Frames run.
    pub frames: u64,
    /// Last size of the window's drawable area.
    pub final_size: (u32, u32),
    /// The renderer the window drew with (`None` when rendering was unavailable), kept for
    /// a final offscreen screenshot.
    pub render: Option<RenderSystem>,
}

/// A renderer drawing into the window's surface.
struct WindowGraphics {
    system: RenderSystem,
    target: SurfaceTarget,
}

fn window_graphics(
    window: Arc<Window>,
    vsync: bool,
    msaa_samples: u32,
    sky: onyx_render::Sky,
) -> Result<WindowGraphics, String> {
    let size = window.inner_size();
    let instance = GpuContext::create_instance();
    let surface = instance
        .create_surface(window)
        .map_err(|e| format!("no surface for the window: {e}"))?;
    let gpu = GpuContext::from_instance(instance, Some(&surface)).map_err(|e| e.to_string())?;
    let settings = RenderSettings {
        shader_dir: crate::render::shader_dir(),
        msaa_samples,
        sky,
        ..RenderSettings::default()
    };
    let renderer = Renderer::new(gpu, settings).map_err(|e| e.to_string())?;
    let target = SurfaceTarget::new(renderer.gpu(), surface, size.width, size.height, vsync)
        .map_err(|e| e.to_string())?;
    let mut system = RenderSystem::new(renderer);
    if let Err(error) = system.watch_shaders() {
        tracing::warn!("shader changes will not be picked up: {error}");
    }
    if let Err(error) = system.watch_assets() {
        tracing::warn!("model and texture changes will not be picked up: {error}");
    }
    Ok(WindowGraphics { system, target })
}

struct App<'h> {
    host: &'h mut Host,
    options: WindowOptions,
    window: Option<Arc<Window>>,
    graphics: Option<WindowGraphics>,
    gui: Option<super::WindowGui>,
    error: Option<WindowError>,
    last_frame: Option<Instant>,
    next_frame: Instant,
    summary: WindowedSummary,
}

/// Opens a window and runs `host` in it until a plugin quits, the window is closed, or
/// `options.frames` frames have run. F5 reloads every plugin whose library changed; F3 toggles
/// physics debug lines. Must be called on the main thread, once per process
/// (winit allows one event loop).
pub fn run_windowed(
    host: &mut Host,
    options: WindowOptions,
) -> Result<WindowedSummary, WindowError> {
    let event_loop = EventLoop::new().map_err(WindowError::EventLoop)?;
    let mut app = App {
        host,
        options,
        window: None,
        graphics: None,
        gui: None,
        error: None,
        last_frame: None,
        next_frame: Instant::now(),
        summary: WindowedSummary::default(),
    };
    let ran = event_loop.run_app(&mut app);
    // The title sink holds the window: let both go.
    crate::watchdog::set_stuck_sink(None);
    ran.map_err(WindowError::EventLoop)?;
    app.summary.render = app.graphics.take().map(|g| g.system);
    match app.error {
        Some(error) => Err(error),
        None => Ok(app.summary),
    }
}

/// While the watchdog reports a stuck plugin call, the title says so (the window cannot
/// repaint then). Not on macOS, where a title is set on the main thread — the stuck one.
fn show_stuck_calls_in_title(window: &Arc<Window>, title: &str) {
    if cfg!(target_os = "macos") {
        return;
    }
    let window = window.clone();
    let title = title.to_owned();
    crate::watchdog::set_stuck_sink(Some(Arc::new(move |stuck: Option<&str>| match stuck {
        Some(sentence) => window.set_title(&format!("{title} (not responding: {sentence})")),
        None => window.set_title(&title),
    })));
}

impl App<'_> {
    fn frame_interval(&self) -> Duration {
        Duration::from_secs_f64(1.0 / self.options.target_fps.max(1.0))
    }

    fn run_frame(&mut self, event_loop: &ActiveEventLoop) {
        let now = Instant::now();
        let dt = self
            .last_frame
            .map(|t| now.duration_since(t).as_secs_f64())
            .unwrap_or(1.0 / self.options.target_fps.max(1.0));
        self.last_frame = Some(now);
        if let (Some(gui), Some(window)) = (&mut self.gui, &self.window) {
            gui.before_frame(self.host, window);
        }
        let report = self.host.frame(dt);
        if let (Some(gui), Some(window)) = (&mut self.gui, &self.window) {
            gui.after_frame(self.host, window);
        }
        if let Some(graphics) = &mut self.graphics {
            if let Err(error) = self.host.render(&mut graphics.system, &mut graphics.target) {
                tracing::error!("frame not drawn: {error}");
            }
        }
        self.summary.frames += 1;
        let done = self
            .options
            .frames
            .is_some_and(|n| self.summary.frames >= n);
        if report.quit || done {
            event_loop.exit();
        }
    }
}

impl ApplicationHandler for App<'_> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.window.is_some() {
            return;
        }
        let (w, h) = self.options.size;
        let attributes = Window::default_attributes()
            .with_title(self.options.title.clone())
            .with_inner_size(PhysicalSize::new(w.max(1), h.max(1)));
        match event_loop.create_window(attributes) {
            Ok(window) => {
                let window = Arc::new(window);
                match window_graphics(
                    window.clone(),
                    self.options.vsync,
                    self.options.msaa_samples,
                    self.options.sky.clone(),
                ) {
                    Ok(graphics) => {
                        let info = graphics.system.renderer().gpu().adapter_info();
                        tracing::info!(adapter = %info.name, backend = ?info.backend, "drawing into the window");
                        self.graphics = Some(graphics);
                    }
                    Err(error) => {
                        tracing::warn!("rendering disabled, the window stays empty: {error}")
                    }
                }
                let size = window.inner_size();
                tracing::info!(width = size.width, height = size.height, "window opened");
                self.summary.final_size = (size.width, size.height);
                self.host.push_event(OnyxWindowEvent::Resized {
                    width: size.width,
                    height: size.height,
                });
                self.gui = Some(super::WindowGui::new(&window));
                show_stuck_calls_in_title(&window, &self.options.title);
                self.window = Some(window);
                self.next_frame = Instant::now();
            }
            Err(error) => {
                self.error = Some(WindowError::CreateWindow(error));
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        if let (Some(gui), Some(window)) = (&mut self.gui, &self.window) {
            gui.on_window_event(window, &event);
        }
        match event {
            WindowEvent::CloseRequested => {
                // Plugins see the event in the next frame; it quits unless one of them keeps
                // the window open to ask about unsaved work (`Ctx::prevent_close`).
                self.host.push_event(OnyxWindowEvent::CloseRequested);
                self.run_frame(event_loop);
            }
            WindowEvent::Resized(size) => {
                self.summary.final_size = (size.width, size.height);
                if let Some(graphics) = &mut self.graphics {
                    let gpu = graphics.system.renderer().gpu();
                    graphics.target.resize(gpu, size.width, size.height);
                }
                self.host.push_event(OnyxWindowEvent::Resized {
                    width: size.width,
                    height: size.height,
                });
            }
            WindowEvent::Focused(focused) => {
                self.host.push_event(OnyxWindowEvent::Focused(focused))
            }
            WindowEvent::KeyboardInput { event, .. } => {
                if event.physical_key == PhysicalKey::Code(KeyCode::F5)
                    && event.state.is_pressed()
                    && !event.repeat
                {
                    tracing::info!(
                        "F5: reloading every plugin whose library changed (and faulted ones)"
                    );
                    self.host.reload_all();
                }
                if event.physical_key == PhysicalKey::Code(KeyCode::F3)
                    && event.state.is_pressed()
                    && !event.repeat
                {
                    if let Some(graphics) = &mut self.graphics {
                        graphics.system.physics_debug = !graphics.system.physics_debug;
                    }
                }
                self.host
                    .push_event(key_event(event.physical_key, event.state, event.repeat));
                if event.state.is_pressed() {
                    if let Some(text) = event.text.filter(|t| !t.chars().all(char::is_control)) {
                        self.host.push_event(InputEvent::Text(text.to_string()));
                    }
                }
            }
            WindowEvent::MouseInput { state, button, .. } => {
                self.host.push_event(InputEvent::MouseButton {
                    button: map_button(button),
                    pressed: state.is_pressed(),
                })
            }
            WindowEvent::CursorMoved { position, .. } => {
                self.host.push_event(InputEvent::CursorMoved {
                    x: position.x as f32,
                    y: position.y as f32,
                })
            }
            WindowEvent::MouseWheel { delta, .. } => self.host.push_event(scroll_event(delta)),
            _ => {}
        }
    }

    fn device_event(&mut self, _: &ActiveEventLoop, _: DeviceId, event: DeviceEvent) {
        if let DeviceEvent::MouseMotion { delta } = event {
            self.host.push_event(InputEvent::MouseMotion {
                dx: delta.0 as f32,
                dy: delta.1 as f32,
            });
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if self.window.is_none() {
            return;
        }
        let now = Instant::now();
        if now >= self.next_frame {
            self.run_frame(event_loop);
            let interval = self.frame_interval();
            self.next_frame += interval;
            if self.next_frame < now {
                self.next_frame = now + interval;
            }
        }
        event_loop.set_control_flow(ControlFlow::WaitUntil(self.next_frame));
    }

    fn exiting(&mut self, _: &ActiveEventLoop) {
        tracing::info!(frames = self.summary.frames, "window closed");
    }
}
