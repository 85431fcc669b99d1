//! The [`Engine`] trait: one interface over Onyx physics and rapier3d so a scene is written
//! once and built in both.

use onyx_physics::glam::{Quat, Vec3};
use rapier3d::prelude as rp;

use crate::joint_spec::{JointKindSpec, JointSpec};

/// What the narrowphase's iterative queries did over a run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NarrowphaseTally {
    /// GJK runs.
    pub gjk_runs: u64,
    /// GJK iterations summed.
    pub gjk_iterations: u64,
    /// GJK runs that hit their iteration cap.
    pub gjk_not_converged: u64,
    /// EPA runs.
    pub epa_runs: u64,
    /// EPA iterations summed.
    pub epa_iterations: u64,
    /// EPA runs that failed or met a flat Minkowski difference (a fallback was used).
    pub epa_failures: u64,
}

impl NarrowphaseTally {
    /// Runs that did not converge or failed.
    #[must_use]
    pub fn failures(&self) -> u64 {
        self.gjk_not_converged + self.epa_failures
    }
}

impl std::fmt::Display for NarrowphaseTally {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mean = |iters: u64, runs: u64| {
            if runs == 0 {
                0.0
            } else {
                iters as f64 / runs as f64
            }
        };
        write!(
            f,
            "GJK {} runs, {:.2} iterations each, {} not converged; EPA {} runs, {:.2} \
             iterations each, {} failed",
            self.gjk_runs,
            mean(self.gjk_iterations, self.gjk_runs),
            self.gjk_not_converged,
            self.epa_runs,
            mean(self.epa_iterations, self.epa_runs),
            self.epa_failures
        )
    }
}

/// Which engine.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum EngineKind {
    /// Onyx (`onyx-physics`).
    Onyx,
    /// rapier3d.
    Rapier,
}

impl EngineKind {
    /// Both engines, in report order.
    pub const ALL: [EngineKind; 2] = [EngineKind::Onyx, EngineKind::Rapier];

    /// Short name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            EngineKind::Onyx => "onyx",
            EngineKind::Rapier => "rapier",
        }
    }

    /// A fresh engine of this kind with the given settings.
    #[must_use]
    pub fn create(self, s: StepSettings) -> Box<dyn Engine> {
        match self {
            EngineKind::Onyx => Box::new(OnyxEngine::new(s)),
            EngineKind::Rapier => Box::new(RapierEngine::new(s)),
        }
    }
}

/// Matched step settings: step rate, and substeps (Onyx) or solver iterations (rapier).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepSettings {
    /// Steps per simulated second.
    pub hz: f32,
    /// Onyx `substeps` / rapier `num_solver_iterations`.
    pub iterations: u32,
}

impl StepSettings {
    /// The converged reference setting: 240 Hz, 8 substeps.
    pub const REFERENCE: StepSettings = StepSettings {
        hz: 240.0,
        iterations: 8,
    };

    /// The setting of an Onyx preset: its step rate, and its substeps as the iterations.
    #[must_use]
    pub fn of_preset(p: onyx_physics::PhysicsPreset) -> Self {
        Self {
            hz: p.step_hz(),
            iterations: p.substeps(),
        }
    }

    /// Step length, seconds.
    #[must_use]
    pub fn dt(self) -> f32 {
        1.0 / self.hz
    }
}

/// Collision shape of a [`BodySpec`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShapeSpec {
    /// Sphere of this radius.
    Sphere(f32),
    /// Box of these half extents.
    Cuboid(Vec3),
    /// Convex hull of these points (body-local).
    Hull(&'static [Vec3]),
}

