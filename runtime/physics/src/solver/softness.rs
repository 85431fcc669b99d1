//! [`Softness`]: soft-constraint coefficients (mass-spring-damper) for one substep size.

/// Coefficients of a soft constraint with stiffness `hertz` and damping ratio `zeta`
/// at substep `h` (Box2D v3 / "soft step" formulation):
/// `ω = 2π·hertz`, `a1 = 2ζ + hω`, `a2 = hω·a1`, `a3 = 1/(1 + a2)`,
/// `bias_rate = ω / a1`, `mass_scale = a2·a3`, `impulse_scale = a3`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Softness {
    /// Converts position error (m) into a velocity bias (m/s), 1/s.
    pub bias_rate: f32,
    /// Scales the effective mass (< 1 makes the constraint soft).
    pub mass_scale: f32,
    /// Scales the accumulated impulse fed back (leak that keeps the spring stable).
    pub impulse_scale: f32,
}

impl Softness {
    /// Rigid constraint (no bias, full mass).
    pub const RIGID: Self = Self {
        bias_rate: 0.0,
        mass_scale: 1.0,
        impulse_scale: 0.0,
    };

    /// Builds the coefficients; `hertz <= 0` gives [`Softness::RIGID`].
    #[must_use]
    pub fn new(hertz: f32, zeta: f32, h: f32) -> Self {
        if hertz <= 0.0 {
            return Self::RIGID;
        }
        let omega = 2.0 * std::f32::consts::PI * hertz;
        let a1 = 2.0 * zeta + h * omega;
        let a2 = h * omega * a1;
        let a3 = 1.0 / (1.0 + a2);
        Self {
            bias_rate: omega / a1,
            mass_scale: a2 * a3,
            impulse_scale: a3,
        }
    }
}
