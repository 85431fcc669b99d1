//! Autosave and recovery: while the open scene has unsaved edits, a copy of it is written
//! to a recovery folder every few seconds (and once more when the editor ends with edits
//! still unsaved); the next start finds the copy and offers it back.
//!
//! Each editor process writes its own pair of files, `scene-PID.ron` (the copy, through
//! [`Ctx::save_scene_copy`], atomically: a crash while writing leaves the previous copy; the
//! scene's own file is never touched by an autosave) and `about-PID.json` (which scene it is
//! a copy of, and when). A copy whose process is still running belongs to that editor and is
//! neither offered to another one nor deleted by it; the copies of processes that are gone
//! are offered one by one, newest first.
//!
//! Settings: `editor.autosave=SECS` (default 30; `0` turns autosave off) and
//! `editor.recovery=DIR` (default `.onyx/recovery`).

use std::path::{Path, PathBuf};
use std::time::{Instant, SystemTime, UNIX_EPOCH};

use onyx_plugin_api::{egui, AttachInfo, Ctx, PlayMode};
use serde::{Deserialize, Serialize};

use crate::history::History;
use crate::state::EditorState;

/// Where copies are kept unless `editor.recovery` says otherwise.
pub const DEFAULT_DIR: &str = ".onyx/recovery";
/// Seconds between autosaves unless `editor.autosave` says otherwise.
pub const DEFAULT_INTERVAL_SECS: f32 = 30.0;

/// What a recovery copy is a copy of.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct About {
    /// The scene file the copy was made from (`None`: an untitled scene).
    pub scene: Option<String>,
    /// When it was written, in seconds since the Unix epoch.
    pub saved_at: u64,
    /// The process that wrote it.
    pub pid: u32,
}

/// A copy left by an editor that did not end cleanly, waiting for the user's answer.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Offer {
    /// What it is a copy of.
    pub about: About,
    /// The copy.
    pub copy: PathBuf,
    /// Its note (`about-PID.json`; it may be missing).
    pub note: PathBuf,
}

/// The autosave clock, this editor's copy, and the copies on offer.
#[derive(Debug)]
pub struct Recovery {
    /// The recovery folder.
    pub dir: PathBuf,
    /// Seconds between autosaves; 0: off.
    pub interval: f32,
    /// When autosave last looked (wall time: the user's time, which passes in Edit mode
    /// too, where the frame's `dt` is 0).
    checked: Option<Instant>,
    /// The history revision this editor's copy on disk holds.
    written: Option<u64>,
    /// The last autosave error, reported once until it changes.
    last_error: Option<String>,
    /// Copies left by editors that did not end cleanly, newest first; the first is asked
    /// about. Autosave waits until every one is answered (one of them may be the copy this
    /// process would write over).
    pub offers: Vec<Offer>,
}

impl Default for Recovery {
    fn default() -> Self {
        Self {
            dir: PathBuf::from(DEFAULT_DIR),
            interval: DEFAULT_INTERVAL_SECS,
            checked: None,
            written: None,
            last_error: None,
            offers: Vec::new(),
        }
    }
}

impl Recovery {
    /// Reads `editor.autosave` and `editor.recovery`; a malformed interval is reported and
    /// the default kept.
    pub fn from_settings(ctx: &mut Ctx, info: &AttachInfo) -> Self {
        let mut recovery = Self::default();
        if let Some(dir) = info.setting("recovery") {
            recovery.dir = PathBuf::from(dir);
        }
        if let Some(text) = info.setting("autosave") {
            match text.trim().parse::<f32>() {
                Ok(secs) if secs.is_finite() && secs >= 0.0 => recovery.interval = secs,
                _ => ctx.warn(format!(
                    "editor.autosave={text} is not a number of seconds (0 turns autosave \
                     off); autosaving every {DEFAULT_INTERVAL_SECS} s"
                )),
            }
        }
        recovery
    }

    fn copy_path(&self, pid: u32) -> PathBuf {
        self.dir.join(format!("scene-{pid}.ron"))
    }

    fn note_path(&self, pid: u32) -> PathBuf {
        self.dir.join(format!("about-{pid}.json"))
    }

    /// Finds the copies left by editors that did not end cleanly (see [`show_offer`]).
    pub fn look_for_copies(&mut self) {
        self.offers.clear();
        let Ok(entries) = std::fs::read_dir(&self.dir) else {
            return; // no folder: nothing was ever autosaved here
        };
        for entry in entries.flatten() {
            let name = entry.file_name();
            let Some(pid) = name
                .to_str()
                .and_then(|n| n.strip_prefix("scene-"))
                .and_then(|n| n.strip_suffix(".ron"))
                .and_then(|n| n.parse::<u32>().ok())
            else {
                continue;
            };
            if pid != std::process::id() && process_alive(pid) {
                continue; // another editor is running: the copy is its own
            }
            let copy = entry.path();
            let note = self.note_path(pid);
            let about = std::fs::read(&note)
                .ok()
                .and_then(|bytes| serde_json::from_slice::<About>(&bytes).ok())
                .unwrap_or_else(|| About {
                    // A copy without its note (the note is written second): still worth it.
                    scene: None,
                    saved_at: modified_secs(&copy).unwrap_or(0),
                    pid,
                });
            self.offers.push(Offer { about, copy, note });
        }
        self.offers
            .sort_by_key(|o| std::cmp::Reverse(o.about.saved_at));
    }