/// One body with one collider, engine-neutral.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodySpec {
    /// Fixed (static) instead of dynamic.
    pub fixed: bool,
    /// Position of the centre.
    pub position: Vec3,
    /// Orientation.
    pub rotation: Quat,
    /// Initial linear velocity.
    pub velocity: Vec3,
    /// Initial angular velocity, rad/s (world axes).
    pub angular_velocity: Vec3,
    /// Shape.
    pub shape: ShapeSpec,
    /// Density, kg/m³.
    pub density: f32,
    /// Coulomb friction (static = dynamic), combined as max... both colliders of a scene
    /// use the same value unless stated.
    pub friction: f32,
    /// Restitution, combined with the max rule in both engines.
    pub restitution: f32,
    /// Continuous collision detection on this body.
    pub ccd: bool,
    /// Gravity scale.
    pub gravity_scale: f32,
}

impl BodySpec {
    /// A dynamic body of this shape at `position` (density 1000, friction 0.5, no bounce).
    #[must_use]
    pub fn dynamic(shape: ShapeSpec, position: Vec3) -> Self {
        Self {
            fixed: false,
            position,
            rotation: Quat::IDENTITY,
            velocity: Vec3::ZERO,
            angular_velocity: Vec3::ZERO,
            shape,
            density: 1000.0,
            friction: 0.5,
            restitution: 0.0,
            ccd: false,
            gravity_scale: 1.0,
        }
    }

    /// A fixed body of this shape at `position`.
    #[must_use]
    pub fn fixed(shape: ShapeSpec, position: Vec3) -> Self {
        Self {
            fixed: true,
            ..Self::dynamic(shape, position)
        }
    }

    /// A fixed ground box whose top face is at `top` (centre x/z), `half` wide.
    #[must_use]
    pub fn ground(center: Vec3, half: f32) -> Self {
        Self::fixed(
            ShapeSpec::Cuboid(Vec3::new(half, 0.5, half)),
            center - Vec3::Y * 0.5,
        )
    }

    /// With this initial velocity.
    #[must_use]
    pub fn velocity(mut self, v: Vec3) -> Self {
        self.velocity = v;
        self
    }

    /// With this initial angular velocity.
    #[must_use]
    pub fn angular_velocity(mut self, w: Vec3) -> Self {
        self.angular_velocity = w;
        self
    }

    /// With this orientation.
    #[must_use]
    pub fn rotation(mut self, q: Quat) -> Self {
        self.rotation = q;
        self
    }

    /// With this friction.
    #[must_use]
    pub fn friction(mut self, mu: f32) -> Self {
        self.friction = mu;
        self
    }

    /// With this restitution.
    #[must_use]
    pub fn restitution(mut self, e: f32) -> Self {
        self.restitution = e;
        self
    }

    /// With this density.
    #[must_use]
    pub fn density(mut self, d: f32) -> Self {
        self.density = d;
        self
    }

    /// With CCD on or off.
    #[must_use]
    pub fn ccd(mut self, on: bool) -> Self {
        self.ccd = on;
        self
    }

    /// With this gravity scale.
    #[must_use]
    pub fn gravity_scale(mut self, s: f32) -> Self {
        self.gravity_scale = s;
        self
    }
}

/// Index of a body inside an [`Engine`] (insertion order).
pub type BodyId = usize;

