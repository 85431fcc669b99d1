//! [`Builtin`]: what every built-in component defines, once, in its own file — its stable
//! name, default, checks, and scene-file form. The list of built-ins is in `builtins.rs`.

use std::fmt::Debug;

use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::{AnimationId, Entity, MeshId, TextureId};

/// A component the host knows: drawn, simulated, saved in scene files, shown in state dumps
/// and edited by tools. Each built-in is one type implementing this trait in its own file,
/// plus one line in the list (`builtins.rs`); everything else — the typed [`Ctx`](crate::Ctx)
/// calls, the boundary, the host's world, scene files, dumps, play-mode snapshots and the
/// editor — iterates that list.
///
/// You do not implement it for your own components: those are [`Component`](crate::Component)s.
pub trait Builtin:
    Clone + PartialEq + Debug + Serialize + DeserializeOwned + Send + Sync + 'static + Listed
{
    /// The stable name tools, dumps and errors use (`"Transform"`).
    const NAME: &'static str;

    /// The form scene files and state dumps write (asset ids as file paths, entities as
    /// file-local ids).
    type File: Serialize + DeserializeOwned + Clone + PartialEq + Debug;

    /// The value a tool adds when asked for one (the editor's Add Component); `None` when
    /// there is no sensible default (a [`Parent`](crate::Parent) needs an entity).
    fn tool_default() -> Option<Self>;

    /// Checks a value before the host writes it (from a plugin, a tool or a scene file).
    fn validate(&self, refs: &dyn HostRefs) -> Result<(), InvalidValue>;

    /// The value as a scene file or state dump writes it.
    fn to_file(&self, refs: &dyn HostRefs) -> Self::File;

    /// A value read from a scene file (registering the assets it names).
    fn from_file(file: Self::File, refs: &mut dyn FileRefs) -> Result<Self, InvalidValue>;
}

/// What a component's checks and file form may ask the host.
pub trait HostRefs {
    /// Whether `mesh` is a built-in shape or a model this host loaded.
    fn knows_mesh(&self, mesh: MeshId) -> bool;
    /// Whether `texture` is none or an image this host loaded.
    fn knows_texture(&self, texture: TextureId) -> bool;
    /// The file of a loaded model (`None` for built-in shapes and unknown ids).
    fn mesh_file(&self, mesh: MeshId) -> Option<String>;
    /// The file of a loaded image.
    fn texture_file(&self, texture: TextureId) -> Option<String>;
    /// Whether `animation` is none or an animation this host registered.
    fn knows_animation(&self, animation: AnimationId) -> bool;
    /// The file (and piece: `file.glb#animation/N`) of a registered animation.
    fn animation_file(&self, animation: AnimationId) -> Option<String>;
    /// Whether `entity` exists.
    fn contains(&self, entity: Entity) -> bool;
    /// The id a scene file (or a dump) names `entity` by.
    fn file_id(&self, entity: Entity) -> Option<u64>;
}

/// What reading a component from a scene file may ask the host.
pub trait FileRefs {
    /// The id of the model file at `path` (registered if new).
    fn mesh(&mut self, path: &str) -> MeshId;
    /// The id of the image file at `path` (registered if new).
    fn texture(&mut self, path: &str) -> TextureId;
    /// The id of the animation at `path` (`file.glb#animation/N`; registered if new).
    fn animation(&mut self, path: &str) -> AnimationId;
    /// The entity the file names `file_id`.
    fn entity(&self, file_id: u64) -> Option<Entity>;
}

/// Why a component value was refused: which field, and what is wrong with it.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum InvalidValue {
    /// The field holds NaN or infinity.
    #[error("`{field}` holds NaN or infinity")]
    NonFinite {
        /// The field.
        field: &'static str,
    },
    /// The field holds a value out of its range, or names something that is not there.
    #[error("`{field}` {message}")]
    Invalid {
        /// The field.
        field: &'static str,
        /// What is wrong, completing "`field` …" ("must be > 0, got -1").
        message: String,
    },
}

impl InvalidValue {
    /// The field the problem is in.
    pub fn field(&self) -> &'static str {
        match self {
            InvalidValue::NonFinite { field } | InvalidValue::Invalid { field, .. } => field,
        }
    }

    /// `field` holds a bad value: `message` completes "`field` …".
    pub fn invalid(field: &'static str, message: impl Into<String>) -> Self {
        InvalidValue::Invalid {
            field,
            message: message.into(),
        }
    }
}

/// Checks that every number in `values` is finite, else names `field`.
pub(crate) fn finite(field: &'static str, values: &[f32]) -> Result<(), InvalidValue> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(InvalidValue::NonFinite { field })
    }
}

/// Ties a built-in to its place in the list; implemented by the list, not by hand.
#[doc(hidden)]
pub trait Listed: Sized {
    /// Its id.
    const ID: crate::BuiltinId;
    /// Wraps it.
    fn into_value(self) -> crate::BuiltinValue;
    /// Unwraps it, or gives the value back when it is another component. (The value comes
    /// back whole, as large as the largest built-in, a `Joint`'s 130-odd bytes: it is a
    /// plain copy on a path that runs per tool call, not per body.)
    #[allow(clippy::result_large_err)]
    fn from_value(value: crate::BuiltinValue) -> Result<Self, crate::BuiltinValue>;
    /// Borrows it out of a value of the same component.
    fn ref_from(value: &crate::BuiltinValue) -> Option<&Self>;
}

/// A function generic over the built-in component types, called for one of them
/// ([`BuiltinId::dispatch`](crate::BuiltinId::dispatch)).
pub trait BuiltinFn {
    /// What the call returns.
    type Output;
    /// Called with `T` the chosen component type.
    fn call<T: Builtin>(&mut self) -> Self::Output;
}

/// A function generic over the built-in component types, called with a value of one of them
/// ([`BuiltinValue::visit`](crate::BuiltinValue::visit)).
pub trait BuiltinVisitor {
    /// What the call returns.
    type Output;
    /// Called with the value.
    fn call<T: Builtin>(&mut self, value: &T) -> Self::Output;
}
