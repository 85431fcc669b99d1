//! [`CtxError`]: why a call through [`Ctx`](crate::Ctx) did not happen.

use crate::Entity;

/// Why the host refused or failed a request made through [`Ctx`](crate::Ctx). Nothing in the
/// world changed when one of these comes back.
///
/// Errors about a component name the entity it was meant for: `None` while it is being
/// spawned (the entity does not exist yet).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum CtxError {
    /// The entity was despawned (or never existed).
    #[error("entity {entity} does not exist (it was despawned, or the handle is stale)")]
    NoSuchEntity {
        /// The handle that was used.
        entity: Entity,
    },
    /// The entity exists but has no such component.
    #[error("entity {entity} has no `{component}` component")]
    MissingComponent {
        /// The entity.
        entity: Entity,
        /// The component's name.
        component: String,
    },
    /// A value held NaN or infinity; it was not written.
    #[error("the `{component}` written to {} holds NaN or infinity in `{field}`; it was rejected", target(.entity))]
    NonFinite {
        /// The entity it was meant for (`None`: being spawned).
        entity: Option<Entity>,
        /// The component's name.
        component: String,
        /// The field that held it (`translation`, `material.color`, …).
        field: String,
    },
    /// A component value is out of range or names something that is not there.
    #[error("the `{component}` written to {} was rejected: `{field}` {message}", target(.entity))]
    InvalidValue {
        /// The entity it was meant for (`None`: being spawned).
        entity: Option<Entity>,
        /// The component's name.
        component: String,
        /// The field at fault.
        field: String,
        /// What is wrong with it, completing "`field` …".
        message: String,
    },
    /// The parent given to an entity cannot be its parent.
    #[error("entity {entity} cannot be put under entity {parent}: {problem}")]
    InvalidParent {
        /// The child.
        entity: Entity,
        /// The parent asked for.
        parent: Entity,
        /// Why not.
        problem: ParentProblem,
    },
    /// A value could not be serialized.
    #[error("could not encode `{component}`: {message}")]
    Encode {
        /// The component or event name.
        component: String,
        /// The serializer's message.
        message: String,
    },
    /// Stored bytes did not parse as the requested type (a changed struct, or another
    /// plugin using the same name).
    #[error("could not decode `{component}`: {message}")]
    Decode {
        /// The component or event name.
        component: String,
        /// The deserializer's message.
        message: String,
    },
    /// A scene file could not be read, parsed or spawned.
    #[error("{message}")]
    Scene {
        /// The file.
        path: String,
        /// 1-based line of the problem, when it is in the text.
        line: Option<u32>,
        /// 1-based column of the problem, when it is in the text.
        column: Option<u32>,
        /// The whole sentence (naming the file, and the line and column when known).
        message: String,
    },
    /// This host does not offer the service (a minimal host, or a tool service).
    #[error("this host does not offer `{service}`")]
    Unsupported {
        /// The service (`Ctx` method) asked for.
        service: String,
    },
    /// The request is not valid in this host (a feature that is not running, bad argument).
    #[error("{message}")]
    Invalid {
        /// What was wrong, as a sentence.
        message: String,
    },
}

fn target(entity: &Option<Entity>) -> String {
    match entity {
        Some(entity) => format!("entity {entity}"),
        None => "a new entity".to_owned(),
    }
}

/// Why an entity cannot have the parent it was given ([`CtxError::InvalidParent`]).
#[repr(u8)]
#[derive(abi_stable::StableAbi, Clone, Copy, Debug, PartialEq, Eq, Hash, thiserror::Error)]
pub enum ParentProblem {
    /// The parent is the entity itself.
    #[error("an entity cannot be its own parent")]
    Itself,
    /// The parent is one of the entity's descendants: the hierarchy would be a cycle.
    #[error("the parent is one of its descendants (that would make a cycle)")]
    Descendant,
    /// The parent does not exist (despawned, or a stale or unknown handle).
    #[error("the parent does not exist (it was despawned, or the handle is stale)")]
    Missing,
}
