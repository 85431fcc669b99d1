//! [`ShaderKind`]: which shader file a pipeline is built from.

use crate::shading_mode::ShadingMode;

/// One shader file of the `shaders/` folder, besides the preludes prepended to it
/// (`common.wgsl` always, `lighting.wgsl` for lit ones).
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
    /// The sky behind the scene.
    Sky,
    /// Depth of shadow casters into a shadow map.
    Shadow,
    /// HDR → display: exposure, tone mapping, sRGB.
    Tonemap,
}

impl ShaderKind {
    /// Every shader, in a stable order.
    pub(crate) const ALL: [ShaderKind; 11] = [
        ShaderKind::Mesh(ShadingMode::Unlit),
        ShaderKind::Mesh(ShadingMode::LitLow),
        ShaderKind::Mesh(ShadingMode::Lit),
        ShaderKind::Mesh(ShadingMode::Normal),
        ShaderKind::Mesh(ShadingMode::Wireframe),
        ShaderKind::Grid,
        ShaderKind::DebugLines,
        ShaderKind::Placeholder,
        ShaderKind::Sky,
        ShaderKind::Shadow,
        ShaderKind::Tonemap,
    ];

    /// File name inside the shader folder.
    pub(crate) const fn file(self) -> &'static str {
        match self {
            ShaderKind::Mesh(mode) => mode.shader_file(),
            ShaderKind::Grid => "grid.wgsl",
            ShaderKind::DebugLines => "debug_lines.wgsl",
            ShaderKind::Placeholder => "placeholder.wgsl",
            ShaderKind::Sky => "sky.wgsl",
            ShaderKind::Shadow => "shadow.wgsl",
            ShaderKind::Tonemap => "tonemap.wgsl",
        }
    }

    /// Files prepended to this one after `common.wgsl`: the material maps (`material.wgsl`)
    /// and the lights, shadows and sky light (`lighting.wgsl`).
    pub(crate) const fn preludes(self) -> &'static [&'static str] {
        match self {
            ShaderKind::Mesh(ShadingMode::Lit | ShadingMode::LitLow) | ShaderKind::Placeholder => {
                &["material.wgsl", "lighting.wgsl"]
            }
            ShaderKind::Mesh(ShadingMode::Unlit) | ShaderKind::Shadow => &["material.wgsl"],
            _ => &[],
        }
    }
}
