//! [`FileDialog`]: an egui window listing a folder, with a text field for the file name.
//!
//! Why not `egui-file-dialog` (0.15 speaks egui 0.36): what the editor needs is a folder
//! listing filtered by extension, a typed name, and a start folder (the current scene's) —
//! about 200 lines here, driven by label in the editor's tests. That crate would add
//! `sysinfo` (it lists disks), `directories` and `dunce` to the editor's build, which every CI
//! run compiles on two cores, for features (drives, bookmarks, multi-select) no tool asks for
//! yet. Revisit when one does.

use std::path::{Path, PathBuf};

use onyx_plugin_api::egui;

/// What the chosen file is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FilePurpose {
    /// Open a scene.
    Open,
    /// Save the scene as.
    SaveAs,
    /// Import a model as a new entity.
    ImportObj,
    /// Load a plugin library.
    LoadPlugin,
}

impl FilePurpose {
    fn title(self) -> &'static str {
        match self {
            FilePurpose::Open => "Open scene",
            FilePurpose::SaveAs => "Save scene as",
            FilePurpose::ImportObj => "Import OBJ model",
            FilePurpose::LoadPlugin => "Load plugin",
        }
    }

    fn verb(self) -> &'static str {
        match self {
            FilePurpose::Open => "Open",
            FilePurpose::SaveAs => "Save",
            FilePurpose::ImportObj => "Import",
            FilePurpose::LoadPlugin => "Load",
        }
    }

    /// The files listed (folders always are).
    fn extension(self) -> &'static str {
        match self {
            FilePurpose::Open | FilePurpose::SaveAs => "ron",
            FilePurpose::ImportObj => "obj",
            FilePurpose::LoadPlugin => std::env::consts::DLL_EXTENSION,
        }
    }
}

/// An open file dialog.
#[derive(Debug)]
pub struct FileDialog {
    /// Open or save.
    pub purpose: FilePurpose,
    /// The folder listed.
    pub dir: PathBuf,
    /// The file name typed or clicked.
    pub name: String,
    entries: Vec<(String, bool)>,
}

/// What the dialog did this frame.
pub enum DialogResult {
    /// Still open.
    Open,
    /// Closed without a choice.
    Cancelled,
    /// A file was chosen.
    Chosen(String),
}

impl FileDialog {
    /// A dialog listing `dir` (a file path's folder works too).
    pub fn new(purpose: FilePurpose, start: &Path) -> Self {
        let (dir, name) = if start.is_dir() {
            (start.to_path_buf(), String::new())
        } else {
            (
                start
                    .parent()
                    .filter(|p| !p.as_os_str().is_empty())
                    .map(Path::to_path_buf)
                    .unwrap_or_else(|| PathBuf::from(".")),
                start
                    .file_name()
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or_default(),
            )
        };
        let mut dialog = Self {
            purpose,
            dir,
            name,
            entries: Vec::new(),
        };
        dialog.refresh();
        dialog
    }

    fn refresh(&mut self) {
        self.entries.clear();
        if let Ok(read) = std::fs::read_dir(&self.dir) {
            for entry in read.flatten() {
                let is_dir = entry.file_type().is_ok_and(|t| t.is_dir());
                let wanted = Path::new(&entry.file_name())
                    .extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case(self.purpose.extension()));
                if !is_dir && !wanted {
                    continue;
                }
                self.entries
                    .push((entry.file_name().to_string_lossy().into_owned(), is_dir));
            }
        }
        self.entries
            .sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    }

    /// Shows the dialog.
    pub fn show(&mut self, ctx: &egui::Context) -> DialogResult {
        let mut result = DialogResult::Open;
        egui::Window::new(self.purpose.title())
            .collapsible(false)
            .default_size([420.0, 320.0])
            .show(ctx, |ui| {
                ui.label(self.dir.display().to_string());
                let mut go_to = None;
                egui::ScrollArea::vertical()
                    .max_height(200.0)
                    .show(ui, |ui| {
                        if ui.selectable_label(false, "..").clicked() {
                            go_to = Some(self.dir.join(".."));
                        }
                        for (name, is_dir) in &self.entries {
                            let label = if *is_dir {
                                format!("{name}/")
                            } else {
                                name.clone()
                            };
                            let response = ui.selectable_label(&self.name == name, label);
                            if response.clicked() {
                                if *is_dir {
                                    go_to = Some(self.dir.join(name));
                                } else {
                                    self.name = name.clone();
                                }
                            }
                            if response.double_clicked() && !is_dir {
                                result = DialogResult::Chosen(self.path());
                            }
                        }
                    });
                if let Some(dir) = go_to {
                    self.dir = dir.canonicalize().unwrap_or(dir);
                    self.refresh();
                }
                ui.horizontal(|ui| {
                    ui.label("File name");
                    ui.text_edit_singleline(&mut self.name);
                });
                ui.horizontal(|ui| {
                    if ui
                        .add_enabled(
                            !self.name.trim().is_empty(),
                            egui::Button::new(self.purpose.verb()),
                        )
                        .clicked()
                    {
                        result = DialogResult::Chosen(self.path());
                    }
                    if ui.button("Cancel").clicked() {
                        result = DialogResult::Cancelled;
                    }
                });
            });
        result
    }

    /// The chosen path.
    pub fn path(&self) -> String {
        let name = self.name.trim();
        if Path::new(name).is_absolute() {
            name.to_owned()
        } else {
            self.dir.join(name).to_string_lossy().into_owned()
        }
    }
}
