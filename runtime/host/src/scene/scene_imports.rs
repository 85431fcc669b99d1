//! [`ImportSettingsFile`]: how a scene file asks for one model file to be brought in (scale,
//! up axis, generated normals), under the scene's `imports` table keyed by the model's path.

use onyx_render::mesh::DEFAULT_CREASE_DEGREES;
use onyx_render::{ImportSettings, NormalMode, UpAxis};
use serde::{Deserialize, Serialize};

/// Which axis of a model file points up.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum UpAxisFile {
    /// Y up, as Onyx (and glTF, and most OBJ exporters).
    #[default]
    Y,
    /// Z up (CAD tools, Blender's raw axes, 3ds Max): turned to Y up.
    Z,
}

/// How normals a model file lacks are generated.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum NormalsFile {
    /// Round everywhere.
    Smooth,
    /// Faceted.
    Flat,
    /// Edges sharper than this many degrees stay sharp.
    Crease(f32),
}

impl Default for NormalsFile {
    fn default() -> Self {
        NormalsFile::Crease(DEFAULT_CREASE_DEGREES)
    }
}

/// A model's import settings as a scene writes them:
/// `imports: { "models/part.obj": (scale: 0.001, up_axis: Z, normals: Crease(30.0)) }`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ImportSettingsFile {
    /// Uniform scale (0.01 for a file in centimetres); > 0. Absent: 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scale: Option<f32>,
    /// Which axis of the file points up.
    pub up_axis: UpAxisFile,
    /// How missing normals are generated.
    pub normals: NormalsFile,
}

impl ImportSettingsFile {
    /// The settings, or a sentence saying which value is out of range.
    pub fn settings(&self) -> Result<ImportSettings, String> {
        let scale = self.scale.unwrap_or(1.0);
        if !(scale.is_finite() && scale > 0.0) {
            return Err(format!("`scale` must be a number > 0, got {scale}"));
        }
        let normals = match self.normals {
            NormalsFile::Smooth => NormalMode::Smooth,
            NormalsFile::Flat => NormalMode::Flat,
            NormalsFile::Crease(degrees) => {
                if !(0.0..=180.0).contains(&degrees) {
                    return Err(format!(
                        "`normals: Crease(..)` must be 0 to 180 degrees, got {degrees}"
                    ));
                }
                NormalMode::Crease { degrees }
            }
        };
        Ok(ImportSettings {
            scale,
            up_axis: match self.up_axis {
                UpAxisFile::Y => UpAxis::Y,
                UpAxisFile::Z => UpAxis::Z,
            },
            normals,
        })
    }

    /// The file form of `settings`.
    pub fn from_settings(settings: &ImportSettings) -> Self {
        Self {
            scale: (settings.scale != 1.0).then_some(settings.scale),
            up_axis: match settings.up_axis {
                UpAxis::Y => UpAxisFile::Y,
                UpAxis::Z => UpAxisFile::Z,
            },
            normals: match settings.normals {
                NormalMode::Smooth => NormalsFile::Smooth,
                NormalMode::Flat => NormalsFile::Flat,
                NormalMode::Crease { degrees } => NormalsFile::Crease(degrees),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settings_round_trip_and_bad_values_are_named() {
        let file = ImportSettingsFile {
            scale: Some(0.01),
            up_axis: UpAxisFile::Z,
            normals: NormalsFile::Crease(30.0),
        };
        let settings = file.settings().unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(settings.up_axis, UpAxis::Z);
        assert_eq!(ImportSettingsFile::from_settings(&settings), file);
        assert_eq!(
            ImportSettingsFile::default().settings(),
            Ok(ImportSettings::default())
        );
        let bad = ImportSettingsFile {
            scale: Some(-1.0),
            ..ImportSettingsFile::default()
        };
        assert!(bad.settings().is_err_and(|e| e.contains("scale")));
        let bad = ImportSettingsFile {
            normals: NormalsFile::Crease(200.0),
            ..ImportSettingsFile::default()
        };
        assert!(bad.settings().is_err_and(|e| e.contains("Crease")));
    }
}
