//! Benchmarks: ms/step for 1,000 / 10,000 bodies settled on a ground (asleep and awake),
//! the idle cost (empty world, 10,000 sleeping bodies vs awake), what locking rotation
//! saves (a packed block of spheres free to turn vs locked), the 20-row pyramid, and GJK
//! query time. Run: `cargo bench -p onyx-physics`.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, Criterion};
use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::narrowphase::gjk_distance;
use onyx_physics::shape::ConvexCore;
use onyx_physics::{ColliderDesc, LockedAxes, PhysicsSettings, PhysicsWorld, Pose, RigidBodyDesc};

/// A world with default settings (sleeping on or off) and a ground plane at y = 0.
fn ground_world(sleep: bool) -> PhysicsWorld {
    let mut w = PhysicsWorld::new(PhysicsSettings {
        sleep_enabled: sleep,
        ..Default::default()
    });
    let g = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::half_space(Vec3::Y), g);
    w
}

/// `n` bodies (alternating boxes and spheres) on a grid above a ground plane, stepped
/// until they rest.
fn settled_world(n: usize, sleep: bool) -> PhysicsWorld {
    let mut w = ground_world(sleep);
    let side = (n as f32).sqrt().ceil() as usize;
    for i in 0..n {
        let (x, z) = ((i % side) as f32 * 1.5, (i / side) as f32 * 1.5);
        let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(
            x,
            0.6 + (i % 3) as f32 * 0.3,
            z,
        )));
        let c = if i % 2 == 0 {
            ColliderDesc::cuboid(0.5, 0.5, 0.5)
        } else {
            ColliderDesc::sphere(0.5)
        };
        w.insert_collider(c, b);
    }
    for _ in 0..120 {
        w.step();
    }
    w
}

fn pyramid(rows: usize) -> PhysicsWorld {
    let mut w = ground_world(false);
    for row in 0..rows {
        let n = rows - row;
        for i in 0..n {
            let x = (i as f32 - (n - 1) as f32 * 0.5) * 1.02;
            let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(
                x,
                0.5 + row as f32,
                0.0,
            )));
            w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5), b);
        }
    }
    for _ in 0..60 {
        w.step();
    }
    w
}

/// Prints the mean ms/step and the stage breakdown of the last step.
fn report(name: &str, w: &mut PhysicsWorld, steps: usize) {
    let t = Instant::now();
    for _ in 0..steps {
        w.step();
    }
    let ms = t.elapsed().as_secs_f64() * 1e3 / steps as f64;
    let c = w.last_step().counters;
    println!(
        "FIGURE {name}: {ms:.3} ms/step (awake {}, pairs {}, contacts {}; broad {:?} narrow {:?} solve {:?} integrate {:?} sleep {:?})",
        c.awake_bodies, c.pairs, c.contacts, c.broadphase, c.narrowphase, c.solve, c.integrate, c.sleep
    );
}

fn bench_steps(c: &mut Criterion) {
    let mut group = c.benchmark_group("step");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    for (n, sleep) in [(1000, true), (1000, false), (10_000, true), (10_000, false)] {
        let name = format!("settled_{n}_{}", if sleep { "sleeping" } else { "awake" });
        let mut w = settled_world(n, sleep);
        report(&name, &mut w, 20);
        group.bench_function(&name, |b| b.iter(|| black_box(w.step().counters.contacts)));
    }
    let mut w = pyramid(20);
    report("pyramid_20_rows", &mut w, 20);
    group.bench_function("pyramid_20_rows", |b| {
        b.iter(|| black_box(w.step().counters.contacts))
    });
    group.finish();
}

fn bench_gjk(c: &mut Criterion) {
    let a = ConvexCore::Cuboid(Vec3::new(0.5, 0.7, 0.9));
    let b = ConvexCore::Cuboid(Vec3::new(0.4, 0.4, 1.2));
    let pa = Pose::new(Vec3::ZERO, Quat::from_rotation_y(0.3));
    let pb = Pose::new(
        Vec3::new(2.1, 0.4, 0.2),
        Quat::from_euler(glam_euler(), 0.2, 0.7, 0.1),
    );
    let t = Instant::now();
    let iters = 100_000;
    for _ in 0..iters {
        black_box(gjk_distance(black_box(&a), &pa, &b, &pb));
    }
    println!(
        "FIGURE gjk_box_box_distance: {:.1} ns/query",
        t.elapsed().as_nanos() as f64 / iters as f64
    );
    c.bench_function("gjk_box_box_distance", |bench| {
        bench.iter(|| black_box(gjk_distance(black_box(&a), &pa, &b, &pb)))
    });
}

