//! [`FaceContact`]: what a manifold of two to four points adds to the rows of a
//! [`ContactBatch`](super::contact_batch::ContactBatch): the shared normal step over its
//! points, the coupling between its points' normal rows, and twist friction about the normal.

use super::contact_batch::{
    fmax, set, Leveled, ManifoldRows, NormalRows, PointLanes, LEVEL_MAX_FRICTION, LEVEL_SHARE,
};
use super::contact_constraint::{PreparedManifold, PAIR_SLOT};
use super::lanes::{Velocities, F, V3};

/// The multi-point rows of four manifolds, one per lane (see
/// [`NormalBlock`](super::contact_constraint::NormalBlock)).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FaceContact {
    /// `impulse_scale / mass_scale`: a soft row's compliance per unit `inv_normal_mass`.
    soft_compliance: F,
    /// Lane mask: the shared normal step applies.
    patch: F,
    /// Lane mask: a patch levelled while it rests ([`FaceContact::level_patch`]): one with
    /// friction below `LEVEL_MAX_FRICTION`, or under a load past its tilt limit
    /// (`levelled_for_load`); set once per step, with the lane.
    levelled: F,
    /// How much of each point's leak is the patch's mean impulse, for the levelled lanes.
    level_share: F,
    patch_k: F,
    row_sum: [F; 4],
    coupling: [F; 6],
    count: F,
    inv_count: F,
    /// Per point: `J M⁻¹ Jᵀ` of its normal row, its distance from the manifold centre in the
    /// contact plane (twist lever), and 1 where the lane's manifold has the point, else 0.
    inv_normal_mass: [F; 4],
    twist_lever: [F; 4],
    active: [F; 4],
    twist_impulse: F,
    twist_mass: F,
    /// World inverse inertia times the normal, for A and B.
    in_a: V3,
    in_b: V3,
}

impl FaceContact {
    /// Per lane, the mean over the patch's points of their rows' residuals (soft:
    /// `vn + bias + impulse_scale·λ / (mass_scale·m)`; speculative: `vn + s/h`), and how much
    /// the compliance of the soft rows moves that mean per unit of total impulse shared
    /// equally among the points (`Σ compliance / count²`).
    #[inline(always)]
    pub(crate) fn patch_residual<const N: usize>(
        &self,
        points: &[PointLanes; N],
        rows: &NormalRows<N>,
        vn: &[F; N],
    ) -> (F, F) {
        let (mut residual, mut total_compliance) = (F::ZERO, F::ZERO);
        for k in 0..N {
            // The row each point has in the per-point pass: speculative (rigid) or soft,
            // whose compliance is `impulse_scale / (mass_scale · m)` beyond the mechanical part.
            let compliance = if rows.use_bias {
                rows.speculative[k].select(F::ZERO, self.soft_compliance * self.inv_normal_mass[k])
            } else {
                F::ZERO
            };
            residual +=
                self.active[k] * (vn[k] + rows.bias[k] + compliance * points[k].normal_impulse);
            total_compliance += compliance;
        }
        let inv = self.inv_count;
        (residual * inv, total_compliance * inv * inv)
    }

    /// Adds `total` normal impulse per lane to the patch, shared equally among its points but
    /// no point's accumulated impulse below zero; returns what each point got.
    #[inline(always)]
    pub(crate) fn share_impulse<const N: usize>(
        &self,
        points: &mut [PointLanes; N],
        total: F,
    ) -> F {
        let mut min_impulse = F::splat(f32::MAX);
        for (k, cp) in points.iter().enumerate() {
            let active = self.active[k].simd_gt(F::ZERO);
            min_impulse = active.select(cp.normal_impulse.fast_min(min_impulse), min_impulse);
        }
        let total = fmax(-self.count * min_impulse, total);
        let each = total * self.inv_count;
        for (k, cp) in points.iter_mut().enumerate() {
            let mine = each * self.active[k];
            cp.normal_impulse += mine;
            cp.max_normal_impulse = fmax(cp.max_normal_impulse, mine);
        }
        each
    }

    /// 1 where lane `l`'s manifold has point `k`, else 0.
    #[inline(always)]
    pub(crate) fn active(&self, k: usize) -> F {
        self.active[k]
    }
}

