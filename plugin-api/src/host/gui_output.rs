//! [`GuiOutput`]: what one frame of a plugin's user interface produced, as egui types.

use std::sync::Arc;

use egui::epaint::{ClippedPrimitive, ColorImage, ImageDelta, Mesh, Primitive, Vertex};
use egui::{Color32, Pos2, Rect, TextureId, TexturesDelta};

use crate::__ffi::{GuiOutputFfi, TextureIdFfi, TextureSetFfi};

/// One GUI frame of a plugin, rebuilt as real egui types on the host's side. Texture ids are
/// the plugin's own: a host showing several plugins must map them to ids of its own.
#[derive(Clone)]
pub struct GuiOutput {
    /// Tessellated triangles with their clip rectangles, back to front, in points.
    pub primitives: Vec<ClippedPrimitive>,
    /// Textures to create, patch or free before drawing `primitives` (dropping a
    /// `GuiOutput` discards them; egui's own guard against unapplied deltas is disarmed).
    pub textures: TexturesDelta,
    /// Cursor icon, copied text, IME position, the AccessKit tree (when asked for)…
    pub platform: egui::PlatformOutput,
    /// Physical pixels per point the UI was laid out for.
    pub pixels_per_point: f32,
    /// egui is using the pointer (a widget is being dragged): pointer input is the UI's.
    pub using_pointer: bool,
    /// A widget has keyboard focus (a text field): key and text input is the UI's.
    pub wants_keyboard: bool,
    /// Windows, popups and menus, in points.
    pub floating_areas: Vec<Rect>,
    /// What the plugin's panels left free, in points: the pointer there belongs to the scene
    /// unless a floating area covers it.
    pub free_rect: Rect,
}

impl std::fmt::Debug for GuiOutput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GuiOutput")
            .field("primitives", &self.primitives.len())
            .field("pixels_per_point", &self.pixels_per_point)
            .field("using_pointer", &self.using_pointer)
            .field("wants_keyboard", &self.wants_keyboard)
            .field("free_rect", &self.free_rect)
            .finish_non_exhaustive()
    }
}

impl Drop for GuiOutput {
    fn drop(&mut self) {
        self.textures.clear();
    }
}

impl GuiOutput {
    /// Whether the pointer at `pos` (points) is over this UI.
    pub fn covers(&self, pos: Pos2) -> bool {
        !self.free_rect.contains(pos) || self.floating_areas.iter().any(|r| r.contains(pos))
    }
}

fn texture_id(id: TextureIdFfi) -> TextureId {
    if id.user {
        TextureId::User(id.id)
    } else {
        TextureId::Managed(id.id)
    }
}

fn rect(r: [f32; 4]) -> Rect {
    Rect::from_min_max(Pos2::new(r[0], r[1]), Pos2::new(r[2], r[3]))
}

fn image_delta(set: &TextureSetFfi) -> Option<ImageDelta> {
    let size = [
        usize::try_from(set.size[0]).ok()?,
        usize::try_from(set.size[1]).ok()?,
    ];
    if set.pixels.len() != size[0].checked_mul(size[1])?.checked_mul(4)? {
        return None;
    }
    let pixels = set
        .pixels
        .chunks_exact(4)
        .map(|p| Color32::from_rgba_premultiplied(p[0], p[1], p[2], p[3]))
        .collect();
    let options = serde_json::from_str(set.options_json.as_str()).unwrap_or_default();
    let image = Arc::new(ColorImage::new(size, pixels));
    let pos = set
        .pos
        .into_option()
        .and_then(|[x, y]| Some([usize::try_from(x).ok()?, usize::try_from(y).ok()?]));
    Some(match pos {
        Some(pos) => ImageDelta::partial(pos, image, options),
        None => ImageDelta::full(image, options),
    })
}

impl From<GuiOutputFfi> for GuiOutput {
    fn from(ffi: GuiOutputFfi) -> Self {
        let primitives = ffi
            .meshes
            .iter()
            .map(|mesh| ClippedPrimitive {
                clip_rect: rect(mesh.clip_rect),
                primitive: Primitive::Mesh(Mesh {
                    indices: mesh.indices.to_vec(),
                    vertices: mesh
                        .vertices
                        .iter()
                        .map(|v| Vertex {
                            pos: Pos2::new(v.pos[0], v.pos[1]),
                            uv: Pos2::new(v.uv[0], v.uv[1]),
                            color: Color32::from_rgba_premultiplied(
                                v.color[0], v.color[1], v.color[2], v.color[3],
                            ),
                        })
                        .collect(),
                    texture_id: texture_id(mesh.texture),
                }),
            })
            .collect();
        let mut textures = TexturesDelta::default();
        for set in &ffi.textures_set {
            if let Some(delta) = image_delta(set) {
                textures.push(texture_id(set.id), delta);
            }
        }
        for id in &ffi.textures_free {
            textures.free(texture_id(*id));
        }
        Self {
            primitives,
            textures,
            platform: serde_json::from_str(ffi.platform_output_json.as_str()).unwrap_or_default(),
            pixels_per_point: ffi.pixels_per_point,
            using_pointer: ffi.using_pointer,
            wants_keyboard: ffi.wants_keyboard,
            floating_areas: ffi.floating_areas.iter().map(|r| rect(*r)).collect(),
            free_rect: rect(ffi.free_rect),
        }
    }
}
