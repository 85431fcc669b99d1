//! Solve stage: gather awake bodies and manifolds into solver arrays and run the substeps.

use glam::{Vec3, Vec3A};

use super::column_supports::{is_support, ColumnSupports};
use super::heavy_on_light::{
    scaling_onset, support_mass_scale, upper_lower, SupportMass, HEAVY_COLUMN_DEPTH_SHARE,
    HEAVY_COLUMN_RESTING_DEPTHS, PINCHED_MASS_RATIO,
};
use super::resting_accelerations::RestingAccelerations;
use crate::body_type::BodyType;
use crate::locked_axes::LockedAxes;
use crate::narrowphase::narrow_phase::is_active;
use crate::overloaded_contact::OverloadedContact;
use crate::physics_preset::PhysicsPreset;
use crate::physics_world::PhysicsWorld;
use crate::physics_world::SolverSlot;
use crate::pipeline::jointed_masses::JointedMasses;
use crate::rigid_body::mask_mat;
use crate::solver::body_state::BodyState;
use crate::solver::column_chain::ChainFace;
use crate::solver::contact_batch::{
    column_face, column_rest_speed, levelled_for_load, Jitter, COLUMN_SETTLE_STEPS,
    LEVEL_MAX_FRICTION, LOADED_LEVEL_SHARE,
};
use crate::solver::contact_constraint::{
    prepare, touching_distance, ContactConstraint, FrictionPart, ManifoldRef, NormalBlock,
    PreparedManifold,
};
use crate::solver::noise::matrix_without_noise;
use crate::solver::restitution::{bounce_velocity, held_velocity};
use crate::solver::softness::LOAD_MEMORY_HALF_LIFE;
use crate::solver::solve::{column_passes, solve_substeps, SolveParams};
use crate::solver::solver_body::SolverBody;
use crate::solver::Softness;

/// A contact is reported overloaded when it settles deeper than this many times its
/// penetration budget (`PhysicsSettings::max_penetration_fraction` of the smaller body's
/// size): a contact at the budget is what the setting asks for, twice is what a user sees.
pub const OVERLOAD_DEPTH_FACTOR: f32 = 2.0;

/// Steps running a contact must be overloaded to be reported: an impact loads one step, and
/// a column settling into place presses its faces harder for a few (ten 3 mm cubes at
/// precise were named at 3.2 times their budget while settling, then held 2.6 %).
pub const OVERLOAD_SUSTAIN_STEPS: u16 = 10;

/// Steps a new face carries at least the column resting on it
/// (`ColumnSupports::column_mass`), whatever its warm-started impulse, which grows to a
/// column's load over steps. Until then a column placed at rest was stiffened for the body
/// on top alone and taken for no column: its faces telescoped into each other, five 1 mm
/// cubes at 60 Hz × 4 by up to 56 % of a cube in the first step (Gauss–Seidel in free fall
/// sees no relative velocity above the lowest face), and they fell where offset by a tenth
/// of a cube per level, or yawed 45° every other level, or laid as 5:1 bricks. Column faces
/// then had to wait three steps before stiffening past the step's cap (stiffened at once,
/// ten 1 mm cubes fell while the flags of their settling column came and went); with their
/// load known from the first step, a face that has been a column since it first touched
/// stiffens at once (`COLUMN_SETTLE_STEPS`), and the columns settle within their 2 %
/// budget from the first step. Bounded `[1, ∞)`: at 1 and 3 the same; at 10 five 1 mm
/// cubes at fast, which fall, were not named (`tests/stacking.rs`): their faces' overload
/// is judged on their own load, which the floor hid while they settled.
pub const NEW_FACE_STEPS: u16 = 3;

/// Most a face's reduced mass may exceed the sum of its points' effective masses in its size
/// stiffening: the face may be up to the square root of it (twice) stiffer than the cap of
/// its points (see `lever` in the solve stage). A cube's face is at 1 and a thin plate's at
/// 1.75 (its corners' levers); a single corner at the end of a long lever shrinks its point
/// without bound, and is not stiffened past twice the cap for it. Bounded `[1, ∞)`: at 1
/// a 1 mm plate on the ground sinks 5.4 % of its thickness at balanced.
pub const MAX_LEVER_STIFFENING: f32 = 4.0;

/// A contact deeper than [`OVERLOAD_DEPTH_FACTOR`] times its budget in one step: a candidate
/// for [`StepOutput::overloaded_contacts`](crate::StepOutput).
struct Overload {
    pair: u32,
    /// Static deflection at the stiffest the contact gets, and the budget, m.
    depth: f32,
    budget: f32,
    /// Stiffness that would hold it within `OVERLOAD_DEPTH_FACTOR` times the budget, Hz.
    needed_hz: f32,
    /// The load in weights of its own effective mass.
    load_ratio: f32,
    /// For a column face, its `Softness::column_lift` (its cap is
    /// `Softness::max_column_hertz`).
    column_lift: Option<f32>,
}

