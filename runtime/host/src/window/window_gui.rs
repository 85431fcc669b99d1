//! [`WindowGui`]: the window's side of plugin GUIs, through egui-winit — winit events become
//! egui input (with the platform's modifiers, clipboard paste, IME), and the plugins'
//! platform output is applied (cursor icon, copied text to the clipboard, IME position).

use winit::event::WindowEvent;
use winit::window::Window;

use crate::Host;

/// egui-winit's state for the host window.
pub struct WindowGui {
    state: egui_winit::State,
}

impl std::fmt::Debug for WindowGui {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("WindowGui").finish_non_exhaustive()
    }
}

impl WindowGui {
    /// The GUI state of `window`. Its egui context lives in the host's image and is used
    /// only by egui-winit's bookkeeping; each plugin draws with its own.
    pub fn new(window: &Window) -> Self {
        let state = egui_winit::State::new(
            egui::Context::default(),
            egui::ViewportId::ROOT,
            window,
            Some(window.scale_factor() as f32),
            window.theme(),
            None,
        );
        Self { state }
    }

    /// Feeds a window event to egui-winit (the host gets its own Onyx input event as well).
    pub fn on_window_event(&mut self, window: &Window, event: &WindowEvent) {
        let _ = self.state.on_window_event(window, event);
    }

    /// Hands the next frame's egui input and the window's scale to the host.
    pub fn before_frame(&mut self, host: &mut Host, window: &Window) {
        let raw = self.state.take_egui_input(window);
        let input = host.gui_mut().input_mut();
        input.set_pixels_per_point(window.scale_factor() as f32);
        input.set_external(raw);
    }

    /// Applies what the plugins' UIs asked of the platform this frame.
    pub fn after_frame(&mut self, host: &mut Host, window: &Window) {
        let output = host.gui_mut().take_platform_output();
        self.state.handle_platform_output(window, output);
    }
}
