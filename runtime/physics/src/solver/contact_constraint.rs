//! [`ContactConstraint`]: soft non-penetration per point, Coulomb friction and twist
//! friction at the manifold centre, restitution.

use glam::{Mat3A, Vec3A};

use super::body_state::BodyState;
use super::lanes::{F, LANES, V3};
use super::noise::vector_without_noise;
use super::softness::Softness;
use super::solver_body::SolverBody;

/// Inverse mass and world inverse inertia of one body (what effective masses need).
#[derive(Clone, Copy)]
struct MassView {
    inv_mass: Vec3A,
    inv_i: Mat3A,
}

/// Solver data of one contact point (normal direction only; friction acts per manifold).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ConstraintPoint {
    /// Separation at step start; the current separation is this plus the normal part of the
    /// position deltas (relative quantities only, so precise far from the origin).
    pub base_separation: f32,
    /// Accumulated normal impulse, N·s.
    pub normal_impulse: f32,
    /// Largest single normal impulse of the step.
    pub max_normal_impulse: f32,
    /// Effective mass along the normal.
    pub normal_mass: f32,
    /// Its inverse `J M⁻¹ Jᵀ` (the soft row's compliance is this times
    /// `impulse_scale / mass_scale`).
    pub inv_normal_mass: f32,
    /// Normal relative velocity at step start (pre-solve), m/s.
    pub relative_velocity: f32,
    /// Restitution's target for this point after the substeps, m/s: a rebound speed > 0
    /// where it bounces ([`super::restitution::bounce_velocity`]), else the relative normal
    /// velocity it is held to, ≤ 0 ([`super::restitution::held_velocity`]); NaN in a
    /// manifold without restitution.
    pub restitution_velocity: f32,
    /// Distance from the manifold centre in the contact plane (twist friction lever), m.
    pub twist_lever: f32,
    /// Angular Jacobians `r × n` for A and B (fixed for the step).
    pub rn_a: Vec3A,
    pub rn_b: Vec3A,
    /// The same premultiplied by each body's world inverse inertia.
    pub irn_a: Vec3A,
    pub irn_b: Vec3A,
}

/// Friction of one manifold, applied at the centre of its points: a 2-D Coulomb impulse in
/// the contact plane bounded by `μ Σλₙ`, and a twist impulse about the normal bounded by
/// `μ Σ λₙ·lever` (rapier's "twist friction"). Three rows per manifold instead of two per
/// point: less work, and no corner-point anisotropy.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct FrictionPart {
    /// Coulomb coefficient chosen for the step (static while sticking, else dynamic).
    pub friction: f32,
    /// Accumulated impulse along the two tangents, N·s.
    pub tangent_impulse: [f32; 2],
    /// Accumulated twist impulse about the normal, N·m·s.
    pub twist_impulse: f32,
    /// Inverse of the 2×2 tangent block of `K` (`[m11, m12, m22]`), for sticking
    /// (see [`friction_masses`]).
    pub tangent_mass: [f32; 3],
    /// Isotropic friction mass `1 / λ_max`, for sliding.
    pub slide_mass: f32,
    /// Effective inertia about the normal.
    pub twist_mass: f32,
    /// Angular Jacobians `r × t1`, `r × t2` at the centre, for A and B.
    pub rt_a: [Vec3A; 2],
    pub rt_b: [Vec3A; 2],
    /// The same premultiplied by each body's world inverse inertia.
    pub irt_a: [Vec3A; 2],
    pub irt_b: [Vec3A; 2],
    /// World inverse inertia times the normal, for A and B (twist).
    pub in_a: Vec3A,
    pub in_b: Vec3A,
}

impl FrictionPart {
    /// Sets to zero the components of the twist rows' [`Self::in_a`] and [`Self::in_b`]
    /// within rounding of their largest (`noise::vector_without_noise`). A body's inverse inertia turned onto a normal along
    /// one of its axes has rounding in the other two (1e-20 of the first), and in a column
    /// (whose passes drive its twist towards zero) their products with the twist impulses
    /// were subnormal floats, a microcode assist each on x86: the 20-box stack's twist rows
    /// ran at ten times their cost (see `lanes::TINY_SPEED`).
    pub(crate) fn denoise_twist(&mut self) {
        self.in_a = vector_without_noise(self.in_a);
        self.in_b = vector_without_noise(self.in_b);
    }
}

