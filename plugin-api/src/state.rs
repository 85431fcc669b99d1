//! Helpers for [`Plugin::save_state`](crate::Plugin::save_state) and
//! [`Plugin::load_state`](crate::Plugin::load_state): serde in, bytes out.
//!
//! ```
//! use onyx_plugin_api::{state, Plugin, PluginError};
//! use serde::{Deserialize, Serialize};
//!
//! #[derive(Default, Serialize, Deserialize)]
//! struct Counter { frames: u64 }
//!
//! impl Plugin for Counter {
//!     fn save_state(&self) -> Result<Vec<u8>, PluginError> {
//!         state::encode(self)
//!     }
//!     fn load_state(&mut self, bytes: &[u8]) -> Result<(), PluginError> {
//!         *self = state::decode(bytes)?;
//!         Ok(())
//!     }
//! }
//! ```
//!
//! The encoding is JSON, so a new build may add fields (with `#[serde(default)]`) and still
//! read the old build's state.

use serde::{de::DeserializeOwned, Serialize};

use crate::PluginError;

/// Serializes `value` for [`Plugin::save_state`](crate::Plugin::save_state).
pub fn encode<T: Serialize>(value: &T) -> Result<Vec<u8>, PluginError> {
    Ok(serde_json::to_vec(value)?)
}

/// Deserializes what [`encode`] wrote.
pub fn decode<T: DeserializeOwned>(bytes: &[u8]) -> Result<T, PluginError> {
    Ok(serde_json::from_slice(bytes)?)
}
