//! Write-back stage: commit solver motion to bodies (with CCD clamping and NaN quarantine),
//! clear forces, refresh bounds.
//!
//! Three passes: every awake body's end pose from the solver; then CCD for the bodies that
//! ask for it, against every other body's motion over the step (static, kinematic and
//! dynamic alike, see [`super::ccd`]), where two dynamic bodies with CCD that stop each
//! other stop at the same time (unless one moves much less than the other: it goes on, and
//! carries the other along) and a stop from a start in contact ends the pair's closing as
//! an impact does; then the poses are committed.

use std::time::Instant;

use glam::Vec3;

use super::ccd::{sweep_body, BodyMotion, Carry, CcdClamp, SweepHit, CCD_MOTION_THRESHOLD};
use crate::aabb::Aabb;
use crate::body_handle::BodyHandle;
use crate::body_set::BodySet;
use crate::body_type::BodyType;
use crate::collider::Collider;
use crate::far_body::FarBody;
use crate::physics_settings::PhysicsSettings;
use crate::physics_world::PhysicsWorld;
use crate::pose::{unit_rotation, Pose};
use crate::rigid_body::RigidBody;
use crate::rigid_body::SpinCache;
use crate::solver::solver_body::{CAPPED_ANGULAR, CAPPED_LINEAR};
use crate::speed_cap_hit::{SpeedCap, SpeedCapHit};

