//! [`free_rotation_step`]: one substep of torque-free rotation by the implicit midpoint
//! rule on Euler's equations, with the Cayley rotation that goes with it.
//!
//! Euler's equations in the body frame, `I ω̇ + ω × I ω = 0`, have two quadratic invariants:
//! the kinetic energy `½ ω·Iω` and `|Iω|²` (the size of the angular momentum). The implicit
//! midpoint rule keeps every quadratic invariant of an ODE exactly, so a body tumbling about
//! any axis, the unstable intermediate one included, keeps its energy and `|L|` to rounding
//! at any step size. Integrating the orientation with the Cayley transform of `h·ω_mid` (not
//! the exponential) then keeps the world angular momentum `L = R I ω` exactly too:
//! the midpoint equation `(1 + h/2·[ω_mid]×) Π₁ = (1 − h/2·[ω_mid]×) Π₀` for the body
//! momentum `Π = Iω` says `Π₀ = cay(h·[ω_mid]×) Π₁`, so `R₁ = R₀ cay(h·[ω_mid]×)` gives
//! `R₁Π₁ = R₀Π₀`. (This is the energy-conserving variant of the implicit gyroscopic
//! integration of Box2D v3 / Box3D and rapier, which take one implicit-Euler Newton step and
//! so lose energy: a body spun about its intermediate axis settles on its major axis.)
//!
//! The Cayley rotation of the rotation vector `θ = h·ω_mid` is the unit quaternion along
//! `(θ/2, 1)`: a turn of `2·atan(|θ|/2)` about `θ`, which matches `|θ|` to third order.

use glam::{Mat3, Mat3A, Quat, Vec3, Vec3A};

/// Newton iterations of the midpoint equation per substep at most. Bounded `[2, 32]`: the
/// iteration converges quadratically, in 2–3 iterations while `h·|ω|` is below 1 and in
/// about 6 at the speed cap of a 30 Hz step; reaching the cap splits the substep (see
/// [`free_rotation_step`]), and a piece that misses at the last split keeps its last iterate
/// (energy then kept to the remaining residual), counted in `StepCounters::gyro_not_converged`.
pub const FREE_ROTATION_MAX_ITERATIONS: u32 = 16;

/// The Newton iteration stops when a step changes `ω_mid` by less than this fraction of
/// `|ω₀|`. Bounded `[1e-7, 1e-4]`: f32 rounding sits near 1e-7, larger values leave energy
/// errors of about this size per substep.
pub const FREE_ROTATION_TOLERANCE: f32 = 1e-6;

/// Levels a substep whose Newton iteration misses its tolerance is halved at most (see
/// [`free_rotation_step`]): up to 2⁶ = 64 pieces. Bounded `[0, ∞)`: each level halves
/// `h·|ω|`, and the iteration converges from below about two radians a substep.
pub const FREE_ROTATION_MAX_SPLITS: u32 = 6;

/// Turn per substep, rad, below which a substep is not split (see [`free_rotation_step`]):
/// there the iteration converges, and where it misses, the miss is rounding (a body at rest
/// turning by noise, `|ω|` of 1e-30 rad/s), which halving does not mend: split, each such
/// body took 127 midpoint solves a substep, and the size ladder cost 6 times as much.
/// Bounded `(0, 2]`.
pub const FREE_ROTATION_SPLIT_TURN: f32 = 0.5;

/// Result of [`free_rotation_step`].
///
/// The vectors are [`Vec3A`], all four lanes set: as `Vec3` beside `converged`, the rotation
/// vector was read back with one 16-byte load whose fourth lane was that flag's byte and
/// the padding after it (with the padding zero, the denormal 1.4e-45), and each substep's
/// arithmetic on it took a microcode assist: after a code layout change elsewhere a tumbling
/// box cost twice as much (`rotation_energy` 0.16 → 0.32 ms per simulated second at
/// balanced, the bridge's planks 1.45×).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FreeRotationStep {
    /// Angular velocity at the end of the substep, body frame, rad/s.
    pub omega: Vec3A,
    /// Rotation over the substep, body frame (`R₁ = R₀ · rotation`).
    pub rotation: Quat,
    /// Rotation vector of the substep, body frame (`h·ω_mid`), rad.
    pub rotation_vector: Vec3A,
    /// The Newton iteration met [`FREE_ROTATION_TOLERANCE`].
    pub converged: bool,
}

/// Cross-product matrix `[v]×` (`[v]× u = v × u`).
#[inline]
fn skew(v: Vec3A) -> Mat3A {
    Mat3A::from_cols(
        Vec3A::new(0.0, v.z, -v.y),
        Vec3A::new(-v.z, 0.0, v.x),
        Vec3A::new(v.y, -v.x, 0.0),
    )
}

