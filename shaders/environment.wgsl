// Environment bake (standalone: no common.wgsl): renders the procedural sky into a cube map,
// prefilters it for glossy reflections (GGX importance sampling with filtered lookups, one mip
// level per roughness) and for diffuse light (cosine-weighted irradiance, divided by π so a
// white surface under a uniform sky of radiance L is L bright), and integrates the split-sum
// BRDF table (Karis 2013). Each draw is one fullscreen triangle into one face of one mip.

const PI: f32 = 3.14159265358979;
const SPECULAR_SAMPLES: u32 = 64u;
const BRDF_SAMPLES: u32 = 128u;
const IRRADIANCE_STEPS: u32 = 24u;

struct Bake {
    // x: cube face, y: roughness, z: target side (texels), w: source cube side (texels).
    params: vec4<f32>,
    zenith: vec4<f32>,
    horizon: vec4<f32>,
    ground: vec4<f32>,
};

@group(0) @binding(0) var<uniform> bake: Bake;
@group(0) @binding(1) var source: texture_cube<f32>;
@group(0) @binding(2) var source_sampler: sampler;

struct Out {
    @builtin(position) clip_position: vec4<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex_index: u32) -> Out {
    let x = f32((vertex_index << 1u) & 2u) * 2.0 - 1.0;
    let y = f32(vertex_index & 2u) * 2.0 - 1.0;
    var out: Out;
    out.clip_position = vec4<f32>(x, y, 0.0, 1.0);
    return out;
}

// The direction of a texel of a cube face (the inverse of the sampling rule of Vulkan and
// Direct3D: +X, -X, +Y, -Y, +Z, -Z; t runs down the face).
fn face_direction(face: u32, pixel: vec2<f32>, size: f32) -> vec3<f32> {
    let st = pixel / size * 2.0 - vec2<f32>(1.0);
    let s = st.x;
    let t = st.y;
    var d: vec3<f32>;
    switch (face) {
        case 0u: { d = vec3<f32>(1.0, -t, -s); }
        case 1u: { d = vec3<f32>(-1.0, -t, s); }
        case 2u: { d = vec3<f32>(s, 1.0, t); }
        case 3u: { d = vec3<f32>(s, -1.0, -t); }
        case 4u: { d = vec3<f32>(s, -t, 1.0); }
        default: { d = vec3<f32>(-s, -t, -1.0); }
    }
    return normalize(d);
}

fn sky(dir: vec3<f32>) -> vec3<f32> {
    let y = clamp(dir.y, -1.0, 1.0);
    if (y >= 0.0) {
        return mix(bake.horizon.rgb, bake.zenith.rgb, sqrt(y));
    }
    return mix(bake.horizon.rgb, bake.ground.rgb, min(-y * 4.0, 1.0));
}

fn radical_inverse(bits_in: u32) -> f32 {
    var bits = bits_in;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return f32(bits) * 2.3283064365386963e-10;
}

fn hammersley(i: u32, n: u32) -> vec2<f32> {
    return vec2<f32>(f32(i) / f32(n), radical_inverse(i));
}

// A GGX-distributed half vector around `n` for roughness alpha `a`.
fn sample_ggx(xi: vec2<f32>, n: vec3<f32>, a: f32) -> vec3<f32> {
    let phi = 2.0 * PI * xi.x;
    let cos_theta = sqrt((1.0 - xi.y) / (1.0 + (a * a - 1.0) * xi.y));
    let sin_theta = sqrt(1.0 - cos_theta * cos_theta);
    let h = vec3<f32>(cos(phi) * sin_theta, sin(phi) * sin_theta, cos_theta);
    let up = select(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 0.0, 1.0), abs(n.z) < 0.999);
    let tx = normalize(cross(up, n));
    let ty = cross(n, tx);
    return normalize(tx * h.x + ty * h.y + n * h.z);
}

@fragment
fn fs_sky(in: Out) -> @location(0) vec4<f32> {
    let dir = face_direction(u32(bake.params.x), in.clip_position.xy, bake.params.z);
    return vec4<f32>(sky(dir), 1.0);
}

