//! Shaders and render pipelines.
//!
//! - `shader_source`: [`ShaderSource`], reads WGSL from a folder or the embedded copies.
//! - `shader_error`: [`ShaderError`] and [`ShaderReloadError`], why a shader did not compile.
//! - `shader_kind`: which shader file a pipeline is built from.
//! - `layouts`: bind-group and vertex layouts shared by all pipelines.
//! - `pipeline_library`: compiles shaders inside error scopes and keeps the last good pipelines.

mod layouts;
mod pipeline_library;
mod shader_error;
mod shader_kind;
mod shader_source;

pub(crate) use layouts::Layouts;
pub(crate) use pipeline_library::{PipelineKey, PipelineLibrary};
pub use shader_error::{ShaderError, ShaderReloadError};
pub(crate) use shader_kind::ShaderKind;
pub use shader_source::ShaderSource;
