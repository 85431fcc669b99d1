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

/// The image at half size, box-filtered.
fn halve(image: &RgbaImage) -> RgbaImage {
    let (w, h) = image.dimensions();
    let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
    let src = image.as_raw();
    let row = w as usize * 4;
    let mut out = vec![0u8; nw as usize * nh as usize * 4];
    for y in 0..nh as usize {
        let y0 = (2 * y).min(h as usize - 1);
        let y1 = (2 * y + 1).min(h as usize - 1);
        for x in 0..nw as usize {
            let x0 = (2 * x).min(w as usize - 1) * 4;
            let x1 = (2 * x + 1).min(w as usize - 1) * 4;
            for c in 0..4 {
                let sum = u32::from(src[y0 * row + x0 + c])
                    + u32::from(src[y0 * row + x1 + c])
                    + u32::from(src[y1 * row + x0 + c])
                    + u32::from(src[y1 * row + x1 + c]);
                out[(y * nw as usize + x) * 4 + c] = ((sum + 2) / 4) as u8;
            }
        }
    }
    RgbaImage::from_raw(nw, nh, out).unwrap_or_else(|| RgbaImage::new(nw, nh))
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
}
