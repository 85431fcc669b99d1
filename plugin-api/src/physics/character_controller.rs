//! [`CharacterController`] and [`CharacterMove`]: a kinematic character moved against the
//! world ([`Ctx::move_character`](crate::Ctx::move_character)).

use abi_stable::StableAbi;
use glam::Vec3;

use crate::RayHit;

/// How [`Ctx::move_character`](crate::Ctx::move_character) moves a character. Up is +Y.
/// `Default` is a walking human: 1 cm skin, 45° slopes, 30 cm steps, 20 cm snap, pushing
/// on.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct CharacterController {
    /// Gap kept between the character and everything it meets, metres (default `0.01`).
    pub offset: f32,
    /// Steepest slope walked up, radians from horizontal (default π/4). Steeper surfaces
    /// are walls: the character slides along them sideways and is not carried up.
    pub max_slope_climb_angle: f32,
    /// Highest step climbed while on the ground, metres; `0` climbs none (default `0.3`).
    pub step_height: f32,
    /// Farthest the character is pulled down to stay on the ground when it was on it and
    /// is not moving up (down slopes and steps), metres; `0` turns it off (default `0.2`).
    pub snap_to_ground: f32,
    /// Give dynamic bodies it walks into its speed (default `true`).
    pub push_dynamic_bodies: bool,
}

impl Default for CharacterController {
    fn default() -> Self {
        Self {
            offset: 0.01,
            max_slope_climb_angle: std::f32::consts::FRAC_PI_4,
            step_height: 0.3,
            snap_to_ground: 0.2,
            push_dynamic_bodies: true,
        }
    }
}

/// What [`Ctx::move_character`](crate::Ctx::move_character) did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CharacterMove {
    /// How far the character moved (world axes, metres); its transform has already moved.
    pub translation: Vec3,
    /// It ended the move standing on walkable ground.
    pub grounded: bool,
    /// What it ran into, in order: the entity, the contact point, the surface's normal
    /// (facing the character) and the distance along that part of the move.
    pub collisions: Vec<RayHit>,
}
