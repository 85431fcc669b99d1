//! Import benchmark: the texture-heavy Khronos samples (DamagedHelmet, WaterBottle, Avocado,
//! from `../shared/fixtures/gltf/`; skipped, saying so, when absent) and a 2M-triangle OBJ
//! the bench writes, read as Onyx reads them ([`ModelSource::load`]: parse, every image
//! decoded with its mip chain, tangents generated — what a loader thread does) next to the
//! bare cost of the same files in the same run: the `gltf` crate's parse, its buffers and
//! every image decoded with `image`; `tobj` alone for the OBJ. Wall time (best of
//! [`RUNS`]) and peak heap (a counting allocator) for each, and their ratios (goal ≤ 1.3×);
//! "no tangents" is Onyx's time without generating tangents, to show their share.
//! Then each model is uploaded to a renderer: GPU bytes of its mesh buffers against its
//! indexed data (vertices + 32-bit indices; goal ≤ 1.1×).
//!
//! `cargo bench -p onyx-render --bench import`, or in the dev profile with this crate
//! optimised: `cargo --config 'profile.dev.package.onyx-render.opt-level=3' bench --profile
//! dev -p onyx-render --bench import`.

#[path = "../tests/common/lavapipe_env.rs"]
mod lavapipe_env;

use std::alloc::{GlobalAlloc, Layout, System};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use onyx_render::{ImportSettings, ModelSource, RenderSettings, Renderer, Vertex};

/// Runs per measurement; the best is kept.
const RUNS: usize = 3;
/// Quads a side of the generated OBJ grid (2 triangles each: 2,000,000 triangles).
const GRID: usize = 1000;

/// The system allocator, counting bytes in use and their peak.
struct Counting;

static IN_USE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is forwarded to the system allocator unchanged; only counters are added.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded as is.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let now = IN_USE.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(now, Ordering::Relaxed);
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: forwarded as is.
        unsafe { System.dealloc(ptr, layout) };
        IN_USE.fetch_sub(layout.size(), Ordering::Relaxed);
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: forwarded as is.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            if new_size >= layout.size() {
                let now = IN_USE.fetch_add(new_size - layout.size(), Ordering::Relaxed) + new_size
                    - layout.size();
                PEAK.fetch_max(now, Ordering::Relaxed);
            } else {
                IN_USE.fetch_sub(layout.size() - new_size, Ordering::Relaxed);
            }
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Best wall time of [`RUNS`] runs of `f` and the largest heap growth over any run, bytes.
fn measure<T>(mut f: impl FnMut() -> T) -> (Duration, usize) {
    let mut best = Duration::MAX;
    let mut peak = 0;
    for _ in 0..RUNS {
        let base = IN_USE.load(Ordering::Relaxed);
        PEAK.store(base, Ordering::Relaxed);
        let start = Instant::now();
        let out = f();
        best = best.min(start.elapsed());
        peak = peak.max(PEAK.load(Ordering::Relaxed) - base);
        drop(out);
    }
    (best, peak)
}

/// The bare cost of a glTF file: the `gltf` crate's parse, every buffer, every image decoded.
fn bare_gltf(path: &Path) -> (gltf::Document, Vec<Vec<u8>>, Vec<image::RgbaImage>) {
    let bytes = std::fs::read(path).expect("the sample is readable");
    let gltf = gltf::Gltf::from_slice(&bytes).expect("the sample is valid");
    let folder = path.parent().unwrap_or(Path::new(""));
    let buffers: Vec<Vec<u8>> = gltf
        .document
        .buffers()
        .map(|b| match b.source() {
            gltf::buffer::Source::Bin => gltf.blob.clone().unwrap_or_default(),
            gltf::buffer::Source::Uri(uri) => {
                std::fs::read(folder.join(uri)).expect("the buffer is readable")
            }
        })
        .collect();
    let images = gltf
        .document
        .images()
        .map(|image| {
            let encoded = match image.source() {
                gltf::image::Source::View { view, .. } => buffers[view.buffer().index()]
                    [view.offset()..view.offset() + view.length()]
                    .to_vec(),
                gltf::image::Source::Uri { uri, .. } => {
                    std::fs::read(folder.join(uri)).expect("the image is readable")
                }
            };
            image::load_from_memory(&encoded)
                .expect("the image decodes")
                .into_rgba8()
        })
        .collect();
    (gltf.document, buffers, images)
}

/// The bare cost of an OBJ file: `tobj` alone, triangulated, one index per vertex.
fn bare_obj(path: &Path) -> Vec<tobj::Model> {
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..tobj::LoadOptions::default()
    };
    tobj::load_obj(path, &options).expect("the OBJ parses").0
}

/// Onyx's import, as a loader thread does it.
fn onyx_import(path: &Path, max_side: u32) -> ModelSource {
    let mut source =
        ModelSource::load(path, &ImportSettings::default(), max_side).expect("the model loads");
    source.generate_tangents();
    source
}

