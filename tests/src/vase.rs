//! The textured vase in `assets/models/vase/`: an OBJ + MTL + PNG the project makes itself, so
//! the demo, the README's drawing example and the showcase golden use a model with a texture
//! without committing a file fetched from elsewhere (the real-world models live in
//! `../shared/fixtures/`).
//!
//! A surface of revolution: a profile in (radius, height) — up the outside, over the lip and
//! down the inside to a floor — turned about the y axis. Normals are the profile's in-plane
//! perpendicular turned with it (smooth around, a crease at the lip and the foot where the
//! profile turns sharply: those points are emitted twice); `u` runs once around, `v` along the
//! profile's length, so the painted bands follow the shape and an upside-down or mirrored
//! texture shows at a glance (the zig-zag band leans one way, the foot is dark).
//!
//! `e2e::made_assets` checks that the committed files are exactly what this module writes;
//! `ONYX_UPDATE_GOLDEN=1` rewrites them.

use std::fmt::Write as _;
use std::path::Path;

use onyx_render::image::{Rgba, RgbaImage};

/// Segments around the axis.
const AROUND: usize = 48;
/// Points along each smooth stretch of the profile.
const ALONG: usize = 16;
/// Texture size in pixels (square).
pub const TEXTURE_SIZE: u32 = 256;

/// The file names written by [`write`], in `assets/models/vase/`.
pub const OBJ: &str = "vase.obj";
pub const MTL: &str = "vase.mtl";
pub const TEXTURE: &str = "vase_texture.png";

/// One smooth stretch of the profile: points (radius, height), from bottom to top for the
/// outside. Consecutive stretches share their end point, which becomes a crease.
fn profile() -> Vec<Vec<(f32, f32)>> {
    let outside: Vec<(f32, f32)> = (0..=ALONG * 2)
        .map(|i| {
            let t = i as f32 / (ALONG * 2) as f32;
            // A bulb low down, a narrow neck, a flared lip: 0.6 m tall.
            let r = 0.16 + 0.14 * (std::f32::consts::PI * (t * 1.3)).sin().max(0.0) - 0.06 * t
                + 0.08 * (t - 0.8).max(0.0) * 5.0;
            (r, 0.6 * t)
        })
        .collect();
    let (lip_r, lip_y) = outside[outside.len() - 1];
    let wall = 0.015;
    let lip = vec![(lip_r, lip_y), (lip_r - wall, lip_y)];
    let inside: Vec<(f32, f32)> = outside
        .iter()
        .rev()
        .filter(|&&(_, y)| y >= 0.04)
        .map(|&(r, y)| ((r - wall).max(0.01), y))
        .collect();
    let floor_y = inside[inside.len() - 1].1;
    let floor = vec![inside[inside.len() - 1], (0.0, floor_y)];
    let base = vec![(0.0, 0.0), outside[0]];
    vec![base, outside, lip, inside, floor]
}

