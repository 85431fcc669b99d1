//! [`GpuMesh`]: a mesh's GPU buffers and model-space bounds.

use glam::Vec3;
use wgpu::util::DeviceExt;

use super::mesh_data::MeshData;

/// GPU buffers of one mesh: its vertices and indices, nothing else. The wireframe reads the
/// same two buffers as storage (through `wire_bind_group`), so a mesh costs its indexed
/// data only.
#[derive(Debug)]
pub(crate) struct GpuMesh {
    pub(crate) vertex_buffer: wgpu::Buffer,
    pub(crate) index_buffer: wgpu::Buffer,
    pub(crate) index_count: u32,
    /// Group 1 of the wireframe pipeline: both buffers as storage.
    pub(crate) wire_bind_group: wgpu::BindGroup,
    /// Bounding sphere centre, model space.
    pub(crate) bounds_center: Vec3,
    /// Bounding sphere radius, model space.
    pub(crate) bounds_radius: f32,
}

impl GpuMesh {
    /// Uploads a valid mesh (see [`MeshData::is_valid`]); `storage_layout` is the
    /// wireframe's mesh-storage bind group layout.
    pub(crate) fn upload(
        device: &wgpu::Device,
        storage_layout: &wgpu::BindGroupLayout,
        data: &MeshData,
        label: &str,
    ) -> Self {
        let vertex_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(&data.vertices),
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::STORAGE,
        });
        let index_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(&data.indices),
            usage: wgpu::BufferUsages::INDEX | wgpu::BufferUsages::STORAGE,
        });
        let wire_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(label),
            layout: storage_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: vertex_buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: index_buffer.as_entire_binding(),
                },
            ],
        });
        let (bounds_center, bounds_radius) = data.bounding_sphere();
        Self {
            vertex_buffer,
            index_buffer,
            index_count: data.indices.len() as u32,
            wire_bind_group,
            bounds_center,
            bounds_radius,
        }
    }

    /// Bytes of this mesh's GPU buffers.
    pub(crate) fn bytes(&self) -> u64 {
        self.vertex_buffer.size() + self.index_buffer.size()
    }
}
