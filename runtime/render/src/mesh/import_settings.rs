//! [`ImportSettings`]: how one model file is brought in.

use super::normal_mode::NormalMode;
use super::up_axis::UpAxis;

/// How a model file is imported: a scene can give these per asset. The default leaves a
/// Y-up file in metres as it is and creases generated normals at 45°.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImportSettings {
    /// Uniform scale applied to positions (0.01 for a file in centimetres). Must be > 0.
    pub scale: f32,
    /// Which axis of the file points up.
    pub up_axis: UpAxis,
    /// How missing normals are generated.
    pub normals: NormalMode,
}

impl Default for ImportSettings {
    fn default() -> Self {
        Self {
            scale: 1.0,
            up_axis: UpAxis::Y,
            normals: NormalMode::default(),
        }
    }
}

impl ImportSettings {
    /// A file-space position in Onyx space (up axis turned, then scaled).
    #[must_use]
    pub fn position(&self, p: [f32; 3]) -> [f32; 3] {
        let [x, y, z] = self.up_axis.to_y_up(p);
        [x * self.scale, y * self.scale, z * self.scale]
    }

    /// A file-space normal in Onyx space (scale does not change directions).
    #[must_use]
    pub fn normal(&self, n: [f32; 3]) -> [f32; 3] {
        self.up_axis.to_y_up(n)
    }
}