    /// Every interval, writes this editor's copy when the scene has edits the copy on disk
    /// does not hold. Only in Edit mode: while playing, the world is the play session, not
    /// the scene.
    pub fn tick(&mut self, ctx: &mut Ctx, history: &History) {
        if self.interval <= 0.0 || !self.offers.is_empty() {
            return;
        }
        let now = Instant::now();
        let checked = *self.checked.get_or_insert(now);
        if now.duration_since(checked).as_secs_f32() < self.interval {
            return;
        }
        self.checked = Some(now);
        if ctx.play_mode() != PlayMode::Edit {
            return;
        }
        if !history.is_modified() {
            // Undone back to the saved state: there is nothing to recover.
            if self.written.is_some() {
                self.forget(ctx);
            }
            return;
        }
        if self.written != Some(history.revision()) {
            self.write(ctx, history.revision());
        }
    }

    /// Writes this editor's copy and its note now; a failure is reported (once until it
    /// changes) and leaves the previous copy.
    pub fn write(&mut self, ctx: &mut Ctx, revision: u64) {
        match self.try_write(ctx) {
            Ok(()) => {
                self.written = Some(revision);
                self.last_error = None;
            }
            Err(error) => {
                if self.last_error.as_ref() != Some(&error) {
                    ctx.warn(format!(
                        "autosave to {} failed: {error}",
                        self.dir.display()
                    ));
                    self.last_error = Some(error);
                }
            }
        }
    }

    fn try_write(&self, ctx: &mut Ctx) -> Result<(), String> {
        std::fs::create_dir_all(&self.dir).map_err(|e| e.to_string())?;
        let pid = std::process::id();
        ctx.save_scene_copy(&self.copy_path(pid).to_string_lossy())
            .map_err(|e| e.to_string())?;
        let about = About {
            scene: ctx.scene_path(),
            saved_at: now_secs(),
            pid,
        };
        let text = serde_json::to_vec_pretty(&about).map_err(|e| e.to_string())?;
        crate::atomic_file::write(&self.note_path(pid), &text).map_err(|e| e.to_string())
    }

    /// Deletes this editor's copy: the scene was saved, or its edits thrown away on purpose.
    pub fn forget(&mut self, ctx: &mut Ctx) {
        self.written = None;
        let pid = std::process::id();
        remove(ctx, &[self.copy_path(pid), self.note_path(pid)]);
    }

    /// The editor is ending: unsaved edits that were not thrown away on purpose are kept
    /// as a copy for the next start; otherwise this editor's copy goes. Copies on offer
    /// (never answered) stay for the next start.
    pub fn on_detach(&mut self, ctx: &mut Ctx, history: &History, quitting_on_purpose: bool) {
        if !self.offers.is_empty() {
            return;
        }
        if history.is_modified() && !quitting_on_purpose {
            if self.written != Some(history.revision()) {
                self.write(ctx, history.revision());
            }
        } else {
            self.forget(ctx);
        }
    }
}

fn remove(ctx: &mut Ctx, paths: &[PathBuf]) {
    for path in paths {
        match std::fs::remove_file(path) {
            Ok(()) => {}
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => ctx.warn(format!("cannot delete {}: {e}", path.display())),
        }
    }
}

/// Shows "Recover unsaved changes?" while a copy is on offer, and acts on the answer:
/// **Recover** opens the copy in place of the world, named after the scene it was a copy
/// of and marked modified (Save writes it there); **Discard** deletes the copy.
pub fn show_offer(ui: &egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    let Some(offer) = state.recovery.offers.first().cloned() else {
        return;
    };
    let about = &offer.about;
    let what = match &about.scene {
        Some(scene) => format!("unsaved changes to {scene}"),
        None => "an untitled scene with unsaved changes".to_owned(),
    };
    let mut recover = None;
    egui::Modal::new(egui::Id::new("editor-recovery")).show(ui.ctx(), |ui| {
        ui.heading("Recover unsaved changes?");
        ui.label(format!(
            "The editor ended without saving {what}. A copy was autosaved {}.",
            ago(about.saved_at)
        ));
        ui.add_space(8.0);
        ui.horizontal(|ui| {
            if ui.button("Recover").clicked() {
                recover = Some(true);
            }
            if ui.button("Discard").clicked() {
                recover = Some(false);
            }
        });
    });
    match recover {
        Some(true) => recover_copy(ctx, state, &offer),
        Some(false) => {
            state.recovery.offers.remove(0);
            remove(ctx, &[offer.copy, offer.note]);
        }
        None => {}
    }
}