/// A physics engine under test. Sleeping is off in both engines so that resting scenes
/// measure the solver, not the sleep threshold.
pub trait Engine {
    /// Which engine.
    fn kind(&self) -> EngineKind;
    /// Adds a body with its collider.
    fn add(&mut self, spec: &BodySpec) -> BodyId;
    /// Adds a joint between bodies already added (the joined bodies stop colliding with
    /// each other).
    fn add_joint(&mut self, spec: &JointSpec);
    /// Number of joints.
    fn joint_count(&self) -> usize;
    /// One fixed step.
    fn step(&mut self);
    /// Centre position of a body.
    fn position(&self, id: BodyId) -> Vec3;
    /// Orientation of a body.
    fn rotation(&self, id: BodyId) -> Quat;
    /// Linear velocity of a body.
    fn velocity(&self, id: BodyId) -> Vec3;
    /// Angular velocity of a body.
    fn angular_velocity(&self, id: BodyId) -> Vec3;
    /// Mass of a body, kg (0 for fixed bodies).
    fn mass(&self, id: BodyId) -> f32;
    /// Kinetic energy of a body (translation and rotation), J.
    fn kinetic_energy(&self, id: BodyId) -> f64;
    /// Size of the angular momentum of a body about its centre of mass, kg·m²/s.
    fn angular_momentum(&self, id: BodyId) -> f64;
    /// Sets the impact speed below which contacts do not bounce, m/s, where the engine has
    /// such a setting (Onyx: `restitution_threshold`); rapier 0.36 has none and bounces
    /// every impact. Returns whether the engine took it.
    fn set_restitution_threshold(&mut self, _speed: f32) -> bool {
        false
    }
    /// Number of bodies.
    fn len(&self) -> usize;
    /// GJK and EPA runs, iterations and failures so far, where the engine reports them;
    /// `None` otherwise (rapier does not).
    fn narrowphase_tally(&self) -> Option<NarrowphaseTally> {
        None
    }
    /// Time per stage summed over the steps so far, `(stage, seconds)`, where the engine
    /// reports it (for profiling; the sweep measures whole steps).
    fn stage_seconds(&self) -> Vec<(&'static str, f64)> {
        Vec::new()
    }
    /// Whether there are no bodies.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Onyx physics behind [`Engine`].
pub struct OnyxEngine {
    world: onyx_physics::PhysicsWorld,
    bodies: Vec<onyx_physics::BodyHandle>,
    joints: usize,
    tally: NarrowphaseTally,
    /// Broadphase, narrowphase, solve, integrate, ccd, sleep: seconds summed over steps.
    stages: [f64; 6],
}

impl OnyxEngine {
    /// Empty world with these settings (other settings at their defaults, sleeping off).
    #[must_use]
    pub fn new(s: StepSettings) -> Self {
        let settings = onyx_physics::PhysicsSettings {
            dt: s.dt(),
            substeps: s.iterations.max(1),
            sleep_enabled: false,
            ..Default::default()
        };
        Self {
            world: onyx_physics::PhysicsWorld::new(settings),
            bodies: Vec::new(),
            joints: 0,
            tally: NarrowphaseTally::default(),
            stages: [0.0; 6],
        }
    }

    /// The wrapped world.
    #[must_use]
    pub fn world(&self) -> &onyx_physics::PhysicsWorld {
        &self.world
    }
}

impl Engine for OnyxEngine {
    fn kind(&self) -> EngineKind {
        EngineKind::Onyx
    }

    fn add(&mut self, spec: &BodySpec) -> BodyId {
        use onyx_physics::{ColliderDesc, RigidBodyDesc};
        let desc = if spec.fixed {
            RigidBodyDesc::fixed()
        } else {
            RigidBodyDesc::dynamic()
                .linvel(spec.velocity)
                .angvel(spec.angular_velocity)
                .ccd_enabled(spec.ccd)
                .gravity_scale(spec.gravity_scale)
                .can_sleep(false)
        }
        .translation(spec.position)
        .rotation(spec.rotation);
        let h = self.world.insert_body(desc);
        let c = match spec.shape {
            ShapeSpec::Sphere(r) => ColliderDesc::sphere(r),
            ShapeSpec::Cuboid(he) => ColliderDesc::cuboid(he.x, he.y, he.z),
            ShapeSpec::Hull(points) => {
                ColliderDesc::convex_hull(points).expect("scene hull points form a hull (onyx)")
            }
        }
        .density(spec.density)
        .friction(spec.friction)
        .restitution(spec.restitution);
        self.world.insert_collider(c, h);
        self.bodies.push(h);
        self.bodies.len() - 1
    }

