//! [`HostState`]: everything a plugin call can reach, in parts that systems borrow one at a
//! time.

use onyx_plugin_api::{Entity, EntityTransform, Event};

use super::FrameIo;
use crate::assets::AssetRegistry;
use crate::clock::FixedClock;
use crate::physics::PhysicsSystem;
use crate::render::{RenderInput, ViewState};
use crate::tools::ToolState;
use crate::world::WorldState;

/// The host's state apart from its plugins: the world (entities, scene graph, assets), the
/// frame's input and output, the clock, physics, the view and the tool services' state.
/// A system takes the part it needs (physics: the world and the events), never the whole.
#[derive(Debug)]
pub struct HostState {
    /// Entities, components, the scene graph and the assets they name.
    pub world: WorldState,
    /// Events, input, requests and debug lines of this frame.
    pub io: FrameIo,
    /// The fixed-step clock.
    pub clock: FixedClock,
    /// Rigid-body physics.
    pub physics: PhysicsSystem,
    /// The chosen camera, the orbit camera, the view switches.
    pub view: ViewState,
    /// What the tool services keep (diagnostics, play mode, scripts, scene path).
    pub tools: ToolState,
    /// Buffers bulk calls hand to plugins, reused from call to call.
    pub(crate) buffers: CallBuffers,
}

/// Host-owned buffers a plugin reads (and edits) in place during one call.
#[derive(Debug, Default)]
pub(crate) struct CallBuffers {
    pub entities: Vec<Entity>,
    pub transforms: Vec<EntityTransform>,
}

impl HostState {
    /// An empty world with `clock`, resolving asset paths with `assets`.
    pub fn new(clock: FixedClock, assets: AssetRegistry) -> Self {
        Self {
            world: WorldState::new(assets),
            io: FrameIo::default(),
            clock,
            physics: PhysicsSystem::default(),
            view: ViewState::default(),
            tools: ToolState::default(),
            buffers: CallBuffers::default(),
        }
    }

    /// Replaces the whole world (new or opened scene) by despawning `old`, the entities
    /// there were before (an opened scene has spawned its own beside them): physics rebuilt
    /// from the components, the chosen camera forgotten, Stop no longer restores an older
    /// world. Handles are never reused, so a plugin's handle from before names nothing.
    pub fn retire_entities(&mut self, old: &[hecs::Entity]) {
        self.world.despawn_all_of(old);
        self.after_world_replaced();
        self.tools.play.forget_snapshot();
    }

    /// What the renderer draws from, and where it reports asset and GPU failures.
    pub fn render_input(&mut self) -> (RenderInput<'_>, &mut Vec<Event>) {
        let input = RenderInput {
            world: &self.world,
            view: &self.view,
            debug_lines: &self.io.debug_lines,
            physics: &self.physics,
            alpha: self.clock.time().alpha,
        };
        (input, &mut self.io.events)
    }

    /// Bookkeeping after the world's entities were all replaced.
    pub fn after_world_replaced(&mut self) {
        self.physics.reset();
        self.view.camera_override = None;
        self.tools.world_generation += 1;
    }
}
