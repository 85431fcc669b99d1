//! [`CombineRule`]: how two colliders' material coefficients mix.

/// Rule mixing two coefficients `a`, `b` into one for a contact.
///
/// When the two colliders ask for different rules, the one listed later wins
/// (`Average < GeometricMean < Min < Multiply < Max`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub enum CombineRule {
    /// `(a + b) / 2`.
    Average,
    /// `sqrt(a * b)` (default for friction).
    #[default]
    GeometricMean,
    /// `min(a, b)`.
    Min,
    /// `a * b`.
    Multiply,
    /// `max(a, b)` (default for restitution).
    Max,
}

impl CombineRule {
    /// Mixes `a` and `b` with the winning rule of `self` and `other`.
    #[must_use]
    pub fn combine(self, other: Self, a: f32, b: f32) -> f32 {
        match self.max(other) {
            Self::Average => 0.5 * (a + b),
            Self::GeometricMean => (a * b).max(0.0).sqrt(),
            Self::Min => a.min(b),
            Self::Multiply => a * b,
            Self::Max => a.max(b),
        }
    }
}
