//! [`Layouts`]: bind-group layouts, pipeline layouts and vertex layouts shared by pipelines.
//!
//! Groups of the camera pass: 0 frame (uniforms + the objects' storage buffer), 1 material
//! maps (or, for the wireframe, the mesh's own buffers), 2 lighting (shadow maps and the
//! sky's prefiltered maps and its cube). Shadow passes: 0 the objects (binding 1) + the shadow view
//! (binding 2, dynamic offset), 1 material maps (masked casters only). Tone mapping: its own
//! group 0 (frame uniforms at 0, the HDR colour at 2). Bindings never collide with
//! `common.wgsl`'s, which every shader includes.

use crate::frame::{FrameUniforms, LineRaw, ShadowViewRaw};
use crate::mesh::Vertex;

/// Layouts shared by every pipeline.
#[derive(Debug)]
pub(crate) struct Layouts {
    /// Group 0: the frame uniforms and the objects.
    pub(crate) frame: wgpu::BindGroupLayout,
    /// Group 1: five material maps and their sampler.
    pub(crate) material: wgpu::BindGroupLayout,
    /// Group 2: shadow maps, comparison sampler, sky maps, their sampler, the sky cube.
    pub(crate) lighting: wgpu::BindGroupLayout,
    /// Group 1 of the wireframe: one mesh's vertex and index buffers, read as storage.
    pub(crate) mesh_storage: wgpu::BindGroupLayout,
    /// Group 0 of shadow passes: the view (dynamic offset) and the objects.
    pub(crate) shadow_view: wgpu::BindGroupLayout,
    /// Group 0 of tone mapping: frame uniforms and the resolved HDR colour.
    pub(crate) tonemap: wgpu::BindGroupLayout,
    /// Frame only (normals, grid, debug lines).
    pub(crate) frame_only: wgpu::PipelineLayout,
    /// Frame + material (unlit).
    pub(crate) textured: wgpu::PipelineLayout,
    /// Frame + material + lighting (lit, lit-low, placeholder, and the sky: an image sky
    /// reads its cube from the lighting group).
    pub(crate) lit: wgpu::PipelineLayout,
    /// Frame + mesh storage (wireframe: vertices pulled by index, no unindexed copy).
    pub(crate) wireframe: wgpu::PipelineLayout,
    /// Shadow view only (opaque casters).
    pub(crate) shadow: wgpu::PipelineLayout,
    /// Shadow view + material (masked casters).
    pub(crate) shadow_masked: wgpu::PipelineLayout,
    /// Tone mapping.
    pub(crate) tonemap_layout: wgpu::PipelineLayout,
}

fn entry(
    binding: u32,
    visibility: wgpu::ShaderStages,
    ty: wgpu::BindingType,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty,
        count: None,
    }
}

fn texture(view_dimension: wgpu::TextureViewDimension) -> wgpu::BindingType {
    wgpu::BindingType::Texture {
        sample_type: wgpu::TextureSampleType::Float { filterable: true },
        view_dimension,
        multisampled: false,
    }
}

fn depth_array() -> wgpu::BindingType {
    wgpu::BindingType::Texture {
        sample_type: wgpu::TextureSampleType::Depth,
        view_dimension: wgpu::TextureViewDimension::D2Array,
        multisampled: false,
    }
}

fn objects() -> wgpu::BindingType {
    wgpu::BindingType::Buffer {
        ty: wgpu::BufferBindingType::Storage { read_only: true },
        has_dynamic_offset: false,
        min_binding_size: None,
    }
}

