//! [`BatchKey`] and [`ShadowKey`]: what objects are grouped by in a camera pass and in a
//! shadow pass, and [`KeyTable`], which numbers the keys met in a frame.

use std::collections::HashMap;
use std::hash::Hash;

use crate::mesh::MeshHandle;
use crate::shading_mode::ShadingMode;
use crate::texture::TextureHandle;

/// How a material's alpha is drawn; orders opaque before masked before blended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum AlphaClass {
    Opaque,
    Mask,
    Blend,
}

/// The maps of a material, in bind-group order (`None`: the slot's neutral texture).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct MaterialMaps {
    pub(crate) base_color: Option<TextureHandle>,
    pub(crate) metallic_roughness: Option<TextureHandle>,
    pub(crate) normal: Option<TextureHandle>,
    pub(crate) occlusion: Option<TextureHandle>,
    pub(crate) emissive: Option<TextureHandle>,
}

/// What objects of a camera pass are grouped by. Ordered so batches of one pipeline are
/// adjacent.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct BatchKey {
    pub(crate) alpha: AlphaClass,
    pub(crate) shading: ShadingMode,
    /// Drawn as the missing-texture placeholder (its base colour map failed to load).
    pub(crate) placeholder: bool,
    pub(crate) double_sided: bool,
    /// Maps, for modes that sample them; all `None` otherwise.
    pub(crate) maps: MaterialMaps,
    pub(crate) mesh: MeshHandle,
}

/// What objects of a shadow pass are grouped by: only what changes the depth drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct ShadowKey {
    /// Cut by the base colour's alpha (the map in `mask_texture`, `None` for white).
    pub(crate) masked: bool,
    pub(crate) double_sided: bool,
    pub(crate) mask_texture: Option<TextureHandle>,
    pub(crate) mesh: MeshHandle,
}

/// Numbers the distinct keys of a frame (0, 1, …). Objects usually come in runs that share a
/// key, so the last few are checked before the hash map.
#[derive(Debug)]
pub(crate) struct KeyTable<K> {
    keys: Vec<K>,
    ids: HashMap<K, u32>,
    recent: [(u32, bool); RECENT],
    next_recent: usize,
}

/// Keys remembered before the hash map is asked.
const RECENT: usize = 4;

impl<K> Default for KeyTable<K> {
    fn default() -> Self {
        Self {
            keys: Vec::new(),
            ids: HashMap::new(),
            recent: [(0, false); RECENT],
            next_recent: 0,
        }
    }
}

impl<K: Copy + Eq + Hash> KeyTable<K> {
    pub(crate) fn clear(&mut self) {
        self.keys.clear();
        self.ids.clear();
        self.recent = [(0, false); RECENT];
    }

    /// The number of `key`, given it if new.
    pub(crate) fn id(&mut self, key: K) -> u32 {
        for &(id, used) in &self.recent {
            if used && self.keys[id as usize] == key {
                return id;
            }
        }
        let id = match self.ids.get(&key) {
            Some(&id) => id,
            None => {
                let id = self.keys.len() as u32;
                self.keys.push(key);
                self.ids.insert(key, id);
                id
            }
        };
        self.recent[self.next_recent] = (id, true);
        self.next_recent = (self.next_recent + 1) % RECENT;
        id
    }

    pub(crate) fn get(&self, id: u32) -> K {
        self.keys[id as usize]
    }

    pub(crate) fn keys(&self) -> &[K] {
        &self.keys
    }
}
