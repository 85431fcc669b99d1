//! [`StepOutput`]: everything a step reports (counters, events, quarantined bodies).

use crate::body_handle::BodyHandle;
use crate::broken_joint::BrokenJoint;
use crate::contact_event::ContactEvent;
use crate::far_body::FarBody;
use crate::overloaded_contact::OverloadedContact;
use crate::speed_cap_hit::SpeedCapHit;
use crate::step_counters::StepCounters;

/// What [`crate::PhysicsWorld::step`] returns; valid until the next step.
#[derive(Clone, Debug, Default)]
pub struct StepOutput {
    /// Timings and work counts.
    pub counters: StepCounters,
    /// Contact starts and ends of this step (plus ends caused by removals since the last step).
    pub events: Vec<ContactEvent>,
    /// Bodies whose state went non-finite this step: rolled back, disabled.
    pub quarantined: Vec<BodyHandle>,
    /// Bodies clamped to a speed cap for the first time (once per body and cap, ever).
    pub speed_caps: Vec<SpeedCapHit>,
    /// Contacts first found deeper than their penetration budget (once per pair).
    pub overloaded_contacts: Vec<OverloadedContact>,
    /// Moving bodies first found past `PhysicsSettings::precise_range` (once per body).
    pub far_bodies: Vec<FarBody>,
    /// Joints that broke this step (their force or torque passed their threshold).
    pub broken_joints: Vec<BrokenJoint>,
}
