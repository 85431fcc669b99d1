// Normal: the world-space normal as a colour (x -> red, y -> green, z -> blue, mapped from
// -1..1 to 0..1). A debug view: alpha 0 tells tone mapping to show the values as they are.

@vertex
fn vs_main(vertex: VertexIn, instance: InstanceIn) -> MeshOut {
    return transform_mesh_vertex(vertex, instance);
}

@fragment
fn fs_main(in: MeshOut) -> @location(0) vec4<f32> {
    let n = normalize(in.world_normal);
    return vec4<f32>(n * 0.5 + vec3<f32>(0.5), 0.0);
}
