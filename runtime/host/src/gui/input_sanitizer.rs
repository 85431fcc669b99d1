//! Input made safe before any plugin sees it: a value no device sends (NaN, infinity, a
//! scroll of `-f32::MAX`) is dropped or brought into range, so a plugin's UI library never
//! computes with it (egui turned such a scroll into NaN and panicked).

use onyx_plugin_api::egui::{self, RawInput};
use onyx_plugin_api::InputEvent;

/// Largest pointer coordinate kept, pixels or points (a screen is a few thousand).
pub const MAX_COORDINATE: f32 = 1.0e5;
/// Largest motion or scroll of one event kept, in its unit (lines, points or pixels).
pub const MAX_DELTA: f32 = 1.0e4;
/// Range of a pinch zoom factor kept.
pub const ZOOM_RANGE: (f32, f32) = (1.0e-3, 1.0e3);

fn coordinate(v: f32) -> Option<f32> {
    v.is_finite()
        .then(|| v.clamp(-MAX_COORDINATE, MAX_COORDINATE))
}

fn delta(v: f32) -> Option<f32> {
    v.is_finite().then(|| v.clamp(-MAX_DELTA, MAX_DELTA))
}

fn pos(p: egui::Pos2) -> Option<egui::Pos2> {
    Some(egui::pos2(coordinate(p.x)?, coordinate(p.y)?))
}

fn vec(v: egui::Vec2) -> Option<egui::Vec2> {
    Some(egui::vec2(delta(v.x)?, delta(v.y)?))
}

/// `event` with its numbers in range, or `None` when a number is not finite.
pub fn sanitized(event: InputEvent) -> Option<InputEvent> {
    Some(match event {
        InputEvent::CursorMoved { x, y } => InputEvent::CursorMoved {
            x: coordinate(x)?,
            y: coordinate(y)?,
        },
        InputEvent::MouseMotion { dx, dy } => InputEvent::MouseMotion {
            dx: delta(dx)?,
            dy: delta(dy)?,
        },
        InputEvent::Scroll { dx, dy } => InputEvent::Scroll {
            dx: delta(dx)?,
            dy: delta(dy)?,
        },
        other => other,
    })
}

/// Drops or brings into range every number of `raw` a device could not have sent.
pub fn sanitize(raw: &mut RawInput) {
    if let Some(rect) = raw.screen_rect {
        if pos(rect.min).is_none() || pos(rect.max).is_none() || !rect.is_positive() {
            raw.screen_rect = None;
        }
    }
    if !raw.predicted_dt.is_finite() || raw.predicted_dt < 0.0 {
        raw.predicted_dt = 1.0 / 60.0;
    }
    raw.events.retain_mut(|event| match event {
        egui::Event::PointerMoved(p) => pos(*p)
            .map(|p| *event = egui::Event::PointerMoved(p))
            .is_some(),
        egui::Event::MouseMoved(d) => vec(*d)
            .map(|d| *event = egui::Event::MouseMoved(d))
            .is_some(),
        egui::Event::PointerButton { pos: p, .. } => pos(*p).map(|q| *p = q).is_some(),
        egui::Event::Touch { pos: p, force, .. } => {
            if force.is_some_and(|f| !f.is_finite()) {
                *force = None;
            }
            pos(*p).map(|q| *p = q).is_some()
        }
        egui::Event::MouseWheel { delta: d, .. } => vec(*d).map(|v| *d = v).is_some(),
        egui::Event::Zoom(z) => {
            if z.is_finite() && *z > 0.0 {
                *z = z.clamp(ZOOM_RANGE.0, ZOOM_RANGE.1);
                true
            } else {
                false
            }
        }
        egui::Event::Rotate(r) => r.is_finite(),
        _ => true,
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn impossible_numbers_are_dropped_and_huge_ones_brought_into_range() {
        assert_eq!(
            sanitized(InputEvent::Scroll {
                dx: 0.0,
                dy: f32::NAN
            }),
            None
        );
        assert_eq!(
            sanitized(InputEvent::Scroll {
                dx: 0.0,
                dy: -f32::MAX
            }),
            Some(InputEvent::Scroll {
                dx: 0.0,
                dy: -MAX_DELTA
            })
        );
        assert_eq!(
            sanitized(InputEvent::CursorMoved {
                x: f32::INFINITY,
                y: 1.0
            }),
            None
        );
        let mut raw = RawInput {
            events: vec![
                egui::Event::PointerMoved(egui::pos2(f32::NAN, 0.0)),
                egui::Event::MouseWheel {
                    unit: egui::MouseWheelUnit::Line,
                    delta: egui::vec2(0.0, -f32::MAX),
                    phase: egui::TouchPhase::Move,
                    modifiers: egui::Modifiers::NONE,
                },
                egui::Event::Zoom(f32::INFINITY),
                egui::Event::Text("kept".into()),
            ],
            ..RawInput::default()
        };
        sanitize(&mut raw);
        assert_eq!(raw.events.len(), 2, "{:?}", raw.events);
        assert!(
            matches!(raw.events[0], egui::Event::MouseWheel { delta, .. } if delta.y == -MAX_DELTA)
        );
    }
}
