//! [`V3`]: a 3-vector over four lanes (structure of arrays), and moving body velocities
//! between [`BodyState`]s and lanes. The contact solver works on four manifolds at once, one
//! per lane, none of them sharing a body it writes (see [`super::contact_batch`]).

use std::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

use glam::{Mat3A, Vec3A};
use wide::f32x4;

use super::body_state::BodyState;

/// Four `f32` lanes.
pub(crate) type F = f32x4;

/// Manifolds solved together.
pub(crate) const LANES: usize = 4;

/// Velocity components (m/s, rad/s) smaller than this are written back as zero by the
/// batches that hold a column face (see `ContactBatch::solve`). A column's passes drive the
/// sideways and twisting rounding of a settled, centred stack towards zero geometrically,
/// into subnormal floats, and each product with one is a microcode assist on x86: the
/// 20-box stack at 60 Hz × 4 cost 0.124 ms a step, 0.061 ms with the processor flushing
/// subnormals (which Rust code may not switch on: its optimiser assumes the default
/// floating-point environment), 0.074 ms flushed here (0.069 ms flushed in every batch,
/// which cost the 20-row pyramid, with no columns, 3 %). 1e-20 m/s moves a body a metre in
/// 3·10¹² years; its products with masses, levers and compliances stay normal floats.
pub const TINY_SPEED: f32 = 1e-20;

/// One 3-vector per lane.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct V3 {
    pub x: F,
    pub y: F,
    pub z: F,
}

impl V3 {
    pub const ZERO: Self = Self {
        x: F::ZERO,
        y: F::ZERO,
        z: F::ZERO,
    };

    /// Each component smaller than `tiny` in magnitude set to zero.
    #[inline(always)]
    pub fn flush(self, tiny: F) -> Self {
        let f = |x: F| tiny.simd_gt(x.abs()).select(F::ZERO, x);
        Self {
            x: f(self.x),
            y: f(self.y),
            z: f(self.z),
        }
    }

    /// Lane `l` holds `v[l]` (a 4×4 transpose).
    #[inline(always)]
    pub fn from_lanes(v: [Vec3A; LANES]) -> Self {
        let [x, y, z, _] = F::transpose(v.map(|v| F::new(v.extend(0.0).to_array())));
        Self { x, y, z }
    }

    /// `v` in every lane.
    #[inline(always)]
    pub fn splat(v: Vec3A) -> Self {
        Self {
            x: F::splat(v.x),
            y: F::splat(v.y),
            z: F::splat(v.z),
        }
    }

    /// Lane by lane `self × o`.
    #[inline(always)]
    pub fn cross(self, o: Self) -> Self {
        Self {
            x: self.y * o.z - self.z * o.y,
            y: self.z * o.x - self.x * o.z,
            z: self.x * o.y - self.y * o.x,
        }
    }

    /// `m` times the vector of each lane.
    #[inline(always)]
    pub fn transformed(self, m: &Mat3A) -> Self {
        let (cx, cy, cz) = (
            Self::splat(m.x_axis),
            Self::splat(m.y_axis),
            Self::splat(m.z_axis),
        );
        Self {
            x: cx.x * self.x + cy.x * self.y + cz.x * self.z,
            y: cx.y * self.x + cy.y * self.y + cz.y * self.z,
            z: cx.z * self.x + cy.z * self.y + cz.z * self.z,
        }
    }

    /// Sets lane `l` to `v`.
    #[inline(always)]
    pub fn set(&mut self, l: usize, v: Vec3A) {
        self.x.as_mut_array()[l] = v.x;
        self.y.as_mut_array()[l] = v.y;
        self.z.as_mut_array()[l] = v.z;
    }

    /// The vector in each lane.
    #[inline(always)]
    pub fn to_lanes(self) -> [Vec3A; LANES] {
        F::transpose([self.x, self.y, self.z, F::ZERO]).map(|c| {
            let [x, y, z, _] = c.to_array();
            Vec3A::new(x, y, z)
        })
    }

