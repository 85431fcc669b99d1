// LitLow: lit by ambient, sun and point lights; untextured.

@vertex
fn vs_main(vertex: VertexIn, instance: InstanceIn) -> MeshOut {
    return transform_mesh_vertex(vertex, instance);
}

@fragment
fn fs_main(in: MeshOut) -> @location(0) vec4<f32> {
    return vec4<f32>(shade(in.world_position, in.world_normal, in.color.rgb), 1.0);
}
