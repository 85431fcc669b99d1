//! Frame benchmark on whatever adapter the environment picks (lavapipe by default here):
//! CPU preparation time (culling, batching, instance upload), draw calls and whole-frame
//! time (render + wait for the GPU) for 1,000 / 10,000 / 100,000 cubes, instanced and with
//! one draw per object.
//!
//! `cargo bench --bench render` — criterion measures the whole frame (small samples), then a
//! table of CPU prepare time and draw calls is printed.

use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion};
use glam::{Mat4, Vec3};
use onyx_render::{
    Camera, DrawObject, Lights, Material, OffscreenTarget, RenderScene, RenderSettings, Renderer,
    ShadingMode,
};

const SIZE: u32 = 512;
const COUNTS: [usize; 3] = [1_000, 10_000, 100_000];

fn setup_env() {
    for (key, value) in [
        ("WGPU_BACKEND", "vulkan"),
        ("WGPU_ADAPTER_NAME", "llvmpipe"),
    ] {
        if std::env::var_os(key).is_none() {
            std::env::set_var(key, value);
        }
    }
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        let dir = std::env::temp_dir().join("onyx-render-xdg");
        let _ = std::fs::create_dir_all(&dir);
        std::env::set_var("XDG_RUNTIME_DIR", dir);
    }
}

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
    let lights = Lights::default();
    let mut group = c.benchmark_group("frame_512x512");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    for instancing in [true, false] {
        let mut renderer = renderer(instancing);
        let mut target = OffscreenTarget::new(renderer.gpu(), SIZE, SIZE);
        for count in COUNTS {
            if !instancing && count > 10_000 {
                continue; // seconds per frame on a CPU rasteriser: measured once in the table
            }
            let objects = cubes(&renderer, count);
            let scene = RenderScene::new(camera(count), &lights).with_objects(&objects);
            let name = if instancing {
                "instanced"
            } else {
                "draw_per_object"
            };
            group.bench_with_input(BenchmarkId::new(name, count), &count, |b, _| {
                b.iter(|| frame(&mut renderer, &mut target, &scene));
            });
        }
    }
    group.finish();
}

fn table() {
    let lights = Lights::default();
    println!(
        "\n{:<16} {:>8} {:>11} {:>10} {:>16} {:>14}",
        "mode", "cubes", "draw calls", "instances", "cpu prepare (ms)", "frame (ms)"
    );
    for instancing in [true, false] {
        let mut renderer = renderer(instancing);
        let mut target = OffscreenTarget::new(renderer.gpu(), SIZE, SIZE);
        for count in COUNTS {
            let objects = cubes(&renderer, count);
            let scene = RenderScene::new(camera(count), &lights).with_objects(&objects);
            let frames = if count >= 100_000 { 3 } else { 10 };
            frame(&mut renderer, &mut target, &scene); // warm-up: pipelines, buffer growth
            let mut prepare = Duration::ZERO;
            let start = Instant::now();
            let mut stats = Default::default();
            for _ in 0..frames {
                stats = frame(&mut renderer, &mut target, &scene);
                prepare += stats.cpu_prepare_time;
            }
            let wall = start.elapsed();
            let stats: onyx_render::RenderStats = stats;
            println!(
                "{:<16} {:>8} {:>11} {:>10} {:>16.2} {:>14.1}",
                if instancing {
                    "instanced"
                } else {
                    "draw per object"
                },
                count,
                stats.draw_calls,
                stats.instances,
                prepare.as_secs_f64() * 1000.0 / f64::from(frames),
                wall.as_secs_f64() * 1000.0 / f64::from(frames),
            );
        }
    }
    if let Ok(renderer) = Renderer::new_headless(RenderSettings::deterministic()) {
        let info = renderer.gpu().adapter_info();
        println!(
            "adapter: {} ({:?}, {}), target {SIZE}×{SIZE}, MSAA off\n",
            info.name, info.backend, info.driver_info
        );
    }
}

fn main() {
    setup_env();
    let mut criterion = Criterion::default().configure_from_args();
    criterion_frames(&mut criterion);
    criterion.final_summary();
    table();
}
