//! Values the tool services pass across: the entity list as flat buffers, and the selectors
//! of the report and scene calls (reports are JSON of the `tools` types).

use abi_stable::{
    std_types::{RString, RVec},
    StableAbi,
};

use crate::tools::EntityList;
use crate::Entity;

/// [`EntityList`] as it crosses: entities, end offsets of each name, all names in one string,
/// and each row's parent row.
#[repr(C)]
#[derive(StableAbi, Clone, Debug, Default)]
pub struct EntityListFfi {
    pub entities: RVec<Entity>,
    pub name_ends: RVec<u32>,
    pub names: RString,
    pub parents: RVec<u32>,
}

impl From<EntityList> for EntityListFfi {
    fn from(list: EntityList) -> Self {
        Self {
            entities: list.entities.into(),
            name_ends: list.name_ends.into(),
            names: list.names.into(),
            parents: list.parents.into(),
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
        let mut parents = list.parents.into_vec();
        let rows = entities.len();
        if parents.len() != rows
            || parents
                .iter()
                .any(|&p| p != EntityList::NO_PARENT && p as usize >= rows)
        {
            parents = vec![EntityList::NO_PARENT; rows];
        }
        Self {
            entities,
            name_ends,
            names,
            parents,
        }
    }
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
    /// Save the world to the file without making it the world's file.
    SaveCopy,
    /// Name the file the world belongs to (empty: none).
    Rename,
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
}

/// An axis-aligned box in an entity's frame, metres.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct BoundsFfi {
    pub min: [f32; 3],
    pub max: [f32; 3],
}

/// A pixel of a view and the view's size, both in pixels.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct ScreenPointFfi {
    pub at: [f32; 2],
    pub size: [f32; 2],
}
