//! [`Stage`]: a lifecycle method, for fault reports.

/// A plugin lifecycle method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Stage {
    /// Opening the library (the system loader, and any static initialisers it runs).
    Load,
    /// Building the plugin object.
    Construct,
    /// `on_attach`.
    Attach,
    /// `on_init`.
    Init,
    /// `on_event`.
    Event,
    /// `on_fixed_update`.
    FixedUpdate,
    /// `on_update`.
    Update,
    /// `on_render`.
    Render,
    /// `draw_gui`.
    DrawGui,
    /// `on_resize`.
    Resize,
    /// `on_detach`.
    Detach,
    /// `save_state`.
    SaveState,
    /// `load_state`.
    LoadState,
    /// `on_script` (a registered script running on an entity).
    Script,
    /// The plugin's `Drop` (when it is unloaded, replaced by a new build, or the host ends).
    Drop,
}

impl Stage {
    /// The method's name as a plugin author wrote it.
    pub fn as_str(self) -> &'static str {
        match self {
            Stage::Load => "loading",
            Stage::Construct => "constructor",
            Stage::Attach => "on_attach",
            Stage::Init => "on_init",
            Stage::Event => "on_event",
            Stage::FixedUpdate => "on_fixed_update",
            Stage::Update => "on_update",
            Stage::Render => "on_render",
            Stage::DrawGui => "draw_gui",
            Stage::Resize => "on_resize",
            Stage::Detach => "on_detach",
            Stage::SaveState => "save_state",
            Stage::LoadState => "load_state",
            Stage::Script => "on_script",
            Stage::Drop => "drop",
        }
    }

    /// Every stage, in declaration order (`ALL[stage as usize] == stage`).
    pub const ALL: [Stage; 15] = [
        Stage::Load,
        Stage::Construct,
        Stage::Attach,
        Stage::Init,
        Stage::Event,
        Stage::FixedUpdate,
        Stage::Update,
        Stage::Render,
        Stage::DrawGui,
        Stage::Resize,
        Stage::Detach,
        Stage::SaveState,
        Stage::LoadState,
        Stage::Script,
        Stage::Drop,
    ];

    /// The stage numbered `index` (its `as u8`).
    pub fn from_index(index: u8) -> Option<Stage> {
        Self::ALL.get(usize::from(index)).copied()
    }

    /// The methods the diagnostics time, in frame order.
    pub const ALL_TIMED: [Stage; 9] = [
        Stage::Event,
        Stage::FixedUpdate,
        Stage::Update,
        Stage::Script,
        Stage::Render,
        Stage::DrawGui,
        Stage::Resize,
        Stage::Init,
        Stage::Attach,
    ];
}

#[cfg(test)]
#[test]
fn stages_round_trip_through_their_index() {
    for stage in Stage::ALL {
        assert_eq!(Stage::from_index(stage as u8), Some(stage));
    }
}

impl std::fmt::Display for Stage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}
