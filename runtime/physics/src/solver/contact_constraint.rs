//! [`ContactConstraint`]: soft non-penetration per point, Coulomb friction and twist
//! friction at the manifold centre, restitution.

use glam::{Mat3A, Vec3A};

use super::body_state::BodyState;
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
    /// Normal relative velocity at step start (for restitution), m/s.
    pub relative_velocity: f32,
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

/// Slot of the coupling between points `i < j` in [`NormalBlock::coupling`].
const PAIR_SLOT: [[usize; 4]; 4] = [[0, 0, 1, 2], [0, 0, 3, 4], [1, 3, 0, 5], [2, 4, 5, 0]];

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

/// One manifold as a solver constraint.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ContactConstraint {
    pub body_a: u32,
    pub body_b: u32,
    pub normal: Vec3A,
    pub tangent: [Vec3A; 2],
    pub restitution: f32,
    pub softness: Softness,
    /// First point in the shared point array (points live apart so that one-point
    /// manifolds do not drag four points' worth of memory through the cache).
    pub first: u32,
    pub count: u8,
    /// Pair and manifold index, to store impulses back.
    pub pair: u32,
    pub manifold: u32,
    /// Friction at the manifold centre.
    pub friction: FrictionPart,
    /// The normal rows as a block.
    pub block: NormalBlock,
}

/// `max(floor, x)` where only `x` may be NaN (then `floor`, as `f32::max` gives): a plain
/// compare, since `f32::max` spends three extra instructions on NaN handling in the solver's
/// innermost loop.
#[inline(always)]
fn fmax(floor: f32, x: f32) -> f32 {
    if x > floor {
        x
    } else {
        floor
    }
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
    let a = &MassView {
        inv_mass: sa.inv_mass,
        inv_i: Mat3A::from(bodies[c.body_a as usize].inv_i),
    };
    let b = &MassView {
        inv_mass: sb.inv_mass,
        inv_i: Mat3A::from(bodies[c.body_b as usize].inv_i),
    };
    let n = c.normal;
    let inv_count = 1.0 / anchors.len().max(1) as f32;
    let (mut ca, mut cb) = (Vec3A::ZERO, Vec3A::ZERO);
    for &(ra, rb) in anchors {
        ca += ra;
        cb += rb;
    }
    ca *= inv_count;
    cb *= inv_count;
    for (cp, &(ra, rb)) in points.iter_mut().zip(anchors) {
        cp.rn_a = ra.cross(n);
        cp.rn_b = rb.cross(n);
        cp.irn_a = a.inv_i * cp.rn_a;
        cp.irn_b = b.inv_i * cp.rn_b;
        // `J M⁻¹ Jᵀ` from the Jacobians just computed (the same products, not recomputed).
        let k = n.dot(a.inv_mass * n)
            + n.dot(b.inv_mass * n)
            + cp.rn_a.dot(cp.irn_a)
            + cp.rn_b.dot(cp.irn_b);
        cp.inv_normal_mass = k;
        cp.normal_mass = if k > 0.0 { 1.0 / k } else { 0.0 };
        let dv = sb.v + sb.w.cross(rb) - sa.v - sa.w.cross(ra);
        cp.relative_velocity = dv.dot(n);
        let off = ra - ca;
        cp.twist_lever = (off - n * off.dot(n)).length();
        cp.max_normal_impulse = 0.0;
    }
    let count = anchors.len().min(points.len()).min(4);
    let block = &mut c.block;
    *block = NormalBlock::default();
    let k_lin = n.dot(a.inv_mass * n) + n.dot(b.inv_mass * n);
    for i in 0..count {
        block.row_sum[i] += points[i].inv_normal_mass;
        for j in i + 1..count {
            let (pi, pj) = (&points[i], &points[j]);
            let k = k_lin + pi.rn_a.dot(pj.irn_a) + pi.rn_b.dot(pj.irn_b);
            block.coupling[PAIR_SLOT[i][j]] = k;
            block.row_sum[i] += k;
            block.row_sum[j] += k;
        }
    }
    if count > 1 && points[..count].iter().all(|cp| cp.normal_mass > 0.0) {
        let sum: f32 = block.row_sum[..count].iter().sum();
        block.patch_k = sum / (count * count) as f32;
        block.patch = block.patch_k > 0.0;
    }
    let f = &mut c.friction;
    for k in 0..2 {
        f.rt_a[k] = ca.cross(c.tangent[k]);
        f.rt_b[k] = cb.cross(c.tangent[k]);
        f.irt_a[k] = a.inv_i * f.rt_a[k];
        f.irt_b[k] = b.inv_i * f.rt_b[k];
    }
    (f.tangent_mass, f.slide_mass) = friction_masses(a, b, f, c.tangent);
    f.in_a = a.inv_i * n;
    f.in_b = b.inv_i * n;
    let kt = n.dot(f.in_a) + n.dot(f.in_b);
    f.twist_mass = if kt > 0.0 { 1.0 / kt } else { 0.0 };
    let dv = sb.v + sb.w.cross(cb) - sa.v - sa.w.cross(ca);
    let slip = (dv - n * dv.dot(n)).length();
    f.friction = if slip < static_speed {
        friction_s
    } else {
        friction_d
    };
}

