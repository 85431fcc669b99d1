// Missing texture: a magenta / dark checker laid in world space (0.25 m cells), lit, drawn
// for every object whose texture failed to load. It ignores the object's colour (a black
// material would hide a multiplied checker) and its texture coordinates (a mesh without any
// would show stripes), and is box-filtered by its screen footprint, so it does not shimmer
// in the distance (the mip-mapping a procedural pattern needs).

const CELL_M: f32 = 0.25;
// Keeps cell boundaries off round coordinates, where faces of unit shapes lie.
const CELL_OFFSET: f32 = 0.37;
const MAGENTA: vec3<f32> = vec3<f32>(1.0, 0.0, 1.0);
const DARK: vec3<f32> = vec3<f32>(0.007, 0.007, 0.007);
// Share of the unlit pattern kept in the dark, so the placeholder is never black.
const MIN_BRIGHTNESS: f32 = 0.35;

@vertex
fn vs_main(vertex: VertexIn, instance: InstanceIn) -> MeshOut {
    return transform_mesh_vertex(vertex, instance);
}

// 0 on magenta cells, 1 on dark ones, averaged over the pixel's footprint `w`.
fn checker(p: vec3<f32>) -> f32 {
    let w = max(fwidth(p), vec3<f32>(1e-4));
    let i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
    return 0.5 - 0.5 * i.x * i.y * i.z;
}

@fragment
fn fs_main(in: MeshOut) -> @location(0) vec4<f32> {
    // The pattern is laid in world space: the camera-relative position plus the camera's.
    let world = in.world_position + frame.camera_world.xyz;
    let albedo = mix(MAGENTA, DARK, checker(world / CELL_M + vec3<f32>(CELL_OFFSET)));
    let lit = shade_simple(in.world_position, in.world_normal, albedo);
    return vec4<f32>(max(lit, albedo * MIN_BRIGHTNESS), 1.0);
}
