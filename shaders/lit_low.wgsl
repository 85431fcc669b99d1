// LitLow: fast lighting (Lambert + a Blinn-Phong highlight from the direct lights, the sky's
// irradiance), no maps, no shadows. One fragment entry per alpha mode.

@vertex
fn vs_main(vertex: VertexIn, instance: InstanceIn) -> MeshOut {
    return transform_mesh_vertex(vertex, instance);
}

fn lit_low(in: MeshOut, front: bool, mode: u32) -> vec4<f32> {
    let o = objects[in.object];
    let alpha = apply_alpha(o.color.a, o.emissive.w, mode);
    let n = normalize(in.world_normal) * select(-1.0, 1.0, front);
    let color = shade_simple(in.world_position, n, o.color.rgb) + o.emissive.rgb;
    return vec4<f32>(color, alpha);
}

@fragment
fn fs_opaque(in: MeshOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    return lit_low(in, front, 0u);
}

@fragment
fn fs_mask(in: MeshOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    return lit_low(in, front, 1u);
}

@fragment
fn fs_blend(in: MeshOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    return lit_low(in, front, 2u);
}
