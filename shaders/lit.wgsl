// Lit: physically based (metallic-roughness). Base colour, metallic-roughness, normal,
// occlusion and emissive maps; the sky's image-based light, the sun and local lights with
// their shadows (lighting.wgsl). One fragment entry per alpha mode.

@vertex
fn vs_main(vertex: VertexIn, instance: InstanceIn) -> MeshOut {
    return transform_mesh_vertex(vertex, instance);
}

fn lit(in: MeshOut, front: bool, mode: u32) -> vec4<f32> {
    let o = objects[in.object];
    let base = base_color(o, in.uv);
    let mr = textureSample(metallic_roughness_map, material_sampler, in.uv);
    let encoded_normal = textureSample(normal_map, material_sampler, in.uv).xyz;
    let ao = textureSample(occlusion_map, material_sampler, in.uv).r;
    let emitted = textureSample(emissive_map, material_sampler, in.uv).rgb * o.emissive.rgb;
    let alpha = apply_alpha(base.a, o.emissive.w, mode);

    // Back faces (double-sided materials) are lit from their own side.
    let side = select(-1.0, 1.0, front);
    let geometric = normalize(in.world_normal) * side;
    var n = geometric;
    let tangent_length = length(in.world_tangent.xyz);
    if (tangent_length > 1e-6) {
        let t = normalize(in.world_tangent.xyz - geometric * dot(geometric, in.world_tangent.xyz));
        let b = cross(geometric, t) * in.world_tangent.w;
        var tn = encoded_normal * 2.0 - vec3<f32>(1.0);
        tn = vec3<f32>(tn.xy * o.pbr.z, tn.z);
        n = normalize(t * tn.x + b * tn.y + geometric * max(tn.z, 1e-3));
    }
    var s: Surface;
    s.position = in.world_position;
    s.view = view_direction(in.world_position);
    // A normal map must not turn the surface away from the viewer (black speckles).
    n = normalize(n + s.view * max(0.0, -dot(n, s.view) + 0.01));
    s.normal = n;
    s.geometric_normal = geometric;
    let metallic = clamp(o.pbr.x * mr.b, 0.0, 1.0);
    s.roughness = clamp(o.pbr.y * mr.g, 0.0, 1.0);
    s.diffuse_color = base.rgb * (1.0 - metallic);
    s.f0 = mix(vec3<f32>(0.04), base.rgb, metallic);
    s.occlusion = 1.0 + o.pbr.w * (ao - 1.0);
    let color = shade_pbr(s) + emitted;
    return vec4<f32>(color, alpha);
}

@fragment
fn fs_opaque(in: MeshOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    return lit(in, front, 0u);
}

@fragment
fn fs_mask(in: MeshOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    return lit(in, front, 1u);
}

@fragment
fn fs_blend(in: MeshOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    return lit(in, front, 2u);
}
