//! Finding a widget by its label in a plugin's AccessKit tree (as `egui_kittest` does), so
//! tests click real widgets instead of guessing coordinates.

use egui::accesskit::TreeUpdate;
use egui::{Pos2, Rect};

/// The screen rectangle (points) of the first widget in `tree` whose label (or, for plain
/// text, whose value) is exactly `label`. Disabled widgets are found too.
pub fn find_widget(tree: &TreeUpdate, label: &str) -> Option<Rect> {
    tree.nodes.iter().find_map(|(_, node)| {
        let named = node.label() == Some(label) || node.value() == Some(label);
        let bounds = node.bounds()?;
        named.then(|| {
            Rect::from_min_max(
                Pos2::new(bounds.x0 as f32, bounds.y0 as f32),
                Pos2::new(bounds.x1 as f32, bounds.y1 as f32),
            )
        })
    })
}