/// The OBJ text (positions, texture coordinates, normals, triangles; `usemtl vase`).
pub fn obj() -> String {
    let stretches = profile();
    let total_length: f32 = stretches.iter().map(|s| length(s)).sum();
    let mut out = String::new();
    out.push_str("# A vase made by onyx-tests (tests/src/vase.rs); not from any other source.\n");
    out.push_str(&format!("mtllib {MTL}\no vase\n"));
    let mut rings: Vec<usize> = Vec::new(); // first vertex index (1-based) of each ring
    let mut ring_count = 0usize;
    let mut travelled = 0.0f32;
    let mut vertex = 1usize;
    let mut normals = String::new();
    let mut coords = String::new();
    let mut positions = String::new();
    let mut faces = String::new();
    for stretch in &stretches {
        let first_ring = ring_count;
        for (k, &(r, y)) in stretch.iter().enumerate() {
            if k > 0 {
                let (pr, py) = stretch[k - 1];
                travelled += ((r - pr).powi(2) + (y - py).powi(2)).sqrt();
            }
            // The in-plane normal: the profile's tangent turned a quarter to the right (the
            // profile runs counter-clockwise around the solid in the (r, y) plane).
            let (tr, ty) = tangent(stretch, k);
            let (nr, ny) = (ty, -tr);
            let v = 1.0 - travelled / total_length;
            rings.push(vertex);
            for a in 0..=AROUND {
                let angle = std::f32::consts::TAU * a as f32 / AROUND as f32;
                let (s, c) = angle.sin_cos();
                let _ = writeln!(positions, "v {:.5} {:.5} {:.5}", r * c, y, -r * s);
                let _ = writeln!(coords, "vt {:.5} {:.5}", a as f32 / AROUND as f32, v);
                let _ = writeln!(normals, "vn {:.4} {:.4} {:.4}", nr * c, ny, -nr * s);
                vertex += 1;
            }
            ring_count += 1;
        }
        for ring in first_ring..ring_count - 1 {
            for a in 0..AROUND {
                let i0 = rings[ring] + a;
                let i1 = i0 + 1;
                let j0 = rings[ring + 1] + a;
                let j1 = j0 + 1;
                let _ = writeln!(faces, "f {i0}/{i0}/{i0} {i1}/{i1}/{i1} {j1}/{j1}/{j1}");
                let _ = writeln!(faces, "f {i0}/{i0}/{i0} {j1}/{j1}/{j1} {j0}/{j0}/{j0}");
            }
        }
    }
    out.push_str(&positions);
    out.push_str(&coords);
    out.push_str(&normals);
    out.push_str("usemtl vase\ns 1\n");
    out.push_str(&faces);
    out
}

/// The MTL text: white diffuse (the texture carries the colour), a soft highlight.
pub fn mtl() -> String {
    format!(
        "# Made by onyx-tests (tests/src/vase.rs).\nnewmtl vase\nKa 1 1 1\nKd 1 1 1\nKs 0.2 0.2 0.2\nNs 40\nmap_Kd {TEXTURE}\n"
    )
}

/// The texture: glazed terracotta with a dark foot, two cream bands and a zig-zag between
/// them that leans one way (so a flipped or mirrored mapping is visible).
pub fn texture() -> RgbaImage {
    let size = TEXTURE_SIZE;
    RgbaImage::from_fn(size, size, |x, y| {
        let u = x as f32 / size as f32;
        let v = 1.0 - y as f32 / size as f32; // OBJ v runs up the image
        let terracotta = [176, 84, 48];
        let cream = [236, 220, 180];
        let dark = [52, 30, 24];
        let teal = [40, 118, 120];
        // `v` is 1 at the bottom of the outside and falls along the profile.
        let c = if v > 0.93 {
            dark
        } else if (0.70..0.73).contains(&v) || (0.50..0.53).contains(&v) {
            cream
        } else if (0.53..0.70).contains(&v) {
            // Zig-zag: a triangle wave in u, sheared so it leans.
            let wave = ((u * 12.0 + (v - 0.53) * 3.0).fract() - 0.5).abs() * 2.0;
            let band = (v - 0.53) / 0.17;
            if (wave - band).abs() < 0.12 {
                teal
            } else {
                terracotta
            }
        } else if v < 0.42 {
            // The inside and the lip: a plain darker glaze.
            [120, 56, 36]
        } else {
            terracotta
        };
        Rgba([c[0], c[1], c[2], 255])
    })
}

/// Writes the three files into `dir`.
pub fn write(dir: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    std::fs::write(dir.join(OBJ), obj())?;
    std::fs::write(dir.join(MTL), mtl())?;
    texture()
        .save(dir.join(TEXTURE))
        .map_err(std::io::Error::other)
}

fn length(points: &[(f32, f32)]) -> f32 {
    points
        .windows(2)
        .map(|w| ((w[1].0 - w[0].0).powi(2) + (w[1].1 - w[0].1).powi(2)).sqrt())
        .sum()
}

/// The unit tangent at point `k` of a stretch (central difference inside, one-sided at ends).
fn tangent(points: &[(f32, f32)], k: usize) -> (f32, f32) {
    let a = points[k.saturating_sub(1)];
    let b = points[(k + 1).min(points.len() - 1)];
    let (dr, dy) = (b.0 - a.0, b.1 - a.1);
    let len = (dr * dr + dy * dy).sqrt().max(f32::MIN_POSITIVE);
    (dr / len, dy / len)
}
