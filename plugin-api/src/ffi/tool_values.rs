//! Values the tool services pass across: the entity list as three flat buffers, and the
//! selectors of the byte-carrying calls (their payloads are JSON of the `tools` types).

use abi_stable::{
    std_types::{RString, RVec},
    StableAbi,
};

use crate::tools::EntityList;
use crate::Entity;

/// [`EntityList`] as it crosses: entities, end offsets of each name, all names in one string.
#[repr(C)]
#[derive(StableAbi, Clone, Debug, Default)]
pub struct EntityListFfi {
    pub entities: RVec<Entity>,
    pub name_ends: RVec<u32>,
    pub names: RString,
}

impl From<EntityList> for EntityListFfi {
    fn from(list: EntityList) -> Self {
        Self {
            entities: list.entities.into(),
            name_ends: list.name_ends.into(),
            names: list.names.into(),
        }
    }
}

impl From<EntityListFfi> for EntityList {
    fn from(list: EntityListFfi) -> Self {
        let entities = list.entities.into_vec();
        let mut name_ends = list.name_ends.into_vec();
        let names = list.names.into_string();
        // A malformed list (a host bug) must not make `name` slice out of bounds.
        if name_ends.len() != entities.len()
            || name_ends.windows(2).any(|w| w[0] > w[1])
            || name_ends.last().is_some_and(|&e| e as usize > names.len())
        {
            name_ends = vec![0; entities.len()];
        }
        Self {
            entities,
            name_ends,
            names,
        }
    }
}

/// What `edit_component` does.
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ComponentOpFfi {
    /// Parse the value (JSON) and write it.
    Set,
    /// Add the type's default value.
    AddDefault,
    /// Remove it.
    Remove,
}

/// What `scene_op` does.
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneOpFfi {
    /// Empty world.
    New,
    /// Replace the world with the file.
    Open,
    /// Save the world to the file.
    Save,
}

/// Which report `host_report` returns (as JSON).
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReportFfi {
    /// `Vec<PluginInfo>`.
    Plugins,
    /// `Diagnostics`.
    Diagnostics,
    /// `Vec<LogLine>` after the sequence number given.
    LogLines,
    /// `Vec<ScriptInfo>`.
    Scripts,
    /// `Vec<ComponentEntry>` of the entity given (bits in the number argument).
    Components,
}

/// A pixel of a view and the view's size, both in pixels.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct ScreenPointFfi {
    pub at: [f32; 2],
    pub size: [f32; 2],
}
