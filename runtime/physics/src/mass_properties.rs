//! [`MassProperties`]: mass, centre of mass and inertia tensor of a body or collider.

use glam::{Mat3, Vec3};

use crate::pose::Pose;

/// Mass (kg), centre of mass (m, local frame) and inertia tensor about the centre of mass
/// (kg·m², local frame axes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassProperties {
    /// Mass in kilograms. Zero means "no mass contribution".
    pub mass: f32,
    /// Centre of mass in the local frame, metres.
    pub local_com: Vec3,
    /// Inertia tensor about `local_com`, expressed in local axes, kg·m².
    pub inertia: Mat3,
}

impl Default for MassProperties {
    fn default() -> Self {
        Self::ZERO
    }
}

impl MassProperties {
    /// No mass, no inertia.
    pub const ZERO: Self = Self {
        mass: 0.0,
        local_com: Vec3::ZERO,
        inertia: Mat3::ZERO,
    };

    /// Explicit mass properties with a diagonal (principal) inertia.
    #[must_use]
    pub fn new(local_com: Vec3, mass: f32, principal_inertia: Vec3) -> Self {
        Self {
            mass,
            local_com,
            inertia: Mat3::from_diagonal(principal_inertia),
        }
    }

    /// Solid sphere of radius `r` (m) and density `rho` (kg/m³): `I = 2/5 m r²`.
    #[must_use]
    pub fn sphere(rho: f32, r: f32) -> Self {
        let m = rho * 4.0 / 3.0 * std::f32::consts::PI * r * r * r;
        let i = 0.4 * m * r * r;
        Self::new(Vec3::ZERO, m, Vec3::splat(i))
    }

    /// Solid box with half extents `h` (m): `I_x = m/3 (h_y² + h_z²)`.
    #[must_use]
    pub fn cuboid(rho: f32, h: Vec3) -> Self {
        let m = rho * 8.0 * h.x * h.y * h.z;
        let s = h * h;
        let k = m / 3.0;
        Self::new(
            Vec3::ZERO,
            m,
            Vec3::new(k * (s.y + s.z), k * (s.x + s.z), k * (s.x + s.y)),
        )
    }

    /// Solid capsule along local Y: cylinder of half height `hh` plus two hemispheres of radius `r`.
    #[must_use]
    pub fn capsule(rho: f32, hh: f32, r: f32) -> Self {
        let pi = std::f32::consts::PI;
        let m_cyl = rho * pi * r * r * 2.0 * hh;
        let m_sph = rho * 4.0 / 3.0 * pi * r * r * r;
        let iy = m_cyl * r * r * 0.5 + m_sph * 0.4 * r * r;
        let h = 2.0 * hh;
        let ix =
            m_cyl * (h * h / 12.0 + r * r / 4.0) + m_sph * (0.4 * r * r + hh * hh + 0.75 * hh * r);
        Self::new(Vec3::ZERO, m_cyl + m_sph, Vec3::new(ix, iy, ix))
    }

    /// The same properties expressed in a parent frame where the local frame sits at `pose`.
    #[must_use]
    pub fn transformed(&self, pose: &Pose) -> Self {
        let r = Mat3::from_quat(pose.rotation);
        Self {
            mass: self.mass,
            local_com: pose.transform_point(self.local_com),
            inertia: r * self.inertia * r.transpose(),
        }
    }

    /// Sum of two mass distributions (parallel-axis theorem about the joint centre of mass).
    #[must_use]
    pub fn combined(&self, other: &Self) -> Self {
        let m = self.mass + other.mass;
        if m <= 0.0 {
            return Self::ZERO;
        }
        let com = (self.local_com * self.mass + other.local_com * other.mass) / m;
        let shift = |p: &Self| {
            let d = p.local_com - com;
            p.inertia + (Mat3::from_diagonal(Vec3::splat(d.dot(d))) - outer(d, d)) * p.mass
        };
        Self {
            mass: m,
            local_com: com,
            inertia: shift(self) + shift(other),
        }
    }

    /// True when every number is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.mass.is_finite() && self.local_com.is_finite() && self.inertia.is_finite()
    }
}

/// Outer product `a bᵀ`.
#[must_use]
pub(crate) fn outer(a: Vec3, b: Vec3) -> Mat3 {
    Mat3::from_cols(a * b.x, a * b.y, a * b.z)
}
