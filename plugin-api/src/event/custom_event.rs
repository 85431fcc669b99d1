//! [`CustomEvent`] and [`Message`]: events plugins send each other.

use serde::{de::DeserializeOwned, Serialize};

use crate::CtxError;

/// A typed payload for custom events: a serde type with a stable name.
///
/// ```
/// use onyx_plugin_api::Message;
/// use serde::{Deserialize, Serialize};
///
/// #[derive(Serialize, Deserialize)]
/// struct Explosion { x: f32, y: f32, z: f32 }
///
/// impl Message for Explosion {
///     const NAME: &'static str = "my_game.explosion";
/// }
/// ```
pub trait Message: Serialize + DeserializeOwned {
    /// The stable name events of this type are sent under.
    const NAME: &'static str;
}

/// A custom event as delivered: its name, the plugin that sent it, and its bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CustomEvent {
    /// The event's name ([`Message::NAME`] for typed events).
    pub name: String,
    /// The name of the plugin that sent it.
    pub sender: String,
    /// The payload (JSON for typed events).
    pub payload: Vec<u8>,
}

impl CustomEvent {
    /// Whether this event carries an `M`.
    pub fn is<M: Message>(&self) -> bool {
        self.name == M::NAME
    }

    /// Decodes the payload as an `M`. Fails if the name differs or the bytes do not parse.
    pub fn decode<M: Message>(&self) -> Result<M, CtxError> {
        if !self.is::<M>() {
            return Err(CtxError::Decode {
                component: M::NAME.to_owned(),
                message: format!("the event is a `{}`", self.name),
            });
        }
        serde_json::from_slice(&self.payload).map_err(|e| CtxError::Decode {
            component: M::NAME.to_owned(),
            message: e.to_string(),
        })
    }
}
