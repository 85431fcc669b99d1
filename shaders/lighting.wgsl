// Lighting (group 2), prepended to lit shaders: physically based shading (Cook-Torrance with
// GGX distribution, height-correlated Smith visibility, Schlick Fresnel, Lambert diffuse),
// the sun, point and spot lights with inverse-square falloff, their shadow maps (filtered
// with percentage-closer filtering), and the sky's image-based light (prefiltered specular +
// irradiance, combined through the split-sum BRDF table).
//
// Units: a light of intensity I lights a white diffuse surface facing it to brightness I, so
// a light's radiance is multiplied by π before the BRDF (whose diffuse term is albedo / π).

@group(2) @binding(0) var sun_shadow_map: texture_depth_2d_array;
@group(2) @binding(1) var local_shadow_map: texture_depth_2d_array;
@group(2) @binding(2) var shadow_sampler: sampler_comparison;
@group(2) @binding(3) var sky_specular: texture_cube<f32>;
@group(2) @binding(4) var sky_irradiance: texture_cube<f32>;
@group(2) @binding(5) var brdf_table: texture_2d<f32>;
@group(2) @binding(6) var sky_sampler: sampler;

// Below this GGX is numerically unstable (and nothing real is that smooth).
const MIN_ROUGHNESS: f32 = 0.045;

struct Surface {
    // Camera-relative position.
    position: vec3<f32>,
    // Shading normal (normal-mapped, facing the viewer).
    normal: vec3<f32>,
    // Geometric normal, for shadow biases.
    geometric_normal: vec3<f32>,
    view: vec3<f32>,
    diffuse_color: vec3<f32>,
    f0: vec3<f32>,
    // Perceptual roughness.
    roughness: f32,
    occlusion: f32,
};

fn d_ggx(n_dot_h: f32, a: f32) -> f32 {
    let a2 = a * a;
    let f = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (PI * f * f);
}

fn v_smith_correlated(n_dot_v: f32, n_dot_l: f32, a: f32) -> f32 {
    let a2 = a * a;
    let gv = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
    let gl = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
    return 0.5 / max(gv + gl, 1e-6);
}

fn f_schlick(f0: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    return f0 + (vec3<f32>(1.0) - f0) * pow(1.0 - v_dot_h, 5.0);
}

// Light `radiance` arriving from direction `l` (unit, towards the light), reflected to the
// viewer.
fn brdf_direct(s: Surface, l: vec3<f32>, radiance: vec3<f32>) -> vec3<f32> {
    let n_dot_l = dot(s.normal, l);
    if (n_dot_l <= 0.0) {
        return vec3<f32>(0.0);
    }
    let h = normalize(l + s.view);
    let n_dot_v = max(dot(s.normal, s.view), 1e-4);
    let n_dot_h = clamp(dot(s.normal, h), 0.0, 1.0);
    let v_dot_h = clamp(dot(s.view, h), 0.0, 1.0);
    let r = max(s.roughness, MIN_ROUGHNESS);
    let a = r * r;
    let f = f_schlick(s.f0, v_dot_h);
    let specular = d_ggx(n_dot_h, a) * v_smith_correlated(n_dot_v, n_dot_l, a) * f;
    let diffuse = (vec3<f32>(1.0) - f) * s.diffuse_color / PI;
    return (diffuse + specular) * radiance * PI * n_dot_l;
}

// Percentage-closer filtering: a 3×3 grid of bilinear comparisons spread over `radius`
// texels (0: one hard tap).
fn filter_shadow(map: texture_depth_2d_array, layer: i32, uv: vec2<f32>, depth: f32, texel: f32) -> f32 {
    let spread = frame.sun_shadow.w * texel;
    var lit = 0.0;
    for (var y = -1; y <= 1; y += 1) {
        for (var x = -1; x <= 1; x += 1) {
            let offset = vec2<f32>(f32(x), f32(y)) * spread;
            lit += textureSampleCompareLevel(map, shadow_sampler, uv + offset, layer, depth);
        }
    }
    return lit / 9.0;
}