    fn add_joint(&mut self, spec: &JointSpec) {
        use onyx_physics::JointDesc;
        let desc = match spec.kind {
            JointKindSpec::Revolute {
                axis,
                limits,
                motor,
            } => {
                let mut d = JointDesc::revolute(axis);
                if let Some([lo, hi]) = limits {
                    d = d.limits(lo, hi);
                }
                if let Some(m) = motor {
                    d = d.motor_velocity(m.speed, m.max_torque);
                }
                d
            }
            JointKindSpec::Prismatic { axis, limits } => {
                let d = JointDesc::prismatic(axis);
                match limits {
                    Some([lo, hi]) => d.limits(lo, hi),
                    None => d,
                }
            }
            JointKindSpec::Spherical { axis, cone, twist } => {
                let mut d = JointDesc::spherical().local_axis_a(axis).local_axis_b(axis);
                if let Some(c) = cone {
                    d = d.cone_limit(c);
                }
                if let Some([lo, hi]) = twist {
                    d = d.limits(lo, hi);
                }
                d
            }
        }
        .local_anchor_a(spec.anchor_a)
        .local_anchor_b(spec.anchor_b);
        let a = spec.a.map(|id| self.bodies[id]);
        self.world
            .insert_joint(desc, a, self.bodies[spec.b])
            .expect("scene joints are valid (onyx)");
        self.joints += 1;
    }

    fn joint_count(&self) -> usize {
        self.joints
    }

    fn step(&mut self) {
        let c = self.world.step().counters;
        let t = &mut self.tally;
        t.gjk_runs += u64::from(c.gjk_calls);
        t.gjk_iterations += u64::from(c.gjk_iterations);
        t.gjk_not_converged += u64::from(c.gjk_not_converged);
        t.epa_runs += u64::from(c.epa_calls);
        t.epa_iterations += u64::from(c.epa_iterations);
        t.epa_failures += u64::from(c.epa_failures);
        let stages = [
            c.broadphase,
            c.narrowphase,
            c.solve,
            c.integrate,
            c.ccd,
            c.sleep,
        ];
        for (sum, d) in self.stages.iter_mut().zip(stages) {
            *sum += d.as_secs_f64();
        }
    }

    fn position(&self, id: BodyId) -> Vec3 {
        self.world
            .body(self.bodies[id])
            .map_or(Vec3::NAN, |b| b.translation())
    }

    fn rotation(&self, id: BodyId) -> Quat {
        self.world
            .body(self.bodies[id])
            .map_or(Quat::NAN, |b| b.rotation())
    }

    fn velocity(&self, id: BodyId) -> Vec3 {
        self.world
            .body(self.bodies[id])
            .map_or(Vec3::NAN, |b| b.linvel())
    }

    fn angular_velocity(&self, id: BodyId) -> Vec3 {
        self.world
            .body(self.bodies[id])
            .map_or(Vec3::NAN, |b| b.angvel())
    }

    fn mass(&self, id: BodyId) -> f32 {
        self.world.body(self.bodies[id]).map_or(0.0, |b| {
            if b.body_type() == onyx_physics::BodyType::Dynamic {
                b.mass()
            } else {
                0.0
            }
        })
    }

    fn kinetic_energy(&self, id: BodyId) -> f64 {
        self.world.body(self.bodies[id]).map_or(f64::NAN, |b| {
            let w = b.angvel();
            f64::from(
                0.5 * b.mass() * b.linvel().length_squared() + 0.5 * w.dot(b.world_inertia() * w),
            )
        })
    }

    fn angular_momentum(&self, id: BodyId) -> f64 {
        self.world.body(self.bodies[id]).map_or(f64::NAN, |b| {
            f64::from((b.world_inertia() * b.angvel()).length())
        })
    }

    fn set_restitution_threshold(&mut self, speed: f32) -> bool {
        self.world.settings_mut().restitution_threshold = speed;
        true
    }

    fn len(&self) -> usize {
        self.bodies.len()
    }

    fn narrowphase_tally(&self) -> Option<NarrowphaseTally> {
        Some(self.tally)
    }