/// Writes a `GRID` × `GRID` quad grid with positions, UVs and normals (2M triangles).
fn write_grid_obj(path: &Path) {
    use std::io::Write;
    let file = std::fs::File::create(path).expect("the temporary folder is writable");
    let mut out = std::io::BufWriter::new(file);
    let n = GRID + 1;
    for z in 0..n {
        for x in 0..n {
            let (fx, fz) = (x as f32 / GRID as f32, z as f32 / GRID as f32);
            let y = (fx * 40.0).sin() * (fz * 30.0).cos() * 0.02;
            writeln!(out, "v {fx:.5} {y:.5} {fz:.5}").expect("write");
        }
    }
    for z in 0..n {
        for x in 0..n {
            writeln!(
                out,
                "vt {:.5} {:.5}",
                x as f32 / GRID as f32,
                z as f32 / GRID as f32
            )
            .expect("write");
        }
    }
    writeln!(out, "vn 0 1 0").expect("write");
    for z in 0..GRID {
        for x in 0..GRID {
            let i = z * n + x + 1;
            let (a, b, c, d) = (i, i + 1, i + n + 1, i + n);
            writeln!(out, "f {a}/{a}/1 {d}/{d}/1 {c}/{c}/1 {b}/{b}/1").expect("write");
        }
    }
    out.flush().expect("write");
}

fn mib(bytes: usize) -> f64 {
    bytes as f64 / (1024.0 * 1024.0)
}

fn main() {
    // `cargo bench` passes `--bench`; any other argument is a filter, as criterion's are.
    let filter: Option<String> = std::env::args().skip(1).find(|a| !a.starts_with("--"));
    lavapipe_env::pin_lavapipe();
    let renderer = Renderer::new_headless(RenderSettings::deterministic());
    let max_side = renderer.as_ref().map_or(8192, Renderer::max_texture_side);
    let samples = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/fixtures/gltf");
    let mut files: Vec<(String, PathBuf, bool)> = Vec::new();
    for name in ["DamagedHelmet", "WaterBottle", "Avocado"] {
        let path = samples.join(format!("{name}/glTF/{name}.gltf"));
        if path.is_file() {
            files.push((name.to_owned(), path, true));
        } else {
            println!("skipped {name}: {} is absent", path.display());
        }
    }
    let dir = std::env::temp_dir().join(format!("onyx-import-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("the temporary folder is writable");
    let grid = dir.join("grid-2m.obj");
    write_grid_obj(&grid);
    files.push(("grid 2M-triangle OBJ".to_owned(), grid, false));
    files.retain(|(name, _, _)| filter.as_ref().is_none_or(|f| name.contains(f.as_str())));

    println!(
        "{:<22} {:>10} {:>12} {:>10} {:>7} {:>10} {:>10} {:>7}",
        "file", "onyx ms", "no tangents", "bare ms", "time×", "onyx MiB", "bare MiB", "heap×"
    );
    let mut uploads = Vec::new();
    for (name, path, is_gltf) in &files {
        let (onyx_time, onyx_peak) = measure(|| onyx_import(path, max_side));
        // The same without tangent generation (MikkTSpace), to show its share.
        let (read_time, _) = measure(|| {
            ModelSource::load(path, &ImportSettings::default(), max_side).expect("the model loads")
        });
        let (bare_time, bare_peak) = if *is_gltf {
            measure(|| bare_gltf(path))
        } else {
            measure(|| bare_obj(path))
        };
        println!(
            "{:<22} {:>10.1} {:>12.1} {:>10.1} {:>6.2}× {:>10.1} {:>10.1} {:>6.2}×",
            name,
            onyx_time.as_secs_f64() * 1e3,
            read_time.as_secs_f64() * 1e3,
            bare_time.as_secs_f64() * 1e3,
            onyx_time.as_secs_f64() / bare_time.as_secs_f64(),
            mib(onyx_peak),
            mib(bare_peak),
            onyx_peak as f64 / bare_peak.max(1) as f64,
        );
        uploads.push((name.clone(), path.clone()));
    }

    let Ok(mut renderer) = renderer else {
        println!("GPU memory per mesh: skipped, no adapter to upload to");
        return;
    };
    println!(
        "\n{:<22} {:>14} {:>14} {:>7}",
        "GPU memory", "indexed MiB", "buffers MiB", "ratio"
    );
    for (name, path) in uploads {
        let source = onyx_import(&path, max_side);
        let indexed: usize = source
            .parts
            .iter()
            .map(|p| {
                p.mesh.vertices.len() * std::mem::size_of::<Vertex>() + p.mesh.indices.len() * 4
            })
            .sum();
        let (before, _) = renderer.gpu_bytes();
        let (_model, problems) = renderer.upload_model(source);
        assert!(problems.is_empty(), "{name}: {problems:?}");
        let (after, _) = renderer.gpu_bytes();
        let buffers = after - before;
        println!(
            "{:<22} {:>14.2} {:>14.2} {:>6.3}×",
            name,
            mib(indexed),
            buffers as f64 / (1024.0 * 1024.0),
            buffers as f64 / indexed as f64
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
