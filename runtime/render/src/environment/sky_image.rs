//! [`SkyImage`]: an equirectangular HDR sky (a Radiance `.hdr` file) resampled into the faces
//! of a cube map, mip chain included, ready for the environment bake to upload.

use std::path::Path;

use glam::Vec3;

/// Why a sky image could not be used.
#[derive(Debug, thiserror::Error)]
pub(crate) enum SkyImageError {
    #[error("cannot read the sky image {path}: {source}")]
    Decode {
        path: String,
        source: image::ImageError,
    },
    #[error("the sky image {path} is empty ({width}x{height})")]
    Empty {
        path: String,
        width: u32,
        height: u32,
    },
}

/// The six faces of a cube (order +X, −X, +Y, −Y, +Z, −Z, as `environment.wgsl` reads them),
/// each level half the previous; texels are linear RGBA as f16 bits.
#[derive(Debug)]
pub(crate) struct SkyImage {
    /// Side of level 0, texels.
    pub(crate) size: u32,
    /// `levels[mip][face]`: `(size >> mip)²` texels, row by row.
    pub(crate) levels: Vec<[Vec<[u16; 4]>; 6]>,
}

impl SkyImage {
    /// Reads the equirectangular image at `path` (laid out as [`equirect_uv`] says) and
    /// resamples it into cube faces of side `size`, scaled by `intensity`.
    ///
    /// # Errors
    /// [`SkyImageError`] when the file is missing, not an image, or empty.
    pub(crate) fn load(path: &Path, size: u32, intensity: f32) -> Result<Self, SkyImageError> {
        let name = path.display().to_string();
        let decoded = image::open(path).map_err(|source| SkyImageError::Decode {
            path: name.clone(),
            source,
        })?;
        let mut equirect = decoded.into_rgb32f();
        let (width, height) = equirect.dimensions();
        if width == 0 || height == 0 {
            return Err(SkyImageError::Empty {
                path: name,
                width,
                height,
            });
        }
        // Box-filter the image down to about four texels per cube texel around the equator,
        // so bilinear reads below do not alias.
        while equirect.width() > 8 * size && equirect.height() > 1 {
            equirect = halve(&equirect);
        }
        let faces = std::array::from_fn(|face| face_texels(&equirect, face as u32, size));
        let mut levels = vec![faces];
        let mut side = size;
        while side > 1 {
            let Some(previous) = levels.last() else { break };
            let next = std::array::from_fn(|face| halve_face(&previous[face], side));
            levels.push(next);
            side /= 2;
        }
        let levels = levels
            .into_iter()
            .map(|faces| faces.map(|texels| encode(&texels, intensity)))
            .collect();
        Ok(Self { size, levels })
    }
}

/// Texture coordinates of direction `dir` in an equirectangular image: u grows with the
/// azimuth from −Z towards +X (u = 0.5 looks down −Z), v from straight up (0) to straight
/// down (1).
pub(crate) fn equirect_uv(dir: Vec3) -> (f32, f32) {
    let u = 0.5 + dir.x.atan2(-dir.z) / std::f32::consts::TAU;
    let v = dir.y.clamp(-1.0, 1.0).acos() / std::f32::consts::PI;
    (u, v)
}

/// The direction of texel centre (x, y) of `face` (`face_direction` in `environment.wgsl`).
fn face_direction(face: u32, x: u32, y: u32, size: u32) -> Vec3 {
    let s = (x as f32 + 0.5) / size as f32 * 2.0 - 1.0;
    let t = (y as f32 + 0.5) / size as f32 * 2.0 - 1.0;
    let d = match face {
        0 => Vec3::new(1.0, -t, -s),
        1 => Vec3::new(-1.0, -t, s),
        2 => Vec3::new(s, 1.0, t),
        3 => Vec3::new(s, -1.0, -t),
        4 => Vec3::new(s, -t, 1.0),
        _ => Vec3::new(-s, -t, -1.0),
    };
    d.normalize()
}

fn face_texels(equirect: &image::Rgb32FImage, face: u32, size: u32) -> Vec<Vec3> {
    let mut texels = Vec::with_capacity((size * size) as usize);
    for y in 0..size {
        for x in 0..size {
            let (u, v) = equirect_uv(face_direction(face, x, y, size));
            texels.push(bilinear(equirect, u, v));
        }
    }
    texels
}

