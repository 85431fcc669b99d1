// Editor grid: an infinite plane at world Y = 0 drawn as one fullscreen triangle. Each pixel
// casts a ray through the inverse (camera-relative) view-projection, intersects the plane,
// draws anti-aliased cell lines that fade with distance, a red X axis (z = 0) and a blue Z
// axis (x = 0), and writes the hit depth so meshes hide the grid correctly.

const AXIS_X_COLOR: vec3<f32> = vec3<f32>(0.85, 0.1, 0.1);
const AXIS_Z_COLOR: vec3<f32> = vec3<f32>(0.1, 0.25, 0.9);
const LINE_COLOR: vec3<f32> = vec3<f32>(0.5, 0.5, 0.5);
const MINOR_ALPHA: f32 = 0.35;
const MAJOR_ALPHA: f32 = 0.6;
const AXIS_ALPHA: f32 = 0.9;

struct GridOut {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) ndc: vec2<f32>,
};

struct GridFragment {
    @location(0) color: vec4<f32>,
    @builtin(frag_depth) depth: f32,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex_index: u32) -> GridOut {
    // One triangle covering the screen: (-1,-1), (3,-1), (-1,3).
    let x = f32((vertex_index << 1u) & 2u) * 2.0 - 1.0;
    let y = f32(vertex_index & 2u) * 2.0 - 1.0;
    var out: GridOut;
    out.clip_position = vec4<f32>(x, y, 0.0, 1.0);
    out.ndc = vec2<f32>(x, y);
    return out;
}

fn unproject(ndc: vec2<f32>, depth: f32) -> vec3<f32> {
    let p = frame.inv_view_proj * vec4<f32>(ndc, depth, 1.0);
    return p.xyz / p.w;
}

// Coverage (0..1) of lines every `spacing` metres, about one pixel wide.
fn line_coverage(coord: vec2<f32>, spacing: f32) -> f32 {
    let c = coord / spacing;
    let derivative = fwidth(c);
    let grid = abs(fract(c - 0.5) - 0.5) / max(derivative, vec2<f32>(1e-6));
    return 1.0 - min(min(grid.x, grid.y), 1.0);
}

fn axis_coverage(distance: f32, derivative: f32) -> f32 {
    return 1.0 - min(abs(distance) / max(derivative * 1.5, 1e-6), 1.0);
}

@fragment
fn fs_main(in: GridOut) -> GridFragment {
    // Reverse-Z: depth 1 is the near plane; 0.5 lies farther along the same ray (a
    // perspective camera's depth 0 is at infinity).
    let near_point = unproject(in.ndc, 1.0);
    let farther = unproject(in.ndc, 0.5);
    let direction = farther - near_point;
    if (abs(direction.y) < 1e-12) {
        discard;
    }
    // The plane is at world Y = 0, camera-relative Y = -camera height.
    let plane_y = -frame.camera_world.y;
    let t = (plane_y - near_point.y) / direction.y;
    if (t <= 0.0) {
        discard;
    }
    let hit = near_point + direction * t;
    // World x, z for the axes (only near an axis does it matter, and there it is small);
    // the lines repeat every major spacing, so they are drawn from the exact phase.
    let coord = hit.xz + frame.camera_world.xz;
    let line_coord = hit.xz + frame.grid_phase.xy;

    let cell = max(frame.grid.x, 1e-4);
    let major = cell * max(frame.grid.z, 1.0);
    let minor = line_coverage(line_coord, cell) * MINOR_ALPHA;
    let major_lines = line_coverage(line_coord, major) * MAJOR_ALPHA;
    var color = LINE_COLOR;
    var alpha = max(minor, major_lines);

    let derivative = fwidth(line_coord);
    let x_axis = axis_coverage(coord.y, derivative.y);
    let z_axis = axis_coverage(coord.x, derivative.x);
    if (x_axis > 0.0) {
        color = mix(color, AXIS_X_COLOR, x_axis);
        alpha = max(alpha, x_axis * AXIS_ALPHA);
    }
    if (z_axis > 0.0) {
        color = mix(color, AXIS_Z_COLOR, z_axis);
        alpha = max(alpha, z_axis * AXIS_ALPHA);
    }

    // Fade with distance from the camera (horizontal distance for a perspective camera,
    // distance from the view centre for an orthographic one).
    var reference = vec3<f32>(0.0);
    if (frame.camera_world.w > 0.5) {
        reference = unproject(vec2<f32>(0.0, 0.0), 1.0);
    }
    let distance = length(hit.xz - reference.xz);
    let fade = 1.0 - smoothstep(frame.grid.y * 0.5, frame.grid.y, distance);
    alpha *= fade;
    if (alpha <= 0.002) {
        discard;
    }

    let clip = frame.view_proj * vec4<f32>(hit, 1.0);
    var out: GridFragment;
    out.color = vec4<f32>(color, alpha);
    out.depth = clamp(clip.z / clip.w, 0.0, 1.0);
    // Orthographic: the far plane bounds the grid too.
    if (clip.z < 0.0) {
        discard;
    }
    return out;
}
