//! [`StepReports`]: what a physics step tells the user, said once per entity — contacts
//! deeper than their budget, speed caps hit, bodies past the precise range of `f32`.

use std::collections::HashSet;

use onyx_physics::{BodyHandle, FarBody, OverloadedContact, SpeedCap, SpeedCapHit, StepOutput};

/// What was said, so a body rebuilt from changed components (a new handle, which the engine
/// reports afresh) is not reported twice.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Said {
    Overload(hecs::Entity, hecs::Entity),
    SpeedCap(hecs::Entity, SpeedCap),
    Far(hecs::Entity),
}

/// The warnings of [`StepOutput::overloaded_contacts`], [`StepOutput::speed_caps`] and
/// [`StepOutput::far_bodies`], each entity (or pair) and kind once.
#[derive(Debug, Default)]
pub(super) struct StepReports {
    said: HashSet<Said>,
}

/// How a body is named to the user: its entity's name and handle.
pub(super) struct Named {
    pub entity: hecs::Entity,
    pub name: Option<String>,
}

impl std::fmt::Display for Named {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let id = crate::entity_id::to_api(self.entity);
        match &self.name {
            Some(name) => write!(f, "{name:?} (entity {id})"),
            None => write!(f, "entity {id}"),
        }
    }
}

impl StepReports {
    /// The sentences for what `output` reports that was not said yet; `named` finds a body's
    /// entity (bodies without one are skipped).
    pub fn sentences(
        &mut self,
        output: &StepOutput,
        named: impl Fn(BodyHandle) -> Option<Named>,
    ) -> Vec<String> {
        let mut lines = Vec::new();
        for c in &output.overloaded_contacts {
            let (Some(a), Some(b)) = (named(c.body_a), named(c.body_b)) else {
                continue;
            };
            if self.said.insert(Said::Overload(a.entity, b.entity)) {
                lines.push(overload_sentence(c, &a, &b));
            }
        }
        for hit in &output.speed_caps {
            let Some(body) = named(hit.body) else {
                continue;
            };
            if self.said.insert(Said::SpeedCap(body.entity, hit.cap)) {
                lines.push(speed_cap_sentence(hit, &body));
            }
        }
        for far in &output.far_bodies {
            let Some(body) = named(far.body) else {
                continue;
            };
            if self.said.insert(Said::Far(body.entity)) {
                lines.push(far_sentence(far, &body));
            }
        }
        lines
    }
}

fn overload_sentence(c: &OverloadedContact, a: &Named, b: &Named) -> String {
    let ratio = c
        .mass_ratio
        .map(|r| format!(" (mass ratio {r:.0}:1)"))
        .unwrap_or_default();
    let cure = match c.holding_preset {
        Some(p) => format!("preset {p} holds it"),
        None => "no preset holds it: more substeps, a lighter load or a larger body do".into(),
    };
    format!(
        "physics: bodies {a}/{b}{ratio}: the contact carries {:.0}× the load of a body \
         resting alone, sinks ≈{} (budget {}); \
         {cure}",
        c.load_ratio,
        length(c.expected_depth),
        length(c.allowed_depth)
    )
}

/// A depth in the unit that shows its digits: a 1 mm ball's budget is 20 µm, not "0.000 m".
fn length(metres: f32) -> String {
    let m = metres.abs();
    if m >= 1.0 {
        format!("{metres:.2} m")
    } else if m >= 1e-3 {
        format!("{:.1} mm", metres * 1e3)
    } else {
        format!("{:.1} µm", metres * 1e6)
    }
}

fn speed_cap_sentence(hit: &SpeedCapHit, body: &Named) -> String {
    let (what, unit) = match hit.cap {
        SpeedCap::Linear => ("speed", "m/s"),
        SpeedCap::Angular => ("spin", "rad/s"),
    };
    format!(
        "physics: body {body} was clamped to the {what} cap of {} {unit} ({}); raise it in \
         the scene's physics settings if it should go faster",
        hit.limit,
        hit.cap.setting()
    )
}

fn far_sentence(far: &FarBody, body: &Named) -> String {
    // The range of `max_position_spacing`, or a shorter one for a body small enough that
    // the spacing there is a sizeable part of it.
    let why = if far.size < f32::MAX {
        format!(
            "where f32 positions hold a body {} across to its resting accuracy \
             (max_position_spacing, max_penetration_fraction)",
            length(far.size)
        )
    } else {
        "where f32 positions are spaced at most max_position_spacing apart".to_owned()
    };
    format!(
        "physics: body {body} is {:.0} m from the origin, past the precise range of {:.0} m \
         {why}: slow motion and resting contacts there lose accuracy to rounding; move the \
         scene nearer the origin",
        far.distance, far.range
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use onyx_physics::{ColliderDesc, PhysicsPreset, PhysicsWorld, RigidBodyDesc};

    #[test]
    fn each_report_is_one_sentence_per_entity_and_kind() {
        let mut world = PhysicsWorld::default();
        let body = world.insert_body(RigidBodyDesc::dynamic());
        world.insert_collider(ColliderDesc::sphere(0.5), body);
        let mut ecs = hecs::World::new();
        let e = ecs.spawn(());
        let output = StepOutput {
            speed_caps: vec![SpeedCapHit {
                body,
                cap: SpeedCap::Angular,
                limit: 200.0,
            }],
            far_bodies: vec![FarBody {
                body,
                distance: 1.0e6,
                range: 16384.0,
                size: 1.0,
            }],
            overloaded_contacts: vec![OverloadedContact {
                body_a: body,
                body_b: body,
                load_ratio: 999.0,
                mass_ratio: Some(1000.0),
                expected_depth: 0.012,
                allowed_depth: 0.002,
                holding_preset: Some(PhysicsPreset::Precise),
            }],
            ..StepOutput::default()
        };
        let named = |_| {
            Some(Named {
                entity: e,
                name: Some("crate".into()),
            })
        };
        let mut reports = StepReports::default();
        let lines = reports.sentences(&output, named);
        assert_eq!(lines.len(), 3, "{lines:#?}");
        assert!(lines[0].contains("bodies \"crate\""), "{}", lines[0]);
        assert!(lines[0].contains("mass ratio 1000:1"), "{}", lines[0]);
        assert!(
            lines[0].contains("carries 999× the load of a body resting alone"),
            "{}",
            lines[0]
        );
        assert!(
            lines[0].contains("sinks ≈12.0 mm (budget 2.0 mm)"),
            "{}",
            lines[0]
        );
        assert!(
            lines[0].ends_with("preset precise holds it"),
            "{}",
            lines[0]
        );
        assert!(lines[1].contains("max_angular_speed"), "{}", lines[1]);
        assert!(lines[1].contains("200 rad/s"), "{}", lines[1]);
        assert!(
            lines[2].contains("1000000 m from the origin"),
            "{}",
            lines[2]
        );
        assert!(lines[2].contains("16384 m"), "{}", lines[2]);
        // A rebuilt body (the engine reports it afresh) is not reported again.
        assert!(reports.sentences(&output, named).is_empty());
    }

    #[test]
    fn depths_are_given_in_a_unit_that_shows_them() {
        assert_eq!(length(0.012), "12.0 mm");
        assert_eq!(length(2.0e-5), "20.0 µm");
        assert_eq!(length(1.5), "1.50 m");
    }
}
