//! [`ContactConstraint`]: soft non-penetration + Coulomb friction + restitution for one manifold.

use glam::Vec3;

use super::softness::Softness;
use super::solver_body::SolverBody;

/// Solver data of one contact point.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ConstraintPoint {
    /// Separation at step start; the current separation is this plus the normal part of the
    /// position deltas (relative quantities only, so precise far from the origin).
    pub base_separation: f32,
    /// Accumulated normal impulse, N·s.
    pub normal_impulse: f32,
    /// Accumulated friction impulse along the tangents, N·s.
    pub tangent_impulse: [f32; 2],
    /// Largest single normal impulse of the step.
    pub max_normal_impulse: f32,
    /// Effective mass along the normal.
    pub normal_mass: f32,
    /// Effective masses along the tangents.
    pub tangent_mass: [f32; 2],
    /// Normal relative velocity at step start (for restitution), m/s.
    pub relative_velocity: f32,
    /// Coulomb coefficient chosen for the step (static while sticking, else dynamic).
    pub friction: f32,
    /// Angular Jacobians `r × n`, `r × t1`, `r × t2` for A and B (fixed for the step).
    pub rn_a: Vec3,
    pub rn_b: Vec3,
    pub rt_a: [Vec3; 2],
    pub rt_b: [Vec3; 2],
    /// The same premultiplied by each body's world inverse inertia.
    pub irn_a: Vec3,
    pub irn_b: Vec3,
    pub irt_a: [Vec3; 2],
    pub irt_b: [Vec3; 2],
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
}

#[inline]
fn effective_mass(a: &SolverBody, b: &SolverBody, ra: Vec3, rb: Vec3, dir: Vec3) -> f32 {
    let rna = ra.cross(dir);
    let rnb = rb.cross(dir);
    let k = dir.dot(a.inv_mass * dir)
        + dir.dot(b.inv_mass * dir)
        + rna.dot(a.inv_i * rna)
        + rnb.dot(b.inv_i * rnb);
    if k > 0.0 {
        1.0 / k
    } else {
        0.0
    }
}

/// Fills Jacobians, masses and relative velocities from the anchors (offsets from each
/// centre of mass, world axes); call once per step before substepping.
pub(crate) fn prepare(
    c: &ContactConstraint,
    points: &mut [ConstraintPoint],
    anchors: &[(Vec3, Vec3)],
    bodies: &[SolverBody],
    friction_s: f32,
    friction_d: f32,
    static_speed: f32,
) {
    let a = &bodies[c.body_a as usize];
    let b = &bodies[c.body_b as usize];
    let n = c.normal;
    for (cp, &(ra, rb)) in points.iter_mut().zip(anchors) {
        cp.rn_a = ra.cross(n);
        cp.rn_b = rb.cross(n);
        cp.irn_a = a.inv_i * cp.rn_a;
        cp.irn_b = b.inv_i * cp.rn_b;
        for k in 0..2 {
            cp.rt_a[k] = ra.cross(c.tangent[k]);
            cp.rt_b[k] = rb.cross(c.tangent[k]);
            cp.irt_a[k] = a.inv_i * cp.rt_a[k];
            cp.irt_b[k] = b.inv_i * cp.rt_b[k];
        }
        cp.normal_mass = effective_mass(a, b, ra, rb, n);
        cp.tangent_mass = [
            effective_mass(a, b, ra, rb, c.tangent[0]),
            effective_mass(a, b, ra, rb, c.tangent[1]),
        ];
        let dv = b.v + b.w.cross(rb) - a.v - a.w.cross(ra);
        cp.relative_velocity = dv.dot(n);
        let slip = (dv - n * cp.relative_velocity).length();
        cp.friction = if slip < static_speed {
            friction_s
        } else {
            friction_d
        };
        cp.max_normal_impulse = 0.0;
    }
}

/// The fields of a solver body that the contact solve reads.
#[derive(Clone, Copy)]
struct Hot {
    v: Vec3,
    w: Vec3,
    dp: Vec3,
    dtheta: Vec3,
    inv_mass: Vec3,
}

