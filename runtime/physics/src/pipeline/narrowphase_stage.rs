//! Narrowphase stage: regenerate manifolds of active pairs, collect wake-ups.

use crate::narrowphase::narrow_body::NarrowBody;
use crate::narrowphase::NarrowStats;
use crate::physics_world::PhysicsWorld;

impl PhysicsWorld {
    pub(crate) fn narrowphase_stage(&mut self) {
        let mut stats = NarrowStats::default();
        let mut wake = std::mem::take(&mut self.wake);
        // The awake bodies' copy for the pair loop (see `NarrowBody`).
        let n = self.bodies.arena.capacity();
        if self.narrow_bodies.len() < n {
            self.narrow_bodies.resize(n, NarrowBody::default());
        }
        for &i in &self.active_bodies {
            if let Some(b) = self.bodies.arena.get_by_index(i) {
                self.narrow_bodies[i as usize] = NarrowBody::of(b);
            }
        }
        self.narrowphase.update(
            &self.bodies,
            &self.colliders,
            &self.broadphase,
            &self.settings,
            &mut stats,
            &mut self.output.events,
            &mut wake,
            &self.active_flags,
            &self.narrow_bodies,
        );
        // Wake touched sleepers now so they take part in this step's solve (their contacts
        // with static bodies are unchanged since they fell asleep). Their pairs were not
        // updated, so the later stages visit every pair this step.
        if !wake.is_empty() {
            let all = 0..self.narrowphase.pairs.len() as u32;
            self.narrowphase.updated_pairs.clear();
            self.narrowphase.updated_pairs.extend(all);
        }
        for h in wake.drain(..) {
            self.wake_island(h);
        }
        self.wake = wake;
        let c = &mut self.output.counters;
        c.gjk_calls = stats.gjk_calls;
        c.gjk_iterations = stats.gjk_iterations;
        c.gjk_not_converged = stats.gjk_not_converged;
        c.epa_calls = stats.epa_calls;
        c.epa_iterations = stats.epa_iterations;
        c.epa_failures = stats.epa_failures;
        c.reused_pairs = stats.reused_pairs;
    }
}
