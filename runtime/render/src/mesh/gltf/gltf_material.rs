//! [`convert_material`]: a glTF material as a [`ModelMaterial`].

use std::path::Path;

use super::gltf_buffers::image_file;
use crate::model_material::{
    AlphaMode, ImageSource, ModelMaterial, SamplerDesc, TextureRef, UvTransform, WrapMode,
};

/// The material, every metallic-roughness field and texture slot carried. Images inside the
/// file are named [`ImageSource::Embedded`], image files by their path.
pub(crate) fn convert_material(material: &gltf::Material<'_>, model: &Path) -> ModelMaterial {
    let folder = model.parent().unwrap_or(Path::new(""));
    let pbr = material.pbr_metallic_roughness();
    let slot = |texture: gltf::Texture<'_>, tex_coord: u32, transform: Option<UvTransform>| {
        let image = texture.source();
        let source = image_file(&image, folder).map_or_else(
            || ImageSource::Embedded {
                model: model.to_owned(),
                index: image.index(),
            },
            ImageSource::File,
        );
        let mut slot = TextureRef::new(source);
        slot.uv_set = tex_coord;
        slot.transform = transform.unwrap_or(UvTransform::IDENTITY);
        slot.sampler = sampler(&texture.sampler());
        slot
    };
    let info = |info: gltf::texture::Info<'_>| {
        let transform = info.texture_transform().map(|t| UvTransform {
            offset: t.offset(),
            rotation: t.rotation(),
            scale: t.scale(),
        });
        let tex_coord = info
            .texture_transform()
            .and_then(|t| t.tex_coord())
            .unwrap_or(info.tex_coord());
        slot(info.texture(), tex_coord, transform)
    };
    ModelMaterial {
        name: material.name().unwrap_or("").to_owned(),
        base_color: pbr.base_color_factor(),
        base_color_texture: pbr.base_color_texture().map(info),
        metallic: pbr.metallic_factor(),
        roughness: pbr.roughness_factor(),
        metallic_roughness_texture: pbr.metallic_roughness_texture().map(info),
        normal_texture: material
            .normal_texture()
            .map(|n| slot(n.texture(), n.tex_coord(), None)),
        normal_scale: material.normal_texture().map_or(1.0, |n| n.scale()),
        bump_texture: None,
        bump_scale: 1.0,
        occlusion_texture: material
            .occlusion_texture()
            .map(|o| slot(o.texture(), o.tex_coord(), None)),
        occlusion_strength: material.occlusion_texture().map_or(1.0, |o| o.strength()),
        emissive: material.emissive_factor(),
        emissive_strength: material.emissive_strength().unwrap_or(1.0),
        emissive_texture: material.emissive_texture().map(info),
        alpha_mode: match material.alpha_mode() {
            gltf::material::AlphaMode::Opaque => AlphaMode::Opaque,
            gltf::material::AlphaMode::Mask => AlphaMode::Mask {
                cutoff: material.alpha_cutoff().unwrap_or(0.5),
            },
            gltf::material::AlphaMode::Blend => AlphaMode::Blend,
        },
        double_sided: material.double_sided(),
        unlit: material.unlit(),
    }
}

fn sampler(sampler: &gltf::texture::Sampler<'_>) -> SamplerDesc {
    use gltf::texture::{MagFilter, MinFilter, WrappingMode};
    let wrap = |mode| match mode {
        WrappingMode::Repeat => WrapMode::Repeat,
        WrappingMode::MirroredRepeat => WrapMode::MirroredRepeat,
        WrappingMode::ClampToEdge => WrapMode::ClampToEdge,
    };
    let min = sampler.min_filter();
    SamplerDesc {
        wrap_u: wrap(sampler.wrap_s()),
        wrap_v: wrap(sampler.wrap_t()),
        mag_linear: sampler.mag_filter() != Some(MagFilter::Nearest),
        min_linear: !matches!(
            min,
            Some(
                MinFilter::Nearest
                    | MinFilter::NearestMipmapNearest
                    | MinFilter::NearestMipmapLinear
            )
        ),
        mipmaps: !matches!(min, Some(MinFilter::Nearest | MinFilter::Linear)),
    }
}