/// Opens the copy in place of the world; this editor writes its own copy of it at once
/// (so a second crash loses nothing), then the old one goes.
fn recover_copy(ctx: &mut Ctx, state: &mut EditorState, offer: &Offer) {
    state.recovery.offers.remove(0);
    let opened = ctx
        .open_scene(&offer.copy.to_string_lossy())
        .and_then(|()| ctx.set_scene_path(offer.about.scene.as_deref()));
    match opened {
        Ok(()) => {
            state.selection.clear();
            state.history.clear();
            state.history.mark_modified();
            state.viewport.forget_camera();
            let name = offer.about.scene.as_deref().unwrap_or("the untitled scene");
            ctx.info(format!(
                "recovered unsaved changes to {name} from {}",
                offer.copy.display()
            ));
            if offer.about.pid != std::process::id() {
                state.recovery.write(ctx, state.history.revision());
                if state.recovery.written.is_some() {
                    remove(ctx, &[offer.copy.clone(), offer.note.clone()]);
                }
            } else {
                state.recovery.written = Some(state.history.revision());
            }
        }
        Err(error) => {
            // Left on disk for the user to look at; no longer offered.
            state.report(
                ctx,
                &format!("cannot recover {} (left there)", offer.copy.display()),
                error,
            );
        }
    }
}

fn now_secs() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
}

fn modified_secs(path: &Path) -> Option<u64> {
    let modified = std::fs::metadata(path).ok()?.modified().ok()?;
    Some(modified.duration_since(UNIX_EPOCH).ok()?.as_secs())
}

/// "just now", "5 minutes ago", "3 hours ago", "2 days ago".
fn ago(saved_at: u64) -> String {
    let secs = now_secs().saturating_sub(saved_at);
    match secs {
        0..=59 => "just now".to_owned(),
        60..=3599 => plural(secs / 60, "minute"),
        3600..=86_399 => plural(secs / 3600, "hour"),
        _ => plural(secs / 86_400, "day"),
    }
}

fn plural(n: u64, unit: &str) -> String {
    if n == 1 {
        format!("1 {unit} ago")
    } else {
        format!("{n} {unit}s ago")
    }
}

/// Whether process `pid` is running (not a zombie). Only Linux can tell; elsewhere every
/// copy is offered.
fn process_alive(pid: u32) -> bool {
    if pid == 0 {
        return false;
    }
    let Ok(stat) = std::fs::read_to_string(format!("/proc/{pid}/stat")) else {
        return false;
    };
    // `pid (comm) S ...`: the state follows the last parenthesis (comm may hold spaces).
    let state = stat
        .rsplit_once(')')
        .and_then(|(_, rest)| rest.trim_start().chars().next());
    !matches!(state, Some('Z' | 'X') | None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ages_read_like_a_person_would_say_them() {
        let now = now_secs();
        assert_eq!(ago(now), "just now");
        assert_eq!(ago(now - 60), "1 minute ago");
        assert_eq!(ago(now - 300), "5 minutes ago");
        assert_eq!(ago(now - 7200), "2 hours ago");
        assert_eq!(ago(now - 86_400 * 3), "3 days ago");
        assert_eq!(ago(now + 100), "just now", "a clock set back");
    }

    #[test]
    fn copies_of_running_editors_are_not_offered_and_the_newest_comes_first() {
        let dir = std::env::temp_dir().join(format!("onyx-recovery-test-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
        let recovery = Recovery {
            dir: dir.clone(),
            ..Recovery::default()
        };
        let dead = u32::MAX - 1;
        let own = std::process::id();
        let note = |pid: u32, scene: &str, saved_at: u64| {
            let about = About {
                scene: Some(scene.to_owned()),
                saved_at,
                pid,
            };
            std::fs::write(recovery.copy_path(pid), "()").unwrap_or_else(|e| panic!("{e}"));
            let text = serde_json::to_vec(&about).unwrap_or_else(|e| panic!("{e}"));
            std::fs::write(recovery.note_path(pid), text).unwrap_or_else(|e| panic!("{e}"));
        };
        note(dead, "old.ron", 100);
        note(own, "mine.ron", 200);
        // A copy without its note is still offered; pid 1 (init) is running: not offered.
        std::fs::write(recovery.copy_path(dead - 1), "()").unwrap_or_else(|e| panic!("{e}"));
        if process_alive(1) {
            note(1, "someone else's.ron", 300);
        }
        std::fs::write(dir.join("unrelated.txt"), "x").unwrap_or_else(|e| panic!("{e}"));

        let mut found = Recovery {
            dir: dir.clone(),
            ..Recovery::default()
        };
        found.look_for_copies();
        let scenes: Vec<Option<&str>> = found
            .offers
            .iter()
            .map(|o| o.about.scene.as_deref())
            .collect();
        // The note-less copy is dated by the file (just now): the newest.
        assert_eq!(
            scenes,
            [None, Some("mine.ron"), Some("old.ron")],
            "{:?}",
            found.offers
        );
        assert_eq!(found.offers[0].about.pid, dead - 1);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn this_process_is_alive_and_a_zombie_or_nobody_is_not() {
        assert!(process_alive(std::process::id()) || !Path::new("/proc").is_dir());
        assert!(!process_alive(0));
        assert!(!process_alive(u32::MAX));
    }
}
