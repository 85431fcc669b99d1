//! Image-based light from the sky: [`EnvironmentMaps`] renders the [`crate::Sky`] into a cube
//! map (or resamples its equirectangular HDR image into one, `sky_image`), prefilters it for glossy reflections (one mip level per roughness, GGX importance
//! sampling) and for diffuse light (cosine-weighted irradiance), and integrates the split-sum
//! BRDF table the lit shader combines them with. All on the GPU, once per sky.

mod environment_maps;
mod sky_image;

pub(crate) use environment_maps::EnvironmentMaps;
