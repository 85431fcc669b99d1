//! [`NarrowPhase`]: persistent contact pairs, updated each step with warm-start matching.

use std::collections::HashMap;

use glam::Vec3;

use super::collide::{collide, CollideScratch};
use super::contact_manifold::ContactManifold;
use super::contact_pair::ContactPair;
use super::contact_point::ContactPoint;
use super::narrow_stats::NarrowStats;
use super::pair_hasher::BuildPairHasher;
use super::raw_manifold::RawManifold;
use crate::body_handle::BodyHandle;
use crate::body_set::BodySet;
use crate::body_type::BodyType;
use crate::broadphase::BroadPhase;
use crate::collider_handle::ColliderHandle;
use crate::collider_set::ColliderSet;
use crate::contact_event::{ContactEvent, ContactEventKind};
use crate::material::Material;
use crate::physics_settings::PhysicsSettings;
use crate::pose::Pose;
use crate::rigid_body::RigidBody;

/// A new point inherits the impulses of an old point closer than this (body-A frame),
/// metres, when feature ids do not match. Bounded `[0.001, 0.1]`.
pub const WARM_START_MATCH_DISTANCE: f32 = 0.02;

/// Same-id points inherit impulses only if they moved less than this, metres.
pub const WARM_START_ID_MAX_DISTANCE: f32 = 0.25;

/// A pair's manifolds are reused (points refreshed from their body-local positions instead of
/// regenerated) while B moved less than this relative to A since generation, as a fraction of
/// the smaller collider's size (its smallest bounding-box half extent).
pub const MANIFOLD_REUSE_SIZE_FRACTION: f32 = 0.02;

/// … and never beyond this distance, metres.
pub const MANIFOLD_REUSE_MAX_DISTANCE: f32 = 0.001;

/// … and while B turned less than this relative to A, radians.
pub const MANIFOLD_REUSE_MAX_ANGLE: f32 = 0.005;

/// All contact pairs of the world.
#[derive(Debug, Default)]
pub struct NarrowPhase {
    pub(crate) pairs: Vec<ContactPair>,
    index: HashMap<u64, u32, BuildPairHasher>,
    raw: Vec<RawManifold>,
    scratch: CollideScratch,
    old: Vec<ContactPoint>,
}

fn key(a: ColliderHandle, b: ColliderHandle) -> u64 {
    index_key(a.index(), b.index())
}

fn index_key(a: u32, b: u32) -> u64 {
    let (x, y) = (a.min(b), a.max(b));
    u64::from(x) << 32 | u64::from(y)
}

/// True when the body takes part in this step's simulation.
#[inline]
pub(crate) fn is_active(b: &RigidBody) -> bool {
    b.body_type != BodyType::Static && !b.sleeping && !b.quarantined
}

impl NarrowPhase {
    /// The contact pairs.
    #[must_use]
    pub fn pairs(&self) -> &[ContactPair] {
        &self.pairs
    }

    /// The pair of two colliders, if their bounds overlap.
    #[must_use]
    pub fn pair(&self, a: ColliderHandle, b: ColliderHandle) -> Option<&ContactPair> {
        let i = *self.index.get(&key(a, b))?;
        let p = &self.pairs[i as usize];
        (p.collider_a == a && p.collider_b == b || p.collider_a == b && p.collider_b == a)
            .then_some(p)
    }

    /// True when the colliders at arena indices `a` and `b` already have a pair (removing a
    /// collider removes its pairs, so an index names a live collider here).
    #[inline]
    pub(crate) fn has_pair_of_indices(&self, a: u32, b: u32) -> bool {
        self.index.contains_key(&index_key(a, b))
    }