    fn stage_seconds(&self) -> Vec<(&'static str, f64)> {
        let names = [
            "broadphase",
            "narrowphase",
            "solve",
            "integrate",
            "ccd",
            "sleep",
        ];
        names.into_iter().zip(self.stages).collect()
    }
}

/// rapier's motor damping factor for a velocity motor meant to be rigid (its compliance is
/// `1 / (dt · factor)`, negligible at this value).
const RIGID_MOTOR_DAMPING: f32 = 1.0e6;

/// rapier3d behind [`Engine`].
pub struct RapierEngine {
    world: rp::PhysicsWorld,
    bodies: Vec<rp::RigidBodyHandle>,
    /// The fixed body at the origin, without collider, that stands for the world in joints.
    ground: Option<rp::RigidBodyHandle>,
    joints: usize,
}

fn rv(v: Vec3) -> rp::Vector {
    rp::Vector::new(v.x, v.y, v.z)
}

fn ov(v: rp::Vector) -> Vec3 {
    Vec3::new(v.x, v.y, v.z)
}

impl RapierEngine {
    /// Empty world with these settings (other parameters at their defaults).
    #[must_use]
    pub fn new(s: StepSettings) -> Self {
        let mut world = rp::PhysicsWorld::new();
        world.gravity = rp::Vector::new(0.0, -9.81, 0.0);
        world.integration_parameters.dt = s.dt();
        world.integration_parameters.num_solver_iterations = s.iterations.max(1) as usize;
        Self {
            world,
            bodies: Vec::new(),
            ground: None,
            joints: 0,
        }
    }
}

impl Engine for RapierEngine {
    fn kind(&self) -> EngineKind {
        EngineKind::Rapier
    }

    fn add(&mut self, spec: &BodySpec) -> BodyId {
        let body = if spec.fixed {
            rp::RigidBodyBuilder::fixed()
        } else {
            rp::RigidBodyBuilder::dynamic()
                .linvel(rv(spec.velocity))
                .angvel(rv(spec.angular_velocity))
                .ccd_enabled(spec.ccd)
                .gravity_scale(spec.gravity_scale)
                .can_sleep(false)
        }
        .translation(rv(spec.position))
        .rotation(rv(spec.rotation.to_scaled_axis()));
        let c = match spec.shape {
            ShapeSpec::Sphere(r) => rp::ColliderBuilder::ball(r),
            ShapeSpec::Cuboid(he) => rp::ColliderBuilder::cuboid(he.x, he.y, he.z),
            ShapeSpec::Hull(points) => {
                let pts: Vec<rp::Vector> = points.iter().map(|&p| rv(p)).collect();
                rp::ColliderBuilder::convex_hull(&pts)
                    .expect("scene hull points form a hull (rapier)")
            }
        }
        .density(spec.density)
        .friction(spec.friction)
        .restitution(spec.restitution)
        .restitution_combine_rule(rp::CoefficientCombineRule::Max)
        .friction_combine_rule(rp::CoefficientCombineRule::GeometricMean);
        let (h, _) = self.world.insert(body, c);
        self.bodies.push(h);
        self.bodies.len() - 1
    }