impl ManifoldRows for FaceContact {
    const EMPTY: Self = Self {
        soft_compliance: F::ZERO,
        patch: F::ZERO,
        levelled: F::ZERO,
        level_share: F::ZERO,
        patch_k: F::ZERO,
        row_sum: [F::ZERO; 4],
        coupling: [F::ZERO; 6],
        count: F::ZERO,
        inv_count: F::ZERO,
        inv_normal_mass: [F::ZERO; 4],
        twist_lever: [F::ZERO; 4],
        active: [F::ZERO; 4],
        twist_impulse: F::ZERO,
        twist_mass: F::ZERO,
        in_a: V3::ZERO,
        in_b: V3::ZERO,
    };

    fn set_lane(&mut self, l: usize, prepared: &PreparedManifold) {
        let c = &prepared.constraint;
        let soft = if c.softness.mass_scale > 0.0 {
            c.softness.impulse_scale / c.softness.mass_scale
        } else {
            0.0
        };
        set(&mut self.soft_compliance, l, soft);
        let mask = if c.block.patch {
            f32::from_bits(u32::MAX)
        } else {
            0.0
        };
        set(&mut self.patch, l, mask);
        let share = if c.friction.friction < LEVEL_MAX_FRICTION {
            LEVEL_SHARE
        } else {
            c.load_level_share
        };
        let level = if c.block.patch && share > 0.0 {
            f32::from_bits(u32::MAX)
        } else {
            0.0
        };
        set(&mut self.levelled, l, level);
        set(&mut self.level_share, l, share);
        set(&mut self.patch_k, l, c.block.patch_k);
        for k in 0..4 {
            set(&mut self.row_sum[k], l, c.block.row_sum[k]);
        }
        for k in 0..6 {
            set(&mut self.coupling[k], l, c.block.coupling[k]);
        }
        set(&mut self.count, l, f32::from(c.count));
        set(&mut self.inv_count, l, 1.0 / f32::from(c.count.max(1)));
        for (k, p) in prepared
            .points
            .iter()
            .enumerate()
            .take(usize::from(c.count))
        {
            set(&mut self.inv_normal_mass[k], l, p.inv_normal_mass);
            set(&mut self.twist_lever[k], l, p.twist_lever);
            set(&mut self.active[k], l, 1.0);
        }
        set(&mut self.twist_impulse, l, c.friction.twist_impulse);
        set(&mut self.twist_mass, l, c.friction.twist_mass);
        self.in_a.set(l, c.friction.in_a);
        self.in_b.set(l, c.friction.in_b);
    }

    #[inline(always)]
    fn warm_start(&self, wa: &mut V3, wb: &mut V3) {
        *wa += self.in_a.scale(self.twist_impulse);
        *wb += self.in_b.scale(self.twist_impulse);
    }

    /// One step of all the manifold's points together (the mean of their rows: one impulse at the
    /// patch centre, shared equally), before the per-point Gauss–Seidel pass.
    ///
    /// Points solved one after another are biased: the first one stops the whole approach on its
    /// own corner and tips the body, the others only partly undo it. A perfectly symmetric stack of
    /// boxes thus left its first step spinning (0.01–0.02 rad/s for three boxes), and a stack of
    /// frictionless boxes, which soft contacts cannot hold against a sideways offset (a box off
    /// centre tilts its support, then slides down it), was seeded to collapse within ~35 s. The
    /// shared step removes the common approach without torque, so the per-point pass only fixes
    /// the differences. It drives the mean of the per-point residuals (soft:
    /// `vn + bias + impulse_scale·λ / (mass_scale·m)`; speculative: `vn + s/h`) to zero, so it has
    /// the fixed point of the per-point rows and never works against them. Speculative rows take
    /// part too: a box landing flat on the ground meets it with all four points speculative, and
    /// solved one by one they tipped it and threw it sideways (a dropped five-box stack drifted
    /// 2 cm; now 2 mm).
    #[inline(always)]
    fn solve_shared<const N: usize>(
        &self,
        points: &mut [PointLanes; N],
        rows: &NormalRows<N>,
        vn: &mut [F; N],
        applied: &mut [F; N],
    ) {
        if !self.patch.any() {
            return;
        }
        let (residual, compliance) = self.patch_residual(points, rows, vn);
        // The mean residual moves by `k` per unit of total impulse shared equally.
        let k = self.patch_k + compliance;
        let total = self.patch.select(-residual / k, F::ZERO);
        let each = self.share_impulse(points, total);
        for k in 0..N {
            applied[k] += each * self.active[k];
            vn[k] += each * self.active[k] * self.row_sum[k];
        }
    }

