//! [`ContactBatch`]: four manifolds solved at once, one per SIMD lane (warm start, the
//! normal and friction rows of [`ContactConstraint`], restitution).
//!
//! The rows are those of the scalar formulation documented on [`ContactConstraint`],
//! [`NormalBlock`](super::contact_constraint::NormalBlock) and
//! [`FrictionPart`](super::contact_constraint::FrictionPart); here every branch is a lane
//! select. The lanes of one batch never share a body they write ([`super::batching`]), so
//! solving them together gives each manifold exactly what solving it alone would. An empty
//! lane has zero masses and changes nothing.
//!
//! Two layouts ([`ManifoldRows`]): [`PointBatch`] for one-point manifolds (spheres, capsule
//! ends), which carry only the point's rows and friction, and [`FaceBatch`] for manifolds of
//! two to four points, which add the shared normal step and twist friction
//! ([`FaceContact`]). The solver streams every batch once per pass, so a one-point batch
//! does not carry what only faces use (a pile of 8,000 spheres is 30,000 manifolds).

use glam::Vec3A;

use super::body_state::BodyState;
use super::contact_constraint::{ConstraintPoint, ContactConstraint};
use super::face_contact::FaceContact;
use super::lanes::{
    gather_deltas, gather_velocities, scatter_velocities, Velocities, F, LANES, V3,
};

/// Four one-point manifolds.
pub(crate) type PointBatch = ContactBatch<1, PointContact>;
/// Four manifolds of two to four points (unused points inactive).
pub(crate) type FaceBatch = ContactBatch<4, FaceContact>;

/// Lanes of one contact point slot.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct PointLanes {
    pub base_separation: F,
    pub normal_impulse: F,
    pub max_normal_impulse: F,
    pub normal_mass: F,
    pub relative_velocity: F,
    pub rn_a: V3,
    pub rn_b: V3,
    pub irn_a: V3,
    pub irn_b: V3,
}

/// Each point's normal row in one pass: where it is speculative (separated: rigid, may not
/// close the gap by more than it is) and its velocity bias.
pub(crate) struct NormalRows<const N: usize> {
    pub speculative: [F; N],
    pub bias: [F; N],
    /// Soft position correction on (solve phase) or off (relax phase).
    pub use_bias: bool,
}

/// What a manifold layout adds to the rows every manifold has.
pub(crate) trait ManifoldRows: Copy + std::fmt::Debug {
    /// Lane values from up to four constraints (and their points).
    fn pack(slots: &[Option<&ContactConstraint>; LANES], points: &[ConstraintPoint]) -> Self;
    /// Adds its warm-start impulses' angular parts (`wa` is subtracted from body A).
    fn warm_start(&self, wa: &mut V3, wb: &mut V3);
    /// Before the per-point sweep: a step shared by all points.
    fn solve_shared<const N: usize>(
        &self,
        points: &mut [PointLanes; N],
        rows: &NormalRows<N>,
        vn: &mut [F; N],
        applied: &mut [F; N],
    );
    /// After point `j` took `imp`: how the later points' normal velocities change.
    fn couple<const N: usize>(&self, j: usize, imp: F, vn: &mut [F; N]);
    /// Friction about the normal, after the friction in the plane.
    fn solve_twist<const N: usize>(
        &mut self,
        points: &[PointLanes; N],
        friction: F,
        normal: V3,
        a: &mut Velocities,
        b: &mut Velocities,
    );
    /// Accumulated twist impulse per lane.
    fn twist_impulse(&self) -> F;
}

/// A one-point manifold: no shared step, no coupling, no lever for twist.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct PointContact;

impl ManifoldRows for PointContact {
    fn pack(_: &[Option<&ContactConstraint>; LANES], _: &[ConstraintPoint]) -> Self {
        Self
    }
    #[inline(always)]
    fn warm_start(&self, _: &mut V3, _: &mut V3) {}
    #[inline(always)]
    fn solve_shared<const N: usize>(
        &self,
        _: &mut [PointLanes; N],
        _: &NormalRows<N>,
        _: &mut [F; N],
        _: &mut [F; N],
    ) {
    }
    #[inline(always)]
    fn couple<const N: usize>(&self, _: usize, _: F, _: &mut [F; N]) {}
    #[inline(always)]
    fn solve_twist<const N: usize>(
        &mut self,
        _: &[PointLanes; N],
        _: F,
        _: V3,
        _: &mut Velocities,
        _: &mut Velocities,
    ) {
    }
    fn twist_impulse(&self) -> F {
        F::ZERO
    }
}

