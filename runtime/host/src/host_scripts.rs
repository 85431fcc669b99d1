//! [`run_scripts`]: the frame's script calls — `Created`, `Update`, `Destroyed` — for each
//! entity whose [`Script`] names a registered behaviour.

use onyx_plugin_api::{PlayMode, Script, ScriptCall, ScriptPhase};

use crate::entity_id::to_api;
use crate::plugins::{PluginSlot, Stage};
use crate::scripts::scripted_entities;
use crate::state::HostState;

fn call(
    plugins: &mut [PluginSlot],
    state: &mut HostState,
    entity: hecs::Entity,
    script: &Script,
    phase: ScriptPhase,
    dt: f32,
) {
    let Some(owner) = state
        .tools
        .scripts
        .get(&script.name)
        .map(|s| s.plugin.clone())
    else {
        return;
    };
    let Some(slot) = plugins.iter_mut().find(|p| p.name() == owner) else {
        return;
    };
    let call = ScriptCall {
        entity: to_api(entity),
        phase,
        name: script.name.clone(),
        params: script.params.clone(),
        dt,
    };
    slot.call(state, Stage::Script, |p, cx| p.on_script(cx, &call));
}

/// Runs one frame of scripts, after `on_update`: while playing, `Created` for scripts that
/// appeared and `Update` for all; `Destroyed` for scripts whose entity or component went
/// away, whose world was replaced, or — on leaving play for Edit — all of them.
pub(crate) fn run_scripts(plugins: &mut [PluginSlot], state: &mut HostState, dt: f32) {
    let mut runner = std::mem::take(&mut state.tools.script_runner);
    let mode = state.tools.play.mode();
    let generation_changed = runner.generation != state.tools.world_generation;
    if generation_changed || mode == PlayMode::Edit {
        let mut gone: Vec<(hecs::Entity, Script)> = runner.live.drain().collect();
        gone.sort_by_key(|(e, _)| e.to_bits());
        for (e, script) in gone {
            call(plugins, state, e, &script, ScriptPhase::Destroyed, 0.0);
        }
        runner.generation = state.tools.world_generation;
    }
    if mode != PlayMode::Playing {
        state.tools.script_runner = runner;
        return;
    }
    let current = scripted_entities(&state.world.ecs);
    let mut ended: Vec<(hecs::Entity, Script)> = runner
        .live
        .iter()
        .filter(|(e, script)| {
            !current
                .iter()
                .any(|(c, s)| c == *e && s.name == script.name)
        })
        .map(|(e, s)| (*e, s.clone()))
        .collect();
    ended.sort_by_key(|(e, _)| e.to_bits());
    for (e, script) in ended {
        runner.live.remove(&e);
        call(plugins, state, e, &script, ScriptPhase::Destroyed, 0.0);
    }
    for (e, script) in current {
        if state.tools.scripts.get(&script.name).is_none() {
            continue;
        }
        if let std::collections::hash_map::Entry::Vacant(slot) = runner.live.entry(e) {
            slot.insert(script.clone());
            call(plugins, state, e, &script, ScriptPhase::Created, 0.0);
        }
        // The script may have despawned its entity or removed itself in `Created`.
        if state.world.ecs.contains(e) {
            if let Some(live) = runner.live.get_mut(&e) {
                live.params = script.params.clone();
            }
            call(plugins, state, e, &script, ScriptPhase::Update, dt);
        }
    }
    state.tools.script_runner = runner;
}
