//! [`NormalMode`]: how normals a file lacks are generated.

/// Default crease angle of [`NormalMode::Crease`], degrees: edges sharper than this stay
/// sharp (a cube's 90° edges, CAD parts), gentler curvature is smoothed (a sphere's facets).
pub const DEFAULT_CREASE_DEGREES: f32 = 45.0;

/// How normals are generated for faces that have none (OBJ faces without `vn`, glTF
/// primitives without `NORMAL`). OBJ smoothing groups (`s 1`, `s off`), where a file has
/// them, decide instead.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalMode {
    /// Every vertex averages all faces around it (area-weighted): round everywhere.
    Smooth,
    /// Each face keeps its own normal: faceted.
    Flat,
    /// Faces meeting at less than `degrees` are smoothed together, sharper edges stay sharp.
    Crease {
        /// Largest angle between two face normals that is still smoothed, degrees.
        degrees: f32,
    },
}

impl Default for NormalMode {
    /// [`NormalMode::Crease`] at [`DEFAULT_CREASE_DEGREES`].
    fn default() -> Self {
        NormalMode::Crease {
            degrees: DEFAULT_CREASE_DEGREES,
        }
    }
}

impl NormalMode {
    /// Cosine of the largest angle smoothed over: 1 for flat, −1 for smooth.
    #[must_use]
    pub fn min_cos(self) -> f32 {
        match self {
            NormalMode::Smooth => -1.0,
            NormalMode::Flat => 1.0,
            NormalMode::Crease { degrees } => degrees.clamp(0.0, 180.0).to_radians().cos(),
        }
    }
}
