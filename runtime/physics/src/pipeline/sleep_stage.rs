//! Sleep stage: islands of touching dynamic bodies (union–find); islands at rest long
//! enough fall asleep together.

use glam::Vec3;

use crate::body_type::BodyType;
use crate::physics_world::PhysicsWorld;
use crate::pipeline::union_find::UnionFind;

impl PhysicsWorld {
    pub(crate) fn sleep_stage(&mut self) {
        let s = self.settings;
        let n = self.solver_bodies.len();
        if !s.sleep_enabled || n <= 1 {
            return;
        }
        let mut islands = UnionFind::new(n);
        for c in &self.manifold_refs {
            let (a, b) = (c.body_a, c.body_b);
            if a == 0 || b == 0 {
                continue;
            }
            if !self.narrowphase.pairs[c.pair as usize].touching {
                continue;
            }
            // Kinematic bodies (zero inverse mass) do not join islands.
            if self.solver_states[a as usize].inv_mass == glam::Vec3A::ZERO
                || self.solver_states[b as usize].inv_mass == glam::Vec3A::ZERO
            {
                continue;
            }
            islands.union(a, b);
        }
        // Jointed dynamic bodies sleep and wake together.
        for c in &self.joint_constraints {
            if c.writes != 3 {
                continue;
            }
            islands.union(c.body_a, c.body_b);
        }
        // Update timers; island minimum.
        let mut island_min = vec![f32::MAX; n];
        for k in 1..n {
            let idx = self.solver_handles[k];
            let Some(b) = self.bodies.arena.get_by_index_mut(idx) else {
                continue;
            };
            let resting = b.linvel.length() < s.sleep_linear_threshold
                && b.angvel.length() < s.sleep_angular_threshold
                && b.can_sleep
                && b.kinematic_target.is_none()
                && !b.quarantined;
            b.sleep_timer = if resting { b.sleep_timer + s.dt } else { 0.0 };
            let r = islands.find(k as u32) as usize;
            island_min[r] = island_min[r].min(b.sleep_timer);
        }
        let mut island_ids: std::collections::HashMap<u32, u32> = std::collections::HashMap::new();
        for k in 1..n {
            let r = islands.find(k as u32);
            if island_min[r as usize] < s.time_to_sleep {
                continue;
            }
            let idx = self.solver_handles[k];
            let handle = self.bodies.handle_of(idx);
            let id = *island_ids.entry(r).or_insert_with(|| {
                self.next_island = self.next_island.wrapping_add(1) % (u32::MAX - 1);
                self.next_island
            });
            if let Some(b) = self.bodies.arena.get_by_index_mut(idx) {
                if b.body_type == BodyType::Static {
                    continue;
                }
                b.sleeping = true;
                b.linvel = Vec3::ZERO;
                b.angvel = Vec3::ZERO;
                b.island = id;
                self.islands.entry(id).or_default().push(handle);
            }
        }
        self.output.counters.islands_slept = island_ids.len() as u32;
    }
}
