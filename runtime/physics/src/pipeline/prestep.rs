//! Pre-step: wake requests, kinematic targets, non-finite input quarantine.

use glam::{Quat, Vec3};

use crate::body_handle::BodyHandle;
use crate::body_type::BodyType;
use crate::physics_world::PhysicsWorld;

impl PhysicsWorld {
    pub(crate) fn prestep(&mut self) {
        let dt = self.settings.dt;
        let margin = self.settings.aabb_margin;
        let mut woken: Vec<BodyHandle> = std::mem::take(&mut self.wake);
        let mut bad: Vec<BodyHandle> = Vec::new();
        self.active_bodies.clear();
        self.active_flags.clear();
        self.active_flags
            .resize(self.bodies.arena.capacity(), false);
        for (h, b) in self.bodies.iter_mut() {
            let requested = b.wake_requested;
            if requested {
                b.wake_requested = false;
                woken.push(h);
            }
            // Sleeping bodies cannot have changed (a change wakes them): nothing to check.
            if b.quarantined || (b.sleeping && !requested) || b.body_type == BodyType::Static {
                continue;
            }
            if let Some(target) = b.kinematic_target {
                b.linvel = (target.translation - b.pose.translation) / dt;
                let dq = (target.rotation * b.pose.rotation.inverse()).normalize();
                let dq = if dq.w < 0.0 { -dq } else { dq };
                let (axis, angle) = dq.to_axis_angle();
                b.angvel = if angle.is_finite() && axis.is_finite() {
                    axis * (angle / dt)
                } else {
                    Vec3::ZERO
                };
            }
            let finite = b.pose.is_finite()
                && b.linvel.is_finite()
                && b.angvel.is_finite()
                && b.force.is_finite()
                && b.torque.is_finite()
                && b.mass.is_finite()
                && b.gravity_scale.is_finite();
            if !finite {
                bad.push(h);
            } else {
                b.last_good_pose = b.pose;
                self.active_bodies.push(h.index());
                self.active_flags[h.index() as usize] = true;
            }
        }
        for h in bad {
            self.quarantine(h);
        }
        for h in woken {
            self.wake_island(h);
            // The user may have teleported it: refresh its bounds now.
            if let Some(b) = self.bodies.get(h) {
                let pose = b.pose;
                for &ch in &b.colliders {
                    if let Some(c) = self.colliders.get_mut(ch) {
                        let p = pose.mul_pose(&c.local_pose);
                        c.aabb = c.shape.aabb(&p);
                        self.broadphase
                            .update_proxy(c.proxy, c.aabb, margin, Vec3::ZERO);
                    }
                }
            }
        }
        self.wake_jointed();
    }

    /// Rolls the body back to its last finite pose, zeroes its motion and disables it.
    pub(crate) fn quarantine(&mut self, h: BodyHandle) {
        let Some(b) = self.bodies.get_mut(h) else {
            return;
        };
        if b.quarantined {
            return;
        }
        b.quarantined = true;
        b.pose = if b.last_good_pose.is_finite() {
            b.last_good_pose
        } else {
            crate::pose::Pose::IDENTITY
        };
        b.pose.rotation = if b.pose.rotation.length_squared() > 0.0 {
            b.pose.rotation.normalize()
        } else {
            Quat::IDENTITY
        };
        b.linvel = Vec3::ZERO;
        b.angvel = Vec3::ZERO;
        b.force = Vec3::ZERO;
        b.torque = Vec3::ZERO;
        b.kinematic_target = None;
        if let Some(f) = self.active_flags.get_mut(h.index() as usize) {
            *f = false;
        }
        self.active_bodies.retain(|&i| i != h.index());
        // Its contacts end now (pairs with a sleeping partner are not revisited).
        let mut events = std::mem::take(&mut self.output.events);
        self.narrowphase
            .end_contacts_of(h, &self.bodies, &mut events);
        self.output.events = events;
        self.output.quarantined.push(h);
        self.output.counters.quarantined += 1;
    }

    /// Wakes a body and every body of its sleeping island.
    pub(crate) fn wake_island(&mut self, h: BodyHandle) {
        let Some(b) = self.bodies.get_mut(h) else {
            return;
        };
        let island = b.island;
        if b.sleeping {
            mark_active(
                &mut self.active_bodies,
                &mut self.active_flags,
                h.index(),
                b,
            );
        }
        b.sleeping = false;
        b.sleep_timer = 0.0;
        b.island = u32::MAX;
        if island == u32::MAX {
            return;
        }
        if let Some(members) = self.islands.remove(&island) {
            for m in members {
                if let Some(mb) = self.bodies.get_mut(m) {
                    if mb.sleeping {
                        mark_active(
                            &mut self.active_bodies,
                            &mut self.active_flags,
                            m.index(),
                            mb,
                        );
                    }
                    mb.sleeping = false;
                    mb.sleep_timer = 0.0;
                    mb.island = u32::MAX;
                }
            }
        }
    }
}

/// Adds a body that just woke to the step's active set (unless static or quarantined).
fn mark_active(
    list: &mut Vec<u32>,
    flags: &mut Vec<bool>,
    index: u32,
    b: &crate::rigid_body::RigidBody,
) {
    if b.quarantined || b.body_type == BodyType::Static {
        return;
    }
    let i = index as usize;
    if flags.len() <= i {
        flags.resize(i + 1, false);
    }
    if !flags[i] {
        flags[i] = true;
        list.push(index);
    }
}
