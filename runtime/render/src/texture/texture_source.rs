//! [`TextureSource`] and [`decode_texture`]: an image file decoded on the CPU, checked
//! against limits from its header before any pixel is decoded.

use std::io::Cursor;
use std::path::Path;

use image::RgbaImage;

use super::mipmaps::generate_mips;
use super::texture_load_error::TextureLoadError;
use crate::asset_io::{read_asset_file, AssetWarning, MAX_ASSET_FILE_BYTES};
use crate::model_material::ImageSource;

/// Most pixels an image may have to be decoded at all (16384 × 16384, 1 GiB as RGBA): the
/// header is read first, and a larger image is refused before its pixels are.
pub const MAX_DECODED_PIXELS: u64 = 16384 * 16384;

/// A decoded texture: level 0 (at most the GPU's largest side) and its mip chain.
#[derive(Clone, Debug)]
pub struct TextureSource {
    /// Mip levels, level 0 first, each half the previous.
    pub levels: Vec<RgbaImage>,
    /// The image's own size, before any downscaling.
    pub original_size: (u32, u32),
    /// Set when the image was downscaled to fit the GPU.
    pub warning: Option<AssetWarning>,
}

impl TextureSource {
    /// Wraps an image already in memory, building its mip chain when `mips` is set.
    #[must_use]
    pub fn from_image(image: RgbaImage, mips: bool) -> Self {
        let original_size = image.dimensions();
        let mut levels = vec![image];
        if mips {
            let rest = generate_mips(&levels[0]);
            levels.extend(rest);
        }
        Self {
            levels,
            original_size,
            warning: None,
        }
    }
}

/// Reads and decodes the image `source` names (files only; images inside model files are
/// decoded by their loader with [`decode_texture_bytes`]).
pub(crate) fn decode_texture(
    source: &ImageSource,
    max_side: u32,
) -> Result<TextureSource, TextureLoadError> {
    match source {
        ImageSource::File(path) => {
            let bytes = read_asset_file(path, MAX_ASSET_FILE_BYTES).map_err(|source| {
                TextureLoadError::Read {
                    path: path.clone(),
                    source,
                }
            })?;
            decode_texture_bytes(&bytes, path, max_side)
        }
        ImageSource::Embedded { model, index } => Err(TextureLoadError::Unsupported {
            path: model.clone(),
            format: format!("embedded image {index} that its loader did not provide"),
        }),
    }
}

/// Decodes PNG or JPEG bytes (format from the content; `name` for messages). The size comes
/// from the header first: over [`MAX_DECODED_PIXELS`] is refused undecoded; a side over
/// `max_side` (the GPU's limit) is decoded, then halved until it fits, with a warning.
pub fn decode_texture_bytes(
    bytes: &[u8],
    name: &Path,
    max_side: u32,
) -> Result<TextureSource, TextureLoadError> {
    let decode_error = |source| TextureLoadError::Decode {
        path: name.to_owned(),
        source,
    };
    let reader = image::ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| decode_error(image::ImageError::IoError(e)))?;
    let Some(format) = reader.format() else {
        return Err(TextureLoadError::Unsupported {
            path: name.to_owned(),
            format: "an image format Onyx does not recognise".to_owned(),
        });
    };
    if !matches!(format, image::ImageFormat::Png | image::ImageFormat::Jpeg) {
        return Err(TextureLoadError::Unsupported {
            path: name.to_owned(),
            format: format!("a {format:?} image"),
        });
    }
    let (width, height) = image::ImageReader::with_format(Cursor::new(bytes), format)
        .into_dimensions()
        .map_err(decode_error)?;
    if u64::from(width) * u64::from(height) > MAX_DECODED_PIXELS {
        return Err(TextureLoadError::TooLarge {
            path: name.to_owned(),
            width,
            height,
            max_pixels: MAX_DECODED_PIXELS,
        });
    }
    let mut reader = image::ImageReader::with_format(Cursor::new(bytes), format);
    // The default allocation limit (512 MiB) would refuse images the check above accepts.
    let mut limits = image::Limits::default();
    limits.max_alloc = Some(u64::from(width) * u64::from(height) * 8 + (64 << 20));
    reader.limits(limits);
    let image = reader.decode().map_err(decode_error)?.into_rgba8();
    let mut levels = vec![image];
    let rest = generate_mips(&levels[0]);
    levels.extend(rest);
    let mut warning = None;
    let fits = |img: &RgbaImage| img.width() <= max_side && img.height() <= max_side;
    if !fits(&levels[0]) {
        let first = levels.iter().position(fits).unwrap_or(levels.len() - 1);
        levels.drain(..first);
        let (w, h) = levels[0].dimensions();
        warning = Some(AssetWarning::new(
            name,
            None,
            format!("texture is {width}×{height} pixels, over this GPU's limit of {max_side}; it was scaled down to {w}×{h}"),
        ));
    }
    Ok(TextureSource {
        levels,
        original_size: (width, height),
        warning,
    })
}
