// Debug lines: each line is one instance of a 6-vertex quad, expanded in screen space to a
// constant width in pixels (no line primitives, so output is the same on every rasteriser).

struct LineIn {
    @location(0) start: vec3<f32>,
    @location(1) width_px: f32,
    @location(2) end: vec3<f32>,
    @location(3) color: vec4<f32>,
};

struct LineOut {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) color: vec4<f32>,
};

const NEAR_W: f32 = 1e-4;

@vertex
fn vs_main(@builtin(vertex_index) vertex_index: u32, line: LineIn) -> LineOut {
    var a = frame.view_proj * vec4<f32>(line.start, 1.0);
    var b = frame.view_proj * vec4<f32>(line.end, 1.0);
    var out: LineOut;
    out.color = line.color;
    // Clip the segment against the plane just in front of the camera.
    if (a.w < NEAR_W && b.w < NEAR_W) {
        out.clip_position = vec4<f32>(0.0, 0.0, 2.0, 1.0);
        return out;
    }
    if (a.w < NEAR_W) {
        a = mix(a, b, (NEAR_W - a.w) / (b.w - a.w));
    }
    if (b.w < NEAR_W) {
        b = mix(b, a, (NEAR_W - b.w) / (a.w - b.w));
    }
    let screen_a = a.xy / a.w * frame.viewport.xy;
    let screen_b = b.xy / b.w * frame.viewport.xy;
    var dir = screen_b - screen_a;
    if (length(dir) < 1e-6) {
        dir = vec2<f32>(1.0, 0.0);
    }
    dir = normalize(dir);
    let side = vec2<f32>(-dir.y, dir.x) * line.width_px;
    // Corners: (0,-), (1,-), (1,+), (0,-), (1,+), (0,+).
    var along = array<f32, 6>(0.0, 1.0, 1.0, 0.0, 1.0, 0.0);
    var across = array<f32, 6>(-1.0, -1.0, 1.0, -1.0, 1.0, 1.0);
    let i = vertex_index % 6u;
    var p = a;
    if (along[i] > 0.5) {
        p = b;
    }
    // Offset in NDC: half the width on each side (viewport.zw = 1/size, NDC spans 2).
    let offset = side * across[i] * frame.viewport.zw;
    out.clip_position = vec4<f32>(p.xy + offset * p.w, p.z, p.w);
    return out;
}

@fragment
fn fs_main(in: LineOut) -> @location(0) vec4<f32> {
    return in.color;
}