/// One torque-free substep of length `h` for body-frame inertia `inertia` and body-frame
/// angular velocity `omega0` (see the module docs).
///
/// Where the Newton iteration misses its tolerance (a flat body tumbling through more than
/// about two radians a substep), the substep is taken as two halves, each split again where
/// it misses, down to [`FREE_ROTATION_MAX_SPLITS`] levels: the halves' rotations compose, and
/// each half keeps the invariants as the whole would have. Not split, the last iterate was
/// kept: a 10 cm × 50 cm × 3 m board spun at 150 rad/s about its intermediate axis at 30 Hz ×
/// 2 passed 3.4 rad a substep as it flipped, and its energy grew 13-fold in 60 s.
#[must_use]
pub fn free_rotation_step(inertia: Mat3, omega0: Vec3, h: f32) -> FreeRotationStep {
    split_step(
        Mat3A::from(inertia),
        Vec3A::from(omega0),
        h,
        FREE_ROTATION_MAX_SPLITS,
    )
}

/// [`midpoint_step`], split into halves where it does not converge, `splits` levels deep.
fn split_step(inertia: Mat3A, omega0: Vec3A, h: f32, splits: u32) -> FreeRotationStep {
    let whole = midpoint_step(inertia, omega0, h);
    if whole.converged || splits == 0 || h * omega0.length() < FREE_ROTATION_SPLIT_TURN {
        return whole;
    }
    let first = split_step(inertia, omega0, 0.5 * h, splits - 1);
    let second = split_step(inertia, first.omega, 0.5 * h, splits - 1);
    FreeRotationStep {
        omega: second.omega,
        rotation: (first.rotation * second.rotation).normalize(),
        // The second half's vector is in the body frame the first half turned to.
        rotation_vector: first.rotation_vector
            + Vec3A::from(first.rotation * Vec3::from(second.rotation_vector)),
        converged: first.converged && second.converged,
    }
}

/// One midpoint substep of length `h`, not split.
fn midpoint_step(inertia: Mat3A, omega0: Vec3A, h: f32) -> FreeRotationStep {
    // Unknown x = ω_mid; ω₁ = 2x − ω₀. Residual f(x) = 2I(x − ω₀) + h·x × Ix,
    // Jacobian J = 2I + h([x]× I − [Ix]×). In `Vec3A`/`Mat3A`, whose fourth lanes hold
    // copies of real values: the compiler packs `Vec3` arithmetic into 4-lane operations
    // with whatever the fourth lane held, and a denormal there costs a microcode assist per
    // operation.
    let scale = omega0.length();
    let mut x = omega0;
    let mut converged = scale == 0.0;
    for _ in 0..FREE_ROTATION_MAX_ITERATIONS {
        if converged {
            break;
        }
        let ix = inertia * x;
        let f = 2.0 * (inertia * (x - omega0)) + h * x.cross(ix);
        let j = 2.0 * inertia + h * (skew(x) * inertia - skew(ix));
        let det = j.determinant();
        if !(det.is_finite() && det != 0.0) {
            break;
        }
        let dx = j.inverse() * f;
        x -= dx;
        converged = dx.length() <= FREE_ROTATION_TOLERANCE * scale;
    }
    let theta = h * x;
    let half = 0.5 * theta;
    let rotation = Quat::from_xyzw(half.x, half.y, half.z, 1.0).normalize();
    FreeRotationStep {
        omega: 2.0 * x - omega0,
        rotation,
        rotation_vector: theta,
        converged,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn midpoint_step_keeps_energy_and_momentum_size_at_a_large_step() {
        let inertia = Mat3::from_diagonal(Vec3::new(1.0, 2.0, 3.0));
        let w0 = Vec3::new(0.3, 20.0, 0.2);
        let r = free_rotation_step(inertia, w0, 1.0 / 30.0);
        let e = |w: Vec3| 0.5 * w.dot(inertia * w);
        let l = |w: Vec3| (inertia * w).length();
        assert!(r.converged);
        let (de, dl) = (
            e(r.omega.into()) / e(w0) - 1.0,
            l(r.omega.into()) / l(w0) - 1.0,
        );
        assert!(de.abs() < 1e-5, "energy changed by {de}, expected 0");
        assert!(dl.abs() < 1e-5, "|L| changed by {dl}, expected 0");
        // World momentum: R₁ I ω₁ = I ω₀ with R₀ = 1.
        let l1 = r.rotation * (inertia * Vec3::from(r.omega));
        let err = (l1 - inertia * w0).length() / l(w0);
        assert!(err < 1e-5, "world L moved by {err} of |L|, expected 0");
    }

    #[test]
    fn spin_about_a_principal_axis_is_a_plain_turn() {
        let inertia = Mat3::from_diagonal(Vec3::new(1.0, 2.0, 3.0));
        let r = free_rotation_step(inertia, Vec3::new(0.0, 0.0, 5.0), 0.01);
        assert!((r.omega - Vec3A::new(0.0, 0.0, 5.0)).length() < 1e-6);
        let angle = 2.0 * (0.5 * 0.05f32).atan();
        assert!((r.rotation.to_axis_angle().1 - angle).abs() < 1e-6);
    }
}