fn glam_euler() -> onyx_physics::glam::EulerRot {
    onyx_physics::glam::EulerRot::XYZ
}

criterion_group!(benches, bench_steps, bench_idle, bench_locked, bench_gjk);
criterion_main!(benches);

/// `n` boxes and spheres on a ground, stepped until every body sleeps (at most 600 steps).
fn sleeping_world(n: usize) -> PhysicsWorld {
    let mut w = settled_world(n, true);
    for _ in 0..600 {
        if w.step().counters.awake_bodies == 0 {
            break;
        }
    }
    w
}

/// What a step costs when there is nothing to do: an empty world, and 10,000 bodies that all
/// sleep (no broadphase, narrowphase or solver work for them), next to the same 10,000 bodies
/// awake. The FIGURE lines give µs/step.
fn bench_idle(c: &mut Criterion) {
    let mut group = c.benchmark_group("idle");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    let mut empty = PhysicsWorld::default();
    let mut sleeping = sleeping_world(10_000);
    let mut awake = settled_world(10_000, false);
    for (name, w, steps) in [
        ("empty_world", &mut empty, 10_000),
        ("sleeping_10000", &mut sleeping, 200),
        ("awake_10000", &mut awake, 10),
    ] {
        let t = Instant::now();
        for _ in 0..steps {
            w.step();
        }
        let us = t.elapsed().as_secs_f64() * 1e6 / steps as f64;
        println!(
            "FIGURE idle {name}: {us:.2} us/step (awake bodies {})",
            w.last_step().counters.awake_bodies
        );
        group.bench_function(name, |b| {
            b.iter(|| black_box(w.step().counters.awake_bodies))
        });
    }
    group.finish();
}

/// A block of 20 × 20 × 5 spheres touching their neighbours, resting on a ground, every
/// body awake, with `locks` on each sphere.
fn sphere_block(locks: LockedAxes) -> PhysicsWorld {
    let mut w = ground_world(false);
    for i in 0..2000 {
        let (x, z, y) = (i % 20, (i / 20) % 20, i / 400);
        let b = w.insert_body(
            RigidBodyDesc::dynamic()
                .translation(Vec3::new(x as f32, 0.5 + y as f32, z as f32))
                .locked_axes(locks),
        );
        w.insert_collider(ColliderDesc::sphere(0.5), b);
    }
    for _ in 0..60 {
        w.step();
    }
    w
}

/// What a scene saves by locking rotation: the same 2,000 resting spheres free to turn and
/// with every rotation locked (no inertia, no angular rows in their contacts). The FIGURE
/// line gives both and their ratio, measured alternately in one process.
fn bench_locked(c: &mut Criterion) {
    let mut group = c.benchmark_group("locked_rotation");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2));
    let mut free = sphere_block(LockedAxes::NONE);
    let mut locked = sphere_block(LockedAxes::ALL_ROTATIONS);
    let (mut t_free, mut t_locked) = (Duration::ZERO, Duration::ZERO);
    for _ in 0..10 {
        for (w, total) in [(&mut free, &mut t_free), (&mut locked, &mut t_locked)] {
            let t = Instant::now();
            for _ in 0..5 {
                w.step();
            }
            *total += t.elapsed();
        }
    }
    let ms = |d: Duration| d.as_secs_f64() * 1e3 / 50.0;
    println!(
        "FIGURE locked_rotation 2000 spheres: free {:.3} ms/step, locked {:.3} ms/step, \
         locked/free {:.2} (contacts {} / {})",
        ms(t_free),
        ms(t_locked),
        ms(t_locked) / ms(t_free),
        free.last_step().counters.contacts,
        locked.last_step().counters.contacts,
    );
    for (name, w) in [("free_2000", &mut free), ("locked_2000", &mut locked)] {
        report(name, w, 10);
        group.bench_function(name, |b| b.iter(|| black_box(w.step().counters.contacts)));
    }
    group.finish();
}
