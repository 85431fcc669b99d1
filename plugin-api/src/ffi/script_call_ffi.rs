//! [`ScriptCallFfi`]: one script call as it crosses (parameters as JSON text).

use abi_stable::{std_types::RStr, StableAbi};

use crate::{Entity, ScriptCall, ScriptPhase};

/// A [`ScriptCall`], borrowed for the call.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug)]
pub struct ScriptCallFfi<'a> {
    pub entity: Entity,
    pub phase: ScriptPhase,
    pub name: RStr<'a>,
    pub params: RStr<'a>,
    pub dt: f32,
}

impl From<ScriptCallFfi<'_>> for ScriptCall {
    fn from(call: ScriptCallFfi<'_>) -> Self {
        Self {
            entity: call.entity,
            phase: call.phase,
            name: call.name.as_str().to_owned(),
            // The host wrote this JSON; should it not parse, the script sees no parameters.
            params: serde_json::from_str(call.params.as_str()).unwrap_or(serde_json::Value::Null),
            dt: call.dt,
        }
    }
}
