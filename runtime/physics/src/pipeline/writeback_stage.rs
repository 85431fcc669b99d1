//! Write-back stage: commit solver motion to bodies (with CCD clamping and NaN quarantine),
//! clear forces, refresh bounds.

use std::time::Instant;

use glam::Vec3;

use super::ccd::sweep_body;
use crate::body_type::BodyType;
use crate::physics_world::PhysicsWorld;
use crate::pose::{unit_rotation, Pose};
use crate::rigid_body::SpinCache;

impl PhysicsWorld {
    pub(crate) fn writeback_stage(&mut self) {
        let s = self.settings;
        let mut bad = Vec::new();
        let mut ccd_time = std::time::Duration::ZERO;
        for k in 1..self.solver_bodies.len() {
            let sb = self.solver_bodies[k];
            let st = self.solver_states[k];
            let idx = self.solver_handles[k];
            let handle = self.bodies.handle_of(idx);
            let Some(b) = self.bodies.arena.get_by_index_mut(idx) else {
                continue;
            };
            let com0 = b.pose.transform_point(b.mass.local_com);
            let rot = unit_rotation(sb.dq * sb.q0);
            let com = com0 + Vec3::from(st.dp);
            let finite = com.is_finite() && rot.is_finite() && st.v.is_finite() && st.w.is_finite();
            if !finite {
                bad.push(handle);
                continue;
            }
            let mut pose = Pose::new(com - rot * b.mass.local_com, rot);
            b.linvel = st.v.into();
            b.angvel = st.w.into();
            if b.body_type == BodyType::Kinematic {
                if let Some(t) = b.kinematic_target.take() {
                    pose = t;
                    b.linvel = Vec3::ZERO;
                    b.angvel = Vec3::ZERO;
                }
            }
            let ccd_on = s.ccd_enabled && b.ccd_enabled && b.body_type == BodyType::Dynamic;
            let start_pose = b.pose;
            if ccd_on {
                let t0 = Instant::now();
                let (t, not_converged) = sweep_body(
                    &self.colliders,
                    &self.bodies,
                    &self.broadphase,
                    handle,
                    &start_pose,
                    &pose,
                    &s,
                );
                if not_converged {
                    self.output.counters.ccd_not_converged += 1;
                }
                if t < 1.0 {
                    pose.translation =
                        start_pose.translation + (pose.translation - start_pose.translation) * t;
                    self.output.counters.ccd_hits += 1;
                }
                ccd_time += t0.elapsed();
            }
            let Some(b) = self.bodies.arena.get_by_index_mut(idx) else {
                continue;
            };
            b.pose = pose;
            b.last_good_pose = pose;
            b.spin_cache = (sb.gyro && sb.omega_world == st.w).then_some(SpinCache {
                world: b.angvel,
                rotation: pose.rotation,
                body: sb.omega_body,
            });
            b.force = Vec3::ZERO;
            b.torque = Vec3::ZERO;
            // Bounds, swept ahead by the expected next-step motion.
            let v = b.linvel;
            let sweep_len = (v.length() * s.dt).min(if ccd_on {
                f32::MAX
            } else {
                s.max_speculative_distance
            });
            let disp = v.normalize_or_zero() * sweep_len;
            for &ch in &b.colliders {
                if let Some(c) = self.colliders.get_mut(ch) {
                    let p = pose.mul_pose(&c.local_pose);
                    c.aabb = c.shape.aabb(&p);
                    let mut swept = c.aabb.expanded(s.speculative_distance);
                    swept.min += disp.min(Vec3::ZERO);
                    swept.max += disp.max(Vec3::ZERO);
                    self.broadphase
                        .update_proxy(c.proxy, swept, s.aabb_margin, disp);
                }
            }
        }
        for h in bad {
            self.quarantine(h);
        }
        // Forces live only on awake dynamic bodies (adding one wakes the body), which the loop
        // above cleared: sleeping bodies are not visited.
        self.output.counters.ccd = ccd_time;
    }
}
