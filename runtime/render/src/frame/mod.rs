//! Per-frame data: GPU layouts of uniforms and objects, reusable buffers, culling and
//! batching for every view, and the HDR / depth / MSAA attachments of a target.
//!
//! - `frame_uniforms`: [`FrameUniforms`], the uniform block every shader reads.
//! - `object_raw`: [`ObjectRaw`], one object's camera-relative transform and material factors.
//! - `shadow_view_raw`: [`ShadowViewRaw`], one shadow pass's view-projection.
//! - `local_light_raw`: one point or spot light in the frame uniforms.
//! - `line_raw`: [`LineRaw`], one debug line on the GPU.
//! - `growable_buffer`: a GPU buffer reused across frames, grown geometrically, written
//!   through a staging belt reused across frames.
//! - `batch_key`: what objects are grouped by, in camera and shadow passes.
//! - `batcher`: culls objects for every view and groups them into instanced batches.
//! - `attachments`: HDR colour, depth and MSAA textures sized to a target.

mod attachments;
mod batch_key;
mod batcher;
mod frame_uniforms;
mod growable_buffer;
mod line_raw;
mod local_light_raw;
mod object_raw;
mod shadow_view_raw;

pub(crate) use attachments::{Attachments, HDR_FORMAT};
pub(crate) use batch_key::{AlphaClass, BatchKey, MaterialMaps};
pub(crate) use batcher::{Batcher, FrameViews, MeshBounds};
pub(crate) use frame_uniforms::{FrameInputs, FrameUniforms};
pub(crate) use growable_buffer::{GrowableBuffer, Upload};
pub(crate) use line_raw::LineRaw;
pub(crate) use shadow_view_raw::{ShadowViewRaw, SHADOW_VIEW_STRIDE};