/// A contact point closer than this fraction of the smaller body's size counts as touching:
/// its row is soft, not speculative (see [`ContactConstraint::touching`]). Bodies placed face
/// to face meet at separations of rounding size and either sign, and a face whose points
/// were split between rigid speculative rows and soft ones pushed unevenly and tipped the
/// body: three 1 mm cubes placed on each other left their first step turning at 0.74 rad/s,
/// and a column of ten 3 cm cubes at precise fell within 1.4 s (with it: 3·10⁻⁶ rad/s, and
/// the column stands). About ten times the rounding of coordinates the size of the smaller
/// body; where the bodies are farther from the origin than that, the rounding of their
/// coordinates is larger ([`TOUCHING_ROUNDING`]). Bounded `(0, 1e-4)`: at 10⁻⁴ a random
/// frictionless stack at `fast` collapsed, its faces soft a little above the surface where
/// they had been rigid.
pub const TOUCHING_SIZE_FRACTION: f32 = 1e-6;

/// A contact point closer than this many times `f32::EPSILON` of the bodies' largest world
/// coordinate counts as touching too: the rounding of where they were placed. Ten 1 mm
/// cubes stacked on a 10 cm box met at 2·10⁻⁹ m, twice the size's fraction (10⁻⁹ m) but a
/// quarter of the rounding at 0.1 m (7.5·10⁻⁹ m); taken for not touching, their faces were
/// rigid speculative rows and not a column, and the cubes telescoped 74 % of a cube into
/// each other in the first step (2.0 % on a 1 cm box).
pub const TOUCHING_ROUNDING: f32 = 4.0;

/// The separation, m, up to which a point of a pair whose smaller body is `size` across, with
/// bodies whose largest world coordinate is `reach`, is touching: [`TOUCHING_SIZE_FRACTION`]
/// of the size or [`TOUCHING_ROUNDING`] roundings of the coordinate, whichever is larger (0
/// where neither body is finite).
#[must_use]
#[inline]
pub fn touching_distance(size: f32, reach: f32) -> f32 {
    if size < f32::MAX {
        (TOUCHING_SIZE_FRACTION * size).max(TOUCHING_ROUNDING * f32::EPSILON * reach)
    } else {
        0.0
    }
}

/// Slot of the coupling between points `i < j` in [`NormalBlock::coupling`].
pub(crate) const PAIR_SLOT: [[usize; 4]; 4] =
    [[0, 0, 1, 2], [0, 0, 3, 4], [1, 3, 0, 5], [2, 4, 5, 0]];

/// Per-step constants of a manifold's normal rows as one block: how an impulse on one point
/// changes the normal velocity of another (`K_ij = J_i M⁻¹ J_jᵀ`, fixed for the step).
///
/// With it the per-point pass updates four scalars instead of both bodies' velocities after
/// every point (the velocities get the summed impulses once at the end): the same
/// Gauss–Seidel sweep, with a dependency chain a few instructions long.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct NormalBlock {
    /// The shared normal step applies (two or more points, each with an effective mass).
    pub patch: bool,
    /// Mechanical part of the shared step's `k`: `Σᵢⱼ K_ij / count²`.
    pub patch_k: f32,
    /// `Σᵢ K_ij` per point `j`: how one unit shared by every point moves point `j`.
    pub row_sum: [f32; 4],
    /// Off-diagonal `K_ij` (`i < j`, see `PAIR_SLOT`); the diagonal is each point's
    /// `inv_normal_mass`.
    pub coupling: [f32; 6],
}

/// A manifold the solver takes this step: where it is, and what batching needs to know
/// before it is prepared (which bodies it writes, how many points).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ManifoldRef {
    /// Pair and manifold index in the narrowphase, to read the contacts and store impulses.
    pub pair: u32,
    pub manifold: u32,
    /// Solver indices of the two bodies.
    pub body_a: u32,
    pub body_b: u32,
    /// As [`ContactConstraint::writes`].
    pub writes: u8,
    /// Points, 1–4.
    pub count: u8,
    /// One of the bodies can rotate (else the manifold goes to a linear batch).
    pub angular: bool,
    /// Bit 0 (1): body A (B) rests on the other body of this manifold (see
    /// `RestingAccelerations`).
    pub rests: u8,
}

/// A constraint and its points, prepared for one step (lives on the stack while a batch
/// is packed).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct PreparedManifold {
    pub constraint: ContactConstraint,
    pub points: [ConstraintPoint; 4],
}

