// Wireframe: triangle edges in the material colour, drawn from barycentric coordinates
// (no line primitives, so the output is identical on every rasteriser). The mesh's own
// vertex and index buffers are read as storage: the draw runs one vertex per index, so
// `vertex_index % 3` names the corner, and no unindexed copy of the mesh is kept.

const WIRE_WIDTH_PX: f32 = 1.0;
// Floats per vertex in the mesh buffer: position (3), normal (3), uv (2), tangent (4).
const VERTEX_FLOATS: u32 = 12u;

@group(1) @binding(0) var<storage, read> mesh_vertices: array<f32>;
@group(1) @binding(1) var<storage, read> mesh_indices: array<u32>;

struct WireOut {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) barycentric: vec3<f32>,
    @location(1) color: vec4<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex_index: u32, instance: InstanceIn) -> WireOut {
    let base = mesh_indices[vertex_index] * VERTEX_FLOATS;
    var vertex: VertexIn;
    vertex.position = vec3<f32>(mesh_vertices[base], mesh_vertices[base + 1u], mesh_vertices[base + 2u]);
    vertex.normal = vec3<f32>(mesh_vertices[base + 3u], mesh_vertices[base + 4u], mesh_vertices[base + 5u]);
    vertex.uv = vec2<f32>(mesh_vertices[base + 6u], mesh_vertices[base + 7u]);
    vertex.tangent = vec4<f32>(mesh_vertices[base + 8u], mesh_vertices[base + 9u], mesh_vertices[base + 10u], mesh_vertices[base + 11u]);
    let mesh = transform_mesh_vertex(vertex, instance);
    var out: WireOut;
    out.clip_position = mesh.clip_position;
    let corner = vertex_index % 3u;
    out.barycentric = vec3<f32>(f32(corner == 0u), f32(corner == 1u), f32(corner == 2u));
    out.color = objects[instance.object].color;
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
    // A debug view: alpha 0 tells tone mapping to show the colour as it is.
    return vec4<f32>(in.color.rgb, 0.0);
}