/// Bilinear read, wrapping around in u and clamped in v.
fn bilinear(image: &image::Rgb32FImage, u: f32, v: f32) -> Vec3 {
    let (w, h) = (image.width() as i64, image.height() as i64);
    let x = u * w as f32 - 0.5;
    let y = (v * h as f32 - 0.5).clamp(0.0, (h - 1) as f32);
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = (x - x0, y - y0);
    let texel = |x: i64, y: i64| {
        let p = image
            .get_pixel(x.rem_euclid(w) as u32, y.clamp(0, h - 1) as u32)
            .0;
        Vec3::from_array(p)
    };
    let (x0, y0) = (x0 as i64, y0 as i64);
    let top = texel(x0, y0).lerp(texel(x0 + 1, y0), fx);
    let bottom = texel(x0, y0 + 1).lerp(texel(x0 + 1, y0 + 1), fx);
    top.lerp(bottom, fy)
}

/// The image at half size (2×2 box filter; an odd last row or column repeats).
fn halve(image: &image::Rgb32FImage) -> image::Rgb32FImage {
    let (w, h) = image.dimensions();
    let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
    image::Rgb32FImage::from_fn(nw, nh, |x, y| {
        let read = |x: u32, y: u32| Vec3::from_array(image.get_pixel(x.min(w - 1), y.min(h - 1)).0);
        let sum = read(2 * x, 2 * y)
            + read(2 * x + 1, 2 * y)
            + read(2 * x, 2 * y + 1)
            + read(2 * x + 1, 2 * y + 1);
        image::Rgb((sum * 0.25).to_array())
    })
}

/// A face of side `side` at half size (2×2 box filter).
fn halve_face(texels: &[Vec3], side: u32) -> Vec<Vec3> {
    let (side, half) = (side as usize, (side / 2).max(1) as usize);
    let mut out = Vec::with_capacity(half * half);
    for y in 0..half {
        for x in 0..half {
            let at = |dx: usize, dy: usize| texels[(2 * y + dy) * side + 2 * x + dx];
            out.push((at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1)) * 0.25);
        }
    }
    out
}

fn encode(texels: &[Vec3], intensity: f32) -> Vec<[u16; 4]> {
    texels
        .iter()
        .map(|&c| {
            let c = c * intensity;
            [f16_bits(c.x), f16_bits(c.y), f16_bits(c.z), f16_bits(1.0)]
        })
        .collect()
}

/// `value` as IEEE half-precision bits: negatives and NaN become 0, values past the largest
/// half (65504) clamp to it, tiny ones flush to zero (radiance needs none of them).
fn f16_bits(value: f32) -> u16 {
    if value.is_nan() || value <= 0.0 {
        return 0;
    }
    let value = value.min(65504.0);
    let bits = value.to_bits();
    let exponent = ((bits >> 23) & 0xff) as i32 - 127 + 15;
    if exponent <= 0 {
        return 0;
    }
    // Round the 23-bit mantissa to 10 bits (to nearest; a carry bumps the exponent).
    let mantissa = bits & 0x7f_ffff;
    let half = ((exponent as u32) << 10) + ((mantissa + 0x1000) >> 13);
    half.min(0x7bff) as u16
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halves_are_exact_for_representable_values() {
        assert_eq!(f16_bits(1.0), 0x3c00);
        assert_eq!(f16_bits(0.5), 0x3800);
        assert_eq!(f16_bits(2.0), 0x4000);
        assert_eq!(f16_bits(65504.0), 0x7bff);
        assert_eq!(f16_bits(1.0e9), 0x7bff);
        assert_eq!(
            (f16_bits(-1.0), f16_bits(f32::NAN), f16_bits(1.0e-9)),
            (0, 0, 0)
        );
    }

    #[test]
    fn the_middle_of_the_image_looks_down_minus_z_and_its_top_up() {
        let (u, v) = equirect_uv(Vec3::NEG_Z);
        assert!((u - 0.5).abs() < 1e-6 && (v - 0.5).abs() < 1e-6, "{u} {v}");
        let (u, _) = equirect_uv(Vec3::X);
        assert!((u - 0.75).abs() < 1e-6, "+X at u = {u}");
        let (_, v) = equirect_uv(Vec3::Y);
        assert!(v.abs() < 1e-6);
    }

    #[test]
    fn a_missing_file_is_an_error_naming_it() {
        let error = SkyImage::load(Path::new("/nonexistent/sky.hdr"), 8, 1.0)
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(error.contains("/nonexistent/sky.hdr"), "{error}");
    }
}
