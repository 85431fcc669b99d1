// Material maps (group 1), prepended to the shaders that sample them, and the alpha rules
// shared by every alpha mode.

@group(1) @binding(0) var base_color_map: texture_2d<f32>;
@group(1) @binding(1) var metallic_roughness_map: texture_2d<f32>;
@group(1) @binding(2) var normal_map: texture_2d<f32>;
@group(1) @binding(3) var occlusion_map: texture_2d<f32>;
@group(1) @binding(4) var emissive_map: texture_2d<f32>;
@group(1) @binding(5) var material_sampler: sampler;

// Base colour × its map.
fn base_color(o: Object, uv: vec2<f32>) -> vec4<f32> {
    return o.color * textureSample(base_color_map, material_sampler, uv);
}

// The fragment's alpha under `mode` (0 opaque, 1 mask, 2 blend); masked-out fragments are
// discarded.
fn apply_alpha(alpha: f32, cutoff: f32, mode: u32) -> f32 {
    if (mode == 1u) {
        if (alpha < cutoff) {
            discard;
        }
        return 1.0;
    }
    if (mode == 2u) {
        return clamp(alpha, 0.0, 1.0);
    }
    return 1.0;
}
