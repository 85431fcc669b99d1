//! [`CharacterController`]: how a kinematic character moves against the world.

/// Most surfaces one move slides along before it stops where it is. Corners take two,
/// a step three; more costs a shape cast each and only matters in tight crevices.
pub const CHARACTER_MAX_SLIDES: u32 = 6;

/// The settings of [`crate::PhysicsWorld::move_character`]. Up is +Y. `Default` is a
/// walking human: 1 cm skin, 45° slopes, 30 cm steps, 20 cm snap, pushing on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CharacterController {
    /// Gap kept between the character's shape and everything it meets, metres. Default
    /// `0.01`. Too small (under ~1 mm) and rounding lets the shape touch and stick; too large
    /// and the character visibly floats.
    pub offset: f32,
    /// Steepest slope walked up, radians from horizontal. Default `π/4` (45°). A steeper
    /// surface is a wall: the character slides along it sideways and is not carried up.
    pub max_slope_climb_angle: f32,
    /// Highest step climbed, metres; `0` climbs none. Default `0.3`. Only while on the
    /// ground, and only onto a top it can stand on (no steeper than the largest slope).
    pub step_height: f32,
    /// Farthest the character is pulled down to keep it on the ground, metres, when it was
    /// on the ground and is not moving up (walking down a slope or a step); `0` turns it off.
    /// Default `0.2`. Too large and walking off a ledge lower than it snaps down instead of
    /// falling.
    pub snap_to_ground: f32,
    /// Give the dynamic bodies the character runs into the velocity it walked into them
    /// with. Default `true`.
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

impl CharacterController {
    /// Whether a surface with unit normal `n` can be walked on.
    #[must_use]
    pub fn walkable(&self, n: glam::Vec3) -> bool {
        n.y >= self.max_slope_climb_angle.cos() - WALKABLE_TOLERANCE
    }
}

/// Slack on the walkable test, so a slope of exactly the largest angle counts as walkable.
const WALKABLE_TOLERANCE: f32 = 1e-4;
