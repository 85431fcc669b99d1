// Tone mapping: the resolved HDR frame, scaled by the exposure, through the chosen operator
// (AgX by default), written to the target (whose sRGB format encodes it; where the target is
// not sRGB the shader encodes). Pixels of debug views (normals, wireframe) carry alpha 0 and
// are shown as they are.

// Group 0 binding 0 is `frame` (common.wgsl); binding 1 (the objects) is not bound here.
@group(0) @binding(2) var hdr: texture_2d<f32>;

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

// AgX (Troy Sobotka), the minimal fit by Benjamin Wrensch as Blender's "AgX Base": an inset
// into a wide working space, a log2 encoding over 16.5 stops, a sigmoid, and back out.
fn agx_contrast(x: vec3<f32>) -> vec3<f32> {
    let x2 = x * x;
    let x4 = x2 * x2;
    return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
}

fn agx(color: vec3<f32>) -> vec3<f32> {
    let inset = mat3x3<f32>(
        0.842479062253094, 0.0423282422610123, 0.0423756549057051,
        0.0784335999999992, 0.878468636469772, 0.0784336,
        0.0792237451477643, 0.0791661274605434, 0.879142973793104,
    );
    let outset = mat3x3<f32>(
        1.19687900512017, -0.0528968517574562, -0.0529716355144438,
        -0.0980208811401368, 1.15190312990417, -0.0980434501171241,
        -0.0990297440797205, -0.0989611768448433, 1.15107367264116,
    );
    let min_ev = -12.47393;
    let max_ev = 4.026069;
    var c = inset * max(color, vec3<f32>(0.0));
    c = clamp(log2(max(c, vec3<f32>(1e-10))), vec3<f32>(min_ev), vec3<f32>(max_ev));
    c = (c - min_ev) / (max_ev - min_ev);
    c = agx_contrast(c);
    c = outset * c;
    // The curve ends display-encoded (gamma 2.2); back to linear for the sRGB target.
    return pow(clamp(c, vec3<f32>(0.0), vec3<f32>(1.0)), vec3<f32>(2.2));
}

// ACES filmic, Krzysztof Narkowicz's fit.
fn aces(x: vec3<f32>) -> vec3<f32> {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), vec3<f32>(0.0), vec3<f32>(1.0));
}

fn luminance(c: vec3<f32>) -> f32 {
    return dot(c, vec3<f32>(0.2126, 0.7152, 0.0722));
}

fn srgb_encode(c: vec3<f32>) -> vec3<f32> {
    let low = c * 12.92;
    let high = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(high, low, c <= vec3<f32>(0.0031308));
}

@fragment
fn fs_main(in: Out) -> @location(0) vec4<f32> {
    let texel = textureLoad(hdr, vec2<i32>(in.clip_position.xy), 0);
    let exposed = max(texel.rgb, vec3<f32>(0.0)) * frame.output.x;
    var mapped: vec3<f32>;
    let tone_map = u32(frame.output.y);
    if (texel.a < 0.5) {
        return vec4<f32>(select(clamp(texel.rgb, vec3<f32>(0.0), vec3<f32>(1.0)), srgb_encode(clamp(texel.rgb, vec3<f32>(0.0), vec3<f32>(1.0))), frame.output.z > 0.5), 1.0);
    }
    switch (tone_map) {
        case 0u: { mapped = agx(exposed); }
        case 1u: { mapped = aces(exposed); }
        case 2u: { mapped = exposed / (1.0 + luminance(exposed)); }
        default: { mapped = clamp(exposed, vec3<f32>(0.0), vec3<f32>(1.0)); }
    }
    if (frame.output.z > 0.5) {
        mapped = srgb_encode(mapped);
    }
    return vec4<f32>(mapped, 1.0);
}
