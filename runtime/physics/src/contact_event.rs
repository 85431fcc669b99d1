//! [`ContactEvent`]: a contact started or ended between two colliders.

use glam::Vec3;

use crate::body_handle::BodyHandle;
use crate::collider_handle::ColliderHandle;

/// Whether a contact began or ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ContactEventKind {
    /// The colliders started touching during this step.
    Started,
    /// They stopped touching (or one of them was removed or quarantined).
    Ended,
}

/// A contact start or end, reported in [`crate::StepOutput::events`].
///
/// Every `Started` is followed by exactly one `Ended` for the same collider pair
/// (at the latest when a collider is removed).
#[derive(Clone, Debug, PartialEq)]
pub struct ContactEvent {
    /// Start or end.
    pub kind: ContactEventKind,
    /// First collider (the normal points away from it).
    pub collider_a: ColliderHandle,
    /// Second collider.
    pub collider_b: ColliderHandle,
    /// Body of `collider_a`.
    pub body_a: BodyHandle,
    /// Body of `collider_b`.
    pub body_b: BodyHandle,
    /// Contact normal from A to B, world (last known for `Ended`).
    pub normal: Vec3,
    /// World contact points (last known for `Ended`).
    pub points: Vec<Vec3>,
    /// Total normal impulse applied in the step of the event, N·s (0 for `Ended`).
    pub impulse: f32,
    /// One of the colliders is a sensor: the event is an overlap starting or ending, and
    /// nothing was pushed.
    pub sensor: bool,
}
