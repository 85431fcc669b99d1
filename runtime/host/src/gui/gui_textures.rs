//! [`GuiTextures`]: every plugin's egui textures under host-unique ids, kept on the CPU so
//! any number of GPU painters (window, screenshots) can upload them when they change.

use std::collections::HashMap;
use std::sync::Arc;

use egui::epaint::{ImageData, ImageDelta};
use egui::{ColorImage, TextureId, TextureOptions, TexturesDelta};

/// The id a plugin's [`VIEWPORT_TEXTURE`](onyx_plugin_api::gui::VIEWPORT_TEXTURE) keeps on the
/// host side: painters bind the scene's texture to it.
pub const HOST_VIEWPORT_TEXTURE: TextureId = onyx_plugin_api::gui::VIEWPORT_TEXTURE;

/// One texture as the painters upload it.
#[derive(Clone, Debug)]
pub struct GuiTexture {
    /// The whole image.
    pub image: Arc<ColorImage>,
    /// Sampling.
    pub options: TextureOptions,
    /// Bumped on every change, so a painter knows when to upload again.
    pub version: u64,
}

/// Host-side egui textures and the map from (plugin GUI owner, plugin texture id) to host id.
#[derive(Debug, Default)]
pub struct GuiTextures {
    textures: HashMap<TextureId, GuiTexture>,
    remap: HashMap<(u64, TextureId), TextureId>,
    next_id: u64,
    next_version: u64,
}

impl GuiTextures {
    /// The host id of `owner`'s texture `id`: managed ids get a host-unique id on first
    /// sight, the viewport keeps its well-known id, other user ids (which a plugin cannot
    /// register) are `None`.
    pub fn host_id(&mut self, owner: u64, id: TextureId) -> Option<TextureId> {
        match id {
            HOST_VIEWPORT_TEXTURE => Some(HOST_VIEWPORT_TEXTURE),
            TextureId::User(_) => None,
            TextureId::Managed(_) => Some(*self.remap.entry((owner, id)).or_insert_with(|| {
                self.next_id += 1;
                TextureId::Managed(self.next_id)
            })),
        }
    }

    /// The host id of `owner`'s texture `id`, if it has one already.
    pub fn existing_host_id(&self, owner: u64, id: TextureId) -> Option<TextureId> {
        match id {
            HOST_VIEWPORT_TEXTURE => Some(HOST_VIEWPORT_TEXTURE),
            TextureId::User(_) => None,
            TextureId::Managed(_) => self.remap.get(&(owner, id)).copied(),
        }
    }

    /// Applies a plugin's texture changes (creations and patches now; frees are applied by
    /// [`GuiTextures::free`] after the frame is painted).
    pub fn apply_sets(&mut self, owner: u64, delta: &TexturesDelta) {
        for (id, deltas) in &delta.set {
            let Some(host) = self.host_id(owner, *id) else {
                continue;
            };
            for delta in deltas {
                self.apply(host, delta);
            }
        }
    }

    fn apply(&mut self, host: TextureId, delta: &ImageDelta) {
        let ImageData::Color(patch) = &delta.image;
        self.next_version += 1;
        let version = self.next_version;
        match (delta.pos, self.textures.get_mut(&host)) {
            (None, _) => {
                self.textures.insert(
                    host,
                    GuiTexture {
                        image: patch.clone(),
                        options: delta.options,
                        version,
                    },
                );
            }
            (Some([x, y]), Some(texture)) => {
                let image = Arc::make_mut(&mut texture.image);
                let [w, h] = image.size;
                for row in 0..patch.size[1] {
                    if y + row >= h {
                        break;
                    }
                    for col in 0..patch.size[0] {
                        if x + col >= w {
                            break;
                        }
                        image.pixels[(y + row) * w + x + col] =
                            patch.pixels[row * patch.size[0] + col];
                    }
                }
                texture.options = delta.options;
                texture.version = version;
            }
            (Some(_), None) => tracing::warn!(?host, "GUI texture patch for an unknown texture"),
        }
    }

    /// Frees a plugin's textures as its frame asked.
    pub fn free(&mut self, owner: u64, ids: impl IntoIterator<Item = TextureId>) {
        for id in ids {
            if let Some(host) = self.remap.remove(&(owner, id)) {
                self.textures.remove(&host);
            }
        }
    }

    /// Frees every texture of `owner` (its plugin was unloaded or replaced).
    pub fn forget_owner(&mut self, owner: u64) {
        let textures = &mut self.textures;
        self.remap.retain(|(o, _), host| {
            let keep = *o != owner;
            if !keep {
                textures.remove(host);
            }
            keep
        });
    }

    /// The live textures by host id.
    pub fn textures(&self) -> &HashMap<TextureId, GuiTexture> {
        &self.textures
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::Color32;

    fn image(w: usize, h: usize, c: Color32) -> Arc<ColorImage> {
        Arc::new(ColorImage::new([w, h], vec![c; w * h]))
    }

    #[test]
    fn two_owners_with_the_same_id_get_two_host_textures() {
        let mut textures = GuiTextures::default();
        let a = textures.host_id(1, TextureId::Managed(0));
        let b = textures.host_id(2, TextureId::Managed(0));
        assert_ne!(a, b);
        assert_eq!(a, textures.host_id(1, TextureId::Managed(0)));
        assert_eq!(textures.host_id(1, TextureId::User(3)), None);
        assert_eq!(
            textures.host_id(1, HOST_VIEWPORT_TEXTURE),
            Some(HOST_VIEWPORT_TEXTURE)
        );
    }

    #[test]
    fn a_patch_changes_only_its_rectangle_and_bumps_the_version() {
        let mut textures = GuiTextures::default();
        let mut delta = TexturesDelta::default();
        let id = TextureId::Managed(0);
        delta.push(
            id,
            ImageDelta::full(image(4, 4, Color32::RED), Default::default()),
        );
        textures.apply_sets(7, &delta);
        delta.clear();
        let host = textures.existing_host_id(7, id).expect("mapped");
        let v1 = textures.textures()[&host].version;
        let mut delta = TexturesDelta::default();
        delta.push(
            id,
            ImageDelta::partial([1, 2], image(2, 1, Color32::BLUE), Default::default()),
        );
        textures.apply_sets(7, &delta);
        delta.clear();
        let texture = &textures.textures()[&host];
        assert!(texture.version > v1);
        assert_eq!(texture.image.pixels[2 * 4 + 1], Color32::BLUE);
        assert_eq!(texture.image.pixels[2 * 4 + 3], Color32::RED);
        textures.forget_owner(7);
        assert!(textures.textures().is_empty());
    }
}
