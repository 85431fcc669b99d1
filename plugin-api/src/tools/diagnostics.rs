//! [`Diagnostics`]: what the last frame cost, for a diagnostics panel.

use serde::{Deserialize, Serialize};

/// Figures of the last complete frame.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Diagnostics {
    /// Wall time of the host's frame (events, fixed steps, plugins), milliseconds.
    pub frame_ms: f64,
    /// Time between the starts of the last two frames, milliseconds (1000 / fps).
    pub frame_interval_ms: f64,
    /// Fixed steps run in the frame.
    pub fixed_steps: u32,
    /// Time spent in physics steps during the frame, milliseconds.
    pub physics_ms: f64,
    /// Contact points solved in the last physics step.
    pub contacts: u32,
    /// Bodies simulated (awake dynamic and kinematic bodies).
    pub awake_bodies: u32,
    /// Bodies asleep.
    pub asleep_bodies: u32,
    /// Draw calls of the last image drawn (0 when nothing is drawn).
    pub draw_calls: u32,
    /// Triangles of the last image drawn (mesh instances after culling).
    pub triangles: u64,
    /// Mesh instances of the last image drawn.
    pub instances: u32,
    /// Entities in the world.
    pub entities: u32,
    /// Time spent in each plugin, per lifecycle method, during the frame.
    pub plugins: Vec<PluginTiming>,
}

/// Time one plugin took in one frame.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PluginTiming {
    /// The plugin's name.
    pub plugin: String,
    /// Per lifecycle method that was called.
    pub stages: Vec<StageTiming>,
}

impl PluginTiming {
    /// Total milliseconds over all stages.
    pub fn total_ms(&self) -> f64 {
        self.stages.iter().map(|s| s.ms).sum()
    }
}

/// Time spent in one lifecycle method during one frame.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StageTiming {
    /// The method (`on_update`, `on_fixed_update`, `on_script`, …).
    pub stage: String,
    /// Calls made.
    pub calls: u32,
    /// Milliseconds spent, summed over the calls.
    pub ms: f64,
}
