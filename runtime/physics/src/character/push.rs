//! The push a character gives the dynamic bodies it runs into.

use glam::Vec3;

use super::character_move::CharacterMove;
use crate::body_type::BodyType;
use crate::physics_world::PhysicsWorld;

impl PhysicsWorld {
    /// Gives each dynamic body the move ran into the character's velocity along the push
    /// direction (into its surface), as an impulse at its centre of mass: a body already
    /// moving away at least that fast is left alone. `velocity` is the character's, m/s.
    pub(super) fn push_bodies(&mut self, moved: &CharacterMove, velocity: Vec3) {
        for hit in &moved.collisions {
            let Some(body) = self.bodies.get_mut(hit.body) else {
                continue;
            };
            if body.body_type() != BodyType::Dynamic {
                continue;
            }
            let into = -hit.normal;
            let closing = velocity.dot(into) - body.linvel().dot(into);
            if closing > 0.0 {
                let mass = body.mass_properties().mass;
                body.apply_impulse(into * (mass * closing));
            }
        }
    }
}