    fn add_joint(&mut self, spec: &JointSpec) {
        let frame = |anchor: Vec3, axis: Vec3| {
            rp::Pose::from_parts(
                rv(anchor),
                rp::Rotation::from_rotation_arc(rp::Vector::X, rv(axis.normalize())),
            )
        };
        let joint: rp::GenericJoint = match spec.kind {
            JointKindSpec::Revolute {
                axis,
                limits,
                motor,
            } => {
                let mut j = rp::RevoluteJointBuilder::new(rv(axis.normalize()))
                    .local_anchor1(rv(spec.anchor_a))
                    .local_anchor2(rv(spec.anchor_b))
                    .contacts_enabled(false);
                if let Some(l) = limits {
                    j = j.limits(l);
                }
                if let Some(m) = motor {
                    // A rigid velocity motor bounded by its torque, as Onyx's: rapier's
                    // damping factor is the inverse of the row's compliance, so a large one
                    // leaves the velocity row stiff.
                    j = j
                        .motor_velocity(m.speed, RIGID_MOTOR_DAMPING)
                        .motor_max_force(m.max_torque);
                }
                j.build().into()
            }
            JointKindSpec::Prismatic { axis, limits } => {
                let mut j = rp::PrismaticJointBuilder::new(rv(axis.normalize()))
                    .local_anchor1(rv(spec.anchor_a))
                    .local_anchor2(rv(spec.anchor_b))
                    .contacts_enabled(false);
                if let Some(l) = limits {
                    j = j.limits(l);
                }
                j.build().into()
            }
            JointKindSpec::Spherical { axis, cone, twist } => {
                let mut j = rp::SphericalJointBuilder::new()
                    .local_frame1(frame(spec.anchor_a, axis))
                    .local_frame2(frame(spec.anchor_b, axis))
                    .contacts_enabled(false);
                if let Some(c) = cone {
                    j = j
                        .limits(rp::JointAxis::AngY, [-c, c])
                        .limits(rp::JointAxis::AngZ, [-c, c]);
                }
                if let Some(t) = twist {
                    j = j.limits(rp::JointAxis::AngX, t);
                }
                j.build().into()
            }
        };
        let a = match spec.a {
            Some(id) => self.bodies[id],
            None => *self
                .ground
                .get_or_insert_with(|| self.world.insert_body(rp::RigidBodyBuilder::fixed())),
        };
        self.world
            .insert_impulse_joint(a, self.bodies[spec.b], joint);
        self.joints += 1;
    }

    fn joint_count(&self) -> usize {
        self.joints
    }

    fn step(&mut self) {
        self.world.step();
    }

    fn position(&self, id: BodyId) -> Vec3 {
        self.world
            .bodies
            .get(self.bodies[id])
            .map_or(Vec3::NAN, |b| ov(b.translation()))
    }

    fn rotation(&self, id: BodyId) -> Quat {
        self.world
            .bodies
            .get(self.bodies[id])
            .map_or(Quat::NAN, |b| {
                let q = b.rotation();
                Quat::from_xyzw(q.x, q.y, q.z, q.w)
            })
    }

    fn velocity(&self, id: BodyId) -> Vec3 {
        self.world
            .bodies
            .get(self.bodies[id])
            .map_or(Vec3::NAN, |b| ov(b.linvel()))
    }

    fn angular_velocity(&self, id: BodyId) -> Vec3 {
        self.world
            .bodies
            .get(self.bodies[id])
            .map_or(Vec3::NAN, |b| ov(b.angvel()))
    }

    fn mass(&self, id: BodyId) -> f32 {
        self.world.bodies.get(self.bodies[id]).map_or(0.0, |b| {
            if b.is_dynamic() {
                b.mass()
            } else {
                0.0
            }
        })
    }

    fn kinetic_energy(&self, id: BodyId) -> f64 {
        self.world
            .bodies
            .get(self.bodies[id])
            .map_or(f64::NAN, |b| f64::from(b.kinetic_energy()))
    }

    fn angular_momentum(&self, id: BodyId) -> f64 {
        self.world
            .bodies
            .get(self.bodies[id])
            .map_or(f64::NAN, |b| {
                // |L| in the principal frame: rotations keep lengths.
                let mp = &b.mass_properties().local_mprops;
                let frame = *b.rotation() * mp.principal_inertia_local_frame;
                let w = frame.inverse() * b.angvel();
                let i = mp.principal_inertia();
                let l = Vec3::new(i.x * w.x, i.y * w.y, i.z * w.z);
                f64::from(l.length())
            })
    }

    fn len(&self) -> usize {
        self.bodies.len()
    }
}