// How much of the sun reaches `position` (1 lit, 0 shadowed).
fn sun_visibility(position: vec3<f32>, normal: vec3<f32>) -> f32 {
    if (frame.sun_color.w < 0.5) {
        return 1.0;
    }
    let count = u32(frame.sun_shadow.z);
    let depth = dot(position, frame.camera_forward.xyz);
    var cascade = count;
    for (var i = 0u; i < count; i += 1u) {
        if (depth < frame.cascade_splits[i]) {
            cascade = i;
            break;
        }
    }
    if (cascade >= count) {
        return 1.0;
    }
    let texel = frame.cascade_texels[cascade];
    let to_light = -frame.sun_direction.xyz;
    let biased = position + normal * (frame.sun_shadow.y * texel) + to_light * frame.sun_shadow.x;
    let clip = frame.cascades[cascade] * vec4<f32>(biased, 1.0);
    let uv = clip.xy * vec2<f32>(0.5, -0.5) + vec2<f32>(0.5);
    if (any(uv < vec2<f32>(0.0)) || any(uv > vec2<f32>(1.0)) || clip.z > 1.0) {
        return 1.0;
    }
    var lit = filter_shadow(sun_shadow_map, i32(cascade), uv, clip.z, 1.0 / f32(max(frame.counts.y, 1u)));
    if (cascade == count - 1u) {
        // Fade out over the last tenth of the shadow distance instead of ending in a line.
        let end = frame.cascade_splits[cascade];
        lit = mix(lit, 1.0, smoothstep(end * 0.9, end, depth));
    }
    return lit;
}

// How much of local light `light` reaches `position` (its shadow map, when it has one).
fn local_visibility(light: LocalLight, position: vec3<f32>, normal: vec3<f32>) -> f32 {
    let first = i32(light.cone_shadow.y);
    if (first < 0) {
        return 1.0;
    }
    let from_light = position - light.position_range.xyz;
    var layer = first;
    if (light.color_kind.w < 0.5) {
        // Point light: the cube face of the major axis (+X, -X, +Y, -Y, +Z, -Z).
        let a = abs(from_light);
        if (a.x >= a.y && a.x >= a.z) {
            layer += select(1, 0, from_light.x > 0.0);
        } else if (a.y >= a.z) {
            layer += select(3, 2, from_light.y > 0.0);
        } else {
            layer += select(5, 4, from_light.z > 0.0);
        }
    }
    let distance = length(from_light);
    let texel = light.shadow_range.z * distance;
    let to_light = -from_light / max(distance, 1e-4);
    let biased = position + normal * (light.cone_shadow.w * texel) + to_light * light.cone_shadow.z;
    let clip = frame.local_shadows[layer] * vec4<f32>(biased, 1.0);
    if (clip.w <= 0.0) {
        return 1.0;
    }
    let ndc = clip.xyz / clip.w;
    let uv = ndc.xy * vec2<f32>(0.5, -0.5) + vec2<f32>(0.5);
    if (any(uv < vec2<f32>(0.0)) || any(uv > vec2<f32>(1.0)) || ndc.z > 1.0) {
        return 1.0;
    }
    return filter_shadow(local_shadow_map, layer, uv, ndc.z, 1.0 / f32(max(frame.counts.z, 1u)));
}

// Radiance of local light `light` at `position` (falloff and cone, no shadow), and the
// direction towards it.
struct Incoming {
    radiance: vec3<f32>,
    l: vec3<f32>,
};

fn local_incoming(light: LocalLight, position: vec3<f32>) -> Incoming {
    let to_light = light.position_range.xyz - position;
    let distance2 = max(dot(to_light, to_light), 1e-8);
    let distance = sqrt(distance2);
    let l = to_light / distance;
    let range = light.position_range.w;
    // Inverse square, windowed smoothly to zero at `range` (Karis 2013).
    let ratio = distance / range;
    let window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    var attenuation = window * window / max(distance2, 1e-4);
    if (light.color_kind.w > 0.5) {
        let cos_angle = dot(light.direction_cos.xyz, -l);
        let cone = clamp((cos_angle - light.direction_cos.w) * light.cone_shadow.x, 0.0, 1.0);
        attenuation *= cone * cone;
    }
    var out: Incoming;
    out.radiance = light.color_kind.rgb * attenuation;
    out.l = l;
    return out;
}

