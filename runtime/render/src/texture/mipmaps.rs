//! CPU mip chain generation: each level the 2×2 box average of the previous.

use image::RgbaImage;

/// Number of mip levels of a full chain down to 1×1.
pub(crate) fn mip_level_count(width: u32, height: u32) -> u32 {
    32 - width.max(height).max(1).leading_zeros()
}

/// Levels 1.. of the mip chain of `base` (level 0 is `base` itself), each half the size of
/// the previous (rounded down, at least 1), every texel the average of the 2×2 block above
/// it (odd edges repeat their last row or column). Averaging happens on the sRGB-encoded
/// values, which slightly darkens high-contrast detail in far mips (acceptable for albedo).
pub(crate) fn generate_mips(base: &RgbaImage) -> Vec<RgbaImage> {
    let mut levels: Vec<RgbaImage> = Vec::new();
    loop {
        let previous = levels.last().unwrap_or(base);
        let (w, h) = previous.dimensions();
        if w <= 1 && h <= 1 {
            return levels;
        }
        levels.push(halve(previous));
    }
}

/// The image at half size, box-filtered: output texel (x, y) averages source texels
/// 2x..2x+1 × 2y..2y+1 (a 1-texel-wide or -high source repeats its only column or row). Rows
/// are walked as slices in 8-byte pairs so the loop has no per-texel bounds checks or clamps
/// (the import bench's DamagedHelmet spends its mip time here).
fn halve(image: &RgbaImage) -> RgbaImage {
    let (w, h) = (image.width() as usize, image.height() as usize);
    let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
    let src = image.as_raw();
    let row = w * 4;
    let mut out = vec![0u8; nw * nh * 4];
    for (y, out_row) in out.chunks_exact_mut(nw * 4).enumerate() {
        let r0 = &src[(2 * y).min(h - 1) * row..][..row];
        let r1 = &src[(2 * y + 1).min(h - 1) * row..][..row];
        if w >= 2 {
            for ((o, a), b) in out_row
                .chunks_exact_mut(4)
                .zip(r0.chunks_exact(8))
                .zip(r1.chunks_exact(8))
            {
                for c in 0..4 {
                    let sum = u16::from(a[c])
                        + u16::from(a[c + 4])
                        + u16::from(b[c])
                        + u16::from(b[c + 4]);
                    o[c] = ((sum + 2) / 4) as u8;
                }
            }
        } else {
            for c in 0..4 {
                let sum = 2 * u16::from(r0[c]) + 2 * u16::from(r1[c]);
                out_row[c] = ((sum + 2) / 4) as u8;
            }
        }
    }
    RgbaImage::from_raw(nw as u32, nh as u32, out)
        .unwrap_or_else(|| RgbaImage::new(nw as u32, nh as u32))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chain_halves_down_to_one_pixel() {
        assert_eq!(mip_level_count(1024, 512), 11);
        assert_eq!(mip_level_count(1, 1), 1);
        let base = RgbaImage::from_pixel(8, 4, image::Rgba([200, 100, 50, 255]));
        let sizes: Vec<_> = generate_mips(&base)
            .iter()
            .map(|m| m.dimensions())
            .collect();
        assert_eq!(sizes, vec![(4, 2), (2, 1), (1, 1)]);
    }

    #[test]
    fn a_checker_averages_to_grey() {
        let checker = RgbaImage::from_fn(4, 4, |x, y| {
            image::Rgba(if (x + y) % 2 == 0 {
                [255; 4]
            } else {
                [0, 0, 0, 255]
            })
        });
        let mips = generate_mips(&checker);
        assert_eq!(mips[0].get_pixel(1, 1).0, [128, 128, 128, 255]);
    }

    /// The definition, texel by texel with clamped coordinates, for odd and thin sizes too.
    #[test]
    fn halving_matches_the_clamped_box_average_at_every_size() {
        for (w, h) in [(1, 1), (1, 7), (7, 1), (2, 2), (5, 3), (6, 9), (33, 17)] {
            let image = RgbaImage::from_fn(w, h, |x, y| {
                let v = (x * 37 + y * 91 + x * y * 13) as u8;
                image::Rgba([v, v.wrapping_mul(3), v.wrapping_add(77), 255 - v])
            });
            let half = halve(&image);
            let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
            assert_eq!(half.dimensions(), (nw, nh));
            for y in 0..nh {
                for x in 0..nw {
                    let (x0, x1) = ((2 * x).min(w - 1), (2 * x + 1).min(w - 1));
                    let (y0, y1) = ((2 * y).min(h - 1), (2 * y + 1).min(h - 1));
                    for c in 0..4 {
                        let sum: u32 = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)]
                            .iter()
                            .map(|&(px, py)| u32::from(image.get_pixel(px, py).0[c]))
                            .sum();
                        assert_eq!(
                            half.get_pixel(x, y).0[c],
                            ((sum + 2) / 4) as u8,
                            "{w}x{h} at ({x}, {y}) channel {c}"
                        );
                    }
                }
            }
        }
    }
}
