//! [`MeshCache`]: every mesh uploaded to a renderer, and loaded models by path.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use super::gpu_mesh::GpuMesh;
use super::mesh_data::MeshData;
use super::mesh_handle::MeshHandle;
use super::model::Model;

/// Uploaded meshes (indexed by [`MeshHandle`]; `None` once released) and models loaded from
/// files.
#[derive(Debug, Default)]
pub(crate) struct MeshCache {
    meshes: Vec<Option<GpuMesh>>,
    models: HashMap<PathBuf, Model>,
}

impl MeshCache {
    /// Uploads a valid mesh, generating its tangents first when it has none.
    pub(crate) fn add(
        &mut self,
        device: &wgpu::Device,
        storage_layout: &wgpu::BindGroupLayout,
        data: &MeshData,
        label: &str,
    ) -> MeshHandle {
        if data.has_tangents() {
            return self.add_as_is(device, storage_layout, data, label);
        }
        let mut with_tangents = data.clone();
        with_tangents.generate_tangents();
        self.add_as_is(device, storage_layout, &with_tangents, label)
    }

    /// Uploads a valid mesh as it is (without tangents, if it has none).
    pub(crate) fn add_as_is(
        &mut self,
        device: &wgpu::Device,
        storage_layout: &wgpu::BindGroupLayout,
        data: &MeshData,
        label: &str,
    ) -> MeshHandle {
        let handle = MeshHandle(self.meshes.len() as u32);
        self.meshes
            .push(Some(GpuMesh::upload(device, storage_layout, data, label)));
        handle
    }

    pub(crate) fn get(&self, handle: MeshHandle) -> Option<&GpuMesh> {
        self.meshes.get(handle.0 as usize)?.as_ref()
    }

    /// Frees the GPU buffers of `handle` (a model replaced by a reload); the handle then
    /// draws nothing, and a model cached with it is forgotten.
    pub(crate) fn release(&mut self, handle: MeshHandle) {
        if let Some(slot) = self.meshes.get_mut(handle.0 as usize) {
            *slot = None;
        }
        self.models
            .retain(|_, model| model.parts.iter().all(|p| p.mesh != handle));
    }

    pub(crate) fn len(&self) -> usize {
        self.meshes.len()
    }

    /// Bytes of every mesh's GPU buffers.
    pub(crate) fn bytes(&self) -> u64 {
        self.meshes.iter().flatten().map(GpuMesh::bytes).sum()
    }

    pub(crate) fn model(&self, key: &Path) -> Option<&Model> {
        self.models.get(key)
    }

    pub(crate) fn insert_model(&mut self, key: PathBuf, model: Model) {
        self.models.insert(key, model);
    }
}

/// The key a file is cached under: its canonical path when it exists, else the path given.
pub(crate) fn cache_key(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_owned())
}
