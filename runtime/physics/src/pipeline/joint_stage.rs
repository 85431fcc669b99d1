//! Joints in the step: sleeping partners woken (pre-step), joints prepared for the solver
//! (solve stage, after the bodies), impulses stored and breaks found (after the substeps).

use glam::{Quat, Vec3, Vec3A};

use crate::body_handle::BodyHandle;
use crate::body_type::BodyType;
use crate::broken_joint::BrokenJoint;
use crate::joint::JointImpulses;
use crate::joint_desc::JointKind;
use crate::joint_handle::JointHandle;
use crate::physics_settings::PhysicsSettings;
use crate::physics_world::PhysicsWorld;
use crate::pose::Pose;
use crate::solver::joint_constraint::{drive_softness, JointConstraint, Rows};
use crate::solver::Softness;

/// Joint stiffness never goes above this fraction of the substep rate, 1/s per Hz: `h·ω` up
/// to π/2. At half the substep rate (`h·ω = π`, Box2D v3's bound) the bench's chains and
/// bridge went unstable wherever the bound was reached (30 Hz × 2, 30 × 4, 60 × 2: a 20-link
/// chain holding 100× a link stretched 150–230 %, a 50-plank bridge's planks still moving at
/// 13 m/s after 5 s), though a lone pendulum did not; at a quarter they settle. Bounded
/// `(0, ∞)`: below it loaded joints stretch further. Not solved at one 30 Hz substep: there
/// the quarter (7.5 Hz) lets a pendulum whose bob hangs 20 radii below its pivot spin up and
/// blow up, and half (15 Hz) holds it but tears the 50-plank bridge apart.
pub const JOINT_STIFFNESS_MAX_SUBSTEP_FRACTION: f32 = 0.25;

/// The softness of one joint at substep `h`: `joint_hertz` stiffened for the load it carried
/// last substep (its warm-start linear impulse `λ`, with a slider's or a distance joint's
/// limit impulses, which carry a load along the axis), the mass-aware treatment contacts get
/// (`Softness::load_hertz`, `Softness::for_supported_mass`). A soft joint's static stretch is
/// `a / ω²` with `a = λ / (m_eff h)` its load over its own effective mass, so a link holding
/// 100 links' weight stretched 100× a lone link's (the 100:1 chain 3 % of its length at
/// every setting from 60 × 4 on); stiffened by `√(a / g)` it stretches about as much as a
/// lone link, up to [`JOINT_STIFFNESS_MAX_SUBSTEP_FRACTION`] of the substep rate, with the
/// damping ratio grown by the same factor so the heavy load does not ring on the light link.
fn loaded_joint_softness(
    s: &PhysicsSettings,
    h: f32,
    kind: &JointKind,
    impulses: &JointImpulses,
    inv_mass_sum: f32,
) -> Softness {
    let cap = JOINT_STIFFNESS_MAX_SUBSTEP_FRACTION / h;
    let base = s.joint_hertz.min(cap);
    let g = s.gravity.length();
    let along_axis = match kind {
        JointKind::Prismatic { .. } | JointKind::Distance { .. } => {
            impulses.lower.abs() + impulses.upper.abs()
        }
        _ => 0.0,
    };
    let lambda = Vec3::from_array(impulses.linear).length() + along_axis;
    let ratio = if g > 0.0 && inv_mass_sum > 0.0 && lambda.is_finite() {
        lambda * inv_mass_sum / (g * h)
    } else {
        1.0
    };
    Softness::new(
        Softness::load_hertz(base, ratio, cap),
        s.joint_damping_ratio,
        h,
    )
}

/// One side of a joint at the step start.
struct Side {
    /// Solver index (0: static, asleep, or the world).
    index: u32,
    dynamic: bool,
    /// Centre of mass (the anchor, for the world), world space.
    center: Vec3,
    /// Anchor offset from the centre of mass, world axes.
    r: Vec3,
    /// Joint frame in world axes.
    frame: Quat,
}

impl PhysicsWorld {
    /// Wakes every sleeping dynamic body jointed to an awake one, until none is left
    /// (bodies that slept together are one island already; this catches joints added
    /// between islands).
    pub(crate) fn wake_jointed(&mut self) {
        if self.joints.is_empty() {
            return;
        }
        loop {
            let mut woken: Vec<BodyHandle> = Vec::new();
            let awake = |h: BodyHandle| {
                self.active_flags
                    .get(h.index() as usize)
                    .copied()
                    .unwrap_or(false)
                    && self.bodies.get(h).is_some()
            };
            let asleep = |h: BodyHandle| {
                self.bodies
                    .get(h)
                    .is_some_and(|b| b.sleeping && b.body_type == BodyType::Dynamic)
            };
            for (_, j) in self.joints.iter() {
                let Some(a) = j.body_a else {
                    continue;
                };
                if j.broken {
                    continue;
                }
                let b = j.body_b;
                if awake(a) && asleep(b) {
                    woken.push(b);
                } else if awake(b) && asleep(a) {
                    woken.push(a);
                }
            }
            if woken.is_empty() {
                return;
            }
            for h in woken {
                self.wake_island(h);
            }
        }
    }