impl Layouts {
    pub(crate) fn new(device: &wgpu::Device) -> Self {
        use wgpu::ShaderStages as S;
        let vf = S::VERTEX_FRAGMENT;
        let uniform = |size: usize, dynamic| wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: dynamic,
            min_binding_size: wgpu::BufferSize::new(size as u64),
        };
        let layout = |label, entries: &[wgpu::BindGroupLayoutEntry]| {
            device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some(label),
                entries,
            })
        };
        let frame = layout(
            "onyx frame",
            &[
                entry(0, vf, uniform(size_of::<FrameUniforms>(), false)),
                entry(1, vf, objects()),
            ],
        );
        let d2 = wgpu::TextureViewDimension::D2;
        let filtering = wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering);
        let material = layout(
            "onyx material",
            &[
                entry(0, S::FRAGMENT, texture(d2)),
                entry(1, S::FRAGMENT, texture(d2)),
                entry(2, S::FRAGMENT, texture(d2)),
                entry(3, S::FRAGMENT, texture(d2)),
                entry(4, S::FRAGMENT, texture(d2)),
                entry(5, S::FRAGMENT, filtering),
            ],
        );
        let cube = wgpu::TextureViewDimension::Cube;
        let lighting = layout(
            "onyx lighting",
            &[
                entry(0, S::FRAGMENT, depth_array()),
                entry(1, S::FRAGMENT, depth_array()),
                entry(
                    2,
                    S::FRAGMENT,
                    wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison),
                ),
                entry(3, S::FRAGMENT, texture(cube)),
                entry(4, S::FRAGMENT, texture(cube)),
                entry(5, S::FRAGMENT, texture(d2)),
                entry(6, S::FRAGMENT, filtering),
                entry(7, S::FRAGMENT, texture(cube)),
            ],
        );
        let storage = |binding| entry(binding, S::VERTEX, objects());
        let mesh_storage = layout("onyx mesh storage", &[storage(0), storage(1)]);
        let shadow_view = layout(
            "onyx shadow view",
            &[
                entry(1, vf, objects()),
                entry(2, S::VERTEX, uniform(size_of::<ShadowViewRaw>(), true)),
            ],
        );
        let tonemap = layout(
            "onyx tone mapping",
            &[
                entry(0, S::FRAGMENT, uniform(size_of::<FrameUniforms>(), false)),
                entry(
                    2,
                    S::FRAGMENT,
                    wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: d2,
                        multisampled: false,
                    },
                ),
            ],
        );
        let pipeline = |label, groups: &[Option<&wgpu::BindGroupLayout>]| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(label),
                bind_group_layouts: groups,
                immediate_size: 0,
            })
        };
        Self {
            frame_only: pipeline("onyx frame-only", &[Some(&frame)]),
            textured: pipeline("onyx textured", &[Some(&frame), Some(&material)]),
            lit: pipeline(
                "onyx lit",
                &[Some(&frame), Some(&material), Some(&lighting)],
            ),
            wireframe: pipeline("onyx wireframe", &[Some(&frame), Some(&mesh_storage)]),
            shadow: pipeline("onyx shadow", &[Some(&shadow_view)]),
            shadow_masked: pipeline("onyx masked shadow", &[Some(&shadow_view), Some(&material)]),
            tonemap_layout: pipeline("onyx tone mapping", &[Some(&tonemap)]),
            frame,
            material,
            lighting,
            mesh_storage,
            shadow_view,
            tonemap,
        }
    }
}

const VERTEX_ATTRIBUTES: [wgpu::VertexAttribute; 4] = wgpu::vertex_attr_array![
    0 => Float32x3, 1 => Float32x3, 2 => Float32x2, 3 => Float32x4
];

const INSTANCE_ATTRIBUTES: [wgpu::VertexAttribute; 1] = wgpu::vertex_attr_array![4 => Uint32];

const LINE_ATTRIBUTES: [wgpu::VertexAttribute; 4] =
    wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32, 2 => Float32x3, 3 => Float32x4];

/// Slot 0: mesh vertices.
pub(crate) fn vertex_layout() -> wgpu::VertexBufferLayout<'static> {
    wgpu::VertexBufferLayout {
        array_stride: size_of::<Vertex>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &VERTEX_ATTRIBUTES,
    }
}

/// Slot 1: per instance, the slot of its object in the objects' storage buffer.
pub(crate) fn instance_layout() -> wgpu::VertexBufferLayout<'static> {
    wgpu::VertexBufferLayout {
        array_stride: size_of::<u32>() as u64,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &INSTANCE_ATTRIBUTES,
    }
}

/// Slot 0 of the debug-line pipeline: one line per instance.
pub(crate) fn line_layout() -> wgpu::VertexBufferLayout<'static> {
    wgpu::VertexBufferLayout {
        array_stride: size_of::<LineRaw>() as u64,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &LINE_ATTRIBUTES,
    }
}