impl PhysicsWorld {
    /// Names each overloaded pair once in the step output, with the cheapest preset whose
    /// step would hold it within the depth that names it (`needed_hz`, within that preset's
    /// stiffness cap: a column face's where it is one), once it has been overloaded for
    /// [`OVERLOAD_SUSTAIN_STEPS`] running.
    fn report_overloads(&mut self, overloads: &[Overload]) {
        let now = self.narrowphase.updates;
        for o in overloads {
            let Some(pair) = self.narrowphase.pairs.get_mut(o.pair as usize) else {
                continue;
            };
            pair.overloaded_steps = if pair.overloaded_at == Some(now.wrapping_sub(1)) {
                pair.overloaded_steps.saturating_add(1)
            } else {
                1
            };
            pair.overloaded_at = Some(now);
            if pair.overload_reported || pair.overloaded_steps < OVERLOAD_SUSTAIN_STEPS {
                continue;
            }
            pair.overload_reported = true;
            let mass = |h| {
                self.bodies
                    .get(h)
                    .map(|b: &crate::rigid_body::RigidBody| b.mass())
                    .unwrap_or(0.0)
            };
            let (ma, mb) = (mass(pair.body_a), mass(pair.body_b));
            let mass_ratio = (ma > 0.0 && mb > 0.0).then(|| ma.max(mb) / ma.min(mb));
            let holding_preset = PhysicsPreset::ALL.into_iter().find(|p| {
                let dt = 1.0 / p.step_hz();
                let h = dt / p.substeps() as f32;
                let cap = if let Some(lift) = o.column_lift {
                    Softness::max_column_hertz(h, dt, lift)
                } else {
                    Softness::max_size_hertz(h, dt)
                };
                o.needed_hz <= cap
            });
            self.output.overloaded_contacts.push(OverloadedContact {
                body_a: pair.body_a,
                body_b: pair.body_b,
                load_ratio: o.load_ratio,
                mass_ratio,
                expected_depth: o.depth,
                allowed_depth: o.budget,
                holding_preset,
            });
        }
    }