/// One manifold as a solver constraint.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ContactConstraint {
    pub body_a: u32,
    pub body_b: u32,
    /// Bit 0: the solver writes body A's velocities (it is dynamic); bit 1: body B's.
    pub writes: u8,
    /// One of the bodies can rotate; when neither can, the lever-arm terms stay zero.
    pub angular: bool,
    pub normal: Vec3A,
    pub tangent: [Vec3A; 2],
    pub restitution: f32,
    /// Restitution 1, no friction, and no impact that the restitution threshold took as
    /// inelastic: the contact does no work over the step (see `solver::elastic_energy`).
    pub elastic: bool,
    /// A face in a column that needs more passes than the step's iterations to hold its
    /// tilt (see `COLUMN_PASSES`): solved again after them.
    pub column: bool,
    /// A column face whose friction the coarse correction solves with its normal rows
    /// (`solver::column_solve`): one under or on a pinched body
    /// (`pipeline::heavy_on_light::PinchedBodies`).
    pub column_friction: bool,
    /// Relative normal acceleration of the bodies (gravity, forces), m/s², for restitution.
    pub bounce_accel: f32,
    /// Per side (A, B): where the body's own supports hold it, the unit direction its
    /// acceleration presses it into them (see `RestingAccelerations::pressing`), else zero.
    /// A rebound leaves from where a held side started the step along it, not from where the
    /// impact pressed it into its supports.
    pub pressing: [Vec3A; 2],
    /// How much of each point's leak is the patch's mean impulse for a face levelled under
    /// its load (see `FaceContact::level_patch`); 0: not levelled for its load.
    pub load_level_share: f32,
    /// Factors on each body's inverse mass and inertia in this manifold's rows (1 but for
    /// the light body of a resting contact past `PhysicsSettings::max_support_mass_ratio`).
    pub mass_scale: [f32; 2],
    pub softness: Softness,
    /// Separation, m, up to which a point's row is soft rather than speculative:
    /// [`TOUCHING_SIZE_FRACTION`] of the smaller body's size.
    pub touching: f32,
    pub count: u8,
    /// Friction at the manifold centre.
    pub friction: FrictionPart,
    /// The normal rows as a block.
    pub block: NormalBlock,
}

/// Friction masses of one point: the inverse of the 2×2 tangent block `K` of `J M⁻¹ Jᵀ`
/// (for sticking) and one isotropic mass `1 / λ_max(K)` (for sliding).
///
/// Friction is clamped to a circular cone, so a sliding point's impulse must point against
/// its slip. With a separate mass per tangent (they differ at off-centre points, where
/// rotation adds to one axis more than the other) the clamped impulse turned away from the
/// slip, part of the friction budget went sideways, and a box slid down an incline ~17 %
/// too fast. The isotropic mass keeps the slip direction and `m·λ ≤ 1` on every direction
/// (no Gauss–Seidel overshoot); the exact inverse keeps sticking points stuck in one pass.
#[inline]
fn friction_masses(a: &MassView, b: &MassView, f: &FrictionPart, t: [Vec3A; 2]) -> ([f32; 3], f32) {
    // `J M⁻¹ Jᵀ` entries from the friction Jacobians `f.rt_*`, `f.irt_*` (already computed).
    let k = |i: usize, j: usize| {
        t[i].dot(a.inv_mass * t[j])
            + t[i].dot(b.inv_mass * t[j])
            + f.rt_a[i].dot(f.irt_a[j])
            + f.rt_b[i].dot(f.irt_b[j])
    };
    let (k11, k22, k12) = (k(0, 0), k(1, 1), k(0, 1));
    let det = k11 * k22 - k12 * k12;
    let inv = if det > f32::EPSILON * (k11 * k22).max(f32::MIN_POSITIVE) {
        let id = 1.0 / det;
        [k22 * id, -k12 * id, k11 * id]
    } else {
        // Singular (locked axes): per-axis masses.
        let m = |k: f32| if k > 0.0 { 1.0 / k } else { 0.0 };
        [m(k11), 0.0, m(k22)]
    };
    let half = 0.5 * (k11 + k22);
    let lmax = half + (0.25 * (k11 - k22) * (k11 - k22) + k12 * k12).sqrt();
    let iso = if lmax > 0.0 { 1.0 / lmax } else { 0.0 };
    (inv, iso)
}

