//! [`SpeedCapHit`]: a body whose speed the step clamped to a cap of
//! [`crate::PhysicsSettings`], reported once per body and cap.

use crate::body_handle::BodyHandle;

/// Which speed cap.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpeedCap {
    /// `PhysicsSettings::max_linear_speed`, m/s.
    Linear,
    /// `PhysicsSettings::max_angular_speed`, rad/s.
    Angular,
}

impl SpeedCap {
    /// The settings field that sets this cap.
    #[must_use]
    pub fn setting(self) -> &'static str {
        match self {
            SpeedCap::Linear => "max_linear_speed",
            SpeedCap::Angular => "max_angular_speed",
        }
    }
}

/// The first time a body's speed was clamped to a cap: in [`crate::StepOutput::speed_caps`]
/// for the step it happened in, never again for the same body and cap (so a host can log
/// every entry, e.g. "body 12 was slowed to the 200 rad/s spin cap (max_angular_speed)").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedCapHit {
    /// The body.
    pub body: BodyHandle,
    /// Which cap.
    pub cap: SpeedCap,
    /// The cap's value, m/s or rad/s.
    pub limit: f32,
}