impl Hot {
    #[inline(always)]
    fn of(b: &SolverBody) -> Self {
        Self {
            v: b.v,
            w: b.w,
            dp: b.dp,
            dtheta: b.dtheta,
            inv_mass: b.inv_mass,
        }
    }
}

/// Re-applies last step's impulses.
pub(crate) fn warm_start(
    c: &ContactConstraint,
    points: &[ConstraintPoint],
    bodies: &mut [SolverBody],
) {
    let (ia, ib) = (c.body_a as usize, c.body_b as usize);
    for cp in points {
        let p = c.normal * cp.normal_impulse
            + c.tangent[0] * cp.tangent_impulse[0]
            + c.tangent[1] * cp.tangent_impulse[1];
        let wa = cp.irn_a * cp.normal_impulse
            + cp.irt_a[0] * cp.tangent_impulse[0]
            + cp.irt_a[1] * cp.tangent_impulse[1];
        let wb = cp.irn_b * cp.normal_impulse
            + cp.irt_b[0] * cp.tangent_impulse[0]
            + cp.irt_b[1] * cp.tangent_impulse[1];
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
}

/// One Gauss–Seidel pass over the constraint. `use_bias` enables the soft position
/// correction (solve phase); without it only speculative bias remains (relax phase).
pub(crate) fn solve(
    c: &ContactConstraint,
    points: &mut [ConstraintPoint],
    bodies: &mut [SolverBody],
    inv_h: f32,
    use_bias: bool,
    slop: f32,
    max_push: f32,
) {
    let (ia, ib) = (c.body_a as usize, c.body_b as usize);
    // Copy only the hot fields (the full solver body is large).
    let a = Hot::of(&bodies[ia]);
    let b = Hot::of(&bodies[ib]);
    let (mut va, mut wa, mut vb, mut wb) = (a.v, a.w, b.v, b.w);
    let n = c.normal;
    // Linearised current separation: base + n·(Δp_b − Δp_a) + Δθ_b·(r_b×n) − Δθ_a·(r_a×n).
    let dpn = (b.dp - a.dp).dot(n);
    for cp in points.iter_mut() {
        let s = cp.base_separation + dpn + b.dtheta.dot(cp.rn_b) - a.dtheta.dot(cp.rn_a);
        let (bias, mass_scale, impulse_scale) = if s > 0.0 {
            (s * inv_h, 1.0, 0.0)
        } else if use_bias {
            let sb = (s + slop).min(0.0);
            (
                (c.softness.bias_rate * sb).max(-max_push),
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
    let (t1, t2) = (c.tangent[0], c.tangent[1]);
    for cp in points.iter_mut() {
        let dv = vb - va;
        let vt1 = dv.dot(t1) + wb.dot(cp.rt_b[0]) - wa.dot(cp.rt_a[0]);
        let vt2 = dv.dot(t2) + wb.dot(cp.rt_b[1]) - wa.dot(cp.rt_a[1]);
        let max_f = cp.friction * cp.normal_impulse;
        let l1 = cp.tangent_impulse[0] - cp.tangent_mass[0] * vt1;
        let l2 = cp.tangent_impulse[1] - cp.tangent_mass[1] * vt2;
        let len2 = l1 * l1 + l2 * l2;
        let (l1, l2) = if len2 > max_f * max_f {
            let s = max_f / len2.sqrt();
            (l1 * s, l2 * s)
        } else {
            (l1, l2)
        };
        let d1 = l1 - cp.tangent_impulse[0];
        let d2 = l2 - cp.tangent_impulse[1];
        cp.tangent_impulse = [l1, l2];
        let p = t1 * d1 + t2 * d2;
        va -= a.inv_mass * p;
        wa -= cp.irt_a[0] * d1 + cp.irt_a[1] * d2;
        vb += b.inv_mass * p;
        wb += cp.irt_b[0] * d1 + cp.irt_b[1] * d2;
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

/// Restitution pass after substepping: points that approached faster than `threshold`
/// and carried load get a separating velocity `e · |approach speed|`.
pub(crate) fn apply_restitution(
    c: &ContactConstraint,
    points: &mut [ConstraintPoint],
    bodies: &mut [SolverBody],
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
        let (a, b) = (Hot::of(&bodies[ia]), Hot::of(&bodies[ib]));
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
