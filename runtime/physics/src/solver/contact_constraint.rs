//! [`ContactConstraint`]: soft non-penetration per point, Coulomb friction and twist
//! friction at the manifold centre, restitution.

use glam::Vec3;

use super::body_state::BodyState;
use super::softness::Softness;
use super::solver_body::SolverBody;

/// Inverse mass and world inverse inertia of one body (what effective masses need).
#[derive(Clone, Copy)]
struct MassView {
    inv_mass: Vec3,
    inv_i: glam::Mat3,
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
    /// Normal relative velocity at step start (for restitution), m/s.
    pub relative_velocity: f32,
    /// Distance from the manifold centre in the contact plane (twist friction lever), m.
    pub twist_lever: f32,
    /// Angular Jacobians `r × n` for A and B (fixed for the step).
    pub rn_a: Vec3,
    pub rn_b: Vec3,
    /// The same premultiplied by each body's world inverse inertia.
    pub irn_a: Vec3,
    pub irn_b: Vec3,
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
    pub rt_a: [Vec3; 2],
    pub rt_b: [Vec3; 2],
    /// The same premultiplied by each body's world inverse inertia.
    pub irt_a: [Vec3; 2],
    pub irt_b: [Vec3; 2],
    /// World inverse inertia times the normal, for A and B (twist).
    pub in_a: Vec3,
    pub in_b: Vec3,
}

/// One manifold as a solver constraint.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ContactConstraint {
    pub body_a: u32,
    pub body_b: u32,
    pub normal: Vec3,
    pub tangent: [Vec3; 2],
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
}

/// Inverse effective mass `k = J M⁻¹ Jᵀ` along `dir` at offsets `ra`, `rb`.
#[inline]
fn inverse_effective_mass(a: &MassView, b: &MassView, ra: Vec3, rb: Vec3, dir: Vec3) -> f32 {
    let rna = ra.cross(dir);
    let rnb = rb.cross(dir);
    dir.dot(a.inv_mass * dir)
        + dir.dot(b.inv_mass * dir)
        + rna.dot(a.inv_i * rna)
        + rnb.dot(b.inv_i * rnb)
}

