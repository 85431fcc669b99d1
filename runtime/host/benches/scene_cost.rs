//! "Model only what a scene requires", measured on the whole host frame (one fixed step:
//! components → physics → components, plugins dispatch, no rendering):
//!
//! - an empty world, and the same with 10,000 entities that have no physics components;
//! - 10,000 boxes resting on the ground, asleep;
//! - the same boxes kept awake (sleeping disabled), the peer that shows what sleep saves;
//! - 10,000 static colliders (level geometry) with nothing moving.
//!
//! `cargo bench -p onyx-runtime --bench scene_cost` prints each figure and the ratios.

use std::hint::black_box;
use std::time::Instant;

use onyx_physics::glam::Vec3;
use onyx_plugin_api::{BodyKind, Collider, ColliderShape, Name, RigidBody, Transform};
use onyx_runtime::{Host, HostConfig};

const N: usize = 10_000;
const DT: f64 = 1.0 / 60.0;

/// Median over `rounds` of the mean time of `iters` calls, nanoseconds.
fn median(rounds: usize, iters: usize, mut f: impl FnMut()) -> f64 {
    let mut v: Vec<f64> = (0..rounds)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..iters {
                f();
            }
            t.elapsed().as_nanos() as f64 / iters as f64
        })
        .collect();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn ground(host: &mut Host) {
    host.world_mut().spawn((
        Name("ground".into()),
        Transform::default(),
        Collider::new(ColliderShape::Plane),
    ));
}

/// A 100 × 100 grid of 1 m boxes resting on the ground, 2 m apart (no box touches another).
fn boxes(host: &mut Host, kind: BodyKind) {
    let side = (N as f64).sqrt() as usize;
    for i in 0..N {
        let (x, z) = ((i % side) as f32 * 2.0, (i / side) as f32 * 2.0);
        host.world_mut().spawn((
            Transform::from_translation(Vec3::new(x, 0.5, z)),
            RigidBody {
                kind,
                ..RigidBody::default()
            },
            Collider::new(ColliderShape::Box {
                half_extents: [0.5; 3],
            }),
        ));
    }
}

fn asleep(host: &Host) -> usize {
    host.world()
        .query::<&RigidBody>()
        .iter()
        .filter(|rb| rb.sleeping)
        .count()
}

fn main() {
    // `cargo bench -p onyx-runtime --bench scene_cost -- asleep` runs only the cases whose
    // key contains `asleep` (keys: empty, plain, asleep, awake, static).
    let filter: Option<String> = std::env::args().skip(1).find(|a| !a.starts_with("--"));
    let wanted = |key: &str| filter.as_deref().is_none_or(|f| key.contains(f));
    let nan = f64::NAN;
    let t_empty = if wanted("empty") { empty_world() } else { nan };
    let t_plain = if wanted("plain") {
        plain_entities()
    } else {
        nan
    };
    let (t_sleeping, slept, settle, counters) = if wanted("asleep") {
        sleeping_boxes()
    } else {
        (nan, 0, 0, Default::default())
    };
    let t_awake = if wanted("awake") { awake_boxes() } else { nan };
    let t_static = if wanted("static") {
        static_level()
    } else {
        nan
    };
    report(
        t_empty,
        t_plain,
        (t_sleeping, slept, settle, counters),
        t_awake,
        t_static,
    );
}

fn empty_world() -> f64 {
    let mut empty = Host::new(HostConfig::default());
    empty.frame(DT);
    median(21, 2_000, || {
        black_box(empty.frame(DT));
    })
}

fn plain_entities() -> f64 {
    let mut plain = Host::new(HostConfig::default());
    for i in 0..N {
        plain
            .world_mut()
            .spawn((Transform::from_translation(Vec3::splat(i as f32)),));
    }
    plain.frame(DT);
    median(11, 200, || {
        black_box(plain.frame(DT));
    })
}

fn sleeping_boxes() -> (f64, usize, usize, onyx_physics::StepCounters) {
    let mut sleeping = Host::new(HostConfig::default());
    ground(&mut sleeping);
    boxes(&mut sleeping, BodyKind::Dynamic);
    let mut settle = 0;
    while asleep(&sleeping) < N && settle < 600 {
        sleeping.frame(DT);
        settle += 1;
    }
    let slept = asleep(&sleeping);
    let t_sleeping = median(11, 50, || {
        black_box(sleeping.frame(DT));
    });
    let counters = sleeping.physics().world().last_step().counters;
    (t_sleeping, slept, settle, counters)
}

fn awake_boxes() -> f64 {
    let mut awake = Host::new(HostConfig::default());
    awake.physics_mut().settings_mut().sleep_enabled = false;
    ground(&mut awake);
    boxes(&mut awake, BodyKind::Dynamic);
    for _ in 0..30 {
        awake.frame(DT);
    }
    median(11, 10, || {
        black_box(awake.frame(DT));
    })
}

fn static_level() -> f64 {
    let mut level = Host::new(HostConfig::default());
    boxes(&mut level, BodyKind::Static);
    level.frame(DT);
    median(11, 50, || {
        black_box(level.frame(DT));
    })
}

fn report(
    t_empty: f64,
    t_plain: f64,
    (t_sleeping, slept, settle, counters): (f64, usize, usize, onyx_physics::StepCounters),
    t_awake: f64,
    t_static: f64,
) {
    println!("\n== scene cost: one host frame with one fixed step (median, this machine) ==");
    println!(
        "empty world:                               {:>10.1} µs",
        t_empty / 1e3
    );
    println!(
        "10,000 entities, no physics components:    {:>10.1} µs",
        t_plain / 1e3
    );
    println!(
        "10,000 boxes asleep ({slept} asleep after {settle} frames): {:>10.1} µs  \
         (awake bodies in the step: {}, contacts solved: {})",
        t_sleeping / 1e3,
        counters.awake_bodies,
        counters.contacts
    );
    println!(
        "10,000 boxes kept awake:                   {:>10.1} µs",
        t_awake / 1e3
    );
    println!(
        "10,000 static colliders:                   {:>10.1} µs",
        t_static / 1e3
    );
    println!(
        "asleep / awake: {:.3} (sleep saves {:.1}x)",
        t_sleeping / t_awake,
        t_awake / t_sleeping.max(1.0)
    );
}
