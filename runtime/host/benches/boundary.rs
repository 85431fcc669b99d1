//! The cost of the plugin boundary.
//!
//! - one lifecycle call through the ABI (host → `PluginInstance` → vtable → `catch_unwind`
//!   → the plugin) vs the same call as a direct trait call;
//! - component get/set through `Ctx` (host ← vtable ← plugin), per operation;
//! - bulk read + write of 10,000 transforms in one frame, vs the same edit as a direct hecs
//!   query in the host.
//!
//! Criterion prints each figure; the summary at the end prints the ratios against the peer
//! and the goals (lifecycle dispatch < 1 µs per plugin per frame; 10,000 transforms < 0.5 ms).
//! `cargo bench -p onyx-runtime --bench boundary`

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, Criterion, Throughput};
use onyx_plugin_api::__ffi::with_ctx;
use onyx_plugin_api::host::PluginInstance;
use onyx_plugin_api::{Ctx, Entity, Flow, Name, Plugin, Transform};
use onyx_runtime::{HeadlessHost, Host, HostConfig};

/// Does nothing: measures pure dispatch.
#[derive(Default)]
struct Idle;
impl Plugin for Idle {
    fn on_update(&mut self, _: &mut Ctx, dt: f32) -> Flow {
        black_box(dt);
        Flow::Continue
    }
}

/// Reads and writes one entity's transform `OPS` times per frame.
const OPS: usize = 1_000;
#[derive(Default)]
struct GetSet {
    entity: Option<Entity>,
}
impl Plugin for GetSet {
    fn on_init(&mut self, ctx: &mut Ctx) {
        self.entity = ctx.spawn((Name::new("e"), Transform::IDENTITY)).ok();
    }
    fn on_update(&mut self, ctx: &mut Ctx, _: f32) -> Flow {
        let e = self.entity.expect("spawned in on_init");
        for _ in 0..OPS {
            let mut t: Transform = ctx.get(e).expect("has a transform");
            t.translation.x += 1e-3;
            ctx.set(e, t).expect("finite");
        }
        Flow::Continue
    }
}

/// Moves every transform in one `update_transforms` call per frame.
const BULK: usize = 10_000;
#[derive(Default)]
struct Bulk;
impl Plugin for Bulk {
    fn on_init(&mut self, ctx: &mut Ctx) {
        for i in 0..BULK {
            ctx.spawn(Transform::from_xyz(i as f32, 0.0, 0.0))
                .expect("finite");
        }
    }
    fn on_update(&mut self, ctx: &mut Ctx, _: f32) -> Flow {
        ctx.update_transforms(|items| {
            for item in items {
                item.transform.translation.y += 1e-3;
            }
        })
        .expect("finite");
        Flow::Continue
    }
}

fn host_with<P: Plugin>(plugin: P) -> HeadlessHost {
    let mut host = HeadlessHost::new();
    host.add_plugin("bench", plugin).expect("attaches");
    host.step(1);
    host
}

fn services_host() -> Host {
    Host::new(HostConfig::default())
}

fn lifecycle(c: &mut Criterion) {
    let mut group = c.benchmark_group("lifecycle");
    let mut host = services_host();
    let mut instance = PluginInstance::from_plugin("idle", Idle).expect("constructs");
    host.with_services("idle", |cx| {
        group.bench_function("on_update through the ABI", |b| {
            b.iter(|| instance.on_update(cx, black_box(1.0 / 60.0)))
        });
    });
    let mut direct = Idle;
    let mut host = services_host();
    host.with_services("idle", |cx| {
        with_ctx(cx, |ctx| {
            group.bench_function("on_update as a direct trait call (peer)", |b| {
                b.iter(|| black_box(&mut direct).on_update(ctx, black_box(1.0 / 60.0)))
            });
        })
    });
    let mut empty = Host::new(HostConfig::default());
    group.bench_function("frame, no plugin", |b| b.iter(|| empty.frame(1.0 / 60.0)));
    let mut one = host_with(Idle);
    group.bench_function("frame, one idle plugin", |b| b.iter(|| one.step(1)));
    group.finish();
}

