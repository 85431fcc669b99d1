//! [`PhysicsWorld`]: owns bodies, colliders and contact state; runs [`PhysicsWorld::step`].

use std::collections::HashMap;
use std::time::Instant;

use glam::Vec3;

use crate::body_handle::BodyHandle;
use crate::body_set::BodySet;
use crate::body_type::BodyType;
use crate::broadphase::BroadPhase;
use crate::collider::NO_PROXY;
use crate::collider_desc::ColliderDesc;
use crate::collider_handle::ColliderHandle;
use crate::collider_set::ColliderSet;
use crate::contact_event::ContactEvent;
use crate::joint::{Joint, JointImpulses};
use crate::joint_desc::{JointDesc, JointKind};
use crate::joint_error::JointError;
use crate::joint_handle::JointHandle;
use crate::joint_set::JointSet;
use crate::mass_properties::MassProperties;
use crate::narrowphase::NarrowPhase;
use crate::physics_settings::PhysicsSettings;
use crate::pipeline::writeback_stage::swept_bounds;
use crate::rigid_body::RigidBody;
use crate::rigid_body_desc::RigidBodyDesc;
use crate::solver::body_state::BodyState;
use crate::solver::contact_constraint::ManifoldRef;
use crate::solver::joint_constraint::{JointConstraint, Rows};
use crate::solver::solver_body::SolverBody;
use crate::step_output::StepOutput;

/// The simulation: bodies, colliders, broadphase tree, contact pairs and settings.
///
/// Mutate bodies through [`PhysicsWorld::body_mut`]; their setters wake them. Call
/// [`PhysicsWorld::step`] once per fixed time step.
#[derive(Debug)]
pub struct PhysicsWorld {
    pub(crate) settings: PhysicsSettings,
    pub(crate) bodies: BodySet,
    pub(crate) colliders: ColliderSet,
    pub(crate) joints: JointSet,
    /// The joints the solver takes this step, prepared.
    pub(crate) joint_constraints: Vec<JointConstraint>,
    /// Their rows in the solver, parallel to `joint_constraints`.
    pub(crate) joint_rows: Vec<Rows>,
    pub(crate) broadphase: BroadPhase,
    pub(crate) narrowphase: NarrowPhase,
    pub(crate) output: StepOutput,
    pub(crate) pending_events: Vec<ContactEvent>,
    pub(crate) solver_bodies: Vec<SolverBody>,
    /// Hot solver state, parallel to `solver_bodies`.
    pub(crate) solver_states: Vec<BodyState>,
    /// Body slot index of each solver body (entry 0 unused).
    pub(crate) solver_handles: Vec<u32>,
    /// The manifolds the solver takes this step, in order.
    pub(crate) manifold_refs: Vec<ManifoldRef>,
    /// Per solver body, how many faces it rests on this step (see `column_face`).
    pub(crate) supports: crate::pipeline::column_supports::ColumnSupports,
    /// What the narrowphase reads of each awake body, by arena index (see `NarrowBody`).
    pub(crate) narrow_bodies: Vec<crate::narrowphase::narrow_body::NarrowBody>,
    /// Solver index and dynamic flag by body arena index (see [`SolverSlot`]).
    pub(crate) solver_slots: Vec<SolverSlot>,
    /// The constraints as SIMD batches for the substeps.
    pub(crate) contact_batches: crate::solver::batching::ContactBatches,
    /// The energy of elastic impacts, kept between steps for its buffers.
    pub(crate) elastic_energy: crate::solver::elastic_energy::ElasticEnergy,
    /// The friction bounds the heavy-on-light scaling hides (see `HiddenLoads`).
    pub(crate) hidden_loads: crate::pipeline::heavy_on_light::HiddenLoads,
    /// The bodies pinched under heavier ones, whose faces are not levelled (see
    /// `PinchedBodies`).
    pub(crate) pinched: crate::pipeline::heavy_on_light::PinchedBodies,
    pub(crate) new_pairs: Vec<(u32, u32)>,
    /// Arena indices of the bodies that take part in this step (awake, not static, not
    /// quarantined), gathered by the pre-step and by wake-ups; sleeping bodies are not in it.
    pub(crate) active_bodies: Vec<u32>,
    /// `active_bodies` as flags by arena index (pair filtering without body lookups).
    pub(crate) active_flags: Vec<bool>,
    /// Pairs regenerated this step that touch (for the contact report).
    pub(crate) report_pairs: Vec<u32>,
    /// Scratch: deepest contact (separation, normal) per solver body.
    pub(crate) deepest_contact: Vec<(f32, Vec3, bool)>,
    pub(crate) wake: Vec<BodyHandle>,
    pub(crate) islands: HashMap<u32, Vec<BodyHandle>>,
    /// Scratch of the write-back: each solver body's pose at the end of the step.
    pub(crate) end_poses: Vec<crate::pose::Pose>,
    /// Scratch of the write-back: the bodies CCD stopped this step.
    pub(crate) ccd_clamps: Vec<crate::pipeline::ccd::CcdClamp>,
    pub(crate) next_island: u32,
    pub(crate) time: f64,
}

