//! [`GuiInput`]: one frame's input for a plugin's user interface.

/// What a plugin's egui context gets each frame.
#[derive(Clone, Debug, Default)]
pub struct GuiInput {
    /// Screen size, time, pointer, keys, text… (egui's own input type).
    pub raw: egui::RawInput,
    /// Build the AccessKit tree (see [`GuiOutput::platform`](super::GuiOutput)): tests find
    /// widgets by label through it. Costs a little per frame.
    pub accesskit: bool,
}

impl GuiInput {
    /// The input as JSON, as it crosses the boundary.
    pub(crate) fn to_json(&self) -> Vec<u8> {
        serde_json::to_vec(&self.raw).unwrap_or_default()
    }
}
