// Unlit: base colour × base colour map (and emissive), ignoring lights. One fragment entry
// per alpha mode.

@vertex
fn vs_main(vertex: VertexIn, instance: InstanceIn) -> MeshOut {
    return transform_mesh_vertex(vertex, instance);
}

fn unlit(in: MeshOut, mode: u32) -> vec4<f32> {
    let o = objects[in.object];
    let base = base_color(o, in.uv);
    let alpha = apply_alpha(base.a, o.emissive.w, mode);
    return vec4<f32>(base.rgb + o.emissive.rgb, alpha);
}

@fragment
fn fs_opaque(in: MeshOut) -> @location(0) vec4<f32> {
    return unlit(in, 0u);
}

@fragment
fn fs_mask(in: MeshOut) -> @location(0) vec4<f32> {
    return unlit(in, 1u);
}

@fragment
fn fs_blend(in: MeshOut) -> @location(0) vec4<f32> {
    return unlit(in, 2u);
}
