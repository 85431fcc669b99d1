//! [`ShadingMode`]: how one object is shaded.

/// How an object is shaded. Each mode is one WGSL file in the workspace `shaders/` folder.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ShadingMode {
    /// The base colour × base colour map, ignoring lights (`unlit.wgsl`).
    Unlit,
    /// Fast lighting: Lambert and a Blinn-Phong highlight from the direct lights plus flat
    /// sky light, no maps and no shadows (`lit_low.wgsl`).
    LitLow,
    /// Physically based (Cook-Torrance: GGX, Smith, Schlick) with every map, image-based sky
    /// light and shadows (`lit.wgsl`). The default.
    #[default]
    Lit,
    /// World-space normals as colour (`normal.wgsl`).
    Normal,
    /// Triangle edges in the material colour (`wireframe.wgsl`), drawn from barycentric
    /// coordinates in the fragment shader rather than line primitives.
    Wireframe,
}

impl ShadingMode {
    /// Every mode, in a stable order.
    pub const ALL: [ShadingMode; 5] = [
        ShadingMode::Unlit,
        ShadingMode::LitLow,
        ShadingMode::Lit,
        ShadingMode::Normal,
        ShadingMode::Wireframe,
    ];

    /// File name of this mode's shader inside the shader folder.
    #[must_use]
    pub const fn shader_file(self) -> &'static str {
        match self {
            ShadingMode::Unlit => "unlit.wgsl",
            ShadingMode::LitLow => "lit_low.wgsl",
            ShadingMode::Lit => "lit.wgsl",
            ShadingMode::Normal => "normal.wgsl",
            ShadingMode::Wireframe => "wireframe.wgsl",
        }
    }

    /// Whether this mode samples the material's maps.
    #[must_use]
    pub const fn uses_texture(self) -> bool {
        matches!(self, ShadingMode::Lit | ShadingMode::Unlit)
    }

    /// Whether this mode honours the material's alpha mode (mask, blend); the others draw
    /// everything opaque.
    #[must_use]
    pub const fn uses_alpha(self) -> bool {
        matches!(
            self,
            ShadingMode::Lit | ShadingMode::Unlit | ShadingMode::LitLow
        )
    }

    /// Whether objects in this mode cast shadows.
    #[must_use]
    pub const fn casts_shadows(self) -> bool {
        !matches!(self, ShadingMode::Wireframe)
    }
}
