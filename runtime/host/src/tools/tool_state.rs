//! [`ToolState`]: what the host keeps for the tool services (the editor's needs).

use std::path::PathBuf;

use onyx_plugin_api::tools::{Diagnostics, PluginInfo};

use super::MeshBounds;
use crate::diagnostics::FrameDiagnostics;
use crate::play_mode::PlaySession;
use crate::scripts::{ScriptRegistry, ScriptRunner};

/// The host's side of the tool services, kept in the host's state.
#[derive(Debug, Default)]
pub struct ToolState {
    /// Frame timings and counts.
    pub diagnostics: FrameDiagnostics,
    /// The plugins as of the start of this frame (plugin calls cannot see the plugins).
    pub plugin_infos: Vec<PluginInfo>,
    /// What `plugin_infos` was built from (names, reloads, faults), to rebuild it only
    /// when that changes.
    pub plugin_infos_signature: Option<u64>,
    /// Edit / play / pause and the snapshot taken at Play.
    pub play: PlaySession,
    /// Registered scripts.
    pub scripts: ScriptRegistry,
    /// Which entities run which script.
    pub script_runner: ScriptRunner,
    /// Bumped each time the whole world is replaced (new or opened scene, Stop), so
    /// per-entity bookkeeping knows its handles are stale.
    pub world_generation: u64,
    /// The scene file the world was last opened from or saved to (or loaded from with
    /// `--scene`).
    pub scene_path: Option<PathBuf>,
    /// The meshes' shapes, for picking and outlines.
    pub mesh_bounds: MeshBounds,
}

impl ToolState {
    /// The last complete frame's figures, with each plugin's time per lifecycle method.
    pub fn diagnostics(&self) -> Diagnostics {
        Diagnostics {
            plugins: (self.diagnostics.timer)
                .last(self.plugin_infos.iter().map(|p| p.name.as_str())),
            ..self.diagnostics.last.clone()
        }
    }
}