/// Fills Jacobians, masses and relative velocities from the anchors (offsets from each
/// centre of mass, world axes); call once per step before substepping. The friction
/// impulses in `c.friction` must already hold the warm-start values.
#[allow(clippy::too_many_arguments)]
pub(crate) fn prepare(
    c: &mut ContactConstraint,
    points: &mut [ConstraintPoint],
    anchors: &[(Vec3A, Vec3A)],
    bodies: &[SolverBody],
    states: &[BodyState],
    friction_s: f32,
    friction_d: f32,
    static_speed: f32,
) {
    let (sa, sb) = (&states[c.body_a as usize], &states[c.body_b as usize]);
    let [ka, kb] = c.mass_scale;
    let a = &MassView {
        inv_mass: sa.inv_mass * ka,
        inv_i: Mat3A::from(bodies[c.body_a as usize].inv_i) * ka,
    };
    let b = &MassView {
        inv_mass: sb.inv_mass * kb,
        inv_i: Mat3A::from(bodies[c.body_b as usize].inv_i) * kb,
    };
    let n = c.normal;
    let count = anchors.len().min(points.len()).min(LANES);
    let inv_count = 1.0 / count.max(1) as f32;
    let (mut ca, mut cb) = (Vec3A::ZERO, Vec3A::ZERO);
    for &(ra, rb) in &anchors[..count] {
        ca += ra;
        cb += rb;
    }
    ca *= inv_count;
    cb *= inv_count;
    let angular = c.angular;
    // The points side by side, one per lane (lanes past `count` hold zero anchors, and
    // what they compute is not used): a manifold's four Jacobians, masses and couplings in
    // the instructions of one, with one division and one square root for all.
    let lanes = |side: fn(&(Vec3A, Vec3A)) -> Vec3A| {
        V3::from_lanes(std::array::from_fn(|k| {
            anchors[..count].get(k).map_or(Vec3A::ZERO, side)
        }))
    };
    let (ra, rb) = (lanes(|p| p.0), lanes(|p| p.1));
    let nl = V3::splat(n);
    let k_lin = n.dot(a.inv_mass * n) + n.dot(b.inv_mass * n);
    let (rn_a, rn_b, irn_a, irn_b, dv) = if angular {
        let (rn_a, rn_b) = (ra.cross(nl), rb.cross(nl));
        let dv = V3::splat(sb.v - sa.v) + V3::splat(sb.w).cross(rb) - V3::splat(sa.w).cross(ra);
        (
            rn_a,
            rn_b,
            rn_a.transformed(&a.inv_i),
            rn_b.transformed(&b.inv_i),
            dv,
        )
    } else {
        let z = V3::ZERO;
        (z, z, z, z, V3::splat(sb.v - sa.v))
    };
    // `J M⁻¹ Jᵀ` from the Jacobians just computed (the same products, not recomputed).
    let k = F::splat(k_lin) + rn_a.dot(irn_a) + rn_b.dot(irn_b);
    let normal_mass = k.simd_gt(F::ZERO).select(F::ONE / k, F::ZERO);
    let off = ra - V3::splat(ca);
    let off = off - nl.scale(off.dot(nl));
    let twist_lever = off.dot(off).sqrt();
    let relative_velocity = dv.dot(nl);
    let (k, normal_mass) = (k.to_array(), normal_mass.to_array());
    let (twist_lever, relative_velocity) = (twist_lever.to_array(), relative_velocity.to_array());
    let (rn_al, rn_bl) = (rn_a.to_lanes(), rn_b.to_lanes());
    let (irn_al, irn_bl) = (irn_a.to_lanes(), irn_b.to_lanes());
    for (i, cp) in points[..count].iter_mut().enumerate() {
        if angular {
            cp.rn_a = rn_al[i];
            cp.rn_b = rn_bl[i];
            cp.irn_a = irn_al[i];
            cp.irn_b = irn_bl[i];
        }
        cp.inv_normal_mass = k[i];
        cp.normal_mass = normal_mass[i];
        cp.relative_velocity = relative_velocity[i];
        cp.restitution_velocity = f32::NAN;
        cp.twist_lever = twist_lever[i];
        cp.max_normal_impulse = 0.0;
    }
    // The block, a row at a time: row `i` holds `K_ij = J_i M⁻¹ J_jᵀ` in lane `j` (its
    // diagonal is `k` above, the same products in the same order); the row sums add the
    // rows of the points there are.
    let block = &mut c.block;
    *block = NormalBlock::default();
    let mut row_sum = F::ZERO;
    let used = F::new(std::array::from_fn(|j| if j < count { 1.0 } else { 0.0 }));
    for i in 0..count {
        let row = F::splat(k_lin) + irn_a.dot(V3::splat(rn_al[i])) + irn_b.dot(V3::splat(rn_bl[i]));
        row_sum += row * used;
        let row = row.to_array();
        for j in i + 1..count {
            block.coupling[PAIR_SLOT[i][j]] = row[j];
        }
    }
    block.row_sum = row_sum.to_array();
    if count > 1 && normal_mass[..count].iter().all(|&m| m > 0.0) {
        let sum: f32 = block.row_sum[..count].iter().sum();
        block.patch_k = sum / (count * count) as f32;
        block.patch = block.patch_k > 0.0;
    }
    let f = &mut c.friction;
    if angular {
        for k in 0..2 {
            f.rt_a[k] = ca.cross(c.tangent[k]);
            f.rt_b[k] = cb.cross(c.tangent[k]);
            f.irt_a[k] = a.inv_i * f.rt_a[k];
            f.irt_b[k] = b.inv_i * f.rt_b[k];
        }
    }
    (f.tangent_mass, f.slide_mass) = friction_masses(a, b, f, c.tangent);
    if angular {
        f.in_a = a.inv_i * n;
        f.in_b = b.inv_i * n;
        let kt = n.dot(f.in_a) + n.dot(f.in_b);
        f.twist_mass = if kt > 0.0 { 1.0 / kt } else { 0.0 };
    }
    let dv = if angular {
        sb.v + sb.w.cross(cb) - sa.v - sa.w.cross(ca)
    } else {
        sb.v - sa.v
    };
    let slip = dv - n * dv.dot(n);
    f.friction = if slip.length_squared() < static_speed * static_speed {
        friction_s
    } else {
        friction_d
    };
}