    /// Adds a pair unless it exists. Returns true when added.
    pub(crate) fn add_pair(
        &mut self,
        ca: ColliderHandle,
        cb: ColliderHandle,
        ba: BodyHandle,
        bb: BodyHandle,
        ma: &Material,
        mb: &Material,
    ) -> bool {
        let k = key(ca, cb);
        if self.index.contains_key(&k) {
            return false;
        }
        let (e, fs, fd) = Material::combine(ma, mb);
        self.index.insert(k, self.pairs.len() as u32);
        self.pairs.push(ContactPair {
            collider_a: ca,
            collider_b: cb,
            body_a: ba,
            body_b: bb,
            manifolds: Vec::new(),
            touching: false,
            restitution: e,
            static_friction: fs,
            dynamic_friction: fd,
            min_separation: f32::MAX,
            updated: false,
            solved_pushing: None,
            generated_at: None,
        });
        true
    }

    fn remove_at(&mut self, i: usize) -> ContactPair {
        let p = self.pairs.swap_remove(i);
        self.index.remove(&key(p.collider_a, p.collider_b));
        if i < self.pairs.len() {
            let moved = &self.pairs[i];
            self.index
                .insert(key(moved.collider_a, moved.collider_b), i as u32);
        }
        p
    }

    /// Removes every pair of a collider, reporting `Ended` for touching ones.
    pub(crate) fn remove_collider(
        &mut self,
        c: ColliderHandle,
        bodies: &BodySet,
        events: &mut Vec<ContactEvent>,
    ) {
        let mut i = 0;
        while i < self.pairs.len() {
            if self.pairs[i].collider_a == c || self.pairs[i].collider_b == c {
                let p = self.remove_at(i);
                if p.touching {
                    events.push(make_event(ContactEventKind::Ended, &p, bodies, 0.0));
                }
            } else {
                i += 1;
            }
        }
    }

    /// Clears the manifolds of every pair of body `h` (quarantined), reporting `Ended` for
    /// touching ones.
    pub(crate) fn end_contacts_of(
        &mut self,
        h: BodyHandle,
        bodies: &BodySet,
        events: &mut Vec<ContactEvent>,
    ) {
        for p in &mut self.pairs {
            if p.body_a != h && p.body_b != h {
                continue;
            }
            if p.touching {
                p.touching = false;
                events.push(make_event(ContactEventKind::Ended, p, bodies, 0.0));
            }
            p.manifolds.clear();
        }
    }

