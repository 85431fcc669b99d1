//! [`ShadowAnchor`]: the world point the cascades' texel grid is laid from.
//!
//! Snapping the cascades to a grid laid from the world origin keeps them still while the
//! camera moves, but the grid's phase then depends on where the scene is: the same scene
//! 100 km out falls on other sub-texel positions and its shadow edges rasterise differently.
//! Laid from where the camera first was (in f64), the grid sits the same under a scene
//! wherever it is placed, and still does not move while the camera does. A camera that ends
//! up farther than [`ANCHOR_REACH`] from the anchor (a teleport, a new scene) lays it again
//! from where it is: one sub-texel step of the shadows, then still again.

use glam::{DVec3, Vec3};

/// How far the camera may be from the anchor before it is laid again, metres.
pub(crate) const ANCHOR_REACH: f64 = 1_000.0;

/// The grid origin, kept between frames.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct ShadowAnchor {
    point: Option<DVec3>,
}

impl ShadowAnchor {
    /// The anchor for a frame seen from `camera`: the kept one, or `camera` itself on the
    /// first frame and after the camera went farther than [`ANCHOR_REACH`].
    pub(crate) fn follow(&mut self, camera: Vec3) -> DVec3 {
        let camera = camera.as_dvec3();
        let point = match self.point {
            Some(point) if point.distance(camera) <= ANCHOR_REACH => point,
            _ => camera,
        };
        self.point = Some(point);
        point
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_anchor_stays_while_the_camera_moves_and_follows_a_jump() {
        let mut anchor = ShadowAnchor::default();
        let start = Vec3::new(1.0e5, 2.0, -1.0e5);
        assert_eq!(anchor.follow(start), start.as_dvec3());
        let walked = start + Vec3::new(300.0, 0.0, 400.0);
        assert_eq!(
            anchor.follow(walked),
            start.as_dvec3(),
            "moved within reach"
        );
        let far = Vec3::new(0.0, 2.0, 5.0);
        assert_eq!(
            anchor.follow(far),
            far.as_dvec3(),
            "laid again after a jump"
        );
    }
}
