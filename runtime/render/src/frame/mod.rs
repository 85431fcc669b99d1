//! Per-frame data: GPU layouts of uniforms and instances, reusable buffers, batching and
//! the depth / MSAA attachments of a target.
//!
//! - `frame_uniforms`: [`FrameUniforms`], the uniform block every shader reads.
//! - `instance_raw`: [`InstanceRaw`], one object's transform and colour on the GPU.
//! - `line_raw`: [`LineRaw`], one debug line on the GPU.
//! - `growable_buffer`: a GPU buffer reused across frames, grown geometrically.
//! - `batcher`: culls objects and groups them into instanced batches.
//! - `attachments`: depth and MSAA textures sized to a target.

mod attachments;
mod batcher;
mod frame_uniforms;
mod growable_buffer;
mod instance_raw;
mod line_raw;

pub(crate) use attachments::Attachments;
pub(crate) use batcher::{BatchKey, Batcher, MeshBounds};
pub(crate) use frame_uniforms::FrameUniforms;
pub(crate) use growable_buffer::GrowableBuffer;
pub(crate) use instance_raw::InstanceRaw;
pub(crate) use line_raw::LineRaw;
