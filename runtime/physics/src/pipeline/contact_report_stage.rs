//! Contact report stage: `Started` events with this step's impulses, grounded flags and
//! last contact normals.

use glam::Vec3;

use crate::body_type::BodyType;
use crate::contact_event::ContactEventKind;
use crate::narrowphase::narrow_phase::make_event;
use crate::physics_world::PhysicsWorld;

impl PhysicsWorld {
    /// Touch transitions of the pairs regenerated this step (after the solve, so that an
    /// impact resolved by a speculative point starts touching in the step it happens).
    /// `Started` events carry this step's impulse.
    pub(crate) fn update_touching(&mut self) {
        let slop = self.settings.linear_slop;
        for p in &mut self.narrowphase.pairs {
            if !p.updated {
                continue;
            }
            p.updated = false;
            let impulse: f32 = p.manifolds.iter().map(|m| m.total_normal_impulse()).sum();
            let pushing = p
                .manifolds
                .iter()
                .any(|m| m.points.iter().any(|c| c.max_normal_impulse > 0.0));
            let now = pushing || p.min_separation <= 0.0;
            if !p.touching && now {
                p.touching = true;
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
        }
    }

    pub(crate) fn contact_report_stage(&mut self) {
        let min_y = self.settings.grounded_min_normal_y;
        for k in 1..self.solver_bodies.len() {
            if let Some(b) = self.bodies.arena.get_by_index_mut(self.solver_handles[k]) {
                b.grounded = false;
                b.last_contact_normal = None;
            }
        }
        let mut deepest: Vec<(u32, f32, Vec3)> = Vec::new();
        for p in &self.narrowphase.pairs {
            if !p.touching {
                continue;
            }
            for m in &p.manifolds {
                let sep = m.min_separation();
                for (h, n) in [(p.body_a, -m.normal), (p.body_b, m.normal)] {
                    let Some(b) = self.bodies.get(h) else {
                        continue;
                    };
                    if b.body_type != BodyType::Dynamic || b.solver_index == 0 {
                        continue;
                    }
                    deepest.push((h.index(), sep, n));
                }
            }
        }
        // Deepest last, so it wins.
        deepest.sort_by(|a, b| b.1.total_cmp(&a.1));
        for (idx, _sep, n) in deepest {
            if let Some(b) = self.bodies.arena.get_by_index_mut(idx) {
                if n.y >= min_y {
                    b.grounded = true;
                }
                b.last_contact_normal = Some(n);
            }
        }
    }
}
