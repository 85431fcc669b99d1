// Shared declarations, prepended by the renderer to every other shader in this folder.
// Conventions: Y up, right-handed, world units are metres, clip depth 0..1.
// Colours are linear; the colour target is sRGB, so the hardware encodes on write.

struct PointLight {
    // xyz: world position, w: range in metres (light reaches zero at this distance).
    position_range: vec4<f32>,
    // rgb: linear colour, w: intensity.
    color_intensity: vec4<f32>,
};

struct Frame {
    view_proj: mat4x4<f32>,
    inv_view_proj: mat4x4<f32>,
    // xyz: camera position, w: 1.0 for an orthographic camera, 0.0 for perspective.
    camera_position: vec4<f32>,
    // xyz: direction the camera looks along (unit).
    camera_forward: vec4<f32>,
    // rgb: ambient colour * intensity.
    ambient: vec4<f32>,
    // xyz: direction the sun light travels (unit), w: 1.0 when the sun is on.
    sun_direction: vec4<f32>,
    // rgb: sun colour * intensity.
    sun_color: vec4<f32>,
    point_lights: array<PointLight, 8>,
    // x: number of point lights in use.
    counts: vec4<u32>,
    // x, y: viewport size in pixels; z, w: their reciprocals.
    viewport: vec4<f32>,
    // x: grid cell size (m), y: grid fade distance (m), z: major line every N cells.
    grid: vec4<f32>,
};

@group(0) @binding(0) var<uniform> frame: Frame;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
};

struct InstanceIn {
    @location(3) model_0: vec4<f32>,
    @location(4) model_1: vec4<f32>,
    @location(5) model_2: vec4<f32>,
    @location(6) model_3: vec4<f32>,
    @location(7) normal_0: vec4<f32>,
    @location(8) normal_1: vec4<f32>,
    @location(9) normal_2: vec4<f32>,
    @location(10) color: vec4<f32>,
};

struct MeshOut {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @location(3) color: vec4<f32>,
};

fn transform_mesh_vertex(vertex: VertexIn, instance: InstanceIn) -> MeshOut {
    let model = mat4x4<f32>(instance.model_0, instance.model_1, instance.model_2, instance.model_3);
    let normal_matrix = mat3x3<f32>(instance.normal_0.xyz, instance.normal_1.xyz, instance.normal_2.xyz);
    let world = model * vec4<f32>(vertex.position, 1.0);
    var out: MeshOut;
    out.clip_position = frame.view_proj * world;
    out.world_position = world.xyz;
    out.world_normal = normal_matrix * vertex.normal;
    out.uv = vertex.uv;
    out.color = instance.color;
    return out;
}

// Direction from the surface towards the viewer.
fn view_direction(world_position: vec3<f32>) -> vec3<f32> {
    if (frame.camera_position.w > 0.5) {
        return -frame.camera_forward.xyz;
    }
    return normalize(frame.camera_position.xyz - world_position);
}

const SPECULAR_STRENGTH: f32 = 0.25;
const SPECULAR_POWER: f32 = 32.0;

fn light_contribution(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, radiance: vec3<f32>, albedo: vec3<f32>) -> vec3<f32> {
    let n_dot_l = max(dot(n, l), 0.0);
    let h = normalize(l + v);
    let specular = SPECULAR_STRENGTH * pow(max(dot(n, h), 0.0), SPECULAR_POWER) * step(0.0001, n_dot_l);
    return radiance * (albedo * n_dot_l + vec3<f32>(specular));
}

// Ambient + sun + point lights, Lambert diffuse with a small Blinn-Phong highlight.
fn shade(world_position: vec3<f32>, world_normal: vec3<f32>, albedo: vec3<f32>) -> vec3<f32> {
    let n = normalize(world_normal);
    let v = view_direction(world_position);
    var color = frame.ambient.rgb * albedo;
    if (frame.sun_direction.w > 0.5) {
        color += light_contribution(n, v, -frame.sun_direction.xyz, frame.sun_color.rgb, albedo);
    }
    let count = min(frame.counts.x, 8u);
    for (var i = 0u; i < count; i += 1u) {
        let light = frame.point_lights[i];
        let to_light = light.position_range.xyz - world_position;
        let distance = length(to_light);
        let range = max(light.position_range.w, 0.0001);
        // Smooth window falloff: 1 at the light, 0 at `range`.
        let window = clamp(1.0 - pow(distance / range, 4.0), 0.0, 1.0);
        let attenuation = window * window / (1.0 + distance * distance);
        let radiance = light.color_intensity.rgb * light.color_intensity.w * attenuation;
        color += light_contribution(n, v, to_light / max(distance, 0.0001), radiance, albedo);
    }
    return color;
}
