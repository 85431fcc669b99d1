//! Frame benchmark on whatever adapter the environment picks (lavapipe by default here):
//! CPU preparation time (shadow views, culling and batching for every view, instance
//! upload), draw calls (scene and shadow passes) and whole-frame time (render + wait for the
//! GPU) for 1,000 / 10,000 / 100,000 cubes, with and without the sun's shadows (3 cascades),
//! instanced and with one draw per object. The ratios the renderer's goals are stated in
//! are printed at the end: the frame with shadows over the frame without (goal ≤ 2×) and the
//! CPU prepare of 100,000 instanced cubes (goal < 5 ms).
//!
//! `cargo bench -p onyx-render` — criterion measures the whole frame of 10,000 cubes with
//! and without shadows (small samples), then the table and the ratios are printed. Without a
//! release build of the dependencies at hand, the same figures for this crate come from the
//! dev profile with only this crate and glam optimised:
//! `cargo --config 'profile.dev.package.onyx-render.opt-level=3' --config
//! 'profile.dev.package.glam.opt-level=3' bench --profile dev -p onyx-render`.
//!
//! The camera looks down on the grid from above; shadows are set to cover the whole grid. A
//! cascade that holds no cube draws nothing, so "shadow draws" can be fewer than cascades.

#[path = "../tests/common/lavapipe_env.rs"]
mod lavapipe_env;

use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion};
use glam::{Mat4, Vec3};
use onyx_render::{
    Camera, DrawObject, Lights, Material, OffscreenTarget, RenderScene, RenderSettings,
    RenderStats, Renderer, ShadingMode,
};

const SIZE: u32 = 512;
const COUNTS: [usize; 3] = [1_000, 10_000, 100_000];
/// Frames drawn before each measurement.
const WARM_UP_FRAMES: u32 = 2;

/// `count` unit cubes on a square grid, two materials, all in view of [`camera`].
fn cubes(renderer: &Renderer, count: usize) -> Vec<DrawObject> {
    let cube = renderer.builtin_meshes().cube;
    let side = (count as f32).sqrt().ceil() as usize;
    let red = Material::color(0.8, 0.2, 0.2);
    let blue = Material::color(0.2, 0.3, 0.9).with_shading(ShadingMode::Unlit);
    (0..count)
        .map(|i| {
            let x = (i % side) as f32 - side as f32 / 2.0;
            let z = (i / side) as f32 - side as f32 / 2.0;
            let material = if i % 2 == 0 { red } else { blue };
            DrawObject::new(
                cube,
                material,
                Mat4::from_translation(Vec3::new(x, 0.0, z)) * Mat4::from_scale(Vec3::splat(0.6)),
            )
        })
        .collect()
}

/// Shadows cover the whole grid (the default 60 m would leave the larger grids unshadowed
/// and the shadow passes empty).
fn cover_grid(renderer: &mut Renderer, count: usize) {
    let side = (count as f32).sqrt().ceil();
    let settings = RenderSettings {
        shadow_distance: 4.0 * side,
        ..renderer.settings().clone()
    };
    if let Err(error) = renderer.set_settings(settings) {
        panic!("{error}");
    }
}

fn camera(count: usize) -> Camera {
    let side = (count as f32).sqrt().ceil();
    Camera::perspective_look_at(
        Vec3::new(0.0, 1.3 * side, 0.01),
        Vec3::ZERO,
        1.2,
        0.1,
        4.0 * side,
    )
}

/// The default lights: sky light and a sun, its shadows on (3 cascades) or off.
fn lights(shadows: bool) -> Lights {
    let mut lights = Lights::default();
    if let Some(sun) = &mut lights.sun {
        sun.shadows.enabled = shadows;
    }
    lights
}

fn renderer(instancing: bool) -> Renderer {
    let settings = RenderSettings {
        instancing,
        ..RenderSettings::deterministic()
    };
    match Renderer::new_headless(settings) {
        Ok(renderer) => renderer,
        Err(error) => panic!("no adapter to benchmark: {error}"),
    }
}

/// One frame: render and wait for the GPU. Returns the renderer's stats.
fn frame(
    renderer: &mut Renderer,
    target: &mut OffscreenTarget,
    scene: &RenderScene<'_>,
) -> onyx_render::RenderStats {
    let stats = match renderer.render(target, scene) {
        Ok(stats) => stats,
        Err(error) => panic!("{error}"),
    };
    if let Err(error) = renderer.gpu().wait_idle() {
        panic!("{error}");
    }
    stats
}

