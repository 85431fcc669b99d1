//! Copying a colour texture back to the CPU as an `image::RgbaImage` (offscreen targets and
//! window screenshots).

use std::sync::mpsc;

use image::RgbaImage;

use crate::gpu_context::GpuContext;
use crate::readback_error::ReadbackError;

/// wgpu requires buffer rows of texture copies to be multiples of this many bytes.
const ROW_ALIGNMENT: u32 = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;

/// Copies mip 0 of an 8-bit RGBA or BGRA texture (with `COPY_SRC`) into an RGBA image and
/// waits for it. Rows are padded to 256 bytes on the GPU and unpadded here.
pub(crate) fn read_texture(
    gpu: &GpuContext,
    texture: &wgpu::Texture,
) -> Result<RgbaImage, ReadbackError> {
    let format = texture.format();
    let swap_red_blue = match format {
        wgpu::TextureFormat::Rgba8Unorm | wgpu::TextureFormat::Rgba8UnormSrgb => false,
        wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb => true,
        _ => return Err(ReadbackError::UnsupportedFormat { format }),
    };
    if !texture.usage().contains(wgpu::TextureUsages::COPY_SRC) {
        return Err(ReadbackError::NotCopyable);
    }
    let (width, height) = (texture.width(), texture.height());
    let row_bytes = width * 4;
    let padded_row = row_bytes.div_ceil(ROW_ALIGNMENT) * ROW_ALIGNMENT;
    let buffer = gpu.device().create_buffer(&wgpu::BufferDescriptor {
        label: Some("onyx readback"),
        size: u64::from(padded_row) * u64::from(height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = gpu
        .device()
        .create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("onyx readback"),
        });
    encoder.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded_row),
                rows_per_image: Some(height),
            },
        },
        wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
    );
    gpu.queue().submit([encoder.finish()]);

    let (sender, receiver) = mpsc::channel();
    buffer.map_async(wgpu::MapMode::Read, .., move |result| {
        // The receiver only disappears if `read_texture` already returned.
        let _ = sender.send(result);
    });
    gpu.device().poll(wgpu::PollType::wait_indefinitely())?;
    receiver.recv().map_err(|_| ReadbackError::NoAnswer)??;

    let mut pixels = Vec::with_capacity((row_bytes * height) as usize);
    {
        let mapped = buffer.get_mapped_range(..)?;
        for row in mapped.chunks_exact(padded_row as usize) {
            pixels.extend_from_slice(&row[..row_bytes as usize]);
        }
    }
    buffer.unmap();
    if swap_red_blue {
        for pixel in pixels.chunks_exact_mut(4) {
            pixel.swap(0, 2);
        }
    }
    RgbaImage::from_raw(width, height, pixels).ok_or(ReadbackError::NoAnswer)
}
