//! [`History`]: the undo/redo stack of edits made in Edit mode.

use onyx_plugin_api::{Ctx, CtxError, Entity};

/// One component of an entity as JSON (type name, value), as `Ctx::components_of` gives it.
pub type ComponentJson = (String, String);

/// One undoable edit.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// A component changed (`None`: absent, so this also covers add and remove; a rename is
    /// a change of `Name`).
    SetComponent {
        /// The entity edited.
        entity: Entity,
        /// The component's type name.
        type_name: String,
        /// JSON before.
        old: Option<String>,
        /// JSON after.
        new: Option<String>,
    },
    /// An entity was created with these components.
    Create {
        /// The entity made.
        entity: Entity,
        /// Its components.
        components: Vec<ComponentJson>,
    },
    /// An entity with these components was deleted.
    Delete {
        /// The entity removed.
        entity: Entity,
        /// Its components.
        components: Vec<ComponentJson>,
    },
}

/// Undo and redo stacks. Edits are applied by the caller, then recorded here.
#[derive(Debug, Default)]
pub struct History {
    undo: Vec<Command>,
    redo: Vec<Command>,
    /// Frame of the last [`History::record_merged`], to merge a drag into one edit.
    last_merge_frame: Option<u64>,
}

/// Most edits kept.
const LIMIT: usize = 500;

impl History {
    /// Records an edit already applied.
    pub fn record(&mut self, command: Command) {
        self.redo.clear();
        self.undo.push(command);
        if self.undo.len() > LIMIT {
            self.undo.remove(0);
        }
        self.last_merge_frame = None;
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
                entity,
                type_name,
                new,
                ..
            }),
            Command::SetComponent {
                entity: e2,
                type_name: t2,
                new: n2,
                ..
            },
        ) = (mergeable, self.undo.last_mut(), &command)
        {
            if entity == e2 && type_name == t2 {
                *new = n2.clone();
                self.last_merge_frame = Some(frame);
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
        let done = self.apply(ctx, &command, true)?;
        self.redo.push(done);
        Ok(())
    }

    /// Redoes the last undone edit.
    pub fn redo(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        let Some(command) = self.redo.pop() else {
            return Ok(());
        };
        self.last_merge_frame = None;
        let done = self.apply(ctx, &command, false)?;
        self.undo.push(done);
        Ok(())
    }

    /// Applies `command` backwards (`undo`) or forwards; returns it with the entity handle
    /// it now refers to (recreating an entity gives it a new handle, which every recorded
    /// edit then uses).
    fn apply(&mut self, ctx: &mut Ctx, command: &Command, undo: bool) -> Result<Command, CtxError> {
        match command {
            Command::SetComponent {
                entity,
                type_name,
                old,
                new,
            } => {
                let value = if undo { old } else { new };
                write_component(ctx, *entity, type_name, value.as_deref())?;
                Ok(command.clone())
            }
            Command::Create { entity, components } | Command::Delete { entity, components } => {
                let despawn = matches!(command, Command::Create { .. }) == undo;
                if despawn {
                    ctx.despawn(*entity)?;
                    Ok(command.clone())
                } else {
                    let fresh = respawn(ctx, components)?;
                    self.remap(*entity, fresh);
                    let mut moved = command.clone();
                    if let Command::Create { entity, .. } | Command::Delete { entity, .. } =
                        &mut moved
                    {
                        *entity = fresh;
                    }
                    Ok(moved)
                }
            }
        }
    }

    /// Points every recorded edit of `from` at `to`.
    pub fn remap(&mut self, from: Entity, to: Entity) {
        for command in self.undo.iter_mut().chain(self.redo.iter_mut()) {
            match command {
                Command::SetComponent { entity, .. }
                | Command::Create { entity, .. }
                | Command::Delete { entity, .. } => {
                    if *entity == from {
                        *entity = to;
                    }
                }
            }
        }
    }

    /// Forgets every edit (a new or opened scene).
    pub fn clear(&mut self) {
        self.undo.clear();
        self.redo.clear();
        self.last_merge_frame = None;
    }
}

/// Sets (`Some`) or removes (`None`) one component.
pub fn write_component(
    ctx: &mut Ctx,
    entity: Entity,
    type_name: &str,
    json: Option<&str>,
) -> Result<(), CtxError> {
    match json {
        Some(json) => ctx.set_component_json(entity, type_name, json),
        None => ctx.remove_component(entity, type_name),
    }
}

/// A new entity with these components.
pub fn respawn(ctx: &mut Ctx, components: &[ComponentJson]) -> Result<Entity, CtxError> {
    let entity = ctx.spawn(())?;
    for (type_name, json) in components {
        ctx.set_component_json(entity, type_name, json)?;
    }
    Ok(entity)
}

/// Every component of `entity` as (type name, JSON).
pub fn snapshot(ctx: &mut Ctx, entity: Entity) -> Result<Vec<ComponentJson>, CtxError> {
    Ok(ctx
        .components_of(entity)?
        .into_iter()
        .map(|c| (c.type_name, c.value))
        .collect())
}