fn components(c: &mut Criterion) {
    let mut group = c.benchmark_group("components");
    group.throughput(Throughput::Elements(2 * OPS as u64));
    let mut host = host_with(GetSet::default());
    group.bench_function("get+set Transform through Ctx", |b| b.iter(|| host.step(1)));
    group.finish();
}

fn bulk(c: &mut Criterion) {
    let mut group = c.benchmark_group("bulk");
    group.throughput(Throughput::Elements(BULK as u64));
    let mut host = host_with(Bulk);
    group.bench_function("10k transforms read+write through Ctx", |b| {
        b.iter(|| host.step(1))
    });
    let mut peer = direct_world();
    group.bench_function("10k transforms, direct hecs query (peer)", |b| {
        b.iter(|| direct_edit(&mut peer))
    });
    group.finish();
}

fn direct_world() -> hecs::World {
    let mut world = hecs::World::new();
    for i in 0..BULK {
        world.spawn((Transform::from_xyz(i as f32, 0.0, 0.0),));
    }
    world
}

fn direct_edit(world: &mut hecs::World) {
    for t in world.query_mut::<&mut Transform>() {
        t.translation.y += 1e-3;
    }
}

/// Median of `runs` timings of `f`, each over `iters` iterations, per iteration, in
/// nanoseconds (a `Duration` cannot hold the fractions of a nanosecond that matter here).
fn median(runs: usize, iters: u32, mut f: impl FnMut()) -> f64 {
    let mut samples: Vec<f64> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..iters {
                f();
            }
            start.elapsed().as_secs_f64() * 1e9 / f64::from(iters)
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[runs / 2]
}

fn summary() {
    let mut host = services_host();
    let mut instance = PluginInstance::from_plugin("idle", Idle).expect("constructs");
    let abi = host.with_services("idle", |cx| {
        median(21, 1_000_000, || {
            black_box(instance.on_update(cx, black_box(1.0 / 60.0)).ok());
        })
    });
    let mut host = services_host();
    let mut idle = Idle;
    let direct = host.with_services("idle", |cx| {
        with_ctx(cx, |ctx| {
            median(21, 1_000_000, || {
                black_box(black_box(&mut idle).on_update(ctx, black_box(1.0 / 60.0)));
            })
        })
    });

    let mut empty = Host::new(HostConfig::default());
    let base = median(21, 2_000, || {
        empty.frame(1.0 / 60.0);
    });
    let mut ten = HeadlessHost::new();
    for name in ["p0", "p1", "p2", "p3", "p4", "p5", "p6", "p7", "p8", "p9"] {
        ten.add_plugin(name, Idle).expect("attaches");
    }
    let with_ten = median(21, 500, || {
        ten.step(1);
    });
    let per_plugin = (with_ten - base).max(0.0) / 10.0;

    let mut gs = host_with(GetSet::default());
    let get_set = median(11, 50, || {
        gs.step(1);
    }) / (2 * OPS) as f64;

    let mut bulk = host_with(Bulk);
    let bulk_time = median(11, 50, || {
        bulk.step(1);
    });
    let mut peer = direct_world();
    let peer_time = median(11, 50, || direct_edit(&mut peer));
    let ratio = |a: f64, b: f64| a / b.max(1e-12);

    println!("\n== boundary summary (median of repeated runs, this machine) ==");
    println!(
        "one on_update call: {abi:.2} ns through the ABI vs {direct:.2} ns as a direct trait call ({:.1}x)",
        ratio(abi, direct)
    );
    println!(
        "all lifecycle calls of one plugin in one frame: {per_plugin:.1} ns (10 idle plugins, \
         frame without plugins {base:.1} ns)   [goal < 1 µs]"
    );
    println!("component get or set through Ctx: {get_set:.1} ns per operation");
    println!(
        "10,000 transforms read+write in one frame: {:.1} µs through Ctx vs {:.1} µs as a \
         direct hecs query ({:.1}x)   [goal < 0.5 ms]",
        bulk_time / 1e3,
        peer_time / 1e3,
        ratio(bulk_time, peer_time)
    );
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    targets = lifecycle, components, bulk
}

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    summary();
}
