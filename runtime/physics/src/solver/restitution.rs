//! [`bounce_velocity`]: the separating velocity restitution gives a contact point, from the
//! relative velocity before the solve (pre-solve relative velocity, as in Box2D v3), taken at
//! the moment of impact inside the step; [`stored_rebound`]: that rebound as the solver's
//! velocity where the step leaves the bodies.
//!
//! Three corrections make `e = 1` elastic, which a plain `v₊ = −e·v₋` on the step-start
//! velocity is not (a ball lost about `g·dt` of speed per bounce and stopped within 24 s):
//!
//! - **Impact speed.** The bodies close the gap `s₀` (the separation at step start) under
//!   their relative normal acceleration `a` (gravity, forces) before they touch: the
//!   approach speed at impact is `√(u² − 2·a·s₀)`, not the step-start `u`. That is the energy
//!   the contact must return.
//! - **Where the step ends.** The substeps leave the bodies at separation `s₁`: a little
//!   inside each other (the soft contact's deflection), or a few millimetres short when the
//!   last substep's speculative row stopped them ahead of the next. The rebound leaves from
//!   there with `√(v² + 2·a·s₁)`, so that the energy is the impact's. A side held by its own
//!   supports (a ball lying on the floor, for one landing on it) counts where it started the
//!   step: `a` treats it as fixed, and the impact pressed it a few millimetres into its
//!   support through that soft contact, which the rebound measured from there lost as
//!   potential energy (the upper ball of a column of two kept 78 % of the column's energy
//!   over 20 s at 60 Hz, now 99 %).
//! - **Substep phase.** The solver's velocities are those of each substep's position update,
//!   which lead (for `a < 0`) the instantaneous velocity at the substep's end by `a·h/2`
//!   (semi-implicit Euler). The step-start velocity is `u = v₀ + a·h/2`; the rebound stored is
//!   the instantaneous one `− a·h/2`, so the next substep's update starts from it exactly.
//!
//! With these a ball with `e = 1` returns to its drop height bounce after bounce; the time it
//! rests on the surface inside the impact step only delays it.
//!
//! **Simultaneous impacts.** Over one step the contact impulses `Λᵢ` change the kinetic
//! energy by `Σ ½·Λᵢ·(vᵢ⁻ + vᵢ⁺)` (relative normal velocities before and after), so the
//! step keeps the energy of `e = 1` impacts when every point that pushed leaves at
//! `v⁺ = −v⁻`. The restitution passes therefore drive every loaded point of a bouncy
//! manifold: one that bounces to its rebound ([`bounce_velocity`]), and one that does not
//! (resting, or pushed by another impact in the same step) to [`held_velocity`], not merely
//! apart. Driven only where they bounced, a ball landing on one that lay on the floor pushed
//! the lower one into it and kept half the impact; 50 elastic balls in a box lost 24 % of
//! their energy over 10,000 steps under gravity at 60 Hz (now 0.4 %). The passes run until
//! no point's velocity changes by more than a tolerance (see `solve.rs`). Their impulses
//! are an impact's, not a load's: the next step does not warm start them.
//!
//! **Energy of elastic impacts.** The passes return each impact's energy at its contact;
//! where a body meets two others in one step the positions the soft substeps leave match
//! no sequence of rigid impacts (a ball hopping on the floor, struck from above, is held by
//! the floor in the air), and up to 0.2 % of the crowd's energy went each such step. Where
//! the law is exact (frictionless `e = 1` contacts only), [`super::elastic_energy`] scales
//! the passes' impulses of each group of bodies so that its energy is its step-start
//! energy: the crowd at 30 Hz lost 2.5–8.7 % over 10,000 steps, now at most 0.6 %.

/// Rebound speed, m/s, that restitution `e` gives a point whose relative normal velocity was
/// `v0` (m/s, negative approaching) at step start, at separation `s0` (m), under relative
/// normal acceleration `accel` (m/s², negative pulling the bodies together) with substeps of
/// `h` seconds in a step of `dt`: `e` times the approach speed at impact (instantaneous, at
/// the surface). `None` if the impact is no faster than `threshold` (m/s), or than the speed
/// one substep of `accel` gives (how a resting contact looks to the integrator: support, not
/// an impact), or the bodies do not close within the step. `e <= 0` never bounces.
///
/// Separating bodies that `accel` pulls back together meet again only after
/// `(u + √(u² − 2·accel·s₀)) / −accel`: a ball that has just left the floor does not hit it
/// again in this step, whatever else pushes it there (a second ball landing on it: counted
/// as a floor impact, its rebound target threw the upper ball up at 3.9 m/s instead of 1.2
/// and a column of two elastic balls gained 45 % of its energy at 30 Hz).
#[must_use]
pub fn bounce_velocity(
    v0: f32,
    s0: f32,
    accel: f32,
    h: f32,
    dt: f32,
    e: f32,
    threshold: f32,
) -> Option<f32> {
    if e <= 0.0 {
        return None;
    }
    let u = v0 + 0.5 * accel * h;
    let impact = if s0 > 0.0 {
        let q = u * u - 2.0 * accel * s0;
        // Closing now, or pulled together within the step.
        if q <= 0.0 || (u >= 0.0 && (accel >= 0.0 || (u + q.sqrt()) > -accel * dt)) {
            return None;
        }
        q.sqrt()
    } else if u < 0.0 {
        -u
    } else {
        return None;
    };
    (impact > threshold.max(accel.abs() * h)).then_some(e * impact)
}