/// Where an awake body sits in the solver arrays this step, by body arena index: the pair
/// loop of the solve stage reads these 8 bytes instead of the body (a cache miss per pair).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct SolverSlot {
    /// Solver index; 0 for a body not in this step (static, asleep).
    pub index: u32,
    /// Dynamic and in the step (the solver writes its velocity).
    pub dynamic: bool,
    /// Can rotate during the step: dynamic with a free rotation axis, or kinematic and
    /// spinning. Contacts between bodies that cannot are solved without angular rows.
    pub rotates: bool,
}

impl SolverSlot {
    pub const NONE: Self = Self {
        index: 0,
        dynamic: false,
        rotates: false,
    };
}

impl Default for PhysicsWorld {
    fn default() -> Self {
        Self::new(PhysicsSettings::default())
    }
}

impl PhysicsWorld {
    /// Empty world.
    #[must_use]
    pub fn new(settings: PhysicsSettings) -> Self {
        Self {
            settings,
            bodies: BodySet::default(),
            colliders: ColliderSet::default(),
            joints: JointSet::default(),
            joint_constraints: Vec::new(),
            joint_rows: Vec::new(),
            broadphase: BroadPhase::default(),
            narrowphase: NarrowPhase::default(),
            output: StepOutput::default(),
            pending_events: Vec::new(),
            solver_bodies: Vec::new(),
            solver_states: Vec::new(),
            solver_handles: Vec::new(),
            manifold_refs: Vec::new(),
            supports: Default::default(),
            narrow_bodies: Vec::new(),
            solver_slots: Vec::new(),
            contact_batches: Default::default(),
            elastic_energy: Default::default(),
            hidden_loads: Default::default(),
            pinched: Default::default(),
            new_pairs: Vec::new(),
            deepest_contact: Vec::new(),
            active_bodies: Vec::new(),
            active_flags: Vec::new(),
            report_pairs: Vec::new(),
            wake: Vec::new(),
            islands: HashMap::new(),
            end_poses: Vec::new(),
            ccd_clamps: Vec::new(),
            next_island: 0,
            time: 0.0,
        }
    }

    /// Settings.
    #[must_use]
    pub fn settings(&self) -> &PhysicsSettings {
        &self.settings
    }

    /// Mutable settings (take effect at the next step).
    pub fn settings_mut(&mut self) -> &mut PhysicsSettings {
        &mut self.settings
    }

    /// Simulated time, seconds.
    #[must_use]
    pub fn time(&self) -> f64 {
        self.time
    }

    /// All bodies.
    #[must_use]
    pub fn bodies(&self) -> &BodySet {
        &self.bodies
    }

    /// All colliders.
    #[must_use]
    pub fn colliders(&self) -> &ColliderSet {
        &self.colliders
    }

    /// Contact pairs (manifolds, impulses).
    #[must_use]
    pub fn narrowphase(&self) -> &NarrowPhase {
        &self.narrowphase
    }

    /// The broadphase (tree of collider bounds).
    #[must_use]
    pub fn broadphase(&self) -> &BroadPhase {
        &self.broadphase
    }

