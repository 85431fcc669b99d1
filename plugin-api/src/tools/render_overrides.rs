//! [`RenderOverrides`]: the editor's view switches.

use abi_stable::{std_types::ROption, StableAbi};

use crate::ShadingMode;

/// Switches a tool sets on the host's view; `None` leaves the host's own setting.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderOverrides {
    /// Draw the grid on Y = 0.
    pub grid: ROption<bool>,
    /// Draw collider outlines and contacts.
    pub physics_debug: ROption<bool>,
    /// Shade every object this way instead of its own material's mode.
    pub shading: ROption<ShadingMode>,
}

impl RenderOverrides {
    /// Grid on or off.
    #[must_use]
    pub fn with_grid(mut self, on: bool) -> Self {
        self.grid = ROption::RSome(on);
        self
    }

    /// Physics debug drawing on or off.
    #[must_use]
    pub fn with_physics_debug(mut self, on: bool) -> Self {
        self.physics_debug = ROption::RSome(on);
        self
    }

    /// Shading of the whole view.
    #[must_use]
    pub fn with_shading(mut self, mode: ShadingMode) -> Self {
        self.shading = ROption::RSome(mode);
        self
    }
}