    /// Builds the step's joint constraints from the joints whose bodies take part (after the
    /// solver bodies are set up).
    pub(crate) fn prepare_joints(&mut self, h: f32) {
        self.joint_constraints.clear();
        if self.joints.is_empty() {
            return;
        }
        let s = self.settings;
        let side = |body: Option<BodyHandle>, frame: &Pose| -> Option<Side> {
            let Some(handle) = body else {
                return Some(Side {
                    index: 0,
                    dynamic: false,
                    center: frame.translation,
                    r: Vec3::ZERO,
                    frame: frame.rotation,
                });
            };
            let b = self.bodies.get(handle)?;
            let slot = self.solver_slots.get(handle.index() as usize).copied();
            let (index, dynamic) = match slot {
                Some(slot) if b.solver_index != 0 => (slot.index, slot.dynamic),
                _ => (0, false),
            };
            let q = b.pose.rotation;
            Some(Side {
                index,
                dynamic,
                center: b.pose.transform_point(b.mass.local_com),
                r: q * (frame.translation - b.mass.local_com),
                frame: q * frame.rotation,
            })
        };
        for (i, _, joint) in self.joints.arena.iter() {
            if joint.broken {
                continue;
            }
            let (Some(a), Some(b)) = (
                side(joint.body_a, &joint.desc.frame_a),
                side(Some(joint.body_b), &joint.desc.frame_b),
            ) else {
                continue;
            };
            if !(a.dynamic || b.dynamic) {
                continue;
            }
            let mass = |side: &Side| {
                if side.index == 0 {
                    (Vec3A::ZERO, glam::Mat3A::ZERO)
                } else {
                    (
                        self.solver_states[side.index as usize].inv_mass,
                        glam::Mat3A::from(self.solver_bodies[side.index as usize].inv_i),
                    )
                }
            };
            let ((inv_mass_a, inv_i_a), (inv_mass_b, inv_i_b)) = (mass(&a), mass(&b));
            let (spring, motor) = match joint.desc.kind {
                JointKind::Revolute { spring, motor, .. }
                | JointKind::Prismatic { spring, motor, .. } => (spring, motor),
                JointKind::Distance { spring, .. } => (spring, None),
                JointKind::Fixed | JointKind::Spherical { .. } => (None, None),
            };
            let (spring_softness, motor_softness) = drive_softness(spring, motor, h);
            let softness = loaded_joint_softness(
                &s,
                h,
                &joint.desc.kind,
                &joint.impulses,
                (inv_mass_a + inv_mass_b).max_element(),
            );
            self.joint_constraints.push(JointConstraint {
                joint: i,
                body_a: a.index,
                body_b: b.index,
                writes: u8::from(a.dynamic) | u8::from(b.dynamic) << 1,
                inv_mass_a,
                inv_mass_b,
                inv_i_a,
                inv_i_b,
                r_a0: a.r.into(),
                r_b0: b.r.into(),
                frame_a0: a.frame,
                frame_b0: b.frame,
                delta_center: (b.center - a.center).into(),
                kind: joint.desc.kind,
                softness,
                spring_softness,
                motor_softness,
                inv_h: 1.0 / h,
                h,
                impulses: joint.impulses,
            });
        }
        self.joint_rows
            .resize(self.joint_constraints.len(), Rows::default());
        self.output.counters.joints = self.joint_constraints.len() as u32;
    }

    /// Stores each joint's impulses (warm start of the next step) and reaction, and breaks
    /// the joints whose force or torque passed their threshold (reported once).
    pub(crate) fn finish_joints(&mut self) {
        for (c, rows) in self.joint_constraints.iter().zip(&self.joint_rows) {
            let (force, torque) = c.reaction(rows);
            let Some(joint) = self.joints.arena.get_by_index_mut(c.joint) else {
                continue;
            };
            joint.impulses = c.impulses;
            joint.force = force;
            joint.torque = torque;
            let broke = force.length() > joint.desc.break_force
                || torque.length() > joint.desc.break_torque;
            if !broke {
                continue;
            }
            joint.broken = true;
            joint.impulses = Default::default();
            let (a, b, apart) = (joint.body_a, joint.body_b, !joint.desc.collide_connected);
            let handle = JointHandle::from_parts(c.joint, self.joints.arena.generation_of(c.joint));
            self.output.broken_joints.push(BrokenJoint {
                joint: handle,
                force,
                torque,
            });
            if apart {
                self.joints.count_no_collide(a, b, false);
            }
        }
    }
}