/// Re-applies last step's impulses.
pub(crate) fn warm_start(
    c: &ContactConstraint,
    points: &[ConstraintPoint],
    bodies: &mut [BodyState],
) {
    let (ia, ib) = (c.body_a as usize, c.body_b as usize);
    let f = &c.friction;
    let (t1, t2) = (f.tangent_impulse[0], f.tangent_impulse[1]);
    let mut p = c.tangent[0] * t1 + c.tangent[1] * t2;
    let mut wa = f.irt_a[0] * t1 + f.irt_a[1] * t2 + f.in_a * f.twist_impulse;
    let mut wb = f.irt_b[0] * t1 + f.irt_b[1] * t2 + f.in_b * f.twist_impulse;
    for cp in points {
        p += c.normal * cp.normal_impulse;
        wa += cp.irn_a * cp.normal_impulse;
        wb += cp.irn_b * cp.normal_impulse;
    }
    if ia != 0 {
        let a = &mut bodies[ia];
        a.v -= a.inv_mass * p;
        a.w -= wa;
    }
    if ib != 0 {
        let b = &mut bodies[ib];
        b.v += b.inv_mass * p;
        b.w += wb;
    }
}

/// One Gauss–Seidel pass over the constraint. `use_bias` enables the soft position
/// correction (solve phase); without it only speculative bias remains (relax phase).
pub(crate) fn solve(
    c: &mut ContactConstraint,
    points: &mut [ConstraintPoint],
    bodies: &mut [BodyState],
    inv_h: f32,
    use_bias: bool,
    max_push: f32,
) {
    let (ia, ib) = (c.body_a as usize, c.body_b as usize);
    let (a, b) = (bodies[ia], bodies[ib]);
    let (mut va, mut wa, mut vb, mut wb) = (a.v, a.w, b.v, b.w);
    let n = c.normal;
    // Linearised current separation: base + n·(Δp_b − Δp_a) + Δθ_b·(r_b×n) − Δθ_a·(r_a×n).
    let dpn = (b.dp - a.dp).dot(n);
    let dvn = (vb - va).dot(n);
    let pass = NormalPass {
        dpn,
        dvn,
        inv_h,
        use_bias,
        max_push,
    };
    let (total, da, db) = solve_normal_any(c, points, (&a, &b), (wa, wb), &pass);
    let p = n * total;
    va -= a.inv_mass * p;
    wa -= da;
    vb += b.inv_mass * p;
    wb += db;
    // Friction at the manifold centre, bounded by the current normal impulses.
    let (mut total, mut twist_limit) = (0.0f32, 0.0f32);
    for cp in points.iter() {
        total += cp.normal_impulse;
        twist_limit += cp.normal_impulse * cp.twist_lever;
    }
    let f = &mut c.friction;
    let max_f = f.friction * total;
    if max_f > 0.0 || f.tangent_impulse != [0.0, 0.0] || f.twist_impulse != 0.0 {
        let (t1, t2) = (c.tangent[0], c.tangent[1]);
        let dv = vb - va;
        let vt1 = dv.dot(t1) + wb.dot(f.rt_b[0]) - wa.dot(f.rt_a[0]);
        let vt2 = dv.dot(t2) + wb.dot(f.rt_b[1]) - wa.dot(f.rt_a[1]);
        let m = f.tangent_mass;
        let l1 = f.tangent_impulse[0] - (m[0] * vt1 + m[1] * vt2);
        let l2 = f.tangent_impulse[1] - (m[1] * vt1 + m[2] * vt2);
        let (l1, l2) = if l1 * l1 + l2 * l2 > max_f * max_f {
            // Sliding: the isotropic mass keeps the impulse against the slip.
            let l1 = f.tangent_impulse[0] - f.slide_mass * vt1;
            let l2 = f.tangent_impulse[1] - f.slide_mass * vt2;
            let len2 = l1 * l1 + l2 * l2;
            if len2 > max_f * max_f {
                let s = if len2 > 0.0 { max_f / len2.sqrt() } else { 0.0 };
                (l1 * s, l2 * s)
            } else {
                (l1, l2)
            }
        } else {
            (l1, l2)
        };
        let d1 = l1 - f.tangent_impulse[0];
        let d2 = l2 - f.tangent_impulse[1];
        f.tangent_impulse = [l1, l2];
        let p = t1 * d1 + t2 * d2;
        va -= a.inv_mass * p;
        wa -= f.irt_a[0] * d1 + f.irt_a[1] * d2;
        vb += b.inv_mass * p;
        wb += f.irt_b[0] * d1 + f.irt_b[1] * d2;
        // Twist about the normal (nothing to do for a single point: no lever, no impulse).
        if twist_limit != 0.0 || f.twist_impulse != 0.0 {
            let limit = f.friction * twist_limit;
            let wt = (wb - wa).dot(n);
            let l = (f.twist_impulse - f.twist_mass * wt).clamp(-limit, limit);
            let d = l - f.twist_impulse;
            f.twist_impulse = l;
            wa -= f.in_a * d;
            wb += f.in_b * d;
        }
    }
    if ia != 0 {
        bodies[ia].v = va;
        bodies[ia].w = wa;
    }
    if ib != 0 {
        bodies[ib].v = vb;
        bodies[ib].w = wb;
    }
}