#[inline]
fn effective_mass(a: &MassView, b: &MassView, ra: Vec3, rb: Vec3, dir: Vec3) -> f32 {
    let k = inverse_effective_mass(a, b, ra, rb, dir);
    if k > 0.0 {
        1.0 / k
    } else {
        0.0
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
fn friction_masses(
    a: &MassView,
    b: &MassView,
    ra: Vec3,
    rb: Vec3,
    t: [Vec3; 2],
) -> ([f32; 3], f32) {
    let k11 = inverse_effective_mass(a, b, ra, rb, t[0]);
    let k22 = inverse_effective_mass(a, b, ra, rb, t[1]);
    let (ra1, ra2, rb1, rb2) = (
        ra.cross(t[0]),
        ra.cross(t[1]),
        rb.cross(t[0]),
        rb.cross(t[1]),
    );
    let k12 = t[0].dot(a.inv_mass * t[1])
        + t[0].dot(b.inv_mass * t[1])
        + ra1.dot(a.inv_i * ra2)
        + rb1.dot(b.inv_i * rb2);
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
    anchors: &[(Vec3, Vec3)],
    bodies: &[SolverBody],
    states: &[BodyState],
    friction_s: f32,
    friction_d: f32,
    static_speed: f32,
) {
    let (sa, sb) = (&states[c.body_a as usize], &states[c.body_b as usize]);
    let a = &MassView {
        inv_mass: sa.inv_mass,
        inv_i: bodies[c.body_a as usize].inv_i,
    };
    let b = &MassView {
        inv_mass: sb.inv_mass,
        inv_i: bodies[c.body_b as usize].inv_i,
    };
    let n = c.normal;
    let inv_count = 1.0 / anchors.len().max(1) as f32;
    let (mut ca, mut cb) = (Vec3::ZERO, Vec3::ZERO);
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
        cp.normal_mass = effective_mass(a, b, ra, rb, n);
        let dv = sb.v + sb.w.cross(rb) - sa.v - sa.w.cross(ra);
        cp.relative_velocity = dv.dot(n);
        let off = ra - ca;
        cp.twist_lever = (off - n * off.dot(n)).length();
        cp.max_normal_impulse = 0.0;
    }
    let f = &mut c.friction;
    for k in 0..2 {
        f.rt_a[k] = ca.cross(c.tangent[k]);
        f.rt_b[k] = cb.cross(c.tangent[k]);
        f.irt_a[k] = a.inv_i * f.rt_a[k];
        f.irt_b[k] = b.inv_i * f.rt_b[k];
    }
    (f.tangent_mass, f.slide_mass) = friction_masses(a, b, ca, cb, c.tangent);
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
    if points.len() > 1 {
        let vels = (&mut va, &mut wa, &mut vb, &mut wb);
        solve_normal_patch(c, points, (&a, &b), vels, dpn, (inv_h, use_bias, max_push));
    }
    for cp in points.iter_mut() {
        let s = cp.base_separation + dpn + b.dtheta.dot(cp.rn_b) - a.dtheta.dot(cp.rn_a);
        let (bias, mass_scale, impulse_scale) = if s > 0.0 {
            (s * inv_h, 1.0, 0.0)
        } else if use_bias {
            // No dead zone (as in Box2D v3 and rapier): a resting contact settles at the
            // soft spring's static deflection (m·g / (m_eff·ω²), ~0.07 mm for a body on the
            // ground at the default 60 Hz static stiffness), not one linear slop deep.
            (
                (c.softness.bias_rate * s).max(-max_push),
                c.softness.mass_scale,
                c.softness.impulse_scale,
            )
        } else {
            (0.0, 1.0, 0.0)
        };
        let vn = (vb - va).dot(n) + wb.dot(cp.rn_b) - wa.dot(cp.rn_a);
        let imp = -cp.normal_mass * mass_scale * (vn + bias) - impulse_scale * cp.normal_impulse;
        let new = (cp.normal_impulse + imp).max(0.0);
        let imp = new - cp.normal_impulse;
        cp.normal_impulse = new;
        cp.max_normal_impulse = cp.max_normal_impulse.max(imp);
        let p = n * imp;
        va -= a.inv_mass * p;
        wa -= cp.irn_a * imp;
        vb += b.inv_mass * p;
        wb += cp.irn_b * imp;
    }
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
        // Twist about the normal.
        let limit = f.friction * twist_limit;
        let wt = (wb - wa).dot(n);
        let l = (f.twist_impulse - f.twist_mass * wt).clamp(-limit, limit);
        let d = l - f.twist_impulse;
        f.twist_impulse = l;
        wa -= f.in_a * d;
        wb += f.in_b * d;
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
#[inline]
fn solve_normal_patch(
    c: &ContactConstraint,
    points: &mut [ConstraintPoint],
    (a, b): (&BodyState, &BodyState),
    (va, wa, vb, wb): (&mut Vec3, &mut Vec3, &mut Vec3, &mut Vec3),
    dpn: f32,
    (inv_h, use_bias, max_push): (f32, bool, f32),
) {
    let n = c.normal;
    let (mass_scale, impulse_scale) = if use_bias {
        (c.softness.mass_scale, c.softness.impulse_scale)
    } else {
        (1.0, 0.0)
    };
    let (mut residual, mut compliance, mut min_impulse) = (0.0, 0.0, f32::MAX);
    let (mut rn_a, mut rn_b, mut irn_a, mut irn_b) =
        (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
    for cp in points.iter() {
        let s = cp.base_separation + dpn + b.dtheta.dot(cp.rn_b) - a.dtheta.dot(cp.rn_a);
        if cp.normal_mass <= 0.0 {
            return;
        }
        // The row each point has in the per-point pass: speculative (rigid, may not
        // approach closer than touching by the end of the substep) or soft.
        let (bias, c_i) = if s > 0.0 {
            (s * inv_h, 0.0)
        } else if use_bias {
            (
                (c.softness.bias_rate * s).max(-max_push),
                // Compliance of the soft row: d(residual)/dλ beyond the mechanical part.
                impulse_scale / (mass_scale * cp.normal_mass),
            )
        } else {
            (0.0, 0.0)
        };
        let vn = (*vb - *va).dot(n) + wb.dot(cp.rn_b) - wa.dot(cp.rn_a);
        residual += vn + bias + c_i * cp.normal_impulse;
        compliance += c_i;
        min_impulse = min_impulse.min(cp.normal_impulse);
        rn_a += cp.rn_a;
        rn_b += cp.rn_b;
        irn_a += cp.irn_a;
        irn_b += cp.irn_b;
    }
    let count = points.len() as f32;
    let inv = 1.0 / count;
    let (rn_a, rn_b, irn_a, irn_b) = (rn_a * inv, rn_b * inv, irn_a * inv, irn_b * inv);
    // The mean residual moves by `k` per unit of total impulse shared equally.
    let k = n.dot(a.inv_mass * n)
        + n.dot(b.inv_mass * n)
        + rn_a.dot(irn_a)
        + rn_b.dot(irn_b)
        + compliance * inv * inv;
    if k <= 0.0 {
        return;
    }
    // No point's accumulated impulse may go below zero.
    let total = (-(residual * inv) / k).max(-count * min_impulse);
    let each = total * inv;
    for cp in points.iter_mut() {
        cp.normal_impulse += each;
        cp.max_normal_impulse = cp.max_normal_impulse.max(each);
    }
    let p = n * total;
    *va -= a.inv_mass * p;
    *wa -= irn_a * total;
    *vb += b.inv_mass * p;
    *wb += irn_b * total;
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
