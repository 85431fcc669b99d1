//! Helpers for [`Plugin::save_state`](crate::Plugin::save_state) and
//! [`Plugin::load_state`](crate::Plugin::load_state): serde in, bytes out, and versions for
//! the changes serde cannot map.
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
//! ## When the state type changes
//!
//! The state is JSON, written by the running build and read by the new one, so serde maps
//! most edits on its own:
//!
//! | edit in the new build | what happens |
//! | --- | --- |
//! | a field added, with `#[serde(default)]` | kept; the new field starts at its default |
//! | a field removed | kept; the old value is ignored |
//! | a field renamed, with `#[serde(alias = "old_name")]` | kept |
//! | a number widened (`u32` → `u64`, `f32` → `f64`, an integer → a float) | kept |
//! | a field added without a default, a type changed (a number → a string, a struct → a list), the type replaced | refused |
//!
//! A refused swap is not a crash and loses nothing: [`decode`] fails with a sentence naming
//! the type and the field (`the saved state does not fit `game::Counter`: at `speed`:
//! invalid type: string "fast", expected f32`), the host reports that the plugin was not
//! reloaded and why, and the running build goes on as it was.
//!
//! For the edits serde cannot map, give the state a version and say how to bring an older
//! version's state forward ([`Versioned`], [`encode_versioned`], [`decode_versioned`]):
//!
//! ```
//! use onyx_plugin_api::{state, Plugin, PluginError};
//! use serde::{Deserialize, Serialize};
//! use serde_json::{json, Value};
//!
//! /// Version 2: `frames` became `ticks`, and the speed moved from cm/s to m/s.
//! #[derive(Default, Serialize, Deserialize)]
//! struct Counter { ticks: u64, speed_mps: f64 }
//!
//! impl state::Versioned for Counter {
//!     const VERSION: u32 = 2;
//!
//!     fn migrate(from: u32, old: Value) -> Result<Value, String> {
//!         match from {
//!             // Version 0: state saved with plain `state::encode`, before versions.
//!             0 => Ok(json!({ "frames": old["frames"], "speed_cms": 0.0 })),
//!             1 => {
//!                 let cms = old["speed_cms"].as_f64().ok_or("no `speed_cms`")?;
//!                 Ok(json!({ "ticks": old["frames"], "speed_mps": cms / 100.0 }))
//!             }
//!             _ => Err(format!("no way from version {from}")),
//!         }
//!     }
//! }
//!
//! impl Plugin for Counter {
//!     fn save_state(&self) -> Result<Vec<u8>, PluginError> {
//!         state::encode_versioned(self)
//!     }
//!     fn load_state(&mut self, bytes: &[u8]) -> Result<(), PluginError> {
//!         *self = state::decode_versioned(bytes)?;
//!         Ok(())
//!     }
//! }
//!
//! // What version 1 saved, and what the plain `encode` of an even older build saved:
//! let v1 = br#"{"onyx_state_version":1,"state":{"frames":90,"speed_cms":250.0}}"#;
//! let counter: Counter = state::decode_versioned(v1).unwrap();
//! assert_eq!((counter.ticks, counter.speed_mps), (90, 2.5));
//! let v0: Counter = state::decode_versioned(br#"{"frames":7}"#).unwrap();
//! assert_eq!(v0.ticks, 7);
//! ```
//!
//! Each `migrate` call takes one step (`from` → `from + 1`); [`decode_versioned`] chains
//! them up to [`Versioned::VERSION`]. State from a *newer* version than the build reading it
//! (a swap back to an older build) is refused.

use serde::{de::DeserializeOwned, Serialize};
use serde_json::Value;

use crate::PluginError;

/// The key under which [`encode_versioned`] writes the version number.
const VERSION_KEY: &str = "onyx_state_version";
/// The key under which [`encode_versioned`] writes the state itself.
const STATE_KEY: &str = "state";

/// Why a saved state could not be written or read. Each Display text is one sentence naming
/// the state type.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum StateError {
    /// The state could not be serialized.
    #[error("the state `{type_name}` cannot be saved: {message}")]
    Encode {
        /// The Rust type being saved.
        type_name: &'static str,
        /// serde's message.
        message: String,
    },
    /// The bytes do not decode into the type (a field missing, of another type, …).
    #[error("the saved state does not fit `{type_name}`: {}{message}", at(.path))]
    Decode {
        /// The Rust type being read.
        type_name: &'static str,
        /// Where in the state it failed (`speed`, `items[2].name`; empty at the top).
        path: String,
        /// serde's message.
        message: String,
    },
    /// The state was written by a newer version of the type than this build knows.
    #[error(
        "the saved state is version {found} of `{type_name}`, newer than this build's version \
         {this}: an older build cannot read a newer one's state"
    )]
    NewerVersion {
        /// The Rust type being read.
        type_name: &'static str,
        /// The version in the bytes.
        found: u32,
        /// [`Versioned::VERSION`] of this build.
        this: u32,
    },
    /// A migration step refused the older state.
    #[error(
        "the saved state (version {from} of `{type_name}`) could not be brought to version \
         {}: {message}", .from + 1
    )]
    Migration {
        /// The Rust type being read.
        type_name: &'static str,
        /// The version the failed step started from.
        from: u32,
        /// What [`Versioned::migrate`] said.
        message: String,
    },
}

