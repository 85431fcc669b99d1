//! The GUI frame as plain data: what the host passes in ([`GuiInputFfi`]) and what the
//! plugin's egui run returns ([`GuiOutputFfi`]): tessellated meshes, texture changes, the
//! platform output and where the UI takes input.
//!
//! Input and platform output cross as JSON (egui's own serde types: small, and free to grow);
//! meshes and pixels cross as `#[repr(C)]` arrays (large, copied once).

use abi_stable::{
    std_types::{ROption, RSlice, RString, RVec},
    StableAbi,
};

/// One frame's input for a plugin's UI.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug)]
pub struct GuiInputFfi<'a> {
    /// `egui::RawInput` as JSON.
    pub raw_input_json: RSlice<'a, u8>,
    /// Whether to build the AccessKit tree (tests find widgets by label through it).
    pub accesskit: bool,
}

/// `egui::epaint::Vertex`: position and uv in points / normalised texels, premultiplied
/// sRGBA colour.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct VertexFfi {
    pub pos: [f32; 2],
    pub uv: [f32; 2],
    pub color: [u8; 4],
}

/// `egui::TextureId`: `user == false` is `Managed(id)`, else `User(id)`.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TextureIdFfi {
    pub user: bool,
    pub id: u64,
}

/// One clipped triangle mesh.
#[repr(C)]
#[derive(StableAbi, Clone, Debug)]
pub struct MeshFfi {
    /// min x, min y, max x, max y, points.
    pub clip_rect: [f32; 4],
    pub texture: TextureIdFfi,
    pub vertices: RVec<VertexFfi>,
    pub indices: RVec<u32>,
}

/// `egui::epaint::ImageDelta` for one texture.
#[repr(C)]
#[derive(StableAbi, Clone, Debug)]
pub struct TextureSetFfi {
    pub id: TextureIdFfi,
    /// Where the patch goes; `None`: the whole texture.
    pub pos: ROption<[u64; 2]>,
    /// Width, height, texels.
    pub size: [u64; 2],
    /// `egui::TextureOptions` as JSON.
    pub options_json: RString,
    /// Premultiplied sRGBA, row by row from the top.
    pub pixels: RVec<u8>,
}

/// What one GUI frame of a plugin produced.
#[repr(C)]
#[derive(StableAbi, Clone, Debug)]
pub struct GuiOutputFfi {
    /// `false`: the plugin does not override `draw_gui`; the host need not call it again.
    pub active: bool,
    pub pixels_per_point: f32,
    pub meshes: RVec<MeshFfi>,
    pub textures_set: RVec<TextureSetFfi>,
    pub textures_free: RVec<TextureIdFfi>,
    /// `egui::PlatformOutput` as JSON.
    pub platform_output_json: RString,
    /// egui is using the pointer (dragging a widget): pointer input is the UI's.
    pub using_pointer: bool,
    /// A widget wants keyboard input (a focused text field).
    pub wants_keyboard: bool,
    /// The floating areas (windows, popups, menus), min x, min y, max x, max y, points.
    pub floating_areas: RVec<[f32; 4]>,
    /// What the root `Ui` left free after the plugin's panels: the pointer is the scene's
    /// there unless a floating area covers it.
    pub free_rect: [f32; 4],
}

impl GuiOutputFfi {
    /// The answer of a plugin without a GUI.
    pub fn inactive() -> Self {
        Self {
            active: false,
            pixels_per_point: 1.0,
            meshes: RVec::new(),
            textures_set: RVec::new(),
            textures_free: RVec::new(),
            platform_output_json: RString::new(),
            using_pointer: false,
            wants_keyboard: false,
            floating_areas: RVec::new(),
            free_rect: [
                f32::NEG_INFINITY,
                f32::NEG_INFINITY,
                f32::INFINITY,
                f32::INFINITY,
            ],
        }
    }
}