fn criterion_frames(c: &mut Criterion) {
    let mut group = c.benchmark_group("frame_512x512_10k_cubes");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    let mut renderer = renderer(true);
    let mut target = OffscreenTarget::new(renderer.gpu(), SIZE, SIZE);
    let objects = cubes(&renderer, 10_000);
    cover_grid(&mut renderer, 10_000);
    for shadows in [false, true] {
        let lights = lights(shadows);
        let scene = RenderScene::new(camera(10_000), &lights).with_objects(&objects);
        let name = if shadows { "shadows" } else { "no_shadows" };
        group.bench_with_input(BenchmarkId::new(name, 10_000), &shadows, |b, _| {
            b.iter(|| frame(&mut renderer, &mut target, &scene));
        });
    }
    group.finish();
}

/// Mean CPU prepare and wall time of `frames` frames (after one warm-up), and the last stats.
fn measure(
    renderer: &mut Renderer,
    target: &mut OffscreenTarget,
    scene: &RenderScene<'_>,
    frames: u32,
) -> (f64, f64, RenderStats) {
    for _ in 0..WARM_UP_FRAMES {
        frame(renderer, target, scene); // pipelines, buffer growth, shadow maps
    }
    let mut prepare = Duration::ZERO;
    let start = Instant::now();
    let mut stats = RenderStats::default();
    for _ in 0..frames {
        stats = frame(renderer, target, scene);
        prepare += stats.cpu_prepare_time;
    }
    let wall = start.elapsed();
    let ms = |d: Duration| d.as_secs_f64() * 1000.0 / f64::from(frames);
    (ms(prepare), ms(wall), stats)
}

fn table() {
    println!(
        "\n{:<16} {:>8} {:>8} {:>11} {:>13} {:>10} {:>16} {:>11}",
        "mode",
        "shadows",
        "cubes",
        "draw calls",
        "shadow draws",
        "instances",
        "cpu prepare (ms)",
        "frame (ms)"
    );
    // (instancing, shadows, cubes) -> (prepare ms, frame ms)
    let mut results = Vec::new();
    for instancing in [true, false] {
        let mut renderer = renderer(instancing);
        let mut target = OffscreenTarget::new(renderer.gpu(), SIZE, SIZE);
        for count in COUNTS {
            if !instancing && count > 10_000 {
                continue; // tens of seconds per frame on a CPU rasteriser
            }
            let objects = cubes(&renderer, count);
            cover_grid(&mut renderer, count);
            for shadows in [false, true] {
                let lights = lights(shadows);
                let scene = RenderScene::new(camera(count), &lights).with_objects(&objects);
                let frames = if count >= 100_000 || !instancing {
                    3
                } else {
                    8
                };
                let (prepare, wall, stats) = measure(&mut renderer, &mut target, &scene, frames);
                println!(
                    "{:<16} {:>8} {:>8} {:>11} {:>13} {:>10} {:>16.2} {:>11.1}",
                    if instancing {
                        "instanced"
                    } else {
                        "draw per object"
                    },
                    if shadows { "3 casc." } else { "off" },
                    count,
                    stats.draw_calls,
                    stats.shadow_draw_calls,
                    stats.instances,
                    prepare,
                    wall,
                );
                results.push(((instancing, shadows, count), (prepare, wall)));
            }
        }
    }
    let get = |key| results.iter().find(|(k, _)| *k == key).map(|(_, v)| *v);
    if let (Some(off), Some(on)) = (get((true, false, 10_000)), get((true, true, 10_000))) {
        println!(
            "10,000 instanced cubes: frame with shadows / without = {:.2}x (goal <= 2x), CPU prepare {:.2}x",
            on.1 / off.1,
            on.0 / off.0
        );
    }
    if let Some(on) = get((true, true, 100_000)) {
        println!(
            "100,000 instanced cubes with shadows: CPU prepare {:.2} ms (goal < 5 ms: {:.2}x of it), frame {:.1} ms",
            on.0,
            on.0 / 5.0,
            on.1
        );
    }
    if let Ok(renderer) = Renderer::new_headless(RenderSettings::deterministic()) {
        let info = renderer.gpu().adapter_info();
        println!(
            "adapter: {} ({:?}, {}), target {SIZE}×{SIZE}, MSAA off, shadow maps {}²\n",
            info.name,
            info.backend,
            info.driver_info,
            renderer.settings().shadow_resolution
        );
    }
}

fn main() {
    lavapipe_env::pin_lavapipe();
    let mut criterion = Criterion::default().configure_from_args();
    criterion_frames(&mut criterion);
    criterion.final_summary();
    table();
}
