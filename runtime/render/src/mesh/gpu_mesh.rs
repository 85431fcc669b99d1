//! [`GpuMesh`]: a mesh's GPU buffers and model-space bounds.

use glam::Vec3;
use wgpu::util::DeviceExt;

use super::mesh_data::MeshData;

/// GPU buffers of one mesh.
#[derive(Debug)]
pub(crate) struct GpuMesh {
    pub(crate) vertex_buffer: wgpu::Buffer,
    pub(crate) index_buffer: wgpu::Buffer,
    pub(crate) index_count: u32,
    /// Unindexed copy (three vertices per triangle) for the barycentric wireframe.
    pub(crate) wire_buffer: wgpu::Buffer,
    pub(crate) wire_vertex_count: u32,
    /// Bounding sphere centre, model space.
    pub(crate) bounds_center: Vec3,
    /// Bounding sphere radius, model space.
    pub(crate) bounds_radius: f32,
}

impl GpuMesh {
    /// Uploads a valid mesh (see [`MeshData::is_valid`]).
    pub(crate) fn upload(device: &wgpu::Device, data: &MeshData, label: &str) -> Self {
        let vertex_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(&data.vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let index_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(&data.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        let wire = data.unindexed_vertices();
        let wire_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(&wire),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let (bounds_center, bounds_radius) = data.bounding_sphere();
        Self {
            vertex_buffer,
            index_buffer,
            index_count: data.indices.len() as u32,
            wire_buffer,
            wire_vertex_count: wire.len() as u32,
            bounds_center,
            bounds_radius,
        }
    }
}