/// What the normal rows of one pass share.
struct NormalPass {
    /// `n·(Δp_b − Δp_a)`.
    dpn: f32,
    /// `n·(v_b − v_a)` at the start of the pass.
    dvn: f32,
    inv_h: f32,
    use_bias: bool,
    max_push: f32,
}

/// The normal rows of a manifold of 1–4 points, dispatched to the fixed-size version.
/// Returns the impulse applied along the normal and its angular parts for A and B
/// (`Σ λ·I⁻¹(r×n)`), for the caller to apply to the velocities.
#[inline(always)]
fn solve_normal_any(
    c: &ContactConstraint,
    points: &mut [ConstraintPoint],
    bodies: (&BodyState, &BodyState),
    w: (Vec3A, Vec3A),
    pass: &NormalPass,
) -> (f32, Vec3A, Vec3A) {
    match points {
        [p0] => solve_normal::<1>(c, std::array::from_mut(p0), bodies, w, pass),
        [_, _] | [_, _, _] | [_, _, _, _] => {
            if let Ok(p) = <&mut [ConstraintPoint; 4]>::try_from(&mut *points) {
                solve_normal(c, p, bodies, w, pass)
            } else if let Ok(p) = <&mut [ConstraintPoint; 2]>::try_from(&mut *points) {
                solve_normal(c, p, bodies, w, pass)
            } else if let Ok(p) = <&mut [ConstraintPoint; 3]>::try_from(&mut *points) {
                solve_normal(c, p, bodies, w, pass)
            } else {
                (0.0, Vec3A::ZERO, Vec3A::ZERO)
            }
        }
        _ => (0.0, Vec3A::ZERO, Vec3A::ZERO),
    }
}