    /// Regenerates manifolds of active pairs, drops pairs whose fat boxes separated, and
    /// records touch transitions. Bodies that a moving body touched while asleep are pushed
    /// to `wake`.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn update(
        &mut self,
        bodies: &BodySet,
        colliders: &ColliderSet,
        bp: &BroadPhase,
        settings: &PhysicsSettings,
        stats: &mut NarrowStats,
        events: &mut Vec<ContactEvent>,
        wake: &mut Vec<BodyHandle>,
        active: &[bool],
    ) {
        let reuse_cos_half = (0.5 * MANIFOLD_REUSE_MAX_ANGLE).cos();
        let mut i = 0;
        while i < self.pairs.len() {
            let (hca, hcb, hba, hbb) = {
                let p = &self.pairs[i];
                (p.collider_a, p.collider_b, p.body_a, p.body_b)
            };
            // Pairs of two sleeping, static or quarantined bodies cost one flag lookup each.
            let flag = |h: BodyHandle| active.get(h.index() as usize).copied().unwrap_or(false);
            if !flag(hba) && !flag(hbb) {
                i += 1;
                continue;
            }
            let (Some(ca), Some(cb), Some(ba), Some(bb)) = (
                colliders.get(hca),
                colliders.get(hcb),
                bodies.get(hba),
                bodies.get(hbb),
            ) else {
                let p = self.remove_at(i);
                if p.touching {
                    events.push(make_event(ContactEventKind::Ended, &p, bodies, 0.0));
                }
                continue;
            };
            if ba.quarantined || bb.quarantined {
                let p = &mut self.pairs[i];
                if p.touching {
                    p.touching = false;
                    events.push(make_event(ContactEventKind::Ended, p, bodies, 0.0));
                }
                p.manifolds.clear();
                i += 1;
                continue;
            }
            let (act_a, act_b) = (is_active(ba), is_active(bb));
            if !act_a && !act_b {
                i += 1;
                continue;
            }
            if !bp.fat_aabb(ca.proxy).intersects(&bp.fat_aabb(cb.proxy)) {
                let p = self.remove_at(i);
                if p.touching {
                    events.push(make_event(ContactEventKind::Ended, &p, bodies, 0.0));
                }
                continue;
            }
            // Speculative margin grows with the closing speed (uncapped under CCD).
            let sweep = (bb.linvel - ba.linvel).length() * settings.dt;
            let ccd = settings.ccd_enabled && (ba.ccd_enabled || bb.ccd_enabled);
            let margin = settings.speculative_distance
                + if ccd {
                    sweep
                } else {
                    sweep.min(settings.max_speculative_distance)
                };
            let rot_a = ba.pose.rotation;
            let rot_b = bb.pose.rotation;
            let d_ab = bb.pose.translation - ba.pose.translation;
            let pa = Pose::new(
                rot_a * ca.local_pose.translation,
                rot_a * ca.local_pose.rotation,
            );
            let pb = Pose::new(
                d_ab + rot_b * cb.local_pose.translation,
                rot_b * cb.local_pose.rotation,
            );
            let inv_a = rot_a.inverse();
            let rel = (inv_a * d_ab, inv_a * rot_b);
            let pair = &mut self.pairs[i];
            if let Some((t0, q0)) = pair.generated_at {
                let size = ca
                    .aabb
                    .half_extents()
                    .min_element()
                    .min(cb.aabb.half_extents().min_element());
                let tol = (MANIFOLD_REUSE_SIZE_FRACTION * size).min(MANIFOLD_REUSE_MAX_DISTANCE);
                let reach = ca
                    .aabb
                    .half_extents()
                    .length()
                    .max(cb.aabb.half_extents().length());
                let motion = ((bb.linvel - ba.linvel).length()
                    + (bb.angvel - ba.angvel).length() * reach)
                    * settings.dt;
                // |cos(θ/2)| of the relative turn since generation, against the bound.
                let cos_half = q0.dot(rel.1).abs();
                if rel.0.distance(t0) + motion < tol && cos_half > reuse_cos_half {
                    refresh_manifolds(pair, ba, bb, d_ab, margin);
                    stats.reused_pairs += 1;
                    i += 1;
                    continue;
                }
            }
            pair.generated_at = Some(rel);
            self.raw.clear();
            collide(
                &ca.shape,
                &pa,
                &cb.shape,
                &pb,
                margin,
                &mut self.raw,
                stats,
                &mut self.scratch,
            );
            let com_a = rot_a * ba.mass.local_com;
            let com_b = d_ab + rot_b * bb.mass.local_com;
            let inv_b = rot_b.inverse();
            let pair = &mut self.pairs[i];
            self.old.clear();
            for m in &pair.manifolds {
                self.old.extend_from_slice(&m.points);
            }
            pair.manifolds
                .resize_with(self.raw.len(), ContactManifold::default);
            let mut min_sep = f32::MAX;
            for (m, rm) in pair.manifolds.iter_mut().zip(&self.raw) {
                m.normal = rm.normal;
                m.local_normal = inv_a * rm.normal;
                m.tangent1 = rm.normal.any_orthonormal_vector();
                m.points.clear();
                for rp in &rm.points {
                    let local_a = inv_a * rp.point;
                    let local_b = inv_b * (rp.point - d_ab);
                    let mut cp = ContactPoint {
                        local_a,
                        local_b,
                        separation: rp.separation,
                        generated_separation: rp.separation,
                        normal_impulse: 0.0,
                        tangent_impulse: Vec3::ZERO,
                        twist_impulse: 0.0,
                        max_normal_impulse: 0.0,
                        id: rp.id,
                        anchor_a: rp.point - com_a,
                        anchor_b: rp.point - com_b,
                    };
                    min_sep = min_sep.min(rp.separation);
                    // Warm start: same feature id nearby, else nearest point.
                    let mut best: Option<(f32, usize)> = None;
                    for (k, o) in self.old.iter().enumerate() {
                        let d2 = o.local_a.distance_squared(local_a);
                        let ok = if o.id == cp.id && cp.id != u32::MAX {
                            d2 < WARM_START_ID_MAX_DISTANCE * WARM_START_ID_MAX_DISTANCE
                        } else {
                            d2 < WARM_START_MATCH_DISTANCE * WARM_START_MATCH_DISTANCE
                        };
                        let score = if o.id == cp.id { d2 * 0.01 } else { d2 };
                        if ok && best.is_none_or(|b| score < b.0) {
                            best = Some((score, k));
                        }
                    }
                    if let Some((_, k)) = best {
                        cp.normal_impulse = self.old[k].normal_impulse;
                        cp.tangent_impulse = self.old[k].tangent_impulse;
                        cp.twist_impulse = self.old[k].twist_impulse;
                    }
                    m.points.push(cp);
                }
            }
            pair.min_separation = min_sep;
            pair.updated = true;
            // Speculative points count: the solver would otherwise treat the sleeper as static.
            if !pair.manifolds.is_empty() {
                if act_a && !act_b && bb.body_type == BodyType::Dynamic && bb.sleeping {
                    wake.push(hbb);
                }
                if act_b && !act_a && ba.body_type == BodyType::Dynamic && ba.sleeping {
                    wake.push(hba);
                }
            }
            i += 1;
        }
    }
}