    /// Output of the last step.
    #[must_use]
    pub fn last_step(&self) -> &StepOutput {
        &self.output
    }

    /// A body.
    #[must_use]
    pub fn body(&self, h: BodyHandle) -> Option<&RigidBody> {
        self.bodies.get(h)
    }

    /// A body, mutably (setters wake it).
    pub fn body_mut(&mut self, h: BodyHandle) -> Option<&mut RigidBody> {
        self.bodies.get_mut(h)
    }

    /// A collider.
    #[must_use]
    pub fn collider(&self, h: ColliderHandle) -> Option<&crate::collider::Collider> {
        self.colliders.get(h)
    }

    /// Adds a body; attach colliders with [`PhysicsWorld::insert_collider`].
    pub fn insert_body(&mut self, desc: RigidBodyDesc) -> BodyHandle {
        let (i, g) = self.bodies.arena.insert(desc.build());
        BodyHandle::from_parts(i, g)
    }

    /// Attaches a collider to a body and updates the body's mass (unless set explicitly).
    /// Returns `None` if the body does not exist.
    pub fn insert_collider(
        &mut self,
        desc: ColliderDesc,
        parent: BodyHandle,
    ) -> Option<ColliderHandle> {
        let body = self.bodies.get(parent)?;
        let body_pose = body.pose;
        let mut c = desc.build(parent);
        let pose = body_pose.mul_pose(&c.local_pose);
        c.aabb = c.shape.aabb(&pose);
        let (i, g) = self.colliders.arena.insert(c);
        let proxy = self.broadphase.create_proxy(
            self.colliders.arena.get(i, g)?.aabb,
            self.settings.aabb_margin,
            i,
        );
        self.colliders.arena.get_mut(i, g)?.proxy = proxy;
        let h = ColliderHandle::from_parts(i, g);
        let body = self.bodies.get_mut(parent)?;
        body.colliders.push(h);
        body.wake_up();
        self.recompute_mass(parent);
        // A body inserted moving gets its bounds swept for its first step as the write-back
        // sweeps them for every later one: without, a paddle created spinning passed over what
        // was within its first step's turn, and a body created moving met nothing ahead of it
        // in that step.
        if let (Some(b), Some(c)) = (self.bodies.get(parent), self.colliders.get(h)) {
            if b.linvel != Vec3::ZERO || b.angvel != Vec3::ZERO {
                let (swept, disp) = swept_bounds(c, b, &self.settings);
                self.broadphase
                    .update_proxy(c.proxy, swept, self.settings.aabb_margin, disp);
            }
        }
        Some(h)
    }

    /// Removes a collider (reports `Ended` for its touching contacts at the next step).
    pub fn remove_collider(&mut self, h: ColliderHandle) -> bool {
        let Some(c) = self.colliders.arena.remove(h.index(), h.generation()) else {
            return false;
        };
        if c.proxy != NO_PROXY {
            self.broadphase.destroy_proxy(c.proxy);
        }
        // Wake bodies that touched it.
        for p in self.narrowphase.pairs() {
            if p.touching && (p.collider_a == h || p.collider_b == h) {
                self.wake.push(p.body_a);
                self.wake.push(p.body_b);
            }
        }
        self.narrowphase
            .remove_collider(h, &self.bodies, &mut self.pending_events);
        if let Some(b) = self.bodies.get_mut(c.parent) {
            b.colliders.retain(|&x| x != h);
            b.wake_up();
            self.recompute_mass(c.parent);
        }
        true
    }

    /// Removes a body, its colliders and its joints.
    pub fn remove_body(&mut self, h: BodyHandle) -> bool {
        let Some(b) = self.bodies.get(h) else {
            return false;
        };
        for c in b.colliders.clone() {
            self.remove_collider(c);
        }
        let attached: Vec<JointHandle> = self
            .joints
            .iter()
            .filter(|(_, j)| j.body_a == Some(h) || j.body_b == h)
            .map(|(jh, _)| jh)
            .collect();
        for jh in attached {
            self.remove_joint(jh);
        }
        self.bodies
            .arena
            .remove(h.index(), h.generation())
            .is_some()
    }

