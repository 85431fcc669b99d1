// Shadow: the depth of shadow casters, seen from a light (a cascade of the sun, a spot
// light, or one face of a point light's cube). Conventional depth (0 nearest the light).
// Opaque casters need no fragment stage; masked ones cut like their material does.

struct ShadowView {
    view_proj: mat4x4<f32>,
};

// Binding 0 of group 0 is `frame` in common.wgsl; shadow passes bind the objects (1) and
// this view (2) instead.
@group(0) @binding(2) var<uniform> shadow_view: ShadowView;

struct ShadowOut {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) uv: vec2<f32>,
    @location(1) @interpolate(flat) object: u32,
};

@vertex
fn vs_main(vertex: VertexIn, instance: InstanceIn) -> ShadowOut {
    let o = objects[instance.object];
    var out: ShadowOut;
    out.clip_position = shadow_view.view_proj * vec4<f32>(object_point(o, vertex.position), 1.0);
    out.uv = vertex.uv;
    out.object = instance.object;
    return out;
}

@fragment
fn fs_mask(in: ShadowOut) {
    let o = objects[in.object];
    let alpha = base_color(o, in.uv).a;
    if (alpha < o.emissive.w) {
        discard;
    }
}