/// Moves a pair's manifolds with its bodies: normals, separations and solver anchors from
/// the points' body-local positions (the bodies barely moved since generation, so the
/// touching features are the same); impulses stay for warm starting.
fn refresh_manifolds(
    pair: &mut ContactPair,
    ba: &RigidBody,
    bb: &RigidBody,
    d_ab: Vec3,
    margin: f32,
) {
    let (rot_a, rot_b) = (ba.pose.rotation, bb.pose.rotation);
    let com_a = rot_a * ba.mass.local_com;
    let com_b = d_ab + rot_b * bb.mass.local_com;
    let mut min_sep = f32::MAX;
    for m in &mut pair.manifolds {
        let n = rot_a * m.local_normal;
        m.normal = n;
        m.tangent1 = n.any_orthonormal_vector();
        for p in &mut m.points {
            let pa = rot_a * p.local_a;
            let pb = d_ab + rot_b * p.local_b;
            p.separation = p.generated_separation + (pb - pa).dot(n);
            let mid = (pa + pb) * 0.5;
            p.anchor_a = mid - com_a;
            p.anchor_b = mid - com_b;
            min_sep = min_sep.min(p.separation);
        }
        // Points that drifted beyond the speculative margin are dropped, as generation would.
        m.points.retain(|p| p.separation <= margin);
    }
    pair.manifolds.retain(|m| !m.points.is_empty());
    pair.min_separation = min_sep;
    pair.updated = true;
}

/// Builds an event from a pair's current manifolds.
pub(crate) fn make_event(
    kind: ContactEventKind,
    p: &ContactPair,
    bodies: &BodySet,
    impulse: f32,
) -> ContactEvent {
    let mut points = Vec::new();
    let mut normal = Vec3::ZERO;
    if let Some(ba) = bodies.get(p.body_a) {
        for m in &p.manifolds {
            normal = m.normal;
            points.extend(m.points.iter().map(|c| ba.pose.transform_point(c.local_a)));
        }
    }
    ContactEvent {
        kind,
        collider_a: p.collider_a,
        collider_b: p.collider_b,
        body_a: p.body_a,
        body_b: p.body_b,
        normal,
        points,
        impulse,
    }
}