    pub(crate) fn solve_stage(&mut self) {
        let s = self.settings;
        let substeps = s.substeps.max(1);
        let h = s.dt / substeps as f32;
        // Only the step's active bodies are visited: last step's solver bodies are reset,
        // sleeping ones are never touched. Arena order keeps results independent of wake order.
        for &idx in &self.solver_handles[1.min(self.solver_handles.len())..] {
            if let Some(b) = self.bodies.arena.get_by_index_mut(idx) {
                b.solver_index = 0;
            }
            if let Some(slot) = self.solver_slots.get_mut(idx as usize) {
                *slot = SolverSlot::NONE;
            }
        }
        self.active_bodies.sort_unstable();
        self.solver_bodies.clear();
        self.solver_states.clear();
        self.solver_handles.clear();
        self.solver_bodies.push(SolverBody::STATIC);
        self.solver_states.push(BodyState::STATIC);
        self.solver_handles.push(u32::MAX);
        // The range of the awake dynamic bodies' inverse masses (see `HiddenLoads`).
        let (mut min_inv_mass, mut max_inv_mass) = (f32::INFINITY, 0.0f32);
        for &i in &self.active_bodies {
            let Some(b) = self.bodies.arena.get_by_index_mut(i) else {
                continue;
            };
            if !is_active(b) {
                continue;
            }
            b.solver_index = self.solver_bodies.len() as u32;
            self.solver_handles.push(i);
            let dynamic = b.body_type == BodyType::Dynamic;
            // A dynamic body with every rotation locked never turns: no world inertia, and
            // its contacts skip the angular rows (unless the other body rotates).
            let rotates = if dynamic {
                !b.locked.contains(LockedAxes::ALL_ROTATIONS)
            } else {
                b.angvel != Vec3::ZERO
            };
            if self.solver_slots.len() <= i as usize {
                self.solver_slots.resize(i as usize + 1, SolverSlot::NONE);
            }
            self.solver_slots[i as usize] = SolverSlot {
                index: b.solver_index,
                dynamic,
                rotates,
            };
            let lin_mask = b.locked.translation_mask();
            let ang_mask = b.locked.rotation_mask();
            let inv_i = if dynamic && rotates {
                matrix_without_noise(b.world_inv_inertia())
            } else {
                glam::Mat3::ZERO
            };
            let (lin_acc, ang_acc) = if dynamic {
                let g = if b.gravity_enabled {
                    s.gravity * b.gravity_scale
                } else {
                    Vec3::ZERO
                };
                ((g + b.force * b.inv_mass).into(), (inv_i * b.torque).into())
            } else {
                (Vec3A::ZERO, Vec3A::ZERO)
            };
            if dynamic && b.inv_mass > 0.0 {
                min_inv_mass = min_inv_mass.min(b.inv_mass);
                max_inv_mass = max_inv_mass.max(b.inv_mass);
            }
            self.solver_states.push(BodyState {
                v: (b.linvel * if dynamic { lin_mask } else { Vec3::ONE }).into(),
                w: (b.angvel * if dynamic { ang_mask } else { Vec3::ONE }).into(),
                dp: Vec3A::ZERO,
                dtheta: Vec3A::ZERO,
                inv_mass: if dynamic {
                    (lin_mask * b.inv_mass).into()
                } else {
                    Vec3A::ZERO
                },
            });
            let gyro = dynamic && b.anisotropic && b.locked.0 & LockedAxes::ALL_ROTATIONS.0 == 0;
            let (omega_body, omega_world) = match b.spin_cache {
                Some(c) if gyro && c.world == b.angvel && c.rotation == b.pose.rotation => {
                    (c.body, Vec3A::from(c.world))
                }
                _ => (Vec3::ZERO, Vec3A::NAN),
            };
            self.solver_bodies.push(SolverBody {
                dq: glam::Quat::IDENTITY,
                inv_i: mask_mat(inv_i, ang_mask),
                lin_acc,
                ang_acc,
                // Per-substep factors, computed once per step (not per substep).
                lin_damp_factor: if dynamic {
                    1.0 / (1.0 + h * b.linear_damping)
                } else {
                    1.0
                },
                ang_damp_factor: if dynamic {
                    1.0 / (1.0 + h * b.angular_damping)
                } else {
                    1.0
                },
                lin_mask: (if dynamic { lin_mask } else { Vec3::ONE }).into(),
                ang_mask: (if dynamic { ang_mask } else { Vec3::ONE }).into(),
                q0: b.pose.rotation,
                inertia_local: b.mass.inertia,
                omega_body,
                omega_world,
                capped: 0,
                gyro,
            });
        }
        self.output.counters.awake_bodies = (self.solver_bodies.len() - 1) as u32;
        self.prepare_joints(h);

        // Manifolds: which the solver takes and which bodies they write; each is prepared
        // when its batch is packed.
        let hertz = s.contact_hertz.min(0.25 / h);
        let max_hertz = Softness::max_load_hertz(h, s.dt);
        let max_ball_hertz = Softness::max_ball_load_hertz(h, s.dt);
        let max_size_hertz = Softness::max_size_hertz(h, s.dt);
        let g_h = s.gravity.length() * h;
        self.manifold_refs.clear();
        let mut contacts = 0u32;
        let mut bouncy = false;
        self.supports.reset();
        // Some contact may be elastic (e = 1, no friction): see `solver::elastic_energy`.
        let mut elastic = false;
        for &pi in &self.narrowphase.updated_pairs {
            let pair = &self.narrowphase.pairs[pi as usize];
            if pair.manifolds.is_empty() || pair.sensor {
                continue;
            }
            // Compact per-body slots, not the bodies themselves: this loop visits every pair.
            let slot = |h: crate::body_handle::BodyHandle| {
                self.solver_slots
                    .get(h.index() as usize)
                    .copied()
                    .unwrap_or(SolverSlot::NONE)
            };
            let (sa, sb) = (slot(pair.body_a), slot(pair.body_b));
            if !sa.dynamic && !sb.dynamic {
                continue;
            }
            bouncy |= pair.restitution > 0.0;
            elastic |= pair.elastic();
            for (mi, m) in pair.manifolds.iter().enumerate() {
                if m.points.is_empty() {
                    continue;
                }
                let count = m.points.len().min(4) as u8;
                contacts += u32::from(count);
                self.manifold_refs.push(ManifoldRef {
                    pair: pi,
                    manifold: mi as u32,
                    body_a: sa.index,
                    body_b: sb.index,
                    writes: u8::from(sa.dynamic) | u8::from(sb.dynamic) << 1,
                    count,
                    angular: sa.rotates || sb.rotates,
                    rests: 0,
                });
            }
        }
        self.output.counters.manifolds = self.manifold_refs.len() as u32;
        self.output.counters.contacts = contacts;

        let g = s.gravity.length();
        let up = -s.gravity.normalize_or_zero();
        let mass_of = |st: &BodyState| {
            let inv = st.inv_mass.max_element();
            if inv > 0.0 {
                1.0 / inv
            } else {
                0.0
            }
        };
        let jointed = JointedMasses::new(
            &self.solver_states,
            self.joint_constraints
                .iter()
                .filter(|j| j.writes == 3)
                .map(|j| (j.body_a, j.body_b)),
            mass_of,
        );
        // Only where some awake body is more than the onset heavier than another (the
        // scaling is off below a ratio of 1).
        if s.max_support_mass_ratio >= 1.0 && max_inv_mass > min_inv_mass * scaling_onset(&s) {
            let (arena, handles) = (&self.bodies.arena, &self.solver_handles);
            self.hidden_loads.update(
                &self.manifold_refs,
                &self.narrowphase.pairs,
                &self.solver_states,
                &s,
                &mut self.supports,
                |i| {
                    handles
                        .get(i as usize)
                        .and_then(|&h| arena.get_by_index(h))
                        .map_or(0.0, |b| -s.gravity.dot(b.pose.translation))
                },
            );
        } else {
            self.hidden_loads.clear();
        }
        if max_inv_mass > min_inv_mass * PINCHED_MASS_RATIO {
            self.pinched.update(
                &self.manifold_refs,
                &self.narrowphase.pairs,
                &self.solver_states,
                s.gravity,
            );
        } else {
            self.pinched.clear();
        }
        let (hidden, pinched) = (&self.hidden_loads, &self.pinched);
        let resting = if bouncy {
            RestingAccelerations::new(
                &mut self.manifold_refs,
                &self.narrowphase.pairs,
                &self.solver_bodies,
                &self.solver_states,
                s.linear_slop,
                s.dt,
            )
        } else {
            RestingAccelerations::default()
        };
        let (pairs, bodies, states, manifolds, supports, handles) = (
            &self.narrowphase.pairs,
            &self.solver_bodies,
            &self.solver_states,
            &self.manifold_refs,
            &mut self.supports,
            &self.solver_handles,
        );
        // Whether a column face is one its depth budget stiffened: how many column passes
        // the step needs (`column_passes`).
        let mut budget_column = false;
        let mut prepare_one = |r: &ManifoldRef,
                               out: &mut PreparedManifold,
                               overloads: &mut Vec<Overload>| {
            // Written in place: the constraint whole, the first `count` points field by field.
            let PreparedManifold {
                constraint: c,
                points,
            } = out;
            let pair = &pairs[r.pair as usize];
            let m = &pair.manifolds[r.manifold as usize];
            let n = m.normal;
            let support_mass = support_mass_scale(r, states, &s, supports, manifolds, pairs);
            let t1 = m.tangent1;
            let t2 = n.cross(t1);
            *c = ContactConstraint {
                body_a: r.body_a,
                body_b: r.body_b,
                writes: r.writes,
                angular: r.angular,
                normal: n.into(),
                tangent: [t1.into(), t2.into()],
                restitution: pair.restitution,
                elastic: false,
                column: false,
                column_friction: false,
                bounce_accel: 0.0,
                pressing: [Vec3A::ZERO; 2],
                load_level_share: 0.0,
                mass_scale: support_mass.factors(),
                softness: Softness::RIGID,
                touching: touching_distance(pair.size, pair.reach),
                count: r.count,
                friction: FrictionPart::default(),
                block: NormalBlock::default(),
            };
            let mut anchors = [(Vec3A::ZERO, Vec3A::ZERO); 4];
            let (mut tangent, mut twist) = (Vec3::ZERO, 0.0f32);
            let count = usize::from(r.count);
            for (k, p) in m.points.iter().take(count).enumerate() {
                anchors[k] = (p.anchor_a.into(), p.anchor_b.into());
                tangent += p.tangent_impulse;
                twist += p.twist_impulse;
                points[k].base_separation = p.separation;
                // An impact's impulse is not a load (see `LaneResult::impact`).
                points[k].normal_impulse = if p.impact { 0.0 } else { p.normal_impulse };
            }
            c.friction.tangent_impulse = [tangent.dot(t1), tangent.dot(t2)];
            c.friction.twist_impulse = twist;
            prepare(
                c,
                &mut points[..count],
                &anchors[..count],
                bodies,
                states,
                pair.static_friction,
                pair.dynamic_friction,
                s.static_friction_speed,
            );
            let (upper, lower) = upper_lower(s.gravity, n, r.body_a, r.body_b);
            // The friction bound of a support under a scaled light body carries the load
            // the scaling hides from it (see `HiddenLoads`): folded into the coefficient
            // (a field of its own in every constraint cost the 100-row pyramid, which has
            // none, 5–10 %), except on faces levelled for having no friction.
            let hidden_factor = hidden.factor(upper);
            let carries_hidden = hidden_factor > 1.0 && c.friction.friction >= LEVEL_MAX_FRICTION;
            if carries_hidden {
                c.friction.friction *= hidden_factor;
            }
            if pair.restitution > 0.0 {
                // Relative normal acceleration (gravity, forces, supports) for the impact
                // speed.
                let accel = n.dot(resting.get(r, 1) - resting.get(r, 0));
                c.bounce_accel = accel;
                c.pressing = [0, 1].map(|side| resting.pressing(r, side).into());
                for cp in &mut points[..count] {
                    cp.restitution_velocity = bounce_velocity(
                        cp.relative_velocity,
                        cp.base_separation,
                        accel,
                        h,
                        s.dt,
                        pair.restitution,
                        s.restitution_threshold,
                    )
                    .unwrap_or_else(|| {
                        held_velocity(
                            cp.relative_velocity,
                            cp.base_separation,
                            accel,
                            s.dt,
                            pair.restitution,
                        )
                    });
                }
                // Elastic: no point's impact was made inelastic by the threshold (one
                // that bounces without it but not with it).
                let threshold = s.restitution_threshold;
                c.elastic = pair.elastic()
                    && points[..count].iter().all(|cp| {
                        cp.restitution_velocity > 0.0
                            || threshold == 0.0
                            || bounce_velocity(
                                cp.relative_velocity,
                                cp.base_separation,
                                accel,
                                h,
                                s.dt,
                                1.0,
                                0.0,
                            )
                            .is_none()
                    });
            }
            // Static contacts are twice as stiff (Box2D v3); both stiffen with load, and
            // further where the load would press them deeper than the penetration budget
            // of the smaller body's size.
            let base_hz = if r.writes == 3 { hertz } else { 2.0 * hertz };
            let (load, mass) = points[..count].iter().fold((0.0f32, 0.0f32), |(p, m), cp| {
                (p + cp.normal_impulse, m + cp.normal_mass)
            });
            let touching = points[..count]
                .iter()
                .any(|cp| cp.base_separation <= s.linear_slop);
            // A new face carries from its first step the column resting on it: its
            // warm-started impulse grows to that load over steps, and meanwhile the faces of
            // a column placed at rest telescope (Gauss–Seidel in free fall sees no relative
            // velocity above the lowest face): five 1 mm cubes at balanced sank 56 % of a
            // cube into each other in the first step, and fell where they were offset.
            let load = if touching && c.block.patch && pair.solved_steps < NEW_FACE_STEPS {
                let column =
                    supports.column_mass(upper, manifolds, pairs, s.gravity, states, mass_of);
                load.max(column * g_h)
            } else {
                load
            };
            let own = mass * g_h;
            let ratio = if own > 0.0 { load / own } else { 1.0 };
            let cap = if pair.ball_ball {
                max_ball_hertz
            } else {
                max_hertz
            };
            // The load: the largest it carried recently, and from the step it is made at
            // least the weight of the body on top (its warm-started load lags by steps, and
            // a contact under a heavy body sinks meanwhile).
            let remembered = load.max(pair.load_memory);
            // The body on the face (its weight, the mass that moves rigidly with the face,
            // what a static face carries in its weights).
            let upper_mass = mass_of(&states[upper as usize]);
            let weight = if touching { g * upper_mass } else { 0.0 };
            let load_accel = if mass > 0.0 {
                (remembered / (mass * h)).max(weight / mass)
            } else {
                0.0
            };
            let budget = s.max_penetration_fraction * pair.size;
            // A face of a heavy body's column on a light one (the heavy body's, and each
            // support face down the column under it) is stiffened for a share of the budget
            // (see `HEAVY_COLUMN_DEPTH_SHARE`).
            let heavy_column = support_mass == SupportMass::Column
                || (hidden.carries_heavy_column(upper)
                    && is_support(r, pair, up)
                    && supports.single(upper, manifolds, pairs, s.gravity));
            let held_depth = if heavy_column {
                let omega_base = 2.0 * std::f32::consts::PI * base_hz;
                let alone = g / (omega_base * omega_base);
                (HEAVY_COLUMN_DEPTH_SHARE * budget).min(HEAVY_COLUMN_RESTING_DEPTHS * alone)
            } else {
                budget
            };
            let load_hz = Softness::load_hertz(base_hz, ratio, cap);
            let omega_load = 2.0 * std::f32::consts::PI * load_hz;
            // Most contacts settle within their budget at the load stiffness: nothing more.
            let within_budget = load_accel <= held_depth * omega_load * omega_load;
            // How much stiffer than its points the face may be: the square root of the
            // pair's reduced mass over the sum of its points' effective masses, which their
            // levers shrink. The points are springs of the same stiffness over their own
            // effective masses, and the face's depth follows the sum of the springs against
            // the pair's reduced mass: a thin plate's corners carry a seventh of its mass
            // each (a cube's a quarter), and at the points' cap a 1 mm plate on the ground
            // sank 5.4 % of its thickness at balanced, a 1 mm cube 3.1 %. Allowed this
            // much stiffer, the face's depth mode reaches the cap; bounded to twice it. Faces
            // only: a single point's effective mass is the pair's reduced one to rounding (a
            // ball pair's ratio read one ulp over 1, its cap rose by 5e-8, and the 8,000
            // poured spheres at balanced settled otherwise and cost 1.8 times as much).
            let lever = || {
                if !c.block.patch || mass <= 0.0 {
                    return 1.0;
                }
                let lower_mass = mass_of(&states[lower as usize]);
                let reduced = if lower_mass > 0.0 {
                    upper_mass * lower_mass / (upper_mass + lower_mass)
                } else {
                    upper_mass
                };
                (reduced / mass).clamp(1.0, MAX_LEVER_STIFFENING).sqrt()
            };
            // The softness and stiffness, Hz, of the face stiffened for its budget up to
            // `max_hz` (times its `lever`).
            let stiffen = |max_hz: f32| {
                if within_budget {
                    return (Softness::new(load_hz, s.contact_damping_ratio, h), load_hz);
                }
                let size_hz = Softness::size_hertz(load_accel, held_depth).min(max_hz * lever());
                let used = size_hz.max(load_hz);
                let softness = if size_hz > load_hz {
                    // The mass it carries, in units of its own effective mass.
                    let stiffening = (used / base_hz).powi(2);
                    let carried = if g > 0.0 { load_accel / g } else { stiffening };
                    // Damped for the mass that moves rigidly with the contact: what it
                    // carries, but no more than the body on it and the bodies jointed to
                    // that one. Bodies resting further up hang on soft contacts of their
                    // own (springs in series) and do not ring with this one; damped as if
                    // they sat on it rigidly, the rows under the 100-row pyramid (ζ·10)
                    // corrected position errors so slowly that an out-of-plane sway grew
                    // in it: its largest displacement over five starts was 0.81–3.21 m
                    // (mean 2.17), now 0.68–1.86 m (mean 1.35; rapier 0.68 m).
                    // A heavy body's column on a light one moves with its faces as one:
                    // the light body between them is too light to part them. Damped for
                    // the light body alone, its base face let a 1000:1 pair of 40 cm cubes
                    // on a 14° incline rock past tipping at balanced and throw the light
                    // one out (`tests/heavy_and_small.rs`).
                    let rigid = if heavy_column {
                        f32::MAX
                    } else if mass > 0.0 {
                        jointed.get(upper).unwrap_or(upper_mass) / mass
                    } else {
                        f32::MAX
                    };
                    Softness::for_supported_mass(
                        size_hz,
                        s.contact_damping_ratio,
                        h,
                        carried.max(stiffening).min(rigid),
                    )
                } else {
                    Softness::new(load_hz, s.contact_damping_ratio, h)
                };
                (softness, used)
            };
            let (softness, used_hz) = stiffen(max_size_hertz);
            // Only a face stiffened past its load's stiffness for its size budget (or the
            // base face of a column, see below), or one of a heavy body's column on a light
            // one (`SupportMass::Column`), between bodies resting on one face each: a
            // column, not a pyramid (whose bricks rest on two and spread the load they
            // carry), and not under a scaled heavy-on-light pair (its friction carries the
            // load the scaling hides, `HiddenLoads`; taken for a column, a 10 cm cube on a
            // 1 cm one rocked 11 % of its size aside at balanced).
            // Resting: every point touching and closing or parting slower than
            // `column_rest_speed`. Tested last: the cheap tests rule out nearly every face
            // first. A new face that has been a column since it first touched was placed at
            // rest: in its first steps it sinks into its budget, closing as fast as the
            // column above it settles (the second face of ten 1 cm cubes on a 10 cm box
            // closed at 0.11 g·dt in its second step, lost its column stiffness and waited
            // `COLUMN_SETTLE_STEPS` for it, sinking 5.3 % of a cube meanwhile); it rests
            // while it closes slower than one step of free fall, as a body that fell onto it
            // for longer than a step does not.
            let resting = |c: &ContactConstraint| {
                let placed =
                    pair.solved_steps < NEW_FACE_STEPS && pair.column_steps == pair.solved_steps;
                let rest_speed = column_rest_speed(budget, used_hz, g, s.dt);
                let rest_speed = if placed {
                    rest_speed.max(g * s.dt)
                } else {
                    rest_speed
                };
                points[..count].iter().all(|cp| {
                    cp.base_separation <= c.touching && cp.relative_velocity.abs() <= rest_speed
                })
            };
            // What the face carries: its load ratio, and on a static body no more than its
            // load in weights of the body on it. The ratio is over the face's own effective
            // mass, which its points' levers shrink: a lone 2 mm plate on the ground
            // measured 1.75, a wedge 3.0, and got the column's passes every step. (Between
            // two dynamic bodies the ratio stays: the effective mass is the pair's reduced
            // one, and the top face of a column belongs to it. The weights alone, in place
            // of the ratio on static faces, took more of the 100-row pyramid's collapse at
            // fast for columns and threw its bricks 477 m instead of 100.)
            let column_load = || {
                if r.writes == 3 {
                    return ratio;
                }
                if upper_mass > 0.0 {
                    ratio.min(load / (upper_mass * g_h))
                } else {
                    0.0
                }
            };
            // The face in the column its bodies make, at a stiffness.
            let chain = |supports: &mut ColumnSupports, hertz: f32| ChainFace {
                length: f32::from(supports.column_length(
                    upper,
                    manifolds,
                    pairs,
                    s.gravity,
                    states.len(),
                )),
                load_ratio: ratio,
                hertz,
                size: pair.size,
                g,
                h,
            };
            // Stiff past a radian a substep: set so by its depth budget, or, at the base
            // rate, under a column (its base face); or a face whose column's chain needs
            // more levelling than the iterations converge, with friction or without (a
            // frictionless face, levelled anyway, was not taken for one: ten frictionless
            // 1 m cubes zig-zag at fast fluttered and fell within 7 s; see `column_face`).
            let arena = |b: u32| handles.get(b as usize).filter(|_| b != 0);
            // Stiffened by its depth budget past the base rate.
            let budgeted = used_hz > load_hz;
            let stiff = column_face(column_load(), used_hz, h)
                && (budgeted || arena(upper).is_some_and(|&b| supports.carries_column(b)));
            // A heavy body's column on a light one is one whenever it rests on it as
            // `support_mass_scale` tells (solved on the true masses, it must be: the
            // passes alone let a 1000:1 pair of 40 cm cubes at fast go through each other
            // once gravity tilted and its faces closed faster than `column_rest_speed`).
            c.column = c.block.patch
                && g > 0.0
                && !carries_hidden
                && c.mass_scale == [1.0; 2]
                && supports.single(upper, manifolds, pairs, s.gravity)
                && supports.single(lower, manifolds, pairs, s.gravity)
                && (heavy_column
                    || ((stiff || chain(supports, used_hz).needs_column()) && resting(c)));
            // A light body pinched between two faces with friction is held sideways and in
            // tilt by both at once, far stiffer than its own inertia: left to the passes
            // their friction rows whirled its tilt (a 1 cm cube under a 10 cm one, on the
            // true masses, was squeezed out at every preset). Elsewhere the passes hold a
            // column's friction, and the coarse system stays three unknowns a face (with
            // friction everywhere the 20-box stack at balanced cost twice as much).
            c.column_friction =
                c.column && (heavy_column || pinched.get(upper) || pinched.get(lower));
            // A column face settled for some steps, or one since it first touched, may
            // stiffen past the step's cap.
            let settled =
                pair.column_steps >= COLUMN_SETTLE_STEPS || pair.column_steps == pair.solved_steps;
            // Its column's lift of the cap, for a column face (see `Softness::column_lift`).
            let column_lift = c.column.then(|| {
                let length =
                    supports.column_length(upper, manifolds, pairs, s.gravity, states.len());
                Softness::column_lift(ratio, length)
            });
            let (softness, final_hz) = match column_lift {
                Some(lift) if settled => stiffen(Softness::max_column_hertz(h, s.dt, lift)),
                _ => (softness, used_hz),
            };
            c.softness = softness;
            if c.column {
                c.friction.denoise_twist();
            }
            // A heavy body's column takes them all: with the soft columns' two passes (or
            // four), a 40 cm cube 1000 times heavier than the one under it, resting 6–12 cm
            // off centre, rocked over within 6 s at fast; from eight it stands
            // (`tests/heavy_and_small.rs`).
            budget_column |= c.column && stiff && budgeted;
            // Deeper than twice the budget even at the stiffest contact, under the load of
            // this step (not the remembered one, which an impact fills for several steps):
            // a candidate, named once it is one `OVERLOAD_SUSTAIN_STEPS` running.
            if !within_budget && load > 0.0 && !pair.overload_reported {
                let omega = 2.0 * std::f32::consts::PI * final_hz;
                let own_accel = (load / (mass * h)).max(weight / mass);
                let depth = own_accel / (omega * omega);
                if depth > OVERLOAD_DEPTH_FACTOR * budget {
                    let stiffening = (final_hz / base_hz).powi(2);
                    overloads.push(Overload {
                        pair: r.pair,
                        depth,
                        budget,
                        // Held where it would not be named: within the reported depth.
                        needed_hz: Softness::size_hertz(load_accel, OVERLOAD_DEPTH_FACTOR * budget),
                        load_ratio: if g > 0.0 { own_accel / g } else { stiffening },
                        column_lift,
                    });
                }
            }
            // Levelled as a column face, for its load, or for the column it is in (a face
            // with friction between bodies resting on one face each: a frictionless face is
            // levelled anyway).
            let for_load = if levelled_for_load(ratio, used_hz, pair.size, g) {
                LOADED_LEVEL_SHARE
            } else {
                0.0
            };
            // Not on a pinched body's support (see `PinchedBodies`): frictionless faces are
            // levelled anyway, and so are a heavy body's column's, whose coarse correction
            // holds the light body's tilt from both faces at once (left unlevelled, two 1 mm
            // cubes under a 1 cm one leaned over at balanced, their soft faces too soft in
            // tilt for the load high on them, and two 1 cm ones under a 10 cm one were
            // thrown apart at fast).
            c.load_level_share =
                if pinched.get(upper) && !heavy_column && c.friction.friction >= LEVEL_MAX_FRICTION
                {
                    0.0
                } else if c.column {
                    chain(supports, final_hz).column_level_share()
                } else if c.block.patch
                    && g > 0.0
                    && c.friction.friction >= LEVEL_MAX_FRICTION
                    && supports.single(upper, manifolds, pairs, s.gravity)
                    && supports.single(lower, manifolds, pairs, s.gravity)
                {
                    for_load.max(chain(supports, used_hz).level_share())
                } else {
                    for_load
                };
        };
        let mut overloads: Vec<Overload> = Vec::new();
        let prepare_one = |r: &ManifoldRef, out: &mut PreparedManifold| {
            prepare_one(r, out, &mut overloads);
        };
        self.contact_batches
            .build(&self.manifold_refs, states, prepare_one);
        self.report_overloads(&overloads);

        let params = SolveParams {
            dt: s.dt,
            substeps,
            iterations: s.solver_iterations,
            relax_iterations: s.relax_iterations,
            max_push: s.max_contact_push_speed,
            restitution: bouncy,
            max_linear_speed: s.max_linear_speed,
            max_angular_speed: s.max_angular_speed,
            column_passes: column_passes(budget_column),
            jitter: Jitter {
                dt: s.dt,
                gravity: s.gravity.length(),
            },
        };
        let elastic = if elastic {
            let e = &mut self.elastic_energy;
            e.pressing.clear();
            e.pressing
                .extend((0..self.solver_states.len()).map(|i| Vec3A::from(resting.pressing_of(i))));
            Some(e)
        } else {
            None
        };
        self.output.counters.gyro_not_converged = solve_substeps(
            &mut self.solver_bodies,
            &mut self.solver_states,
            &mut self.contact_batches,
            &mut self.joint_constraints,
            &mut self.joint_rows,
            &params,
            elastic,
        );
        self.finish_joints();

        let decay = 0.5f32.powf(s.dt / LOAD_MEMORY_HALF_LIFE);
        // Store impulses for warm starting and events; a manifold's friction is shared among
        // its points in proportion to their normal impulses.
        let (refs, pairs) = (&self.manifold_refs, &mut self.narrowphase.pairs);
        let (supports, handles) = (&mut self.supports, &self.solver_handles);
        supports.forget_columns();
        self.contact_batches
            .for_each_result(params.jitter, |ri, result| {
                let c = &refs[ri as usize];
                let pair = &mut pairs[c.pair as usize];
                if result.column {
                    let n = pair.manifolds[c.manifold as usize].normal;
                    let (_, lower) = upper_lower(s.gravity, n, c.body_a, c.body_b);
                    if let Some(&body) = handles.get(lower as usize).filter(|_| lower != 0) {
                        supports.column_rests_on(body);
                    }
                }
                let m = &mut pair.manifolds[c.manifold as usize];
                let count = usize::from(c.count);
                let normal = &result.normal_impulse[..count];
                let [t1, t2] = result.tangent_impulse;
                let tangent = Vec3::from(result.tangent[0] * t1 + result.tangent[1] * t2);
                let total: f32 = normal.iter().sum();
                let load: f32 = normal
                    .iter()
                    .zip(result.impact)
                    .filter_map(|(&j, impact)| (!impact).then_some(j))
                    .sum();
                for (k, p) in m.points.iter_mut().take(count).enumerate() {
                    let share = if total > 0.0 {
                        normal[k] / total
                    } else {
                        1.0 / count as f32
                    };
                    p.normal_impulse = normal[k];
                    p.tangent_impulse = tangent * share;
                    p.twist_impulse = result.twist_impulse * share;
                    p.max_normal_impulse = result.max_normal_impulse[k];
                    p.impact = result.impact[k];
                }
                // Load memory decays once per step (with the pair's first manifold), then takes
                // this step's load (see `LOAD_MEMORY_HALF_LIFE`).
                let kept = if c.manifold == 0 {
                    pair.load_memory * decay
                } else {
                    pair.load_memory
                };
                pair.load_memory = kept.max(load);
                if c.manifold == 0 {
                    pair.solved_steps = pair.solved_steps.saturating_add(1);
                }
                pair.column_steps = if result.column {
                    pair.column_steps.saturating_add(1)
                } else {
                    0
                };
                // Every non-empty manifold of a solved pair is solved: the pair's flag is exact.
                let pushing = m.points.iter().any(|p| p.max_normal_impulse > 0.0);
                pair.solved_pushing = Some(pair.solved_pushing == Some(true) || pushing);
            });
    }
}
