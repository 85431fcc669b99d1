//! [`Panel`]: the editor's dockable panels, their default arrangement, and the layout file.

use std::path::Path;

use egui_dock::{DockState, NodeIndex};
use serde::{Deserialize, Serialize};

/// One dockable panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Panel {
    /// Every entity, filterable.
    Hierarchy,
    /// The selection's name and components.
    Inspector,
    /// The scene, with the fly camera and the gizmo.
    Viewport,
    /// The host's log lines.
    Console,
    /// Frame figures.
    Diagnostics,
}

impl Panel {
    /// Every panel, in menu order.
    pub const ALL: [Panel; 5] = [
        Panel::Hierarchy,
        Panel::Inspector,
        Panel::Viewport,
        Panel::Console,
        Panel::Diagnostics,
    ];

    /// The tab title.
    pub fn title(self) -> &'static str {
        match self {
            Panel::Hierarchy => "Hierarchy",
            Panel::Inspector => "Inspector",
            Panel::Viewport => "Viewport",
            Panel::Console => "Console",
            Panel::Diagnostics => "Diagnostics",
        }
    }
}

/// Where the layout is kept when no `editor.layout` setting names a file.
pub const DEFAULT_LAYOUT_PATH: &str = ".onyx/editor-layout.json";

/// Hierarchy left, inspector right, viewport in the middle, console and diagnostics below it.
pub fn default_layout() -> DockState<Panel> {
    let mut dock = DockState::new(vec![Panel::Viewport]);
    let surface = dock.main_surface_mut();
    let [center, _] = surface.split_left(NodeIndex::root(), 0.2, vec![Panel::Hierarchy]);
    let [center, _] = surface.split_right(center, 0.72, vec![Panel::Inspector]);
    surface.split_below(center, 0.7, vec![Panel::Console, Panel::Diagnostics]);
    dock
}

/// Shows `panel` when hidden (in the focused leaf), hides it when shown.
pub fn toggle(dock: &mut DockState<Panel>, panel: Panel) {
    match dock.find_tab(&panel) {
        Some(path) => {
            dock.remove_tab(path);
        }
        None => dock.push_to_first_leaf(panel),
    }
}

/// Why a layout file could not be read.
#[derive(Debug)]
pub enum LayoutError {
    /// The file could not be read.
    Io(std::io::Error),
    /// The file is not a layout.
    Format(serde_json::Error),
}

impl std::fmt::Display for LayoutError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LayoutError::Io(e) => write!(f, "cannot read it: {e}"),
            LayoutError::Format(e) => write!(f, "it is not an editor layout: {e}"),
        }
    }
}

/// Reads a layout file; `Ok(None)` when there is none yet.
pub fn load_layout(path: &Path) -> Result<Option<DockState<Panel>>, LayoutError> {
    let text = match std::fs::read_to_string(path) {
        Ok(text) => text,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(LayoutError::Io(e)),
    };
    let dock: DockState<Panel> = serde_json::from_str(&text).map_err(LayoutError::Format)?;
    if dock.iter_all_tabs().next().is_none() {
        return Ok(Some(default_layout()));
    }
    Ok(Some(dock))
}

/// Writes a layout file atomically: a temporary file beside it, then a rename.
pub fn save_layout(path: &Path, dock: &DockState<Panel>) -> std::io::Result<()> {
    let text = serde_json::to_string_pretty(dock).map_err(std::io::Error::other)?;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    crate::atomic_file::write(path, text.as_bytes())
}