impl PhysicsWorld {
    pub(crate) fn writeback_stage(&mut self) {
        let s = self.settings;
        let mut bad = Vec::new();
        let mut ccd_time = std::time::Duration::ZERO;
        // Pass 1: end poses (index 0 unused).
        let n = self.solver_bodies.len();
        self.end_poses.clear();
        self.end_poses.push(Pose::IDENTITY);
        for k in 1..n {
            let sb = &self.solver_bodies[k];
            let st = &self.solver_states[k];
            let pose = match self.bodies.arena.get_by_index(self.solver_handles[k]) {
                Some(b) => {
                    let com0 = b.pose.transform_point(b.mass.local_com);
                    let rot = unit_rotation(sb.dq * sb.q0);
                    let com = com0 + Vec3::from(st.dp);
                    match b.kinematic_target {
                        Some(t) if b.body_type == BodyType::Kinematic => t,
                        _ => Pose::new(com - rot * b.mass.local_com, rot),
                    }
                }
                None => Pose::IDENTITY,
            };
            self.end_poses.push(pose);
        }
        // Largest displacement of any body, computed once the first CCD body is met.
        let mut max_move: Option<(f32, f32)> = None;
        // Pass 2: CCD, from the start poses (still in the bodies) to the end poses.
        self.ccd_clamps.clear();
        if s.ccd_enabled {
            let (bodies, end_poses) = (&self.bodies, &self.end_poses);
            let motion_of = |h: BodyHandle| motion_over_step(bodies, end_poses, h);
            for k in 1..n {
                let idx = self.solver_handles[k];
                let Some(b) = self.bodies.arena.get_by_index(idx) else {
                    continue;
                };
                if !b.swept() {
                    continue;
                }
                let end = &self.end_poses[k];
                if !(end.is_finite() && b.pose.is_finite()) {
                    continue;
                }
                let t0 = Instant::now();
                let (others_move, driven) = *max_move.get_or_insert_with(|| {
                    // Every body's displacement, and a kinematic body's with its turn times
                    // its reach (which no sweep of its own covers).
                    (1..n)
                        .filter_map(|j| {
                            let o = self.bodies.arena.get_by_index(self.solver_handles[j])?;
                            let m = BodyMotion::between(&o.pose, &end_poses[j], o.mass.local_com);
                            let moved = m.displacement().length();
                            if o.body_type != BodyType::Kinematic {
                                return Some((moved, 0.0));
                            }
                            let reach = o
                                .colliders
                                .iter()
                                .filter_map(|&ch| self.colliders.get(ch))
                                .map(|c| c.turning_reach(o.mass.local_com))
                                .fold(0.0f32, f32::max);
                            let driven = moved + m.turn() * reach;
                            Some((driven, driven))
                        })
                        .fold((0.0f32, 0.0f32), |a, b| (a.0.max(b.0), a.1.max(b.1)))
                });
                let motion = BodyMotion::between(&b.pose, end, b.mass.local_com);
                let sweep = sweep_body(
                    &self.colliders,
                    &self.bodies,
                    &self.broadphase,
                    self.bodies.handle_of(idx),
                    &motion,
                    s.linear_slop,
                    others_move,
                    driven,
                    &motion_of,
                );
                if sweep.not_converged {
                    self.output.counters.ccd_not_converged += 1;
                }
                if let Some(first) = sweep.first {
                    let fallback = sweep.first_unswept.filter(|f| *f != first);
                    self.ccd_clamps.push(clamp_of(
                        k as u32,
                        first,
                        fallback,
                        &self.bodies,
                        &motion_of,
                    ));
                    self.output.counters.ccd_hits += 1;
                }
                ccd_time += t0.elapsed();
            }
            self.ccd_clamps = self.carried_by_slow_bodies(&motion_of);
            self.stop_together();
            if let Some((others_move, driven)) = max_move.filter(|m| m.1 > 0.0) {
                let (bodies, end_poses) = (&self.bodies, &self.end_poses);
                let motion_of = |h: BodyHandle| motion_over_step(bodies, end_poses, h);
                for (i, carry) in
                    self.carried_by_kinematic_bodies(s.linear_slop, others_move, driven, &motion_of)
                {
                    self.ccd_clamps[i].carry = carry;
                }
            }
            // Bodies carried with a slower one after that one's own stop and carry.
            let with = |c: &CcdClamp| matches!(c.carry, Carry::With(_));
            let order: Vec<usize> = (0..self.ccd_clamps.len())
                .filter(|&i| !with(&self.ccd_clamps[i]))
                .chain((0..self.ccd_clamps.len()).filter(|&i| with(&self.ccd_clamps[i])))
                .collect();
            for i in order {
                let clamp = self.ccd_clamps[i];
                let CcdClamp {
                    t, from_contact, ..
                } = clamp;
                let k = clamp.body as usize;
                let Some(b) = self.bodies.arena.get_by_index(self.solver_handles[k]) else {
                    continue;
                };
                let motion = BodyMotion::between(&b.pose, &self.end_poses[k], b.mass.local_com);
                let at_t = motion.pose_at(t, Vec3::ZERO);
                let pose = match clamp.carry {
                    Carry::Stopped => at_t,
                    Carry::By(d) => Pose::new(at_t.translation + d * (1.0 - t), at_t.rotation),
                    Carry::With(o) => {
                        let o = o as usize;
                        let d = self
                            .bodies
                            .arena
                            .get_by_index(self.solver_handles[o])
                            .map_or(Vec3::ZERO, |ob| {
                                self.end_poses[o].translation - ob.pose.translation
                            });
                        Pose::new(at_t.translation + d * (1.0 - t), at_t.rotation)
                    }
                    // The turning body's motion from `t` to the end.
                    Carry::Rigid(m) => m
                        .pose_at(1.0, Vec3::ZERO)
                        .mul_pose(&m.pose_at(t, Vec3::ZERO).inverse())
                        .mul_pose(&at_t),
                };
                let carry =
                    pose.transform_point(b.mass.local_com) - at_t.transform_point(b.mass.local_com);
                self.end_poses[k] = pose;
                // Stopped short of where the solver left it, the body keeps the energy it
                // has there (as a rebound does, see `solver::restitution`):
                // `v′² = v² + 2·a·(x_stop − x_end)`. Kept at its speed, a ball the solver
                // had already bounced off the floor was raised by the stop distance each
                // time, and 50 elastic balls with CCD on gained 5 % of their energy over
                // 10,000 steps at fast.
                let sb = &self.solver_bodies[k];
                let rise = Vec3::from(sb.lin_acc * sb.lin_mask)
                    .dot(motion.com0 + motion.displacement() * t + carry - motion.com1);
                let st = &mut self.solver_states[k];
                // From a start in contact the body turned only the fraction `t` of what the
                // solver turned it, and it keeps only that spin. Left with the whole of it, a
                // capsule struck off centre by a wall moving into it kept the spin the contact
                // had given it, stopped again at the start of every step, and the contact held
                // it by that spin alone (its point moving with the wall, its centre not) while
                // the wall crept through it.
                if from_contact {
                    st.w *= t;
                }
                let v2 = st.v.length_squared();
                if v2 > 0.0 && rise != 0.0 {
                    st.v *= ((v2 + 2.0 * rise).max(0.0) / v2).sqrt();
                }
                if from_contact {
                    self.stop_closing(&clamp, s.restitution_threshold);
                }
            }
        }
        // Pass 3: commit.
        for k in 1..n {
            let sb = self.solver_bodies[k];
            let st = self.solver_states[k];
            let idx = self.solver_handles[k];
            let handle = self.bodies.handle_of(idx);
            let Some(b) = self.bodies.arena.get_by_index_mut(idx) else {
                continue;
            };
            let pose = self.end_poses[k];
            let finite = pose.is_finite() && st.v.is_finite() && st.w.is_finite();
            if !finite {
                bad.push(handle);
                continue;
            }
            if sb.capped != 0 {
                self.output.counters.speed_capped += 1;
                let new = sb.capped & !b.caps_reported;
                b.caps_reported |= sb.capped;
                for (bit, cap, limit) in [
                    (CAPPED_LINEAR, SpeedCap::Linear, s.max_linear_speed),
                    (CAPPED_ANGULAR, SpeedCap::Angular, s.max_angular_speed),
                ] {
                    if new & bit != 0 {
                        self.output.speed_caps.push(SpeedCapHit {
                            body: handle,
                            cap,
                            limit,
                        });
                    }
                }
            }
            if !b.far_reported {
                // Past the range of `max_position_spacing` or of the body's own size. The range
                // is at least `spacing / ε` (2²³·spacing): the logarithms only for bodies past that.
                let distance = pose.translation.abs().max_element();
                if distance * f32::EPSILON > s.position_spacing_for(b.size) {
                    let range = s.precise_range_for(b.size);
                    if distance > range {
                        b.far_reported = true;
                        self.output.far_bodies.push(FarBody {
                            body: handle,
                            distance,
                            range,
                            size: b.size,
                        });
                    }
                }
            }
            b.linvel = st.v.into();
            b.angvel = st.w.into();
            if b.body_type == BodyType::Kinematic && b.kinematic_target.take().is_some() {
                b.linvel = Vec3::ZERO;
                b.angvel = Vec3::ZERO;
            }
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
            for &ch in &b.colliders {
                if let Some(c) = self.colliders.get_mut(ch) {
                    c.aabb = c.shape.aabb(&pose.mul_pose(&c.local_pose));
                    let (swept, disp) = swept_bounds(c, b, &s);
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

    /// Two dynamic bodies with CCD that stop each other stop at the same fraction of the step,
    /// the earlier of their two: each was swept against the other's whole motion, and only the
    /// poses at one time are known to be apart. Stopped at their own fractions, two plates the
    /// contact had set moving together (one stopped at 0.6 % of the step, the other at 1.5 %)
    /// ended on each other's far side; stopped by one's sweep alone (the other's, by rounding,
    /// found nothing), the one left behind was passed through. A body stopped by one that is
    /// carried on (by a kinematic body it met) is carried with it: a bullet of a volley that a
    /// wall moving at 20 m/s was pushing, stopped by its neighbour at an eighth of the step,
    /// was left there while the wall took the neighbour on, and the wall went through it.
    fn stop_together(&mut self) {
        if self.ccd_clamps.is_empty() {
            return;
        }
        // Which clamp, if any, stops each solver body (index + 1; 0 for none): a look-up,
        // not a search of the clamps for every clamp.
        let mut clamp_of = vec![0u32; self.solver_states.len()];
        for (i, c) in self.ccd_clamps.iter().enumerate() {
            clamp_of[c.body as usize] = i as u32 + 1;
        }
        // Each pass can only lower a fraction or add a body; a chain of n bodies settles in n
        // passes.
        for _ in 0..self.ccd_clamps.len() {
            let mut changed = false;
            for i in 0..self.ccd_clamps.len() {
                let c = self.ccd_clamps[i];
                let Some(o) = self.bodies.get(c.hit) else {
                    continue;
                };
                let other = o.solver_index;
                if !(o.swept() && other != 0) {
                    continue;
                }
                if c.carry.moves() {
                    // Carried by the body it hit (see `carried_by_slow_bodies`).
                    continue;
                }
                match clamp_of[other as usize] {
                    0 => {
                        let body = self.solver_handles[c.body as usize];
                        self.ccd_clamps.push(CcdClamp {
                            body: other,
                            t: c.t,
                            carry: Carry::Stopped,
                            from_contact: c.from_contact,
                            hit: self.bodies.handle_of(body),
                            normal: -c.normal,
                            restitution: c.restitution,
                            fallback: None,
                        });
                        clamp_of[other as usize] = self.ccd_clamps.len() as u32;
                        changed = true;
                    }
                    j => {
                        let theirs = &mut self.ccd_clamps[j as usize - 1];
                        if theirs.carry.moves() {
                            // Carried on (by a kinematic wall it met), it takes this one
                            // along from its own stop.
                            self.ccd_clamps[i].carry = theirs.carry;
                            changed = true;
                        } else if theirs.t > c.t {
                            theirs.t = c.t;
                            changed = true;
                        }
                    }
                }
            }
            if !changed {
                break;
            }
        }
    }

    /// The clamps, where a body stopped by a dynamic body with CCD that moves much less than
    /// it over the step is carried along by that one, as by a kinematic body, instead of
    /// stopping it: the slow one goes on, and a stop it had at the fast one gives way to its
    /// first hit of something that does not stop itself, or to none. The fast body is carried
    /// back along the path it came by, which it has just swept clear. Stopped with the fast
    /// one, a slow body that a kinematic body was pushing was passed by it: a 3 cm box against
    /// a wall moving at 0.5 m/s, struck by a 1 cm bullet, was held at 60 % of its step, 7 mm
    /// into the 1 cm wall, and the wall went through it (in 3 of the 216 cases of
    /// `tests/ccd_walls.rs`, all at fast, once the ghost contacts and the stops from a start
    /// in contact were mended; 34 before).
    ///
    /// Much less: a quarter of the fast body's motion, and what is left of it after the stop
    /// no longer than the part of its path the fast body has swept.
    fn carried_by_slow_bodies(
        &self,
        motion_of: &dyn Fn(BodyHandle) -> Option<BodyMotion>,
    ) -> Vec<CcdClamp> {
        let mut clamps = self.ccd_clamps.clone();
        let disp = |k: usize| {
            let b = self.bodies.arena.get_by_index(self.solver_handles[k])?;
            Some(BodyMotion::between(&b.pose, &self.end_poses[k], b.mass.local_com).displacement())
        };
        // Which clamps carry their body (fast) along a slow swept body it hit.
        let mut carriers = Vec::new();
        for c in &mut clamps {
            let Some(o) = self.bodies.get(c.hit).filter(|o| o.swept()) else {
                continue;
            };
            let other = o.solver_index as usize;
            let (Some(fast), Some(slow)) = (disp(c.body as usize), disp(other)) else {
                continue;
            };
            // What is left of the slow body's motion after the stop, against the part of
            // its own path the fast body has swept: no longer, and no farther from that line
            // than half the fast body's thinnest half extent (a bullet carried by a body going
            // by a wall's edge was taken through the wall).
            let left = slow * (1.0 - c.t);
            let back = -left.dot(fast.normalize_or_zero());
            let across = (left + fast.normalize_or_zero() * back).length();
            let thinnest = self.thinnest_half_extent(c.body as usize);
            let (fast, slow_len) = (fast.length(), slow.length());
            if other != 0
                && 4.0 * slow_len < fast
                && (0.0..=c.t * fast).contains(&back)
                && across <= CCD_MOTION_THRESHOLD * thinnest
            {
                c.carry = Carry::With(other as u32);
                carriers.push((
                    other as u32,
                    self.bodies.handle_of(self.solver_handles[c.body as usize]),
                ));
            }
        }
        if carriers.is_empty() {
            return clamps;
        }
        // The carriers' own stops at the bodies they carry.
        let mut out = Vec::with_capacity(clamps.len());
        for c in clamps {
            if !carriers.contains(&(c.body, c.hit)) {
                out.push(c);
            } else if let Some(f) = c.fallback {
                out.push(clamp_of(c.body, f, None, &self.bodies, motion_of));
            }
        }
        out
    }

    /// The stopped bodies that a kinematic body moving on would reach where they stopped are
    /// carried by it from their stop on (as [`clamp_of`] carries a body that hit one): two
    /// bullets of a volley a wall moving at 20 m/s was pushing stopped each other an eighth of
    /// the way through the step, and the wall, which neither had met on its whole path, went
    /// through both where they stopped. From the stop on, so they stay ahead of the wall.
    fn carried_by_kinematic_bodies(
        &self,
        linear_slop: f32,
        others_move: f32,
        driven: f32,
        motion_of: &dyn Fn(BodyHandle) -> Option<BodyMotion>,
    ) -> Vec<(usize, Carry)> {
        let mut out = Vec::new();
        let kinematic_motion = |h: BodyHandle| {
            self.bodies
                .get(h)
                .filter(|b| b.body_type == BodyType::Kinematic)
                .and_then(|_| motion_of(h))
        };
        for i in 0..self.ccd_clamps.len() {
            let c = self.ccd_clamps[i];
            if c.carry.moves() {
                continue;
            }
            let k = c.body as usize;
            let Some(b) = self.bodies.arena.get_by_index(self.solver_handles[k]) else {
                continue;
            };
            let at_t = BodyMotion::between(&b.pose, &self.end_poses[k], b.mass.local_com)
                .pose_at(c.t, Vec3::ZERO);
            let sweep = sweep_body(
                &self.colliders,
                &self.bodies,
                &self.broadphase,
                self.bodies.handle_of(self.solver_handles[k]),
                &BodyMotion::fixed(&at_t, b.mass.local_com),
                linear_slop,
                others_move,
                driven,
                &|h| kinematic_motion(h),
            );
            if let Some(hit) = sweep.first {
                out.push((
                    i,
                    clamp_of(c.body, hit, None, &self.bodies, motion_of).carry,
                ));
            }
        }
        out
    }

    /// The smallest half extent of the colliders of the body of solver index `k`, metres.
    fn thinnest_half_extent(&self, k: usize) -> f32 {
        self.bodies
            .arena
            .get_by_index(self.solver_handles[k])
            .map_or(0.0, |b| {
                b.colliders
                    .iter()
                    .filter_map(|&ch| self.colliders.get(ch))
                    .map(|c| c.shape.aabb(&Pose::IDENTITY).half_extents().min_element())
                    .fold(f32::INFINITY, f32::min)
            })
    }

    /// After a CCD stop from a start in contact, the centres of the two bodies that still close
    /// along the hit's normal meet as in an impact: an impulse through both centres turns the
    /// closing velocity into a parting one `e` times as fast (`e`, the pair's restitution,
    /// counts only above `restitution_threshold`, as in the solver; a static, kinematic or
    /// sleeping body hit takes none of the impulse).
    ///
    /// The contact the solver had was not enough to part them: light, thin bodies touching
    /// edge to edge are held apart by the spin the contact gives them more than by their
    /// centres' velocities, and the stop takes that spin back (see the write-back). Left
    /// closing, they stay stopped at each step's start, velocities and all: of 23,040 meetings
    /// of small spinning bodies at 50–1,000 m/s (`tests/ccd_meetings.rs`, eight times its
    /// starts), 1,961 still closed at over 1 m/s along their line of centres, within 60 cm of
    /// each other, after 0.1 s; with the impulse 129, bodies sliding along a plate's face.
    fn stop_closing(&mut self, clamp: &CcdClamp, threshold: f32) {
        let n = glam::Vec3A::from(clamp.normal);
        if n == glam::Vec3A::ZERO {
            return;
        }
        let a = clamp.body as usize;
        let (b, v_b) = match self.bodies.get(clamp.hit) {
            Some(o) => {
                let k = o.solver_index as usize;
                if k != 0 && k < self.solver_states.len() {
                    (k, self.solver_states[k].v)
                } else {
                    (0, o.linvel.into())
                }
            }
            None => return,
        };
        let closing = (self.solver_states[a].v - v_b).dot(n);
        if closing <= 0.0 {
            return;
        }
        let (inv_a, inv_b) = (
            self.solver_states[a].inv_mass,
            if b != 0 {
                self.solver_states[b].inv_mass
            } else {
                glam::Vec3A::ZERO
            },
        );
        let k = (inv_a + inv_b).dot(n * n);
        if k <= 0.0 {
            return;
        }
        let e = if closing > threshold {
            clamp.restitution
        } else {
            0.0
        };
        let j = (1.0 + e) * closing / k;
        self.solver_states[a].v -= inv_a * n * j;
        if b != 0 {
            self.solver_states[b].v += inv_b * n * j;
        }
    }
}

/// How body `h` moves over the step: from its pose to its end pose where it is in the solver,
/// else not at all.
fn motion_over_step(bodies: &BodySet, end_poses: &[Pose], h: BodyHandle) -> Option<BodyMotion> {
    let b = bodies.get(h)?;
    let k = b.solver_index as usize;
    Some(if k != 0 && k < end_poses.len() {
        BodyMotion::between(&b.pose, &end_poses[k], b.mass.local_com)
    } else {
        BodyMotion::fixed(&b.pose, b.mass.local_com)
    })
}

/// The stop of the body of solver index `body` at `hit`: a body hit that does not stop
/// itself (static, kinematic, or dynamic without CCD) keeps moving, and this one is carried
/// along for the rest of the step, so that a wall moving into a bullet does not pass it
/// after the impact.
fn clamp_of(
    body: u32,
    hit: SweepHit,
    fallback: Option<SweepHit>,
    bodies: &BodySet,
    motion_of: &dyn Fn(BodyHandle) -> Option<BodyMotion>,
) -> CcdClamp {
    let carry = match bodies.get(hit.body) {
        Some(o) if o.swept() => Carry::Stopped,
        Some(o) if o.body_type == BodyType::Kinematic => match motion_of(hit.body) {
            Some(m) if m.q0 != m.q1 => Carry::Rigid(m),
            m => Carry::By(m.map_or(Vec3::ZERO, |m| m.displacement())),
        },
        _ => Carry::By(motion_of(hit.body).map_or(Vec3::ZERO, |m| m.displacement())),
    };
    CcdClamp {
        body,
        t: hit.t,
        carry,
        from_contact: hit.from_contact,
        hit: hit.body,
        normal: hit.normal,
        restitution: hit.restitution,
        fallback,
    }
}

/// The broadphase bounds of collider `c` (its `aabb` current) of body `b`: swept ahead by the
/// body's expected motion over the next step, its velocity times the step (up to
/// `max_speculative_distance`, without a cap for a body with CCD) and, for a kinematic body,
/// its turn times the collider's reach where that passes `speculative_distance` (a spinning
/// paddle over what is beside it; see `narrow_phase::speculative_margin`); and that
/// displacement, for the broadphase's look-ahead.
pub(crate) fn swept_bounds(c: &Collider, b: &RigidBody, s: &PhysicsSettings) -> (Aabb, Vec3) {
    let cap = if s.ccd_enabled && b.swept() {
        f32::MAX
    } else {
        s.max_speculative_distance
    };
    let v = b.linvel;
    let disp = v.normalize_or_zero() * (v.length() * s.dt).min(cap);
    let turned = if b.body_type == BodyType::Kinematic && b.angvel != Vec3::ZERO {
        b.angvel.length() * s.dt * c.turning_reach(b.mass.local_com)
    } else {
        0.0
    };
    let grow = if turned > s.speculative_distance {
        turned.min(cap)
    } else {
        0.0
    };
    let mut swept = c.aabb.expanded(s.speculative_distance + grow);
    swept.min += disp.min(Vec3::ZERO);
    swept.max += disp.max(Vec3::ZERO);
    (swept, disp)
}
