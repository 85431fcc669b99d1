//! Broadphase stage: new pairs from moved proxies, filtered and added to the narrowphase.

use crate::body_type::BodyType;
use crate::physics_world::PhysicsWorld;

impl PhysicsWorld {
    pub(crate) fn broadphase_stage(&mut self) {
        let mut pairs = std::mem::take(&mut self.new_pairs);
        pairs.clear();
        self.broadphase.find_pairs(&mut pairs);
        let mut added = 0;
        for &(ia, ib) in &pairs {
            // Most reports of a moved proxy are pairs that exist: skip them before touching
            // the colliders and bodies (random memory accesses).
            if self.narrowphase.has_pair_of_indices(ia, ib) {
                continue;
            }
            let (Some(ca), Some(cb)) = (
                self.colliders.arena.get_by_index(ia),
                self.colliders.arena.get_by_index(ib),
            ) else {
                continue;
            };
            if ca.parent == cb.parent
                || !ca.groups.interacts_with(cb.groups)
                || self
                    .joints
                    .keeps_apart(ca.parent.index(), cb.parent.index())
            {
                continue;
            }
            let (Some(ba), Some(bb)) = (self.bodies.get(ca.parent), self.bodies.get(cb.parent))
            else {
                continue;
            };
            if ba.body_type != BodyType::Dynamic && bb.body_type != BodyType::Dynamic {
                continue;
            }
            let ha = self.colliders.handle_of(ia);
            let hb = self.colliders.handle_of(ib);
            if self.narrowphase.add_pair(
                ha,
                hb,
                ca.parent,
                cb.parent,
                &ca.material,
                &cb.material,
                ca.shape.size().min(cb.shape.size()),
                ca.sensor || cb.sensor,
            ) {
                added += 1;
            }
        }
        self.output.counters.new_pairs = added;
        self.new_pairs = pairs;
    }
}