    /// All joints.
    #[must_use]
    pub fn joints(&self) -> &JointSet {
        &self.joints
    }

    /// A joint.
    #[must_use]
    pub fn joint(&self, h: JointHandle) -> Option<&Joint> {
        self.joints.get(h)
    }

    /// Joins body `body_b` to `body_a` (`None`: to the world) as `desc` says, and wakes both.
    /// Unless the joint lets them (`JointDesc::collide_connected`), the two bodies stop
    /// colliding with each other from now on.
    ///
    /// # Errors
    /// A description [`JointDesc::validate`] refuses, a body that is not in the world, or the
    /// same body on both sides.
    pub fn insert_joint(
        &mut self,
        desc: JointDesc,
        body_a: Option<BodyHandle>,
        body_b: BodyHandle,
    ) -> Result<JointHandle, JointError> {
        desc.validate()?;
        for h in body_a.into_iter().chain([body_b]) {
            if self.bodies.get(h).is_none() {
                return Err(JointError::NoSuchBody(h));
            }
        }
        if body_a == Some(body_b) {
            return Err(JointError::SameBody(body_b));
        }
        let (i, g) = self.joints.arena.insert(Joint {
            desc,
            body_a,
            body_b,
            impulses: JointImpulses::default(),
            force: Vec3::ZERO,
            torque: Vec3::ZERO,
            broken: false,
        });
        if !desc.collide_connected {
            self.joints.count_no_collide(body_a, body_b, true);
            if let Some(a) = body_a {
                self.narrowphase.remove_pairs_between(
                    a,
                    body_b,
                    &self.bodies,
                    &mut self.pending_events,
                );
            }
        }
        self.wake_joined(body_a, body_b);
        Ok(JointHandle::from_parts(i, g))
    }

    /// Replaces a joint's description (its impulses start afresh) and wakes its bodies; a
    /// broken joint stays broken.
    ///
    /// # Errors
    /// A description [`JointDesc::validate`] refuses, or a joint that is not there.
    pub fn set_joint_desc(&mut self, h: JointHandle, desc: JointDesc) -> Result<(), JointError> {
        desc.validate()?;
        let joint = self
            .joints
            .arena
            .get_mut(h.index(), h.generation())
            .ok_or(JointError::NoSuchJoint)?;
        let (a, b, was, broken) = (
            joint.body_a,
            joint.body_b,
            joint.desc.collide_connected,
            joint.broken,
        );
        joint.desc = desc;
        joint.impulses = JointImpulses::default();
        if !broken && was != desc.collide_connected {
            self.joints.count_no_collide(a, b, !desc.collide_connected);
            if let (false, Some(a)) = (desc.collide_connected, a) {
                self.narrowphase
                    .remove_pairs_between(a, b, &self.bodies, &mut self.pending_events);
            }
        }
        self.wake_joined(a, b);
        Ok(())
    }

    /// Removes a joint (its bodies collide again if it kept them apart). Returns whether
    /// it was there.
    pub fn remove_joint(&mut self, h: JointHandle) -> bool {
        let Some(joint) = self.joints.arena.remove(h.index(), h.generation()) else {
            return false;
        };
        if !joint.desc.collide_connected && !joint.broken {
            self.joints
                .count_no_collide(joint.body_a, joint.body_b, false);
        }
        self.wake_joined(joint.body_a, joint.body_b);
        true
    }

