//! What the editor's tool services cost on a world of 10,000 named entities: listing them
//! (the hierarchy, every frame), listing one entity's components (the inspector), reading
//! diagnostics and the console, and a Play snapshot + Stop restore. Prints figures.
//!
//! `cargo bench -p onyx-runtime --bench tool_services`

use std::time::{Duration, Instant};

use onyx_plugin_api::{Ctx, Flow, Name, Plugin, RigidBody, Transform};
use onyx_runtime::HeadlessHost;

const ENTITIES: usize = 10_000;
const ROUNDS: u32 = 200;

#[derive(Default)]
struct Probe {
    frame: u32,
}

fn per_call(total: Duration, calls: u32) -> String {
    format!("{:8.1} µs", total.as_secs_f64() * 1e6 / f64::from(calls))
}

fn time(rounds: u32, mut f: impl FnMut()) -> Duration {
    let start = Instant::now();
    for _ in 0..rounds {
        f();
    }
    start.elapsed()
}

impl Plugin for Probe {
    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> Flow {
        self.frame += 1;
        match self.frame {
            1 => {
                for i in 0..ENTITIES {
                    let t = Transform::from_xyz(i as f32, 0.0, 0.0);
                    ctx.spawn((Name::new(format!("entity {i}")), t, RigidBody::dynamic()))
                        .ok();
                }
            }
            2 => {
                let mut n = 0;
                let list = time(ROUNDS, || n += ctx.entity_list().len());
                let first = ctx.entity_list().entities()[0];
                let components = time(ROUNDS, || {
                    n += ctx.components_of(first).map_or(0, |c| c.len());
                });
                let diagnostics = time(ROUNDS, || {
                    n += ctx.diagnostics().map_or(0, |d| d.plugins.len());
                });
                let console = time(ROUNDS, || {
                    n += ctx.log_lines_since(u64::MAX - 1).map_or(0, |l| l.len());
                });
                println!("tool services on {ENTITIES} entities (per call, {ROUNDS} calls):");
                println!("  entity_list          {}", per_call(list, ROUNDS));
                println!("  components_of        {}", per_call(components, ROUNDS));
                println!("  diagnostics          {}", per_call(diagnostics, ROUNDS));
                println!("  log_lines_since(new) {}", per_call(console, ROUNDS));
                std::hint::black_box(n);
                let snapshot = time(1, || {
                    ctx.stop();
                    ctx.play();
                });
                println!(
                    "  Play (snapshot of {ENTITIES} entities) {:.2} ms",
                    snapshot.as_secs_f64() * 1e3
                );
            }
            3 => ctx.stop(),
            _ => {}
        }
        Flow::Continue
    }
}

fn main() {
    let mut host = HeadlessHost::new();
    host.add_plugin("probe", Probe::default()).ok();
    host.step(2);
    // Frame 3 snapshots nothing new; time the frame whose end restores the world.
    let start = Instant::now();
    host.step(1);
    let restore_frame = start.elapsed();
    println!(
        "  Stop (restore {ENTITIES} entities + physics reset), whole frame: {:.2} ms",
        restore_frame.as_secs_f64() * 1e3
    );
    let d = host.host().diagnostics();
    println!(
        "  last frame: {:.2} ms, {} plugin(s) timed",
        d.frame_ms,
        d.plugins.len()
    );
}
