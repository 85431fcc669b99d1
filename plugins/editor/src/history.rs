//! [`History`]: the undo/redo stack of edits made in Edit mode.

use onyx_plugin_api::tools::{ComponentKey, ComponentValue};
use onyx_plugin_api::{BuiltinValue, Ctx, CtxError, Entity, Parent};

/// One undoable edit.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// A component changed (`None`: absent, so this also covers add and remove; a rename is
    /// a change of `Name`, a re-parent a change of `Parent` and `Transform`).
    SetComponent {
        /// The entity edited.
        entity: Entity,
        /// Which component.
        key: ComponentKey,
        /// The value before.
        old: Option<ComponentValue>,
        /// The value after.
        new: Option<ComponentValue>,
    },
    /// An entity was created with these components.
    Create {
        /// The entity made.
        entity: Entity,
        /// Its components.
        components: Vec<ComponentValue>,
    },
    /// An entity with these components was deleted.
    Delete {
        /// The entity removed.
        entity: Entity,
        /// Its components.
        components: Vec<ComponentValue>,
    },
    /// Several edits made as one (a subtree deleted, a re-parent, a multi-selection moved):
    /// undone last to first, redone first to last.
    Group(Vec<Command>),
}

impl Command {
    /// The edits this one is made of, as one undo step (a single edit stays itself).
    pub fn group(mut commands: Vec<Command>) -> Option<Command> {
        match commands.len() {
            0 => None,
            1 => commands.pop(),
            _ => Some(Command::Group(commands)),
        }
    }
}

/// Undo and redo stacks. Edits are applied by the caller, then recorded here. It also knows
/// whether the scene has edits since it was opened or saved ([`History::is_modified`]).
#[derive(Debug)]
pub struct History {
    undo: Vec<Command>,
    redo: Vec<Command>,
    /// The depth of the undo stack when the scene was opened or last saved; `None` once that
    /// state cannot come back by undo or redo (edited over, or dropped past the limit).
    saved_at: Option<usize>,
    /// Frame of the last [`History::record_merged`], to merge a drag into one edit.
    last_merge_frame: Option<u64>,
    /// Entities recreated (old handle, new handle) by the edit being applied: the rest of a
    /// group is pointed at the new ones before it runs.
    recreated: Vec<(Entity, Entity)>,
    /// Counts every change to the stacks: the world the editor shows changed when it did
    /// (what autosave compares against).
    revision: u64,
}

/// Most edits kept.
const LIMIT: usize = 500;

impl Default for History {
    fn default() -> Self {
        Self {
            undo: Vec::new(),
            redo: Vec::new(),
            saved_at: Some(0),
            last_merge_frame: None,
            recreated: Vec::new(),
            revision: 0,
        }
    }
}

impl History {
    /// Records an edit already applied.
    pub fn record(&mut self, command: Command) {
        if self.saved_at.is_some_and(|depth| depth > self.undo.len()) {
            self.saved_at = None; // the saved state was in the redo stack, dropped now
        }
        self.redo.clear();
        self.undo.push(command);
        self.revision += 1;
        if self.undo.len() > LIMIT {
            self.undo.remove(0);
            self.saved_at = self.saved_at.and_then(|depth| depth.checked_sub(1));
        }
        self.last_merge_frame = None;
    }

    /// Whether the scene has edits since it was opened or last saved ([`History::mark_saved`]):
    /// undoing back to that point makes it unmodified again. Edits made while playing are
    /// not edits (Stop puts them back).
    pub fn is_modified(&self) -> bool {
        self.saved_at != Some(self.undo.len())
    }

    /// The scene was just saved: it is unmodified as it stands.
    pub fn mark_saved(&mut self) {
        self.saved_at = Some(self.undo.len());
    }

    /// The world holds edits no file has (a scene recovered from an autosaved copy):
    /// modified until saved, whatever is undone.
    pub fn mark_modified(&mut self) {
        self.saved_at = None;
    }

    /// A number that changes whenever an edit is recorded, merged, undone or redone.
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// Records a component change, merged into the previous edit when that changed the same
    /// component in the previous or this frame (one drag = one undo step).
    pub fn record_merged(&mut self, command: Command, frame: u64) {
        let mergeable = self
            .last_merge_frame
            .is_some_and(|f| f + 1 >= frame && f <= frame);
        if let (
            true,
            Some(Command::SetComponent {
                entity, key, new, ..
            }),
            Command::SetComponent {
                entity: e2,
                key: k2,
                new: n2,
                ..
            },
        ) = (mergeable, self.undo.last_mut(), &command)
        {
            if entity == e2 && key == k2 {
                *new = n2.clone();
                self.last_merge_frame = Some(frame);
                self.revision += 1;
                if self.saved_at == Some(self.undo.len()) {
                    self.saved_at = None; // the saved edit itself changed
                }
                return;
            }
        }
        self.record(command);
        self.last_merge_frame = Some(frame);
    }

    /// Whether there is something to undo.
    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    /// Whether there is something to redo.
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    /// Edits that can be undone.
    pub fn undo_len(&self) -> usize {
        self.undo.len()
    }

    /// Undoes the last edit.
    pub fn undo(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        let Some(command) = self.undo.pop() else {
            return Ok(());
        };
        self.last_merge_frame = None;
        let done = self.apply(ctx, command, true);
        self.recreated.clear();
        self.revision += 1;
        self.redo.push(done?);
        Ok(())
    }