    /// A resting frictionless face (every point of the patch pressed in) leaks mostly the
    /// patch's mean impulse from each point's row instead of the point's own
    /// ([`LEVEL_SHARE`] of it), so it is soft in depth and nearly rigid in tilt; a face with
    /// friction does so in part ([`LOADED_LEVEL_SHARE`](super::contact_batch::LOADED_LEVEL_SHARE))
    /// once its load passes the ratio at which its tilt compliance lets the column on it sway
    /// ([`levelled_for_load`](super::contact_batch::levelled_for_load)).
    ///
    /// A soft row settles at a depth proportional to the impulse it carries, so independent
    /// soft rows make a face as compliant in tilt as in depth: a load off the face's centre
    /// presses one side in further and the face tilts. Friction holds what rests on a face
    /// tilted by a few micro-radians; without friction it slides down the slope, which moves
    /// the load further off centre and tilts the face further: frictionless boxes stacked off
    /// centre slid 17.8 m apart in 20 s at 30 Hz × 2. With the mean leaked, the rows' fixed
    /// point has every point at the same depth whatever the spread of their impulses, while
    /// the patch as a whole keeps the soft contact's stiffness and static deflection (the
    /// rows' mean is the shared step's target); the point's own share keeps the tilt damped
    /// (a frictionless 20-box column rocked and fell without it). Impulses stay non-negative
    /// point by point, so a face whose load leaves its support still tips over its edge.
    /// Friction faces in general keep their own leak: one resting on two supports (a brick
    /// in a pyramid) cannot be level on both, and rows without their own leak wind up
    /// against each other (the 20-row pyramid slumped 3.7 m instead of 2.5 cm).
    #[inline(always)]
    fn level_patch<const N: usize>(
        &self,
        points: &[PointLanes; N],
        rows: &NormalRows<N>,
    ) -> Leveled {
        let mut flat = self.levelled;
        if !rows.use_bias || !flat.any() {
            return Leveled::NONE;
        }
        let mut impulse_sum = F::ZERO;
        for (k, cp) in points.iter().enumerate() {
            let active = self.active[k].simd_gt(F::ZERO);
            flat = (active & rows.speculative[k]).select(F::ZERO, flat);
            impulse_sum += self.active[k] * cp.normal_impulse;
        }
        Leveled {
            lanes: flat,
            mean_impulse: impulse_sum * self.inv_count,
            inv_count: self.inv_count,
            share: self.level_share,
        }
    }

    #[inline(always)]
    fn couple<const N: usize>(&self, j: usize, imp: F, vn: &mut [F; N]) {
        for (i, v) in vn.iter_mut().enumerate().skip(j + 1) {
            *v += self.coupling[PAIR_SLOT[j][i]] * imp;
        }
    }

    /// Twist friction bounded by `μ Σ λₙ·lever` (rapier's "twist friction").
    #[inline(always)]
    fn solve_twist<const N: usize>(
        &mut self,
        points: &[PointLanes; N],
        friction: F,
        normal: V3,
        a: &mut Velocities,
        b: &mut Velocities,
    ) {
        let mut twist_limit = F::ZERO;
        for (cp, lever) in points.iter().zip(&self.twist_lever) {
            twist_limit += cp.normal_impulse * *lever;
        }
        let limit = friction * twist_limit;
        let wt = (b.w - a.w).dot(normal);
        let l = (self.twist_impulse - self.twist_mass * wt)
            .fast_max(-limit)
            .fast_min(limit);
        let d = l - self.twist_impulse;
        self.twist_impulse = l;
        a.w -= self.in_a.scale(d);
        b.w += self.in_b.scale(d);
    }

    fn twist_impulse(&self) -> F {
        self.twist_impulse
    }
}
