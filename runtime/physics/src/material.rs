//! [`Material`]: restitution and friction of a collider.

use crate::combine_rule::CombineRule;

/// Surface material of a collider.
///
/// Combine rules: friction coefficients mix with `friction_combine` (default geometric mean,
/// so a frictionless surface makes any contact frictionless); restitution mixes with
/// `restitution_combine` (default max, so one bouncy body bounces). When the two colliders
/// disagree on a rule, the stronger one wins, see [`CombineRule`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Coefficient of restitution in `[0, 1]`: ratio of separating to approaching normal speed.
    /// Default `0`.
    pub restitution: f32,
    /// Static (sticking) Coulomb coefficient, `>= 0`. Used while the contact point slides slower
    /// than `PhysicsSettings::static_friction_speed`. Default `0.6`.
    pub static_friction: f32,
    /// Dynamic (sliding) Coulomb coefficient, `>= 0`. Default `0.5`.
    pub dynamic_friction: f32,
    /// Rule for both friction coefficients. Default [`CombineRule::GeometricMean`].
    pub friction_combine: CombineRule,
    /// Rule for restitution. Default [`CombineRule::Max`].
    pub restitution_combine: CombineRule,
}

impl Default for Material {
    fn default() -> Self {
        Self {
            restitution: 0.0,
            static_friction: 0.6,
            dynamic_friction: 0.5,
            friction_combine: CombineRule::GeometricMean,
            restitution_combine: CombineRule::Max,
        }
    }
}

impl Material {
    /// Mixed `(restitution, static friction, dynamic friction)` for a contact of `a` and `b`.
    #[must_use]
    pub fn combine(a: &Material, b: &Material) -> (f32, f32, f32) {
        let e = a
            .restitution_combine
            .combine(b.restitution_combine, a.restitution, b.restitution);
        let fs =
            a.friction_combine
                .combine(b.friction_combine, a.static_friction, b.static_friction);
        let fd =
            a.friction_combine
                .combine(b.friction_combine, a.dynamic_friction, b.dynamic_friction);
        (e.clamp(0.0, 1.0), fs.max(0.0), fd.max(0.0))
    }
}