/// The normal rows of an `N`-point manifold: the shared step, then one Gauss–Seidel sweep
/// over the points. Velocities are tracked as the points' normal relative velocities through
/// the block's coupling (`K_ij`), all from one start-of-pass evaluation, so the sweep is a
/// short scalar chain; the summed impulses are returned for the bodies.
#[inline(always)]
fn solve_normal<const N: usize>(
    c: &ContactConstraint,
    points: &mut [ConstraintPoint; N],
    (a, b): (&BodyState, &BodyState),
    (wa, wb): (Vec3A, Vec3A),
    pass: &NormalPass,
) -> (f32, Vec3A, Vec3A) {
    // Current separations and normal velocities, all from the start-of-pass state.
    let (mut sep, mut vn) = ([0.0f32; N], [0.0f32; N]);
    for k in 0..N {
        let cp = &points[k];
        sep[k] = cp.base_separation + pass.dpn + b.dtheta.dot(cp.rn_b) - a.dtheta.dot(cp.rn_a);
        vn[k] = pass.dvn + wb.dot(cp.rn_b) - wa.dot(cp.rn_a);
    }
    // Impulse applied to each point in this pass (shared step and per-point), for the bodies.
    let mut applied = [0.0f32; N];
    if N > 1 && c.block.patch {
        solve_normal_patch(c, points, &sep, &mut vn, &mut applied, pass);
    }
    let block = &c.block;
    for j in 0..N {
        let cp = &mut points[j];
        let s = sep[j];
        let (bias, mass_scale, impulse_scale) = if s > 0.0 {
            (s * pass.inv_h, 1.0, 0.0)
        } else if pass.use_bias {
            // No dead zone (as in Box2D v3 and rapier): a resting contact settles at the
            // soft spring's static deflection (m·g / (m_eff·ω²), ~0.07 mm for a body on the
            // ground at the default 60 Hz static stiffness), not one linear slop deep.
            (
                fmax(-pass.max_push, c.softness.bias_rate * s),
                c.softness.mass_scale,
                c.softness.impulse_scale,
            )
        } else {
            (0.0, 1.0, 0.0)
        };
        let imp = -cp.normal_mass * mass_scale * (vn[j] + bias) - impulse_scale * cp.normal_impulse;
        let new = fmax(0.0, cp.normal_impulse + imp);
        let imp = new - cp.normal_impulse;
        cp.normal_impulse = new;
        cp.max_normal_impulse = fmax(cp.max_normal_impulse, imp);
        applied[j] += imp;
        // The later points see this impulse through the coupling.
        for i in j + 1..N {
            vn[i] += block.coupling[PAIR_SLOT[j][i]] * imp;
        }
    }
    let mut total = 0.0f32;
    let (mut da, mut db) = (Vec3A::ZERO, Vec3A::ZERO);
    for k in 0..N {
        total += applied[k];
        da += points[k].irn_a * applied[k];
        db += points[k].irn_b * applied[k];
    }
    (total, da, db)
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
fn solve_normal_patch<const N: usize>(
    c: &ContactConstraint,
    points: &mut [ConstraintPoint; N],
    sep: &[f32; N],
    vn: &mut [f32; N],
    applied: &mut [f32; N],
    pass: &NormalPass,
) {
    // Compliance of a soft row is `impulse_scale / (mass_scale · m)`: d(residual)/dλ beyond
    // the mechanical part.
    let soft_c = if pass.use_bias {
        c.softness.impulse_scale / c.softness.mass_scale
    } else {
        0.0
    };
    let (mut residual, mut compliance, mut min_impulse) = (0.0, 0.0, f32::MAX);
    for k in 0..N {
        let (cp, s) = (&points[k], sep[k]);
        // The row each point has in the per-point pass: speculative (rigid, may not
        // approach closer than touching by the end of the substep) or soft.
        let (bias, c_i) = if s > 0.0 {
            (s * pass.inv_h, 0.0)
        } else if pass.use_bias {
            (
                fmax(-pass.max_push, c.softness.bias_rate * s),
                soft_c * cp.inv_normal_mass,
            )
        } else {
            (0.0, 0.0)
        };
        residual += vn[k] + bias + c_i * cp.normal_impulse;
        compliance += c_i;
        min_impulse = if cp.normal_impulse < min_impulse {
            cp.normal_impulse
        } else {
            min_impulse
        };
    }
    let count = N as f32;
    let inv = 1.0 / count;
    // The mean residual moves by `k` per unit of total impulse shared equally.
    let k = c.block.patch_k + compliance * inv * inv;
    // No point's accumulated impulse may go below zero.
    let total = fmax(-count * min_impulse, -(residual * inv) / k);
    let each = total * inv;
    for k in 0..N {
        let cp = &mut points[k];
        cp.normal_impulse += each;
        cp.max_normal_impulse = fmax(cp.max_normal_impulse, each);
        applied[k] += each;
        vn[k] += each * c.block.row_sum[k];
    }
}

/// Restitution pass after substepping: points that approached faster than `threshold`
/// and carried load get a separating velocity `e · |approach speed|`.
pub(crate) fn apply_restitution(
    c: &ContactConstraint,
    points: &mut [ConstraintPoint],
    bodies: &mut [BodyState],
    threshold: f32,
) {
    if c.restitution <= 0.0 {
        return;
    }
    let (ia, ib) = (c.body_a as usize, c.body_b as usize);
    let n = c.normal;
    for slot in points.iter_mut() {
        let cp = *slot;
        if cp.relative_velocity > -threshold || cp.max_normal_impulse <= 0.0 {
            continue;
        }
        let (a, b) = (bodies[ia], bodies[ib]);
        let vn = (b.v - a.v).dot(n) + b.w.dot(cp.rn_b) - a.w.dot(cp.rn_a);
        let imp = -cp.normal_mass * (vn + c.restitution * cp.relative_velocity);
        let new = (cp.normal_impulse + imp).max(0.0);
        let imp = new - cp.normal_impulse;
        slot.normal_impulse = new;
        slot.max_normal_impulse = cp.max_normal_impulse.max(imp);
        if ia != 0 {
            bodies[ia].v -= a.inv_mass * (n * imp);
            bodies[ia].w -= cp.irn_a * imp;
        }
        if ib != 0 {
            bodies[ib].v += b.inv_mass * (n * imp);
            bodies[ib].w += cp.irn_b * imp;
        }
    }
}