    /// Redoes the last undone edit.
    pub fn redo(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        let Some(command) = self.redo.pop() else {
            return Ok(());
        };
        self.last_merge_frame = None;
        let done = self.apply(ctx, command, false);
        self.recreated.clear();
        self.revision += 1;
        self.undo.push(done?);
        Ok(())
    }

    /// Applies `command` backwards (`undo`) or forwards; returns it with the entity handles
    /// it now refers to (recreating an entity gives it a new handle, which every recorded
    /// edit then uses — parents included).
    fn apply(&mut self, ctx: &mut Ctx, command: Command, undo: bool) -> Result<Command, CtxError> {
        match command {
            Command::SetComponent {
                entity,
                key,
                old,
                new,
            } => {
                let value = if undo { &old } else { &new };
                write_component(ctx, entity, &key, value.clone())?;
                Ok(Command::SetComponent {
                    entity,
                    key,
                    old,
                    new,
                })
            }
            Command::Create { entity, components } => {
                self.toggle_existence(ctx, entity, components, true, undo)
            }
            Command::Delete { entity, components } => {
                self.toggle_existence(ctx, entity, components, false, undo)
            }
            Command::Group(mut commands) => {
                if undo {
                    commands.reverse();
                }
                let start = self.recreated.len();
                let mut done = Vec::with_capacity(commands.len());
                for mut command in commands {
                    for &(from, to) in &self.recreated[start..] {
                        remap_command(&mut command, from, to);
                    }
                    done.push(self.apply(ctx, command, undo)?);
                }
                if undo {
                    done.reverse();
                }
                // The group as a whole now refers to the new handles too.
                for &(from, to) in &self.recreated[start..] {
                    for command in &mut done {
                        remap_command(command, from, to);
                    }
                }
                if start == 0 {
                    self.recreated.clear();
                }
                Ok(Command::Group(done))
            }
        }
    }

    /// Undoes or redoes a creation (`create`) or a deletion: despawns the entity, or spawns
    /// it again with its components (a new handle, which every recorded edit then uses).
    fn toggle_existence(
        &mut self,
        ctx: &mut Ctx,
        entity: Entity,
        components: Vec<ComponentValue>,
        create: bool,
        undo: bool,
    ) -> Result<Command, CtxError> {
        let entity = if create == undo {
            ctx.despawn(entity)?;
            entity
        } else {
            let fresh = respawn(ctx, &components)?;
            self.remap(entity, fresh);
            self.recreated.push((entity, fresh));
            fresh
        };
        Ok(if create {
            Command::Create { entity, components }
        } else {
            Command::Delete { entity, components }
        })
    }

    /// Points every recorded edit of `from` at `to`, including parents that name it.
    pub fn remap(&mut self, from: Entity, to: Entity) {
        for command in self.undo.iter_mut().chain(self.redo.iter_mut()) {
            remap_command(command, from, to);
        }
    }

    /// Forgets every edit (a new or opened scene, unmodified as it stands).
    pub fn clear(&mut self) {
        self.undo.clear();
        self.redo.clear();
        self.saved_at = Some(0);
        self.last_merge_frame = None;
        self.revision += 1;
    }
}

fn remap_command(command: &mut Command, from: Entity, to: Entity) {
    let swap = |e: &mut Entity| {
        if *e == from {
            *e = to;
        }
    };
    match command {
        Command::SetComponent {
            entity, old, new, ..
        } => {
            swap(entity);
            for value in [old, new].into_iter().flatten() {
                *value = remapped(value.clone(), from, to);
            }
        }
        Command::Create { entity, components } | Command::Delete { entity, components } => {
            swap(entity);
            for value in components {
                *value = remapped(value.clone(), from, to);
            }
        }
        Command::Group(commands) => {
            for command in commands {
                remap_command(command, from, to);
            }
        }
    }
}

/// `value` with a `Parent` naming `from` pointed at `to`.
fn remapped(value: ComponentValue, from: Entity, to: Entity) -> ComponentValue {
    match value {
        ComponentValue::Builtin(BuiltinValue::Parent(Parent(p))) if p == from => {
            ComponentValue::Builtin(BuiltinValue::Parent(Parent(to)))
        }
        other => other,
    }
}

/// Sets (`Some`) or removes (`None`) one component.
pub fn write_component(
    ctx: &mut Ctx,
    entity: Entity,
    key: &ComponentKey,
    value: Option<ComponentValue>,
) -> Result<(), CtxError> {
    match value {
        Some(value) => ctx.set_component(entity, value),
        None => ctx.remove_component(entity, key),
    }
}

/// A new entity with these components.
pub fn respawn(ctx: &mut Ctx, components: &[ComponentValue]) -> Result<Entity, CtxError> {
    let entity = ctx.spawn(())?;
    for value in components {
        ctx.set_component(entity, value.clone())?;
    }
    Ok(entity)
}

/// Every component of `entity`.
pub fn snapshot(ctx: &mut Ctx, entity: Entity) -> Result<Vec<ComponentValue>, CtxError> {
    ctx.components_of(entity)
}

/// One component of `entity`, if it has it.
pub fn component(ctx: &mut Ctx, entity: Entity, key: &ComponentKey) -> Option<ComponentValue> {
    ctx.components_of(entity)
        .ok()?
        .into_iter()
        .find(|c| c.key() == *key)
}