/// The impulses one manifold ends the step with.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct LaneResult {
    /// Accumulated normal impulse per point (points past the manifold's count are 0), N·s.
    pub normal_impulse: [f32; 4],
    /// Largest single normal impulse of the step per point.
    pub max_normal_impulse: [f32; 4],
    /// Friction impulse along the constraint's two tangents.
    pub tangent_impulse: [f32; 2],
    /// Twist friction impulse about the normal.
    pub twist_impulse: f32,
}

/// Four manifolds of at most `N` points as lanes, with the rows of layout `M`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ContactBatch<const N: usize, M: ManifoldRows> {
    /// Index into the step's constraints per lane; `u32::MAX` for an empty lane.
    pub constraint: [u32; LANES],
    body_a: [u32; LANES],
    body_b: [u32; LANES],
    /// Bit `l`: lane `l` writes body A (resp. B) back.
    writes_a: u8,
    writes_b: u8,
    inv_mass_a: V3,
    inv_mass_b: V3,
    normal: V3,
    tangent: [V3; 2],
    bias_rate: F,
    mass_scale: F,
    impulse_scale: F,
    restitution: F,
    points: [PointLanes; N],
    friction: F,
    tangent_impulse: [F; 2],
    tangent_mass: [F; 3],
    slide_mass: F,
    rt_a: [V3; 2],
    rt_b: [V3; 2],
    irt_a: [V3; 2],
    irt_b: [V3; 2],
    manifold: M,
}

/// Lane `l` gets `f(slots[l])`, 0 for an empty slot.
#[inline(always)]
pub(crate) fn lanes<T: Copy>(slots: &[Option<T>; LANES], f: impl Fn(T) -> f32) -> F {
    F::new(std::array::from_fn(|l| slots[l].map_or(0.0, &f)))
}

/// Lane `l` gets `f(slots[l])`, zero for an empty slot.
#[inline(always)]
pub(crate) fn lanes3<T: Copy>(slots: &[Option<T>; LANES], f: impl Fn(T) -> Vec3A) -> V3 {
    V3::from_lanes(std::array::from_fn(|l| slots[l].map_or(Vec3A::ZERO, &f)))
}

/// Point `k` of each lane's constraint, where it has one.
#[inline(always)]
pub(crate) fn point_slots<'a>(
    slots: &[Option<&ContactConstraint>; LANES],
    points: &'a [ConstraintPoint],
    k: usize,
) -> [Option<&'a ConstraintPoint>; LANES] {
    slots.map(|c| {
        c.filter(|c| k < usize::from(c.count))
            .map(|c| &points[c.first as usize + k])
    })
}

/// `max(floor, x)` per lane where only `x` may be NaN (then `floor`): SSE `maxps` returns its
/// second operand when either is NaN.
#[inline(always)]
pub(crate) fn fmax(floor: F, x: F) -> F {
    x.fast_max(floor)
}

/// What the rows of one pass share.
#[derive(Clone, Copy)]
pub(crate) struct Pass {
    pub inv_h: f32,
    /// Soft position correction on (solve phase) or off (relax phase: speculative only).
    pub use_bias: bool,
    pub max_push: f32,
}

