//! [`OrbitCamera`]: the view used when the scene has no camera.

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{InputState, MouseButton};

/// Radians of orbit per pixel of mouse motion.
const ORBIT_SPEED: f32 = 0.005;
/// Fraction of the distance each scroll line zooms.
const ZOOM_STEP: f32 = 0.1;

/// A camera circling a target point: right-drag orbits, the wheel zooms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    /// The point looked at.
    pub target: Vec3,
    /// Distance from the target, metres.
    pub distance: f32,
    /// Angle about Y, radians.
    pub yaw: f32,
    /// Angle above the XZ plane, radians.
    pub pitch: f32,
}

impl Default for OrbitCamera {
    fn default() -> Self {
        Self {
            target: Vec3::new(0.0, 0.5, 0.0),
            distance: 10.0,
            yaw: 0.6,
            pitch: 0.45,
        }
    }
}

impl OrbitCamera {
    /// The eye position.
    pub fn eye(&self) -> Vec3 {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        self.target + Vec3::new(sy * cp, sp, cy * cp) * self.distance
    }

    /// Applies this frame's mouse input.
    pub fn control(&mut self, input: &InputState) {
        if input.mouse_down(MouseButton::Right) {
            let d = input.cursor_delta();
            self.yaw -= d.x * ORBIT_SPEED;
            self.pitch = (self.pitch + d.y * ORBIT_SPEED).clamp(-1.5, 1.5);
        }
        let scroll = input.scroll().y;
        if scroll != 0.0 {
            self.distance = (self.distance * (1.0 - ZOOM_STEP * scroll)).clamp(0.5, 500.0);
        }
    }
}
