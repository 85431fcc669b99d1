//! [`FarBody`]: a moving body past the range where `f32` positions hold the engine's
//! accuracy, reported once per body.

use crate::body_handle::BodyHandle;

/// A moving body whose position is farther from the origin than
/// [`crate::PhysicsSettings::precise_range_for`] its size: there, `f32` positions are spaced
/// more coarsely than `PhysicsSettings::max_position_spacing` or than the resting accuracy
/// of a body that small (a 1 mm box resting on a 1 km one sinks 7 % of itself at balanced),
/// and slow motions are lost to rounding (a box sliding to a stop at 1e6 m stops 26 % short;
/// at 1e7 m it does not move).
/// In [`crate::StepOutput::far_bodies`] the step it first happens, once per body, so a host
/// can warn once, naming the body and the range (moving the origin is the cure).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FarBody {
    /// The body.
    pub body: BodyHandle,
    /// Its distance from the origin (largest coordinate), metres.
    pub distance: f32,
    /// The precise range for it, metres: [`crate::PhysicsSettings::precise_range_for`] its
    /// size.
    pub range: f32,
    /// Its smallest dimension, metres (`f32::MAX` for a body without colliders).
    pub size: f32,
}
