//! Finding a widget by its label in a plugin's AccessKit tree (as `egui_kittest` does), so
//! tests click real widgets instead of guessing coordinates.

use egui::accesskit::TreeUpdate;
use egui::{Pos2, Rect};

/// The screen rectangles (points) of every widget in `tree` whose label (or, for plain
/// text, whose value) passes `test`, in tree order. Disabled widgets are found too.
pub fn find_widgets_where(tree: &TreeUpdate, test: impl Fn(&str) -> bool) -> Vec<Rect> {
    tree.nodes
        .iter()
        .filter(|(_, node)| node.label().is_some_and(&test) || node.value().is_some_and(&test))
        .filter_map(|(_, node)| {
            let bounds = node.bounds()?;
            Some(Rect::from_min_max(
                Pos2::new(bounds.x0 as f32, bounds.y0 as f32),
                Pos2::new(bounds.x1 as f32, bounds.y1 as f32),
            ))
        })
        .collect()
}