    #[inline(always)]
    pub fn dot(self, o: Self) -> F {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Each lane scaled by its own factor.
    #[inline(always)]
    pub fn scale(self, s: F) -> Self {
        Self {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }
}

impl Add for V3 {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

impl Sub for V3 {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

/// Component-wise product (per-axis inverse masses).
impl Mul for V3 {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        Self {
            x: self.x * o.x,
            y: self.y * o.y,
            z: self.z * o.z,
        }
    }
}

impl Neg for V3 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self {
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }
}

impl AddAssign for V3 {
    #[inline(always)]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

impl SubAssign for V3 {
    #[inline(always)]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}

/// Velocities of the bodies on one side of four manifolds.
#[derive(Clone, Copy)]
pub(crate) struct Velocities {
    pub v: V3,
    pub w: V3,
}

impl Velocities {
    /// Each component smaller than [`TINY_SPEED`] in magnitude set to zero.
    #[inline(always)]
    pub fn flush_tiny(self) -> Self {
        let tiny = F::splat(TINY_SPEED);
        Self {
            v: self.v.flush(tiny),
            w: self.w.flush(tiny),
        }
    }
}

/// Reads one field (`field(state)`) of `bodies[l]` into lane `l`.
#[inline(always)]
pub(crate) fn gather(
    states: &[BodyState],
    bodies: &[u32; LANES],
    field: impl Fn(&BodyState) -> Vec3A,
) -> V3 {
    V3::from_lanes(bodies.map(|i| field(&states[i as usize])))
}

/// Reads the velocities of `bodies[l]` into lane `l`.
#[inline(always)]
pub(crate) fn gather_velocities(states: &[BodyState], bodies: &[u32; LANES]) -> Velocities {
    Velocities {
        v: gather(states, bodies, |s| s.v),
        w: gather(states, bodies, |s| s.w),
    }
}

/// Reads the position deltas (`dp`, `dθ`) of `bodies[l]` into lane `l`.
#[inline(always)]
pub(crate) fn gather_deltas(states: &[BodyState], bodies: &[u32; LANES]) -> (V3, V3) {
    (
        gather(states, bodies, |s| s.dp),
        gather(states, bodies, |s| s.dtheta),
    )
}

/// [`scatter_velocities`] for bodies that do not rotate: only the linear velocity.
#[inline(always)]
pub(crate) fn scatter_linear_velocities(
    states: &mut [BodyState],
    bodies: &[u32; LANES],
    writes: u8,
    v: V3,
) {
    let v = v.to_lanes();
    for l in 0..LANES {
        if writes & (1 << l) != 0 {
            states[bodies[l] as usize].v = v[l];
        }
    }
}

/// Writes lane `l` back to `bodies[l]` where bit `l` of `writes` is set (dynamic bodies; the
/// others' velocities do not change, and several lanes may share them).
#[inline(always)]
pub(crate) fn scatter_velocities(
    states: &mut [BodyState],
    bodies: &[u32; LANES],
    writes: u8,
    vel: Velocities,
) {
    let (v, w) = (vel.v.to_lanes(), vel.w.to_lanes());
    for l in 0..LANES {
        if writes & (1 << l) != 0 {
            let s = &mut states[bodies[l] as usize];
            s.v = v[l];
            s.w = w[l];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_round_trip_and_their_arithmetic_matches_glam() {
        let a = [
            Vec3A::new(1.0, 2.0, 3.0),
            Vec3A::new(-4.0, 5.5, 0.25),
            Vec3A::new(0.0, -1.0, 9.0),
            Vec3A::new(7.0, 0.5, -2.0),
        ];
        let b = a.map(|v| Vec3A::new(v.z, v.y, v.x) * 0.5 - Vec3A::ONE);
        let (va, vb) = (V3::from_lanes(a), V3::from_lanes(b));
        assert_eq!(va.to_lanes(), a);
        let dots = va.dot(vb).to_array();
        for l in 0..LANES {
            assert_eq!(dots[l], a[l].dot(b[l]));
        }
        assert_eq!((va * vb - vb).to_lanes()[2], a[2] * b[2] - b[2]);
        let m = Mat3A::from_cols_array(&[1.0, -2.0, 0.5, 3.0, 0.25, -1.0, 4.0, 2.0, -0.75]);
        let (cross, product) = (va.cross(vb).to_lanes(), va.transformed(&m).to_lanes());
        for l in 0..LANES {
            assert!((cross[l] - a[l].cross(b[l])).abs().max_element() <= 1e-5);
            assert!((product[l] - m * a[l]).abs().max_element() <= 1e-5);
            assert_eq!(V3::splat(a[l]).to_lanes(), [a[l]; LANES]);
        }
    }
}