impl<const N: usize, M: ManifoldRows> ContactBatch<N, M> {
    /// Packs up to four prepared constraints (`lanes_of`: indices into `constraints`, whose
    /// points are in `points`).
    pub(crate) fn pack(
        lanes_of: &[u32],
        constraints: &[ContactConstraint],
        points: &[ConstraintPoint],
        states: &[BodyState],
    ) -> Self {
        let slots: [Option<&ContactConstraint>; LANES] =
            std::array::from_fn(|l| lanes_of.get(l).map(|&i| &constraints[i as usize]));
        let constraint = std::array::from_fn(|l| lanes_of.get(l).copied().unwrap_or(u32::MAX));
        let body_a = slots.map(|c| c.map_or(0, |c| c.body_a));
        let body_b = slots.map(|c| c.map_or(0, |c| c.body_b));
        let mut writes_a = 0u8;
        let mut writes_b = 0u8;
        for (l, c) in slots.iter().enumerate() {
            if let Some(c) = c {
                writes_a |= (c.writes & 1) << l;
                writes_b |= ((c.writes >> 1) & 1) << l;
            }
        }
        let one_point = |k: usize| {
            let s = &point_slots(&slots, points, k);
            PointLanes {
                base_separation: lanes(s, |p| p.base_separation),
                normal_impulse: lanes(s, |p| p.normal_impulse),
                max_normal_impulse: lanes(s, |p| p.max_normal_impulse),
                normal_mass: lanes(s, |p| p.normal_mass),
                relative_velocity: lanes(s, |p| p.relative_velocity),
                rn_a: lanes3(s, |p| p.rn_a),
                rn_b: lanes3(s, |p| p.rn_b),
                irn_a: lanes3(s, |p| p.irn_a),
                irn_b: lanes3(s, |p| p.irn_b),
            }
        };
        Self {
            constraint,
            body_a,
            body_b,
            writes_a,
            writes_b,
            inv_mass_a: V3::from_lanes(body_a.map(|i| states[i as usize].inv_mass)),
            inv_mass_b: V3::from_lanes(body_b.map(|i| states[i as usize].inv_mass)),
            normal: lanes3(&slots, |c| c.normal),
            tangent: [
                lanes3(&slots, |c| c.tangent[0]),
                lanes3(&slots, |c| c.tangent[1]),
            ],
            bias_rate: lanes(&slots, |c| c.softness.bias_rate),
            mass_scale: lanes(&slots, |c| c.softness.mass_scale),
            impulse_scale: lanes(&slots, |c| c.softness.impulse_scale),
            restitution: lanes(&slots, |c| c.restitution),
            points: std::array::from_fn(one_point),
            friction: lanes(&slots, |c| c.friction.friction),
            tangent_impulse: [
                lanes(&slots, |c| c.friction.tangent_impulse[0]),
                lanes(&slots, |c| c.friction.tangent_impulse[1]),
            ],
            tangent_mass: std::array::from_fn(|k| lanes(&slots, |c| c.friction.tangent_mass[k])),
            slide_mass: lanes(&slots, |c| c.friction.slide_mass),
            rt_a: std::array::from_fn(|k| lanes3(&slots, |c| c.friction.rt_a[k])),
            rt_b: std::array::from_fn(|k| lanes3(&slots, |c| c.friction.rt_b[k])),
            irt_a: std::array::from_fn(|k| lanes3(&slots, |c| c.friction.irt_a[k])),
            irt_b: std::array::from_fn(|k| lanes3(&slots, |c| c.friction.irt_b[k])),
            manifold: M::pack(&slots, points),
        }
    }

    /// Calls `f(constraint index, impulses)` for each lane in use.
    pub(crate) fn for_each_result(&self, mut f: impl FnMut(u32, &LaneResult)) {
        let ti = self.tangent_impulse.map(F::to_array);
        let twist = self.manifold.twist_impulse().to_array();
        let ni = self.points.map(|p| p.normal_impulse.to_array());
        let max_ni = self.points.map(|p| p.max_normal_impulse.to_array());
        for (l, &ci) in self.constraint.iter().enumerate() {
            if ci == u32::MAX {
                continue;
            }
            let mut r = LaneResult {
                tangent_impulse: [ti[0][l], ti[1][l]],
                twist_impulse: twist[l],
                ..LaneResult::default()
            };
            for k in 0..N {
                r.normal_impulse[k] = ni[k][l];
                r.max_normal_impulse[k] = max_ni[k][l];
            }
            f(ci, &r);
        }
    }