@fragment
fn fs_specular(in: Out) -> @location(0) vec4<f32> {
    let n = face_direction(u32(bake.params.x), in.clip_position.xy, bake.params.z);
    let roughness = max(bake.params.y, 0.045);
    let a = roughness * roughness;
    let texel_solid_angle = 4.0 * PI / (6.0 * bake.params.w * bake.params.w);
    var sum = vec3<f32>(0.0);
    var weight = 0.0;
    for (var i = 0u; i < SPECULAR_SAMPLES; i += 1u) {
        let h = sample_ggx(hammersley(i, SPECULAR_SAMPLES), n, a);
        let l = normalize(2.0 * dot(n, h) * h - n);
        let n_dot_l = dot(n, l);
        if (n_dot_l > 0.0) {
            // Filtered importance sampling: read the mip whose texels match the sample's
            // solid angle, so few samples do not alias.
            let n_dot_h = max(dot(n, h), 0.0);
            let a2 = a * a;
            let f = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
            let d = a2 / (PI * f * f);
            let pdf = d / 4.0;
            let sample_solid_angle = 1.0 / (f32(SPECULAR_SAMPLES) * pdf + 1e-4);
            let lod = max(0.5 * log2(sample_solid_angle / texel_solid_angle) + 1.0, 0.0);
            sum += textureSampleLevel(source, source_sampler, l, lod).rgb * n_dot_l;
            weight += n_dot_l;
        }
    }
    return vec4<f32>(sum / max(weight, 1e-4), 1.0);
}

@fragment
fn fs_irradiance(in: Out) -> @location(0) vec4<f32> {
    let n = face_direction(u32(bake.params.x), in.clip_position.xy, bake.params.z);
    let up = select(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 1.0, 0.0), abs(n.y) < 0.999);
    let tx = normalize(cross(up, n));
    let ty = cross(n, tx);
    // Riemann sum over the hemisphere in (θ, φ): ∫ L cosθ sinθ dθ dφ / π.
    var sum = vec3<f32>(0.0);
    let d_theta = 0.5 * PI / f32(IRRADIANCE_STEPS);
    let d_phi = 2.0 * PI / f32(IRRADIANCE_STEPS * 2u);
    for (var i = 0u; i < IRRADIANCE_STEPS; i += 1u) {
        let theta = (f32(i) + 0.5) * d_theta;
        for (var j = 0u; j < IRRADIANCE_STEPS * 2u; j += 1u) {
            let phi = (f32(j) + 0.5) * d_phi;
            let local = vec3<f32>(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
            let dir = tx * local.x + ty * local.y + n * local.z;
            sum += textureSampleLevel(source, source_sampler, dir, 3.0).rgb * cos(theta) * sin(theta);
        }
    }
    return vec4<f32>(sum * d_theta * d_phi / PI, 1.0);
}

@fragment
fn fs_brdf(in: Out) -> @location(0) vec4<f32> {
    let uv = in.clip_position.xy / bake.params.z;
    let n_dot_v = max(uv.x, 1e-3);
    let roughness = max(uv.y, 0.045);
    let a = roughness * roughness;
    let v = vec3<f32>(sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);
    let n = vec3<f32>(0.0, 0.0, 1.0);
    var scale = 0.0;
    var bias = 0.0;
    for (var i = 0u; i < BRDF_SAMPLES; i += 1u) {
        let h = sample_ggx(hammersley(i, BRDF_SAMPLES), n, a);
        let l = normalize(2.0 * dot(v, h) * h - v);
        let n_dot_l = max(l.z, 0.0);
        let n_dot_h = max(h.z, 0.0);
        let v_dot_h = max(dot(v, h), 0.0);
        if (n_dot_l > 0.0) {
            // Height-correlated Smith, as the lit shader uses.
            let a2 = a * a;
            let gv = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
            let gl = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
            let vis = 0.5 / max(gv + gl, 1e-6);
            let g_vis = vis * 4.0 * n_dot_l * v_dot_h / max(n_dot_h, 1e-6);
            let fc = pow(1.0 - v_dot_h, 5.0);
            scale += (1.0 - fc) * g_vis;
            bias += fc * g_vis;
        }
    }
    return vec4<f32>(scale / f32(BRDF_SAMPLES), bias / f32(BRDF_SAMPLES), 0.0, 1.0);
}
