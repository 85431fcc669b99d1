// Sky: the sky's radiance behind everything, one fullscreen triangle at depth 0 (infinitely
// far, reverse-Z), drawn where no surface was: the procedural sky's function, or the cube an
// image sky was resampled into (frame.sky_zenith.w = 1).

@group(2) @binding(6) var sky_sampler: sampler;
@group(2) @binding(7) var sky_cube: texture_cube<f32>;

struct SkyOut {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) ndc: vec2<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex_index: u32) -> SkyOut {
    let x = f32((vertex_index << 1u) & 2u) * 2.0 - 1.0;
    let y = f32(vertex_index & 2u) * 2.0 - 1.0;
    var out: SkyOut;
    out.clip_position = vec4<f32>(x, y, 0.0, 1.0);
    out.ndc = vec2<f32>(x, y);
    return out;
}

@fragment
fn fs_main(in: SkyOut) -> @location(0) vec4<f32> {
    var dir = frame.camera_forward.xyz;
    if (frame.camera_world.w < 0.5) {
        let p = frame.inv_view_proj * vec4<f32>(in.ndc, 0.5, 1.0);
        dir = normalize(p.xyz / p.w);
    }
    if (frame.sky_zenith.w > 0.5) {
        return vec4<f32>(textureSampleLevel(sky_cube, sky_sampler, dir, 0.0).rgb, 1.0);
    }
    let color = sky_radiance(dir, frame.sky_zenith.rgb, frame.sky_horizon.rgb, frame.sky_ground.rgb);
    return vec4<f32>(color, 1.0);
}
