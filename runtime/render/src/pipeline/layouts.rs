//! [`Layouts`]: bind-group layouts, pipeline layouts and vertex layouts shared by pipelines.

use crate::frame::{FrameUniforms, InstanceRaw, LineRaw};
use crate::mesh::Vertex;

/// Layouts shared by every pipeline.
#[derive(Debug)]
pub(crate) struct Layouts {
    /// Group 0: the per-frame uniform buffer.
    pub(crate) frame: wgpu::BindGroupLayout,
    /// Group 1: albedo texture + sampler.
    pub(crate) material: wgpu::BindGroupLayout,
    /// Frame only (untextured meshes, grid, debug lines).
    pub(crate) frame_only: wgpu::PipelineLayout,
    /// Frame + material (textured meshes).
    pub(crate) textured: wgpu::PipelineLayout,
    /// Group 1 of the wireframe: one mesh's vertex and index buffers, read as storage.
    pub(crate) mesh_storage: wgpu::BindGroupLayout,
    /// Frame + mesh storage (wireframe: vertices pulled by index, no unindexed copy).
    pub(crate) wireframe: wgpu::PipelineLayout,
}

impl Layouts {
    pub(crate) fn new(device: &wgpu::Device) -> Self {
        let frame = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("onyx frame"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(size_of::<FrameUniforms>() as u64),
                },
                count: None,
            }],
        });
        let material = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("onyx material"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: true },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let frame_only = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("onyx frame-only"),
            bind_group_layouts: &[Some(&frame)],
            immediate_size: 0,
        });
        let textured = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("onyx textured"),
            bind_group_layouts: &[Some(&frame), Some(&material)],
            immediate_size: 0,
        });
        let storage = |binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::VERTEX,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only: true },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let mesh_storage = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("onyx mesh storage"),
            entries: &[storage(0), storage(1)],
        });
        let wireframe = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("onyx wireframe"),
            bind_group_layouts: &[Some(&frame), Some(&mesh_storage)],
            immediate_size: 0,
        });
        Self {
            frame,
            material,
            frame_only,
            textured,
            mesh_storage,
            wireframe,
        }
    }
}

const VERTEX_ATTRIBUTES: [wgpu::VertexAttribute; 3] =
    wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x2];

const INSTANCE_ATTRIBUTES: [wgpu::VertexAttribute; 8] = wgpu::vertex_attr_array![
    3 => Float32x4, 4 => Float32x4, 5 => Float32x4, 6 => Float32x4,
    7 => Float32x4, 8 => Float32x4, 9 => Float32x4, 10 => Float32x4
];

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

/// Slot 1: per-instance transform and colour.
pub(crate) fn instance_layout() -> wgpu::VertexBufferLayout<'static> {
    wgpu::VertexBufferLayout {
        array_stride: size_of::<InstanceRaw>() as u64,
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
