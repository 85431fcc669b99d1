//! [`PluginGui`]: the plugin's own `egui::Context`, living inside the plugin's image, and
//! the run of one GUI frame from plain-data input to plain-data output.

use std::cell::Cell;

use abi_stable::std_types::{ROption, RString, RVec};
use egui::epaint::{ClippedPrimitive, ImageData, Primitive};

use super::gui_ffi::{GuiInputFfi, GuiOutputFfi, MeshFfi, TextureIdFfi, TextureSetFfi, VertexFfi};

thread_local! {
    /// Set by the default `Plugin::draw_gui`: the plugin has no GUI.
    static DEFAULT_DRAW_GUI_RAN: Cell<bool> = const { Cell::new(false) };
}

/// Called by the default `Plugin::draw_gui`: marks the plugin as having no GUI, so the SDK
/// stops running egui for it and the host stops calling it.
pub fn mark_no_gui() {
    DEFAULT_DRAW_GUI_RAN.with(|c| c.set(true));
}

/// Whether a plugin draws a GUI, learnt on its first GUI frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum GuiUse {
    Unknown,
    Active,
    Unused,
}

/// One plugin's egui state. Never shared with another image: its context holds boxed
/// callbacks and type-keyed memory that point into this image.
pub struct PluginGui {
    context: Option<egui::Context>,
    usage: GuiUse,
}

impl Default for PluginGui {
    fn default() -> Self {
        Self {
            context: None,
            usage: GuiUse::Unknown,
        }
    }
}

impl PluginGui {
    /// Runs one GUI frame: `draw` is the plugin's `draw_gui` on the root `Ui`.
    pub fn run(
        &mut self,
        input: GuiInputFfi<'_>,
        mut draw: impl FnMut(&mut egui::Ui),
    ) -> GuiOutputFfi {
        if self.usage == GuiUse::Unused {
            return GuiOutputFfi::inactive();
        }
        let raw: egui::RawInput =
            serde_json::from_slice(input.raw_input_json.as_slice()).unwrap_or_default();
        let context = self.context.get_or_insert_with(egui::Context::default);
        if input.accesskit {
            context.enable_accesskit();
        } else {
            context.disable_accesskit();
        }
        DEFAULT_DRAW_GUI_RAN.with(|c| c.set(false));
        let mut free_rect = egui::Rect::EVERYTHING;
        let mut full = context.run_ui(raw, |ui| {
            draw(ui);
            free_rect = ui.available_rect_before_wrap();
        });
        // Whatever happens next, the deltas are handed over (or dropped with the plugin's
        // GUI): egui insists they are not dropped unapplied.
        let mut textures = std::mem::take(&mut full.textures_delta);
        let no_gui = DEFAULT_DRAW_GUI_RAN.with(|c| c.replace(false));
        if no_gui && self.usage == GuiUse::Unknown {
            textures.clear();
            self.usage = GuiUse::Unused;
            self.context = None;
            return GuiOutputFfi::inactive();
        }
        self.usage = GuiUse::Active;
        let pixels_per_point = full.pixels_per_point;
        let primitives = context.tessellate(full.shapes, pixels_per_point);
        let output = GuiOutputFfi {
            active: true,
            pixels_per_point,
            meshes: primitives.iter().filter_map(mesh_ffi).collect(),
            textures_set: textures
                .set
                .iter()
                .flat_map(|(id, deltas)| deltas.iter().map(|d| texture_set_ffi(*id, d)))
                .collect(),
            textures_free: textures.free.iter().map(|id| texture_id_ffi(*id)).collect(),
            platform_output_json: serde_json::to_string(&full.platform_output)
                .map(RString::from)
                .unwrap_or_default(),
            using_pointer: context.egui_is_using_pointer(),
            wants_keyboard: context.egui_wants_keyboard_input(),
            floating_areas: floating_areas(context),
            free_rect: rect_ffi(free_rect),
        };
        textures.clear();
        output
    }
}

fn texture_id_ffi(id: egui::TextureId) -> TextureIdFfi {
    match id {
        egui::TextureId::Managed(id) => TextureIdFfi { user: false, id },
        egui::TextureId::User(id) => TextureIdFfi { user: true, id },
    }
}

fn rect_ffi(rect: egui::Rect) -> [f32; 4] {
    [rect.min.x, rect.min.y, rect.max.x, rect.max.y]
}

/// Paint callbacks run code of this image on the host's GPU: they cannot cross and are
/// dropped.
fn mesh_ffi(primitive: &ClippedPrimitive) -> Option<MeshFfi> {
    let Primitive::Mesh(mesh) = &primitive.primitive else {
        return None;
    };
    Some(MeshFfi {
        clip_rect: rect_ffi(primitive.clip_rect),
        texture: texture_id_ffi(mesh.texture_id),
        vertices: mesh
            .vertices
            .iter()
            .map(|v| VertexFfi {
                pos: [v.pos.x, v.pos.y],
                uv: [v.uv.x, v.uv.y],
                color: v.color.to_array(),
            })
            .collect(),
        indices: RVec::from_slice(&mesh.indices),
    })
}

fn texture_set_ffi(id: egui::TextureId, delta: &egui::epaint::ImageDelta) -> TextureSetFfi {
    let ImageData::Color(image) = &delta.image;
    let mut pixels = RVec::with_capacity(image.pixels.len() * 4);
    for pixel in &image.pixels {
        pixels.extend_from_slice(&pixel.to_array());
    }
    TextureSetFfi {
        id: texture_id_ffi(id),
        pos: match delta.pos {
            Some([x, y]) => ROption::RSome([x as u64, y as u64]),
            None => ROption::RNone,
        },
        size: [image.size[0] as u64, image.size[1] as u64],
        options_json: serde_json::to_string(&delta.options)
            .map(RString::from)
            .unwrap_or_default(),
        pixels,
    }
}

/// Windows, popups and menus: every visible area above the background layer.
fn floating_areas(context: &egui::Context) -> RVec<[f32; 4]> {
    context.memory(|memory| {
        memory
            .areas()
            .visible_layer_ids()
            .into_iter()
            .filter(|layer| layer.order != egui::Order::Background)
            .filter_map(|layer| memory.area_rect(layer.id).map(rect_ffi))
            .collect()
    })
}
