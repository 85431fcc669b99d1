//! The Diagnostics panel: frame time and fps with a history plot, physics, rendering and
//! per-plugin, per-stage times.

use std::collections::VecDeque;

use onyx_plugin_api::tools::Diagnostics;
use onyx_plugin_api::{egui, Ctx};

/// Frames in the plot.
const HISTORY: usize = 240;

/// The panel's state.
#[derive(Debug, Default)]
pub struct DiagnosticsState {
    last: Diagnostics,
    /// Why the last figures could not be read.
    error: Option<String>,
    history: VecDeque<f32>,
}

impl DiagnosticsState {
    /// Reads the last frame's figures.
    pub fn poll(&mut self, ctx: &mut Ctx) {
        match ctx.diagnostics() {
            Ok(last) => {
                self.last = last;
                self.error = None;
            }
            Err(error) => {
                self.error = Some(error.to_string());
                return;
            }
        }
        self.history.push_back(self.last.frame_interval_ms as f32);
        while self.history.len() > HISTORY {
            self.history.pop_front();
        }
    }

    /// Draws the panel.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        if let Some(error) = &self.error {
            ui.colored_label(egui::Color32::LIGHT_RED, error);
        }
        let d = &self.last;
        let fps = if d.frame_interval_ms > 0.0 {
            1000.0 / d.frame_interval_ms
        } else {
            0.0
        };
        ui.label(format!(
            "frame {:.2} ms (work {:.2} ms) · {fps:.0} fps",
            d.frame_interval_ms, d.frame_ms
        ));
        self.plot(ui);
        egui::Grid::new("diag-figures")
            .striped(true)
            .show(ui, |ui| {
                let rows = [
                    ("fixed steps", d.fixed_steps.to_string()),
                    ("physics", format!("{:.3} ms", d.physics_ms)),
                    ("contacts", d.contacts.to_string()),
                    (
                        "bodies awake / asleep",
                        format!("{} / {}", d.awake_bodies, d.asleep_bodies),
                    ),
                    ("draw calls", d.draw_calls.to_string()),
                    ("triangles", d.triangles.to_string()),
                    ("instances", d.instances.to_string()),
                    ("entities", d.entities.to_string()),
                ];
                for (name, value) in rows {
                    ui.label(name);
                    ui.label(value);
                    ui.end_row();
                }
            });
        ui.separator();
        egui::Grid::new("diag-plugins")
            .striped(true)
            .show(ui, |ui| {
                ui.strong("plugin");
                ui.strong("stage");
                ui.strong("calls");
                ui.strong("ms");
                ui.end_row();
                for plugin in &d.plugins {
                    for stage in &plugin.stages {
                        ui.label(&plugin.plugin);
                        ui.label(&stage.stage);
                        ui.label(stage.calls.to_string());
                        ui.label(format!("{:.3}", stage.ms));
                        ui.end_row();
                    }
                }
            });
    }

    fn plot(&self, ui: &mut egui::Ui) {
        let width = ui.available_width().max(50.0);
        let (rect, _) = ui.allocate_exact_size(egui::vec2(width, 60.0), egui::Sense::hover());
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 2.0, egui::Color32::from_gray(25));
        let top = self
            .history
            .iter()
            .copied()
            .fold(1.0f32, f32::max)
            .max(33.4);
        for (ms, color) in [
            (16.7, egui::Color32::from_rgb(60, 120, 60)),
            (33.3, egui::Color32::from_rgb(120, 90, 40)),
        ] {
            let y = rect.bottom() - ms / top * rect.height();
            painter.hline(rect.x_range(), y, egui::Stroke::new(1.0, color));
        }
        let n = self.history.len();
        if n < 2 {
            return;
        }
        let points: Vec<egui::Pos2> = self
            .history
            .iter()
            .enumerate()
            .map(|(i, ms)| {
                egui::pos2(
                    rect.left() + rect.width() * i as f32 / (HISTORY - 1) as f32,
                    rect.bottom() - (ms / top).min(1.0) * rect.height(),
                )
            })
            .collect();
        painter.add(egui::Shape::line(
            points,
            egui::Stroke::new(1.5, egui::Color32::from_rgb(110, 200, 250)),
        ));
    }
}
