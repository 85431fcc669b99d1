// Wireframe: triangle edges in the material colour, drawn from barycentric coordinates
// (no line primitives, so the output is identical on every rasteriser). The mesh is drawn
// unindexed, three vertices per triangle, so `vertex_index % 3` names the corner.

const WIRE_WIDTH_PX: f32 = 1.0;

struct WireOut {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) barycentric: vec3<f32>,
    @location(1) color: vec4<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex_index: u32, vertex: VertexIn, instance: InstanceIn) -> WireOut {
    let mesh = transform_mesh_vertex(vertex, instance);
    var out: WireOut;
    out.clip_position = mesh.clip_position;
    let corner = vertex_index % 3u;
    out.barycentric = vec3<f32>(f32(corner == 0u), f32(corner == 1u), f32(corner == 2u));
    out.color = mesh.color;
    return out;
}

@fragment
fn fs_main(in: WireOut) -> @location(0) vec4<f32> {
    let width = fwidth(in.barycentric);
    let edge = smoothstep(vec3<f32>(0.0), width * WIRE_WIDTH_PX, in.barycentric);
    let coverage = 1.0 - min(min(edge.x, edge.y), edge.z);
    if (coverage < 0.5) {
        discard;
    }
    return vec4<f32>(in.color.rgb, 1.0);
}