fn at(path: &str) -> String {
    if path.is_empty() || path == "." {
        String::new()
    } else {
        format!("at `{path}`: ")
    }
}

/// serde's message without serde_json's "at line 1 column 17" (the path says where).
fn without_position(error: &serde_json::Error) -> String {
    let text = error.to_string();
    match text.rfind(" at line ") {
        Some(i) if error.line() > 0 => text[..i].to_owned(),
        _ => text,
    }
}

/// Serializes `value` for [`Plugin::save_state`](crate::Plugin::save_state).
pub fn encode<T: Serialize>(value: &T) -> Result<Vec<u8>, PluginError> {
    serde_json::to_vec(value).map_err(|e| {
        StateError::Encode {
            type_name: std::any::type_name::<T>(),
            message: e.to_string(),
        }
        .into()
    })
}

/// Deserializes what [`encode`] wrote. The error names the type and the field that did not
/// fit (see the [module docs](self)).
pub fn decode<T: DeserializeOwned>(bytes: &[u8]) -> Result<T, PluginError> {
    let mut deserializer = serde_json::Deserializer::from_slice(bytes);
    let value: T = serde_path_to_error::deserialize(&mut deserializer)
        .map_err(|e| decode_error::<T>(e.path().to_string(), e.inner()))?;
    deserializer
        .end()
        .map_err(|e| decode_error::<T>(String::new(), &e))?;
    Ok(value)
}

fn decode_error<T>(path: String, error: &serde_json::Error) -> StateError {
    StateError::Decode {
        type_name: std::any::type_name::<T>(),
        path,
        message: without_position(error),
    }
}

/// A plugin state with a version number, for the changes serde cannot map by itself (see
/// the [module docs](self)). Save it with [`encode_versioned`], read it with
/// [`decode_versioned`].
pub trait Versioned: Serialize + DeserializeOwned {
    /// The version this build writes. Start at 1 (0 is the state of a build that saved with
    /// plain [`encode`]); add one for each change serde cannot map, and teach
    /// [`Versioned::migrate`] the step.
    const VERSION: u32;

    /// Turns the state of version `from` into the form of version `from + 1`. Called once
    /// per step, from the saved version up to [`Versioned::VERSION`]. The default knows no
    /// step: only the current version is read.
    fn migrate(from: u32, state: Value) -> Result<Value, String> {
        let _ = state;
        Err(format!("no migration from version {from} is defined"))
    }
}

/// Serializes `value` with its [`Versioned::VERSION`].
pub fn encode_versioned<T: Versioned>(value: &T) -> Result<Vec<u8>, PluginError> {
    let state = serde_json::to_value(value).map_err(|e| StateError::Encode {
        type_name: std::any::type_name::<T>(),
        message: e.to_string(),
    })?;
    let mut envelope = serde_json::Map::new();
    envelope.insert(VERSION_KEY.to_owned(), Value::from(T::VERSION));
    envelope.insert(STATE_KEY.to_owned(), state);
    encode(&Value::Object(envelope))
}

/// Deserializes what [`encode_versioned`] wrote — by this version or an older one, migrated
/// step by step — or what plain [`encode`] wrote (version 0).
pub fn decode_versioned<T: Versioned>(bytes: &[u8]) -> Result<T, PluginError> {
    let type_name = std::any::type_name::<T>();
    let value: Value = decode(bytes)?;
    let (version, mut state) = split_envelope(value);
    if version > T::VERSION {
        return Err(StateError::NewerVersion {
            type_name,
            found: version,
            this: T::VERSION,
        }
        .into());
    }
    for from in version..T::VERSION {
        state = T::migrate(from, state).map_err(|message| StateError::Migration {
            type_name,
            from,
            message,
        })?;
    }
    serde_path_to_error::deserialize(state)
        .map_err(|e| decode_error::<T>(e.path().to_string(), e.inner()).into())
}

