// Shared declarations, prepended by the renderer to every other shader in this folder.
// Conventions: Y up, right-handed, world units are metres. Everything the GPU sees is
// camera-relative (the camera sits at the origin; `frame.camera_world` is where it is in the
// world). Depth is reversed: 1 at the near plane, 0 at infinity. The scene is drawn in linear
// HDR; tonemap.wgsl maps it to the display.

const PI: f32 = 3.14159265358979;
const MAX_LOCAL_LIGHTS: u32 = 16u;

struct LocalLight {
    // xyz: camera-relative position, w: range in metres (the light reaches zero there).
    position_range: vec4<f32>,
    // rgb: colour * intensity, w: 0 point light, 1 spot light.
    color_kind: vec4<f32>,
    // xyz: spot direction (unit), w: cosine of the outer cone angle.
    direction_cos: vec4<f32>,
    // x: 1 / (cos inner - cos outer), y: first shadow layer (< 0: none), z: depth bias (m),
    // w: normal bias (texels).
    cone_shadow: vec4<f32>,
    // x: shadow near, y: shadow far, z: texel size one metre from the light.
    shadow_range: vec4<f32>,
};

struct Frame {
    view_proj: mat4x4<f32>,
    inv_view_proj: mat4x4<f32>,
    // xyz: camera world position, w: 1.0 for an orthographic camera, 0.0 for perspective.
    camera_world: vec4<f32>,
    // xyz: direction the camera looks along (unit), w: near plane.
    camera_forward: vec4<f32>,
    // rgb: scale of the sky's image-based light, w: highest mip of the specular sky.
    ambient: vec4<f32>,
    // xyz: direction the sun light travels (unit), w: 1.0 when the sun is on.
    sun_direction: vec4<f32>,
    // rgb: sun colour * intensity, w: 1.0 when it casts shadows.
    sun_color: vec4<f32>,
    // x: depth bias (m), y: normal bias (texels), z: cascades, w: filter radius (texels).
    sun_shadow: vec4<f32>,
    // View depth where each cascade ends.
    cascade_splits: vec4<f32>,
    // World size of one texel of each cascade.
    cascade_texels: vec4<f32>,
    cascades: array<mat4x4<f32>, 4>,
    lights: array<LocalLight, 16>,
    local_shadows: array<mat4x4<f32>, 16>,
    // x: local lights in use, y: directional shadow side, z: local shadow side (texels).
    counts: vec4<u32>,
    // x, y: viewport size in pixels; z, w: their reciprocals.
    viewport: vec4<f32>,
    // x: grid cell size (m), y: grid fade distance (m), z: major line every N cells,
    // w: unused.
    grid: vec4<f32>,
    // x: exposure multiplier, y: tone-mapping operator, z: 1 to encode sRGB here, w: sky on.
    output: vec4<f32>,
    // rgb: procedural zenith colour, w: 1 when the sky is an image (sky.wgsl reads its cube).
    sky_zenith: vec4<f32>,
    sky_horizon: vec4<f32>,
    sky_ground: vec4<f32>,
    // xy: the camera's world x and z modulo the major grid spacing (exact, from the CPU):
    // lines are drawn from it, so they stay put where camera_world + hit would round (8 mm
    // at 100 km in f32).
    grid_phase: vec4<f32>,
};

// One drawn object: rows of its camera-relative model matrix and its material factors.
struct Object {
    row_0: vec4<f32>,
    row_1: vec4<f32>,
    row_2: vec4<f32>,
    // Linear RGBA base colour.
    color: vec4<f32>,
    // Metallic, roughness, normal scale, occlusion strength.
    pbr: vec4<f32>,
    // Emissive RGB, alpha cutoff.
    emissive: vec4<f32>,
};

@group(0) @binding(0) var<uniform> frame: Frame;
@group(0) @binding(1) var<storage, read> objects: array<Object>;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @location(3) tangent: vec4<f32>,
};

struct InstanceIn {
    // Slot of the object in `objects`.
    @location(4) object: u32,
};

struct MeshOut {
    @builtin(position) clip_position: vec4<f32>,
    // Camera-relative position.
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @location(3) @interpolate(flat) object: u32,
    @location(4) world_tangent: vec4<f32>,
};

// The model matrix's linear part applied to `v`.
fn object_linear(o: Object, v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(o.row_0.xyz, v), dot(o.row_1.xyz, v), dot(o.row_2.xyz, v));
}

fn object_point(o: Object, p: vec3<f32>) -> vec3<f32> {
    let h = vec4<f32>(p, 1.0);
    return vec3<f32>(dot(o.row_0, h), dot(o.row_1, h), dot(o.row_2, h));
}

// Normals transform by the cofactor matrix (the inverse transpose up to a positive scale,
// times the determinant's sign): right for any scale, and no inverse on the CPU.
fn object_normal(o: Object, n: vec3<f32>) -> vec3<f32> {
    let c0 = vec3<f32>(o.row_0.x, o.row_1.x, o.row_2.x);
    let c1 = vec3<f32>(o.row_0.y, o.row_1.y, o.row_2.y);
    let c2 = vec3<f32>(o.row_0.z, o.row_1.z, o.row_2.z);
    let cofactor = mat3x3<f32>(cross(c1, c2), cross(c2, c0), cross(c0, c1));
    return cofactor * n;
}

fn transform_mesh_vertex(vertex: VertexIn, instance: InstanceIn) -> MeshOut {
    let o = objects[instance.object];
    let world = object_point(o, vertex.position);
    var out: MeshOut;
    out.clip_position = frame.view_proj * vec4<f32>(world, 1.0);
    out.world_position = world;
    out.world_normal = object_normal(o, vertex.normal);
    out.uv = vertex.uv;
    out.object = instance.object;
    // A mirroring transform flips the bitangent.
    let det = dot(cross(o.row_0.xyz, o.row_1.xyz), o.row_2.xyz);
    out.world_tangent = vec4<f32>(object_linear(o, vertex.tangent.xyz), vertex.tangent.w * select(1.0, -1.0, det < 0.0));
    return out;
}

// Direction from the surface towards the viewer.
fn view_direction(world_position: vec3<f32>) -> vec3<f32> {
    if (frame.camera_world.w > 0.5) {
        return -frame.camera_forward.xyz;
    }
    return normalize(-world_position);
}

// The sky's radiance in direction `dir` (unit): the same function as `Sky::radiance`.
fn sky_radiance(dir: vec3<f32>, zenith: vec3<f32>, horizon: vec3<f32>, ground: vec3<f32>) -> vec3<f32> {
    let y = clamp(dir.y, -1.0, 1.0);
    if (y >= 0.0) {
        return mix(horizon, zenith, sqrt(y));
    }
    return mix(horizon, ground, min(-y * 4.0, 1.0));
}
