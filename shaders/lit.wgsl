// Lit: lit by ambient, sun and point lights; albedo = material colour * texture.

@group(1) @binding(0) var albedo_texture: texture_2d<f32>;
@group(1) @binding(1) var albedo_sampler: sampler;

@vertex
fn vs_main(vertex: VertexIn, instance: InstanceIn) -> MeshOut {
    return transform_mesh_vertex(vertex, instance);
}

@fragment
fn fs_main(in: MeshOut) -> @location(0) vec4<f32> {
    let texel = textureSample(albedo_texture, albedo_sampler, in.uv);
    let albedo = in.color.rgb * texel.rgb;
    return vec4<f32>(shade(in.world_position, in.world_normal, albedo), 1.0);
}