#[cfg(test)]
mod tests {
    use glam::{Mat3, Vec3};

    use super::*;

    /// Two bodies with full (non-diagonal) inverse inertias, moving and spinning, and a
    /// manifold of some points between them.
    struct Scene {
        c: ContactConstraint,
        anchors: Vec<(Vec3A, Vec3A)>,
        bodies: Vec<SolverBody>,
        states: Vec<BodyState>,
    }

    impl Scene {
        /// Prepares the manifold into `points` (friction 0.6 / 0.4, static below 5 cm/s).
        fn prepare(&mut self, points: &mut [ConstraintPoint]) {
            let (anchors, bodies, states) = (&self.anchors, &self.bodies, &self.states);
            prepare(&mut self.c, points, anchors, bodies, states, 0.6, 0.4, 0.05);
        }
    }

    fn scene(count: usize, angular: bool) -> Scene {
        let inv_i = |d: f32| {
            let m = Mat3::from_cols(
                Vec3::new(d, 0.1, -0.05),
                Vec3::new(0.1, 2.0 * d, 0.2),
                Vec3::new(-0.05, 0.2, 1.5 * d),
            );
            SolverBody {
                inv_i: m,
                ..SolverBody::STATIC
            }
        };
        let bodies = vec![inv_i(0.7), inv_i(0.3)];
        let state = |inv_mass: f32, v: Vec3A, w: Vec3A| BodyState {
            v,
            w,
            inv_mass: Vec3A::splat(inv_mass),
            ..BodyState::STATIC
        };
        let states = vec![
            state(0.5, Vec3A::new(0.3, -1.0, 0.2), Vec3A::new(0.5, 0.1, -0.7)),
            state(0.25, Vec3A::new(-0.4, 0.6, 0.1), Vec3A::new(-0.2, 0.9, 0.4)),
        ];
        let normal = Vec3A::new(0.2, 0.9, -0.1).normalize();
        let t1 = normal.any_orthonormal_vector();
        let c = ContactConstraint {
            body_a: 0,
            body_b: 1,
            writes: 3,
            angular,
            normal,
            tangent: [t1, normal.cross(t1)],
            mass_scale: [1.0; 2],
            count: count as u8,
            ..ContactConstraint::default()
        };
        let anchors = [
            (Vec3A::new(0.5, -0.4, 0.3), Vec3A::new(-0.2, 0.6, 0.1)),
            (Vec3A::new(-0.5, -0.4, 0.35), Vec3A::new(0.4, 0.5, -0.3)),
            (Vec3A::new(0.45, -0.5, -0.3), Vec3A::new(-0.3, 0.7, 0.5)),
            (Vec3A::new(-0.6, -0.3, -0.25), Vec3A::new(0.2, 0.4, 0.6)),
        ];
        Scene {
            c,
            anchors: anchors[..count].to_vec(),
            bodies,
            states,
        }
    }

