//! [`BodyType`]: how a body moves.

/// How a body participates in the simulation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum BodyType {
    /// Moved by forces, gravity and contacts.
    #[default]
    Dynamic,
    /// Moved by the user (velocity or target pose); pushes dynamic bodies, takes no impulse.
    Kinematic,
    /// Never moves.
    Static,
}

impl BodyType {
    /// Dynamic bodies only.
    #[inline]
    #[must_use]
    pub fn is_dynamic(self) -> bool {
        self == Self::Dynamic
    }
}
