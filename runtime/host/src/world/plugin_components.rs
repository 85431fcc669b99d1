//! [`PluginComponents`]: the named, serialized components plugins attach to an entity.

use std::collections::BTreeMap;

use onyx_plugin_api::BlobFormat;

/// One stored plugin component.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StoredBlob {
    /// How `bytes` are encoded.
    pub format: BlobFormat,
    /// The encoded value.
    pub bytes: Vec<u8>,
}

/// All plugin components of one entity, by name (a hecs component).
///
/// Names, not Rust types, identify them: a type's `TypeId` differs between builds, and the
/// host never links the plugin's types.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PluginComponents(pub BTreeMap<String, StoredBlob>);