    fn close(a: f32, b: f32) -> bool {
        (a - b).abs() <= 1e-5 * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn prepared_points_hold_their_effective_masses_couplings_and_velocities() {
        for count in 1..=4 {
            let mut s = scene(count, true);
            let mut points = [ConstraintPoint::default(); 4];
            s.prepare(&mut points[..count]);
            let (c, anchors, bodies, states) = (s.c, s.anchors, s.bodies, s.states);
            let n = c.normal;
            let (ia, ib) = (Mat3A::from(bodies[0].inv_i), Mat3A::from(bodies[1].inv_i));
            let (sa, sb) = (&states[0], &states[1]);
            let lin = n.dot(sa.inv_mass * n) + n.dot(sb.inv_mass * n);
            // `K_ij = J_i M⁻¹ J_jᵀ`, the Jacobian of point i being (−n, −rₐ×n, n, r_b×n).
            let k = |i: usize, j: usize| {
                let ((ra_i, rb_i), (ra_j, rb_j)) = (anchors[i], anchors[j]);
                lin + ra_i.cross(n).dot(ia * ra_j.cross(n)) + rb_i.cross(n).dot(ib * rb_j.cross(n))
            };
            let centre = anchors.iter().map(|a| a.0).sum::<Vec3A>() / count as f32;
            let mut row_sum = [0.0f32; 4];
            for i in 0..count {
                let (ra, rb) = anchors[i];
                let p = &points[i];
                assert!(close(p.inv_normal_mass, k(i, i)), "{count} points, k{i}{i}");
                assert!(close(p.normal_mass, 1.0 / k(i, i)));
                let dv = sb.v + sb.w.cross(rb) - sa.v - sa.w.cross(ra);
                assert!(close(p.relative_velocity, dv.dot(n)));
                let off = ra - centre;
                assert!(close(p.twist_lever, (off - n * off.dot(n)).length()));
                assert!((p.rn_a - ra.cross(n)).length() <= 1e-6);
                assert!((p.irn_b - ib * rb.cross(n)).length() <= 1e-6);
                for j in 0..count {
                    row_sum[j] += k(i, j);
                    if i < j {
                        assert!(close(c.block.coupling[PAIR_SLOT[i][j]], k(i, j)), "k{i}{j}");
                    }
                }
            }
            for (j, (&got, &want)) in c.block.row_sum.iter().zip(&row_sum).enumerate() {
                assert!(close(got, want), "{count} points, row {j}");
            }
            assert_eq!(c.block.patch, count > 1);
            if count > 1 {
                let total: f32 = row_sum.iter().sum();
                assert!(close(c.block.patch_k, total / (count * count) as f32));
            }
        }
    }

    #[test]
    fn points_of_bodies_that_cannot_rotate_couple_through_their_masses_alone() {
        let mut s = scene(4, false);
        // Scratch left by an earlier manifold's lever arms must not reach the block.
        let stale = ConstraintPoint {
            rn_a: Vec3A::ONE,
            rn_b: Vec3A::ONE,
            irn_a: Vec3A::ONE,
            irn_b: Vec3A::ONE,
            ..ConstraintPoint::default()
        };
        let mut points = [stale; 4];
        s.prepare(&mut points);
        let (c, states) = (s.c, s.states);
        let n = c.normal;
        let lin = n.dot(states[0].inv_mass * n) + n.dot(states[1].inv_mass * n);
        for cp in &points {
            assert!(close(cp.inv_normal_mass, lin));
            assert!(close(
                cp.relative_velocity,
                (states[1].v - states[0].v).dot(n)
            ));
        }
        for k in c.block.coupling {
            assert!(close(k, lin), "{k} vs {lin}");
        }
        for s in c.block.row_sum {
            assert!(close(s, 4.0 * lin));
        }
    }
}
