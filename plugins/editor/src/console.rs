//! The Console panel: the host's log lines with level colours, a level filter and a text
//! filter.

use std::collections::VecDeque;

use onyx_plugin_api::tools::LogLine;
use onyx_plugin_api::{egui, Ctx};

/// Lines kept.
const KEPT: usize = 5000;
const LEVELS: [&str; 5] = ["TRACE", "DEBUG", "INFO", "WARN", "ERROR"];

/// The console's state.
#[derive(Debug, Default)]
pub struct ConsoleState {
    lines: VecDeque<LogLine>,
    last_seq: u64,
    /// Least level shown (index into TRACE..ERROR).
    pub min_level: usize,
    /// Text a line must contain.
    pub filter: String,
    shown: Vec<usize>,
    /// Why the last lines could not be read.
    error: Option<String>,
}

fn level_index(level: &str) -> usize {
    LEVELS.iter().position(|l| *l == level).unwrap_or(2)
}

fn level_color(level: &str) -> egui::Color32 {
    match level {
        "ERROR" => egui::Color32::from_rgb(240, 90, 90),
        "WARN" => egui::Color32::from_rgb(235, 190, 70),
        "INFO" => egui::Color32::from_rgb(200, 200, 200),
        "DEBUG" => egui::Color32::from_rgb(130, 170, 230),
        _ => egui::Color32::GRAY,
    }
}

impl ConsoleState {
    /// Reads the lines logged since the last call.
    pub fn poll(&mut self, ctx: &mut Ctx) {
        let new = match ctx.log_lines_since(self.last_seq) {
            Ok(new) => {
                self.error = None;
                new
            }
            Err(error) => {
                self.error = Some(error.to_string());
                return;
            }
        };
        if let Some(last) = new.last() {
            self.last_seq = last.seq;
        }
        self.lines.extend(new);
        while self.lines.len() > KEPT {
            self.lines.pop_front();
        }
    }

    /// Lines kept.
    pub fn len(&self) -> usize {
        self.lines.len()
    }

    /// Whether no line is kept.
    pub fn is_empty(&self) -> bool {
        self.lines.is_empty()
    }

    /// Draws the panel.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        if let Some(error) = &self.error {
            ui.colored_label(egui::Color32::LIGHT_RED, error);
        }
        ui.horizontal(|ui| {
            egui::ComboBox::from_id_salt("console-level")
                .selected_text(LEVELS[self.min_level])
                .show_ui(ui, |ui| {
                    for (i, level) in LEVELS.iter().enumerate() {
                        ui.selectable_value(&mut self.min_level, i, *level);
                    }
                });
            ui.label("Search");
            ui.text_edit_singleline(&mut self.filter);
            if ui.button("Clear").clicked() {
                self.lines.clear();
            }
        });
        ui.separator();
        let filter = self.filter.to_lowercase();
        self.shown.clear();
        for (i, line) in self.lines.iter().enumerate() {
            if level_index(&line.level) >= self.min_level
                && (filter.is_empty()
                    || line.message.to_lowercase().contains(&filter)
                    || line.source.to_lowercase().contains(&filter))
            {
                self.shown.push(i);
            }
        }
        let row_height = ui.text_style_height(&egui::TextStyle::Monospace);
        egui::ScrollArea::vertical()
            .auto_shrink([false, false])
            .stick_to_bottom(true)
            .show_rows(ui, row_height, self.shown.len(), |ui, range| {
                for &i in &self.shown[range] {
                    let line = &self.lines[i];
                    ui.label(
                        egui::RichText::new(format!(
                            "{} {:5} {}: {}",
                            clock(line.unix_ms),
                            line.level,
                            line.source,
                            line.message
                        ))
                        .monospace()
                        .color(level_color(&line.level)),
                    );
                }
            });
    }
}

/// `unix_ms` as `HH:MM:SS.mmm`, UTC (as the terminal log's timestamps).
fn clock(unix_ms: u64) -> String {
    let ms = unix_ms % 86_400_000;
    format!(
        "{:02}:{:02}:{:02}.{:03}",
        ms / 3_600_000,
        ms / 60_000 % 60,
        ms / 1000 % 60,
        ms % 1000
    )
}

#[cfg(test)]
mod tests {
    #[test]
    fn clock_reads_the_time_of_day_in_utc() {
        // 2026-11-22 11:40:05.042 UTC
        assert_eq!(super::clock(1_795_347_605_042), "11:40:05.042");
    }
}
