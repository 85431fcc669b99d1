//! [`CtxError`]: why a call through [`Ctx`](crate::Ctx) did not happen.

use crate::Entity;

/// Why the host refused or failed a request made through [`Ctx`](crate::Ctx). Nothing in the
/// world changed when one of these comes back.
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
    #[error("the `{component}` written to entity {entity} holds NaN or infinity; it was rejected")]
    NonFinite {
        /// The entity it was meant for.
        entity: Entity,
        /// The component's name.
        component: String,
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
    /// The request is not valid in this host (a feature that is not running, bad argument).
    #[error("{message}")]
    Invalid {
        /// What was wrong, as a sentence.
        message: String,
    },
}
