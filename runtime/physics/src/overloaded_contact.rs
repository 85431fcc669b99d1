//! [`OverloadedContact`]: a resting contact the settings cannot hold within its penetration
//! budget, reported once per pair (a heavy load on a small body at a coarse step).

use crate::body_handle::BodyHandle;
use crate::physics_preset::PhysicsPreset;

/// A contact whose load would press it deeper than twice the penetration budget
/// (`PhysicsSettings::max_penetration_fraction` of the smaller body's size) even at the
/// stiffest contact the step allows (for a face in a column, the stiffer one it reaches once
/// settled). In [`crate::StepOutput::overloaded_contacts`] the step it is first seen, once
/// per pair, so a host can say so once: e.g. "body 3 carries 850 times its contact's
/// weight; it sinks about 4 mm (budget 2 mm); the `precise` preset holds it".
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OverloadedContact {
    /// First body of the pair.
    pub body_a: BodyHandle,
    /// Second body of the pair.
    pub body_b: BodyHandle,
    /// Load the contact carries over the weight of its own effective mass (1 for a body
    /// resting alone).
    pub load_ratio: f32,
    /// Mass of the heavier body over the lighter, for two dynamic bodies.
    pub mass_ratio: Option<f32>,
    /// Static deflection the contact settles at, metres.
    pub expected_depth: f32,
    /// The penetration budget, metres.
    pub allowed_depth: f32,
    /// The cheapest preset whose step would hold it within the depth that names a contact
    /// (twice the budget), so that it is not reported there; `None` when no preset would.
    pub holding_preset: Option<PhysicsPreset>,
}