/// The version and the state inside an envelope; version 0 and the whole value otherwise.
fn split_envelope(value: Value) -> (u32, Value) {
    match value {
        Value::Object(mut map)
            if map.len() == 2 && map.contains_key(STATE_KEY) && map.contains_key(VERSION_KEY) =>
        {
            let version = map.get(VERSION_KEY).and_then(Value::as_u64);
            match version.and_then(|v| u32::try_from(v).ok()) {
                Some(version) => (version, map.remove(STATE_KEY).unwrap_or(Value::Null)),
                None => (0, Value::Object(map)),
            }
        }
        other => (0, other),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;
    use serde_json::json;

    #[derive(Debug, Default, PartialEq, Serialize, Deserialize)]
    struct V1 {
        count: u64,
        speed: f32,
    }

    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    struct Added {
        count: u64,
        speed: f32,
        #[serde(default)]
        bonus: u32,
    }

    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    struct Renamed {
        count: u64,
        #[serde(alias = "speed")]
        velocity: f64,
    }

    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    struct Retyped {
        count: String,
        speed: f32,
    }

    fn v1_bytes() -> Vec<u8> {
        encode(&V1 {
            count: 7,
            speed: 1.5,
        })
        .unwrap()
    }

    #[test]
    fn the_edits_serde_maps_are_kept() {
        let added: Added = decode(&v1_bytes()).unwrap();
        assert_eq!((added.count, added.bonus), (7, 0));
        let renamed: Renamed = decode(&v1_bytes()).unwrap();
        assert_eq!((renamed.count, renamed.velocity), (7, 1.5));
        #[derive(Deserialize)]
        struct Removed {
            count: u64,
        }
        assert_eq!(decode::<Removed>(&v1_bytes()).unwrap().count, 7);
    }

    #[test]
    fn a_changed_type_is_refused_naming_the_type_and_the_field() {
        let error = decode::<Retyped>(&v1_bytes()).unwrap_err().to_string();
        assert_eq!(
            error,
            "the saved state does not fit `onyx_plugin_api::state::tests::Retyped`: at \
             `count`: invalid type: integer `7`, expected a string"
        );
        let error = decode::<V1>(br#"{"count": 3}"#).unwrap_err().to_string();
        assert!(error.ends_with(": missing field `speed`"), "{error}");
        let error = decode::<V1>(b"{\"count\": 3, \"speed\": 1} trailing")
            .unwrap_err()
            .to_string();
        assert!(error.contains("trailing characters"), "{error}");
    }

    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    struct V3 {
        ticks: u64,
        speed_mps: f64,
    }

    impl Versioned for V3 {
        const VERSION: u32 = 3;
        fn migrate(from: u32, old: Value) -> Result<Value, String> {
            match from {
                0 => {
                    let mps = old["speed"].as_f64().unwrap_or(0.0);
                    Ok(json!({ "count": old["count"], "speed_cms": 100.0 * mps }))
                }
                1 => Ok(json!({ "ticks": old["count"], "speed_cms": old["speed_cms"] })),
                2 => {
                    let cms = old["speed_cms"].as_f64().ok_or("no `speed_cms`")?;
                    Ok(json!({ "ticks": old["ticks"], "speed_mps": cms / 100.0 }))
                }
                _ => Err(format!("no way from {from}")),
            }
        }
    }

    #[test]
    fn older_versions_are_migrated_step_by_step() {
        let now = V3 {
            ticks: 4,
            speed_mps: 2.0,
        };
        assert_eq!(
            decode_versioned::<V3>(&encode_versioned(&now).unwrap()).unwrap(),
            now
        );
        let from_plain: V3 = decode_versioned(&v1_bytes()).unwrap();
        assert_eq!(from_plain.ticks, 7);
        assert!((from_plain.speed_mps - 1.5).abs() < 1e-9, "{from_plain:?}");
        let v2 = br#"{"onyx_state_version":2,"state":{"ticks":9,"speed_cms":250.0}}"#;
        let from_v2: V3 = decode_versioned(v2).unwrap();
        assert_eq!((from_v2.ticks, from_v2.speed_mps), (9, 2.5));
    }

    #[test]
    fn newer_and_unmigratable_states_are_refused() {
        let v4 = br#"{"onyx_state_version":4,"state":{}}"#;
        let error = decode_versioned::<V3>(v4).unwrap_err().to_string();
        assert!(
            error.contains("version 4") && error.contains("version 3"),
            "{error}"
        );
        let v2 = br#"{"onyx_state_version":2,"state":{"ticks":9}}"#;
        let error = decode_versioned::<V3>(v2).unwrap_err().to_string();
        assert!(
            error.contains("version 2") && error.ends_with("no `speed_cms`"),
            "{error}"
        );

        #[derive(Debug, Serialize, Deserialize)]
        struct NoSteps {
            count: u64,
        }
        impl Versioned for NoSteps {
            const VERSION: u32 = 2;
        }
        let v1 = br#"{"onyx_state_version":1,"state":{"count":1}}"#;
        let error = decode_versioned::<NoSteps>(v1).unwrap_err().to_string();
        assert!(error.contains("no migration from version 1"), "{error}");
        let wrong = br#"{"onyx_state_version":2,"state":{"count":"x"}}"#;
        let error = decode_versioned::<NoSteps>(wrong).unwrap_err().to_string();
        assert!(error.contains("at `count`"), "{error}");
    }
}