    /// Re-applies last step's impulses.
    pub(crate) fn warm_start(&self, states: &mut [BodyState]) {
        let mut a = gather_velocities(states, &self.body_a);
        let mut b = gather_velocities(states, &self.body_b);
        let [t1, t2] = self.tangent_impulse;
        let mut p = self.tangent[0].scale(t1) + self.tangent[1].scale(t2);
        let mut wa = self.irt_a[0].scale(t1) + self.irt_a[1].scale(t2);
        let mut wb = self.irt_b[0].scale(t1) + self.irt_b[1].scale(t2);
        self.manifold.warm_start(&mut wa, &mut wb);
        for cp in &self.points {
            p += self.normal.scale(cp.normal_impulse);
            wa += cp.irn_a.scale(cp.normal_impulse);
            wb += cp.irn_b.scale(cp.normal_impulse);
        }
        a.v -= self.inv_mass_a * p;
        a.w -= wa;
        b.v += self.inv_mass_b * p;
        b.w += wb;
        scatter_velocities(states, &self.body_a, self.writes_a, a);
        scatter_velocities(states, &self.body_b, self.writes_b, b);
    }

    /// One Gauss–Seidel pass: the normal rows (shared step, then point by point), then
    /// friction at the manifold centre bounded by the new normal impulses.
    pub(crate) fn solve(&mut self, states: &mut [BodyState], pass: Pass) {
        let mut a = gather_velocities(states, &self.body_a);
        let mut b = gather_velocities(states, &self.body_b);
        let (dp_a, dtheta_a) = gather_deltas(states, &self.body_a);
        let (dp_b, dtheta_b) = gather_deltas(states, &self.body_b);
        let n = self.normal;
        let zero = F::ZERO;
        let one = F::ONE;
        // Linearised current separation: base + n·(Δp_b − Δp_a) + Δθ_b·(r_b×n) − Δθ_a·(r_a×n);
        // normal velocities all from the start-of-pass state (the coupling tracks them
        // through the sweep).
        let dpn = (dp_b - dp_a).dot(n);
        let dvn = (b.v - a.v).dot(n);
        let inv_h = F::splat(pass.inv_h);
        let neg_max_push = F::splat(-pass.max_push);
        let mut vn = [zero; N];
        let mut rows = NormalRows {
            speculative: [zero; N],
            bias: [zero; N],
            use_bias: pass.use_bias,
        };
        let mut mass_scale = [one; N];
        let mut impulse_scale = [zero; N];
        for k in 0..N {
            let cp = &self.points[k];
            let sep = cp.base_separation + dpn + dtheta_b.dot(cp.rn_b) - dtheta_a.dot(cp.rn_a);
            vn[k] = dvn + b.w.dot(cp.rn_b) - a.w.dot(cp.rn_a);
            let speculative = sep.simd_gt(zero);
            rows.speculative[k] = speculative;
            if pass.use_bias {
                // No dead zone (as in Box2D v3 and rapier): a resting contact settles at the
                // soft spring's static deflection.
                let soft = fmax(neg_max_push, self.bias_rate * sep);
                rows.bias[k] = speculative.select(sep * inv_h, soft);
                mass_scale[k] = speculative.select(one, self.mass_scale);
                impulse_scale[k] = speculative.select(zero, self.impulse_scale);
            } else {
                rows.bias[k] = speculative.select(sep * inv_h, zero);
            }
        }
        let mut applied = [zero; N];
        self.manifold
            .solve_shared(&mut self.points, &rows, &mut vn, &mut applied);
        for j in 0..N {
            let cp = &mut self.points[j];
            let imp = -cp.normal_mass * mass_scale[j] * (vn[j] + rows.bias[j])
                - impulse_scale[j] * cp.normal_impulse;
            let new = fmax(zero, cp.normal_impulse + imp);
            let imp = new - cp.normal_impulse;
            cp.normal_impulse = new;
            cp.max_normal_impulse = fmax(cp.max_normal_impulse, imp);
            applied[j] += imp;
            self.manifold.couple(j, imp, &mut vn);
        }
        let mut total = zero;
        let (mut da, mut db) = (V3::ZERO, V3::ZERO);
        for (cp, &imp) in self.points.iter().zip(&applied) {
            total += imp;
            da += cp.irn_a.scale(imp);
            db += cp.irn_b.scale(imp);
        }
        let p = n.scale(total);
        a.v -= self.inv_mass_a * p;
        a.w -= da;
        b.v += self.inv_mass_b * p;
        b.w += db;
        self.solve_friction(&mut a, &mut b);
        scatter_velocities(states, &self.body_a, self.writes_a, a);
        scatter_velocities(states, &self.body_b, self.writes_b, b);
    }