    /// The joint's coordinate at the bodies' current poses: a hinge's angle (rad, in
    /// (−π, π]), a slider's translation (m), a distance joint's length (m), a ball joint's
    /// twist (rad); `None` for a weld or a joint that is not there.
    #[must_use]
    pub fn joint_coordinate(&self, h: JointHandle) -> Option<f32> {
        let joint = self.joints.get(h)?;
        let frame = |body: Option<BodyHandle>, local: &crate::pose::Pose| match body {
            Some(b) => self.bodies.get(b).map(|b| b.pose.mul_pose(local)),
            None => Some(*local),
        };
        let fa = frame(joint.body_a, &joint.desc.frame_a)?;
        let fb = frame(Some(joint.body_b), &joint.desc.frame_b)?;
        let twist = || {
            let q = fa.rotation.inverse() * fb.rotation;
            let q = if q.w < 0.0 { -q } else { q };
            2.0 * q.x.atan2(q.w)
        };
        match joint.desc.kind {
            JointKind::Fixed => None,
            JointKind::Revolute { .. } | JointKind::Spherical { .. } => Some(twist()),
            JointKind::Prismatic { .. } => {
                Some((fa.rotation * Vec3::X).dot(fb.translation - fa.translation))
            }
            JointKind::Distance { .. } => Some(fb.translation.distance(fa.translation)),
        }
    }

    /// Wakes the bodies of a joint that was added, changed or removed.
    fn wake_joined(&mut self, a: Option<BodyHandle>, b: BodyHandle) {
        for h in a.into_iter().chain([b]) {
            if let Some(body) = self.bodies.get_mut(h) {
                body.wake_up();
            }
        }
    }

    /// Recomputes a body's mass properties from its colliders (or its explicit override),
    /// and its size.
    pub(crate) fn recompute_mass(&mut self, h: BodyHandle) {
        let Some(b) = self.bodies.get(h) else {
            return;
        };
        let mp = if let Some(mp) = b.mass_override {
            mp
        } else {
            let mut acc = MassProperties::ZERO;
            for &ch in &b.colliders {
                if let Some(c) = self.colliders.get(ch) {
                    let m = c
                        .shape
                        .mass_properties(c.density)
                        .transformed(&c.local_pose);
                    acc = acc.combined(&m);
                }
            }
            acc
        };
        let size = b
            .colliders
            .iter()
            .filter_map(|&ch| self.colliders.get(ch))
            .filter(|c| !c.sensor)
            .map(|c| c.shape.size())
            .fold(f32::MAX, f32::min);
        let Some(b) = self.bodies.get_mut(h) else {
            return;
        };
        b.size = size;
        b.mass = mp;
        if b.body_type != BodyType::Dynamic {
            b.mass.local_com = Vec3::ZERO;
        }
        b.update_inverse_mass();
    }

    /// Advances the simulation by `settings.dt`: broadphase → narrowphase → solve
    /// (substeps with integration) → write-back and CCD → sleep → events.
    pub fn step(&mut self) -> &StepOutput {
        let t_start = Instant::now();
        self.output.events.clear();
        self.output.events.append(&mut self.pending_events);
        self.output.quarantined.clear();
        self.output.speed_caps.clear();
        self.output.overloaded_contacts.clear();
        self.output.far_bodies.clear();
        self.output.broken_joints.clear();
        self.output.counters = Default::default();
        if !(self.settings.dt > 0.0 && self.settings.dt.is_finite()) {
            return &self.output;
        }
        if self.bodies.is_empty() && self.narrowphase.pairs.is_empty() {
            // Nothing to simulate: no stage has work.
            self.time += f64::from(self.settings.dt);
            self.output.counters.total = t_start.elapsed();
            return &self.output;
        }
        self.prestep();

        let t = Instant::now();
        self.broadphase_stage();
        self.output.counters.broadphase = t.elapsed();

        let t = Instant::now();
        self.narrowphase_stage();
        self.output.counters.narrowphase = t.elapsed();

        let t = Instant::now();
        self.solve_stage();
        self.output.counters.solve = t.elapsed();

        // Integrate (write-back) includes CCD, timed apart inside.
        let t = Instant::now();
        self.writeback_stage();
        self.output.counters.integrate = t.elapsed().saturating_sub(self.output.counters.ccd);

        let t = Instant::now();
        self.update_touching();
        self.sleep_stage();
        self.contact_report_stage();
        self.output.counters.sleep = t.elapsed();

        self.time += f64::from(self.settings.dt);
        self.output.counters.pairs = self.narrowphase.pairs.len() as u32;
        self.output.counters.total = t_start.elapsed();
        &self.output
    }
}
