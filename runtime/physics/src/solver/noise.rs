//! [`matrix_without_noise`]: rounding noise kept out of a body's world inverse inertia;
//! [`vector_without_noise`]: and out of the vectors made from it.
//!
//! `R I⁻¹ Rᵀ` of a body whose principal inertias are equal (a cube, a ball) is diagonal, but
//! computed in f32 for a body that turned by rounding noise it has off-diagonal entries of
//! ~1e-27 next to diagonal ones of ~1e-2. They carry nothing, yet every lever arm and
//! impulse multiplied through them lands below `f32::MIN_POSITIVE`: a still 20-box stack ran
//! most of its solver passes through subnormal arithmetic (a ~100-cycle microcode assist per
//! operation on x86) and cost 1.3× rapier at 120 Hz × 4; without the noise, 0.73×.

use glam::{Mat3, Vec3, Vec3A};

/// `m` with every entry smaller than one f32 epsilon of its largest set to zero: such an
/// entry changes any product with a vector of comparable components by less than the
/// product's own rounding.
#[inline]
pub(crate) fn matrix_without_noise(m: Mat3) -> Mat3 {
    let largest = m
        .x_axis
        .abs()
        .max(m.y_axis.abs())
        .max(m.z_axis.abs())
        .max_element();
    let floor = Vec3::splat(largest * f32::EPSILON);
    let clean = |c: Vec3| Vec3::select(c.abs().cmpge(floor), c, Vec3::ZERO);
    Mat3::from_cols(clean(m.x_axis), clean(m.y_axis), clean(m.z_axis))
}

/// `v` with every component smaller than one f32 epsilon of its largest set to zero (the
/// rule of [`matrix_without_noise`]). A body's inverse inertia turned onto a normal along one
/// of its axes keeps rounding in the other two components.
#[inline]
pub(crate) fn vector_without_noise(v: Vec3A) -> Vec3A {
    let floor = Vec3A::splat(v.abs().max_element() * f32::EPSILON);
    Vec3A::select(v.abs().cmpge(floor), v, Vec3A::ZERO)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn off_diagonal_noise_goes_and_real_coupling_stays() {
        let m = Mat3::from_cols(
            Vec3::new(0.006, 2.4e-27, 0.0),
            Vec3::new(2.4e-27, 0.006, 1e-4),
            Vec3::new(0.0, 1e-4, 0.006),
        );
        let clean = matrix_without_noise(m);
        assert_eq!(clean.x_axis, Vec3::new(0.006, 0.0, 0.0));
        assert_eq!(clean.y_axis, Vec3::new(0.0, 0.006, 1e-4));
        assert_eq!(clean.z_axis, m.z_axis);
        // Nothing is absolute: a light body's tiny inverse inertia keeps its scale.
        let small = Mat3::from_diagonal(Vec3::new(1e-30, 2e-30, 3e-30));
        assert_eq!(matrix_without_noise(small), small);
        assert_eq!(matrix_without_noise(Mat3::ZERO), Mat3::ZERO);
    }

    #[test]
    fn a_vector_loses_its_rounding_and_keeps_its_scale() {
        let v = Vec3A::new(1.2e-22, 0.006, -3e-20);
        assert_eq!(vector_without_noise(v), Vec3A::new(0.0, 0.006, 0.0));
        let coupled = Vec3A::new(1e-4, 0.006, -2e-3);
        assert_eq!(vector_without_noise(coupled), coupled);
        let small = Vec3A::new(1e-30, 2e-30, 3e-30);
        assert_eq!(vector_without_noise(small), small);
        assert_eq!(vector_without_noise(Vec3A::ZERO), Vec3A::ZERO);
    }
}
