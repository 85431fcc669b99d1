//! CPU mip chain generation with `image`'s resampling.

use image::imageops::FilterType;
use image::RgbaImage;

/// Number of mip levels of a full chain down to 1×1.
pub(crate) fn mip_level_count(width: u32, height: u32) -> u32 {
    32 - width.max(height).max(1).leading_zeros()
}

/// Levels 1.. of the mip chain of `base` (level 0 is `base` itself), each half the size of
/// the previous, box-like triangle filtering. Filtering happens on the sRGB-encoded values,
/// which slightly darkens high-contrast detail in far mips (acceptable for albedo).
pub(crate) fn generate_mips(base: &RgbaImage) -> Vec<RgbaImage> {
    let mut levels = Vec::new();
    let (mut width, mut height) = base.dimensions();
    while width > 1 || height > 1 {
        width = (width / 2).max(1);
        height = (height / 2).max(1);
        let previous = levels.last().unwrap_or(base);
        let next = image::imageops::resize(previous, width, height, FilterType::Triangle);
        levels.push(next);
    }
    levels
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
}
