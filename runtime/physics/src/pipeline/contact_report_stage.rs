//! Contact report stage: `Started` events with this step's impulses, grounded flags and
//! last contact normals.

use glam::Vec3;

use crate::contact_event::ContactEventKind;
use crate::narrowphase::narrow_phase::make_event;
use crate::physics_world::{PhysicsWorld, SolverSlot};

impl PhysicsWorld {
    /// Touch transitions of the pairs regenerated this step (after the solve, so that an
    /// impact resolved by a speculative point starts touching in the step it happens).
    /// `Started` events carry this step's impulse.
    pub(crate) fn update_touching(&mut self) {
        let slop = self.settings.linear_slop;
        self.report_pairs.clear();
        // Only updated pairs were solved or can change (see `NarrowPhase::updated_pairs`).
        for &i in &self.narrowphase.updated_pairs {
            let p = &mut self.narrowphase.pairs[i as usize];
            let solved_pushing = p.solved_pushing.take();
            if !p.updated {
                continue;
            }
            p.updated = false;
            let pushing = solved_pushing.unwrap_or_else(|| {
                p.manifolds
                    .iter()
                    .any(|m| m.points.iter().any(|c| c.max_normal_impulse > 0.0))
            });
            let now = pushing || p.min_separation <= 0.0;
            if !p.touching && now {
                p.touching = true;
                // Summed only for the event: walking every pair's points each step cost
                // ~5 % of a step with 8,000 spheres.
                let impulse: f32 = p.manifolds.iter().map(|m| m.total_normal_impulse()).sum();
                self.output.events.push(make_event(
                    ContactEventKind::Started,
                    p,
                    &self.bodies,
                    impulse,
                ));
            } else if p.touching && !now && p.min_separation > slop {
                p.touching = false;
                self.output
                    .events
                    .push(make_event(ContactEventKind::Ended, p, &self.bodies, 0.0));
            }
            // A sensor's overlap neither grounds a body nor gives it a contact normal.
            if p.touching && !p.sensor {
                self.report_pairs.push(i);
            }
        }
    }

    pub(crate) fn contact_report_stage(&mut self) {
        let min_y = self.settings.grounded_min_normal_y;
        // Deepest contact of each awake dynamic body, by solver index (no sort, no allocation
        // once the scratch has grown).
        let mut deepest = std::mem::take(&mut self.deepest_contact);
        deepest.clear();
        deepest.resize(self.solver_bodies.len(), (f32::MAX, Vec3::ZERO, false));
        // Pairs that touch and were regenerated this step: a pair of sleeping bodies has no
        // awake dynamic body to report on.
        for &pi in &self.report_pairs {
            let p = &self.narrowphase.pairs[pi as usize];
            for m in &p.manifolds {
                let sep = m.min_separation();
                for (h, n) in [(p.body_a, -m.normal), (p.body_b, m.normal)] {
                    // The compact solver slot, not the body: one cache line for many bodies.
                    let Some(&SolverSlot {
                        index,
                        dynamic: true,
                        ..
                    }) = self.solver_slots.get(h.index() as usize)
                    else {
                        continue;
                    };
                    let slot = &mut deepest[index as usize];
                    // Grounded by any supporting contact (a box under a stack touches the
                    // box above more deeply than the ground).
                    slot.2 |= n.y >= min_y;
                    if sep <= slot.0 {
                        (slot.0, slot.1) = (sep, n);
                    }
                }
            }
        }
        // One write per awake body (bodies are large: a second pass to reset them first cost
        // a cache miss each).
        for (k, &(sep, n, grounded)) in deepest.iter().enumerate().skip(1) {
            if let Some(b) = self.bodies.arena.get_by_index_mut(self.solver_handles[k]) {
                let touching = sep != f32::MAX;
                b.grounded = touching && grounded;
                b.last_contact_normal = touching.then_some(n);
            }
        }
        self.deepest_contact = deepest;
    }
}