    /// Coulomb friction in the contact plane (exact 2×2 mass while sticking, isotropic while
    /// sliding), then the layout's twist friction, at the manifold centre.
    #[inline(always)]
    fn solve_friction(&mut self, a: &mut Velocities, b: &mut Velocities) {
        let mut total = F::ZERO;
        for cp in &self.points {
            total += cp.normal_impulse;
        }
        let max_f = self.friction * total;
        let max_f2 = max_f * max_f;
        let [t1, t2] = self.tangent;
        let dv = b.v - a.v;
        let vt1 = dv.dot(t1) + b.w.dot(self.rt_b[0]) - a.w.dot(self.rt_a[0]);
        let vt2 = dv.dot(t2) + b.w.dot(self.rt_b[1]) - a.w.dot(self.rt_a[1]);
        let m = self.tangent_mass;
        let [old1, old2] = self.tangent_impulse;
        let stick1 = old1 - (m[0] * vt1 + m[1] * vt2);
        let stick2 = old2 - (m[1] * vt1 + m[2] * vt2);
        let slide1 = old1 - self.slide_mass * vt1;
        let slide2 = old2 - self.slide_mass * vt2;
        let len2 = slide1 * slide1 + slide2 * slide2;
        let clamp = len2.simd_gt(max_f2).select(max_f / len2.sqrt(), F::ONE);
        let sliding = (stick1 * stick1 + stick2 * stick2).simd_gt(max_f2);
        let l1 = sliding.select(slide1 * clamp, stick1);
        let l2 = sliding.select(slide2 * clamp, stick2);
        let (d1, d2) = (l1 - old1, l2 - old2);
        self.tangent_impulse = [l1, l2];
        let p = t1.scale(d1) + t2.scale(d2);
        a.v -= self.inv_mass_a * p;
        a.w -= self.irt_a[0].scale(d1) + self.irt_a[1].scale(d2);
        b.v += self.inv_mass_b * p;
        b.w += self.irt_b[0].scale(d1) + self.irt_b[1].scale(d2);
        self.manifold
            .solve_twist(&self.points, self.friction, self.normal, a, b);
    }

    /// After substepping: points that approached faster than `threshold` and carried load
    /// get a separating velocity `e · |approach speed|`.
    pub(crate) fn apply_restitution(&mut self, states: &mut [BodyState], threshold: f32) {
        let bouncy = self.restitution.simd_gt(F::ZERO);
        if !bouncy.any() {
            return;
        }
        let mut a = gather_velocities(states, &self.body_a);
        let mut b = gather_velocities(states, &self.body_b);
        let n = self.normal;
        let neg_threshold = F::splat(-threshold);
        for cp in &mut self.points {
            let fast = cp.relative_velocity.simd_le(neg_threshold);
            let loaded = cp.max_normal_impulse.simd_gt(F::ZERO);
            let bounce = bouncy & fast & loaded;
            if !bounce.any() {
                continue;
            }
            let vn = (b.v - a.v).dot(n) + b.w.dot(cp.rn_b) - a.w.dot(cp.rn_a);
            let imp = -cp.normal_mass * (vn + self.restitution * cp.relative_velocity);
            let new = fmax(F::ZERO, cp.normal_impulse + imp);
            let imp = bounce.select(new - cp.normal_impulse, F::ZERO);
            cp.normal_impulse += imp;
            cp.max_normal_impulse =
                bounce.select(fmax(cp.max_normal_impulse, imp), cp.max_normal_impulse);
            let p = n.scale(imp);
            a.v -= self.inv_mass_a * p;
            a.w -= cp.irn_a.scale(imp);
            b.v += self.inv_mass_b * p;
            b.w += cp.irn_b.scale(imp);
        }
        scatter_velocities(states, &self.body_a, self.writes_a, a);
        scatter_velocities(states, &self.body_b, self.writes_b, b);
    }
}
