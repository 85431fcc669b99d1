//! [`ShaderKind`]: which shader file a pipeline is built from.

use crate::shading_mode::ShadingMode;

/// One shader file of the `shaders/` folder, besides `common.wgsl` which is prepended to all.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(crate) enum ShaderKind {
    /// A mesh shading mode.
    Mesh(ShadingMode),
    /// The editor grid.
    Grid,
    /// Debug lines.
    DebugLines,
    /// The missing-texture placeholder, drawn for objects whose texture failed.
    Placeholder,
}

impl ShaderKind {
    /// Every shader, in a stable order.
    pub(crate) const ALL: [ShaderKind; 8] = [
        ShaderKind::Mesh(ShadingMode::Unlit),
        ShaderKind::Mesh(ShadingMode::LitLow),
        ShaderKind::Mesh(ShadingMode::Lit),
        ShaderKind::Mesh(ShadingMode::Normal),
        ShaderKind::Mesh(ShadingMode::Wireframe),
        ShaderKind::Grid,
        ShaderKind::DebugLines,
        ShaderKind::Placeholder,
    ];

    /// File name inside the shader folder.
    pub(crate) const fn file(self) -> &'static str {
        match self {
            ShaderKind::Mesh(mode) => mode.shader_file(),
            ShaderKind::Grid => "grid.wgsl",
            ShaderKind::DebugLines => "debug_lines.wgsl",
            ShaderKind::Placeholder => "placeholder.wgsl",
        }
    }
}
