//! [`parse_mtl`]: an MTL material library, read tolerantly into [`ModelMaterial`]s.

use std::path::Path;

use super::obj_document::{parse_float, strip_comment};
use super::texture_map::{parse_texture_map, TextureMap};
use crate::asset_io::{resolve_referenced_path, AssetWarning};
use crate::model_material::{AlphaMode, ImageSource, ModelMaterial, TextureRef, UvTransform};

/// The materials of MTL text at `path`, in file order, with the warnings met (bad numbers,
/// texture options that are not applied: each kind once, at its first line). Texture paths
/// are resolved against the MTL's folder.
pub(crate) fn parse_mtl(text: &str, path: &Path) -> (Vec<ModelMaterial>, Vec<AssetWarning>) {
    let folder = path.parent().unwrap_or(Path::new(""));
    let mut materials: Vec<ModelMaterial> = Vec::new();
    let mut warnings = Vec::new();
    let mut ignored_options: Vec<String> = Vec::new();
    let mut ignored_line = None;
    let mut bad_number = None;
    let mut dissolve_set = false;
    for (index, raw) in text.lines().enumerate() {
        let number = index + 1;
        let line = strip_comment(raw).trim();
        let (keyword, rest) = match line.find(|c: char| c.is_ascii_whitespace()) {
            Some(at) => (&line[..at], line[at..].trim()),
            None => (line, ""),
        };
        if keyword.is_empty() {
            continue;
        }
        let keyword = keyword.to_ascii_lowercase();
        if keyword == "newmtl" {
            materials.push(ModelMaterial {
                name: rest.to_owned(),
                // MTL has no metalness; a dielectric reads closest to Phong's look.
                metallic: 0.0,
                roughness: 0.5,
                ..ModelMaterial::default()
            });
            dissolve_set = false;
            continue;
        }
        let Some(material) = materials.last_mut() else {
            continue;
        };
        let mut numbers = || -> Vec<f32> {
            let values: Vec<f32> = rest
                .split_ascii_whitespace()
                .map_while(parse_float)
                .filter(|v| v.is_finite())
                .collect();
            if values.is_empty() {
                bad_number.get_or_insert(number);
            }
            values
        };
        let mut texture = |map: Option<TextureMap>| -> Option<(TextureRef, f32)> {
            let map = map?;
            if !map.ignored.is_empty() {
                ignored_line.get_or_insert(number);
                for option in &map.ignored {
                    if !ignored_options.contains(option) {
                        ignored_options.push(option.clone());
                    }
                }
            }
            let mut slot = TextureRef::new(ImageSource::File(resolve_referenced_path(
                folder, &map.file,
            )));
            slot.transform = UvTransform {
                offset: map.offset,
                rotation: 0.0,
                scale: map.scale,
            };
            Some((slot, map.bump_multiplier))
        };
        match keyword.as_str() {
            "kd" => {
                let v = numbers();
                if v.len() >= 3 {
                    material.base_color[..3].copy_from_slice(&v[..3]);
                }
            }
            "ke" => {
                let v = numbers();
                if v.len() >= 3 {
                    material.emissive.copy_from_slice(&v[..3]);
                }
            }
            "d" => {
                if let Some(&d) = numbers().first() {
                    material.base_color[3] = d.clamp(0.0, 1.0);
                    dissolve_set = true;
                }
            }
            "tr" => {
                if let Some(&tr) = numbers().first() {
                    if !dissolve_set {
                        material.base_color[3] = (1.0 - tr).clamp(0.0, 1.0);
                    }
                }
            }
            "pr" => material.roughness = numbers().first().copied().unwrap_or(0.5),
            "pm" => material.metallic = numbers().first().copied().unwrap_or(0.0),
            "map_kd" => material.base_color_texture = texture(parse_texture_map(rest)).map(|t| t.0),
            "map_ke" => material.emissive_texture = texture(parse_texture_map(rest)).map(|t| t.0),
            "norm" | "map_kn" => {
                material.normal_texture = texture(parse_texture_map(rest)).map(|t| t.0);
            }
            "map_bump" | "bump" => {
                if let Some((slot, multiplier)) = texture(parse_texture_map(rest)) {
                    material.bump_texture = Some(slot);
                    material.bump_scale = multiplier;
                }
            }
            "map_pr" => {
                material.metallic_roughness_texture = texture(parse_texture_map(rest)).map(|t| t.0);
            }
            _ => {}
        }
        if material.base_color[3] < 1.0 {
            material.alpha_mode = AlphaMode::Blend;
        }
    }
    if let Some(line) = ignored_line {
        warnings.push(AssetWarning::new(
            path,
            Some(line),
            format!(
                "texture option(s) {} ignored: Onyx applies -s (scale), -o (offset) and -bm only",
                ignored_options.join(", ")
            ),
        ));
    }
    if let Some(line) = bad_number {
        warnings.push(AssetWarning::new(
            path,
            Some(line),
            "a material value is not a number; the default was kept",
        ));
    }
    (materials, warnings)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn d_wins_over_tr_and_maps_keep_their_options() {
        let text = "newmtl glass\nKd 0.2 0.4 0.6\nTr 0.75\nd 0.5\nmap_Kd -s 2 2 -o 0.5 0 -clamp on glass tex.png\nnewmtl smoke\nTr 0.75\n";
        let (materials, warnings) = parse_mtl(text, Path::new("/m/a.mtl"));
        assert_eq!(materials.len(), 2);
        assert_eq!(materials[0].base_color, [0.2, 0.4, 0.6, 0.5]);
        assert_eq!(materials[1].base_color[3], 0.25);
        let slot = materials[0]
            .base_color_texture
            .clone()
            .unwrap_or_else(|| panic!("no map"));
        assert_eq!(slot.image, ImageSource::File("/m/glass tex.png".into()));
        assert_eq!(
            (slot.transform.scale, slot.transform.offset),
            ([2.0, 2.0], [0.5, 0.0])
        );
        assert_eq!(warnings.len(), 1, "{warnings:?}");
        assert_eq!(warnings[0].line, Some(5));
    }
}