/// Relative normal velocity, m/s, that restitution `e` holds a loaded point to at least
/// when it does not bounce ([`bounce_velocity`] is `None`), from its relative normal
/// velocity `v0` (m/s) and separation `s0` (m) at step start, under relative normal
/// acceleration `accel` (m/s²) over a step of `dt`: `−e·v0` when the bodies were separating
/// (they may close again at that speed, no faster), else 0 (they do not approach). Bodies
/// apart at step start may also close as fast as `accel` brings them by the step's end:
/// braked in the air by the speculative row, a ball falling the last 1.6 mm onto the floor
/// was otherwise held up by it and lost a third of its next rebound.
#[must_use]
pub fn held_velocity(v0: f32, s0: f32, accel: f32, dt: f32, e: f32) -> f32 {
    let held = -e * v0.max(0.0);
    if s0 > 0.0 {
        held.min(v0 + accel * dt)
    } else {
        held
    }
}

/// The solver velocity, m/s, for a rebound of `speed` (from [`bounce_velocity`]) leaving
/// from separation `s1` (m) under relative normal acceleration `accel` with substeps of `h`
/// (see the module docs): `√max(0, speed² + 2·accel·s1) − accel·h/2`.
#[must_use]
pub fn stored_rebound(speed: f32, accel: f32, s1: f32, h: f32) -> f32 {
    (speed * speed + 2.0 * accel * s1).max(0.0).sqrt() - 0.5 * accel * h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn falling_ball_gets_back_the_speed_it_has_at_the_surface() {
        // 5 cm above the ground at 3 m/s down, under g: at the surface √(u² + 2·g·s₀).
        let (g, h) = (9.81f32, 1.0 / 240.0);
        let v0 = -3.0;
        let u = v0 - 0.5 * g * h;
        let expected = (u * u + 2.0 * g * 0.05).sqrt();
        let v = bounce_velocity(v0, 0.05, -g, h, 4.0 * h, 1.0, 0.0).expect("it bounces");
        assert!(
            (v - expected).abs() < 1e-5,
            "rebound {v}, expected {expected}"
        );
    }

    #[test]
    fn a_rebound_left_short_of_the_surface_keeps_the_impact_energy() {
        // Leaving 5 mm up at v: ½v² + g·0.005 = ½·speed².
        let (g, speed) = (9.81f32, 4.0f32);
        let v = stored_rebound(speed, -g, 0.005, 0.0);
        let e = 0.5 * v * v + g * 0.005;
        assert!(
            (e - 0.5 * speed * speed).abs() < 1e-5,
            "energy {e}, expected {}",
            0.5 * speed * speed
        );
    }

    #[test]
    fn slow_impacts_under_the_threshold_do_not_bounce() {
        assert_eq!(bounce_velocity(-0.5, 0.0, 0.0, 0.01, 0.04, 1.0, 1.0), None);
        assert_eq!(
            bounce_velocity(-0.5, 0.0, 0.0, 0.01, 0.04, 1.0, 0.0),
            Some(0.5)
        );
        assert_eq!(bounce_velocity(0.5, 0.1, 0.0, 0.01, 0.04, 1.0, 0.0), None);
        assert_eq!(bounce_velocity(-5.0, 0.0, 0.0, 0.01, 0.04, 0.0, 0.0), None);
    }

    #[test]
    fn held_points_do_not_approach_unless_they_separated_or_were_apart() {
        let (g, dt) = (9.81f32, 1.0 / 60.0);
        // Touching and approaching or at rest: held apart.
        assert_eq!(held_velocity(-0.3, 0.0, -g, dt, 1.0), 0.0);
        assert_eq!(held_velocity(0.0, -0.001, -g, dt, 0.5), 0.0);
        // Touching and separating at 0.4 m/s: they may close again at e·0.4.
        assert_eq!(held_velocity(0.4, 0.0, -g, dt, 0.5), -0.2);
        // 1.6 mm apart, rising at 3 cm/s: gravity closes them at up to 13 cm/s by the end.
        let v = held_velocity(0.03, 0.0016, -g, dt, 0.8);
        assert!((v - (0.03 - g * dt)).abs() < 1e-6, "{v}");
    }

    #[test]
    fn a_body_leaving_the_surface_does_not_hit_it_again_in_the_same_step() {
        let (g, h, dt) = (9.81f32, 1.0 / 120.0, 1.0 / 30.0);
        // Leaving at 1.5 m/s from 1 mm up: back only after ~0.3 s.
        assert_eq!(bounce_velocity(1.5, 0.001, -g, h, dt, 1.0, 0.0), None);
        // Rising at 5 cm/s from 1 mm up: back after 15 ms, within the step, at √(u² + 2·g·s₀).
        let u = 0.05 - 0.5 * g * h;
        let expected = (u * u + 2.0 * g * 0.001).sqrt();
        let v = bounce_velocity(0.05, 0.001, -g, h, dt, 1.0, 0.0).expect("it lands again");
        assert!(
            (v - expected).abs() < 1e-5,
            "rebound {v}, expected {expected}"
        );
    }
}
