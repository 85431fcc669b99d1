//! Generic editing of a JSON value as a tree of fields: numbers as drags, booleans as
//! checkboxes, strings as text fields, arrays and objects as collapsible groups.

use onyx_plugin_api::egui;
use serde_json::Value;

/// Edits `value` in place; returns whether anything changed.
pub fn edit(ui: &mut egui::Ui, label: &str, value: &mut Value, id: egui::Id) -> bool {
    match value {
        Value::Null => {
            ui.horizontal(|ui| {
                ui.label(label);
                ui.weak("null");
            });
            false
        }
        Value::Bool(b) => ui.checkbox(b, label).changed(),
        Value::Number(n) => {
            let mut x = n.as_f64().unwrap_or(0.0);
            let integer = n.is_i64() || n.is_u64();
            let changed = ui
                .horizontal(|ui| {
                    ui.label(label);
                    let drag = egui::DragValue::new(&mut x).speed(if integer { 1.0 } else { 0.01 });
                    ui.add(drag).changed()
                })
                .inner;
            if changed {
                let new = if integer {
                    Value::from(x.round() as i64)
                } else {
                    serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
                };
                if !new.is_null() {
                    *value = new;
                }
            }
            changed
        }
        Value::String(s) => {
            ui.horizontal(|ui| {
                ui.label(label);
                ui.text_edit_singleline(s).changed()
            })
            .inner
        }
        Value::Array(items) => {
            let mut changed = false;
            egui::CollapsingHeader::new(format!("{label} [{}]", items.len()))
                .id_salt(id)
                .default_open(items.len() <= 4)
                .show(ui, |ui| {
                    for (i, item) in items.iter_mut().enumerate() {
                        changed |= edit(ui, &i.to_string(), item, id.with(i));
                    }
                });
            changed
        }
        Value::Object(fields) => {
            let mut changed = false;
            let mut body = |ui: &mut egui::Ui| {
                for (key, field) in fields.iter_mut() {
                    changed |= edit(ui, key, field, id.with(key.as_str()));
                }
            };
            if label.is_empty() {
                body(ui);
            } else {
                egui::CollapsingHeader::new(label)
                    .id_salt(id)
                    .default_open(true)
                    .show(ui, body);
            }
            changed
        }
    }
}