// The sky's light: diffuse irradiance and prefiltered reflections (split sum).
fn sky_light(s: Surface) -> vec3<f32> {
    let n_dot_v = clamp(dot(s.normal, s.view), 1e-4, 1.0);
    let r = reflect(-s.view, s.normal);
    let irradiance = textureSampleLevel(sky_irradiance, sky_sampler, s.normal, 0.0).rgb;
    let prefiltered = textureSampleLevel(sky_specular, sky_sampler, r, s.roughness * frame.ambient.w).rgb;
    let ab = textureSampleLevel(brdf_table, sky_sampler, vec2<f32>(n_dot_v, s.roughness), 0.0).rg;
    let specular_weight = s.f0 * ab.x + ab.y;
    // Energy lost to single scattering comes back as multiple scattering (Fdez-Agüera 2019).
    let energy = 1.0 + s.f0 * (1.0 / max(ab.x + ab.y, 1e-4) - 1.0);
    let diffuse = irradiance * s.diffuse_color * (vec3<f32>(1.0) - specular_weight);
    return (diffuse + prefiltered * specular_weight * energy) * frame.ambient.rgb * s.occlusion;
}

// Everything that lights surface `s`: sky, sun (shadowed) and local lights (shadowed).
fn shade_pbr(s: Surface) -> vec3<f32> {
    var color = sky_light(s);
    if (frame.sun_direction.w > 0.5) {
        let l = -frame.sun_direction.xyz;
        if (dot(s.geometric_normal, l) > -0.2) {
            let visibility = sun_visibility(s.position, s.geometric_normal);
            color += brdf_direct(s, l, frame.sun_color.rgb) * visibility;
        }
    }
    let count = min(frame.counts.x, MAX_LOCAL_LIGHTS);
    for (var i = 0u; i < count; i += 1u) {
        let light = frame.lights[i];
        let incoming = local_incoming(light, s.position);
        if (all(incoming.radiance <= vec3<f32>(0.0))) {
            continue;
        }
        let visibility = local_visibility(light, s.position, s.geometric_normal);
        color += brdf_direct(s, incoming.l, incoming.radiance) * visibility;
    }
    return color;
}

// Lambert with a small Blinn-Phong highlight, direct lights unshadowed, plus the sky's
// irradiance: the fast `LitLow` mode and the placeholder.
fn shade_simple(position: vec3<f32>, normal: vec3<f32>, albedo: vec3<f32>) -> vec3<f32> {
    let n = normalize(normal);
    let v = view_direction(position);
    let irradiance = textureSampleLevel(sky_irradiance, sky_sampler, n, 0.0).rgb;
    var color = irradiance * frame.ambient.rgb * albedo;
    if (frame.sun_direction.w > 0.5) {
        let l = -frame.sun_direction.xyz;
        color += simple_light(n, v, l, frame.sun_color.rgb, albedo);
    }
    let count = min(frame.counts.x, MAX_LOCAL_LIGHTS);
    for (var i = 0u; i < count; i += 1u) {
        let incoming = local_incoming(frame.lights[i], position);
        color += simple_light(n, v, incoming.l, incoming.radiance, albedo);
    }
    return color;
}

const SIMPLE_SPECULAR: f32 = 0.25;
const SIMPLE_POWER: f32 = 32.0;

fn simple_light(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, radiance: vec3<f32>, albedo: vec3<f32>) -> vec3<f32> {
    let n_dot_l = max(dot(n, l), 0.0);
    let h = normalize(l + v);
    let specular = SIMPLE_SPECULAR * pow(max(dot(n, h), 0.0), SIMPLE_POWER) * step(0.0001, n_dot_l);
    return radiance * (albedo * n_dot_l + vec3<f32>(specular));
}
