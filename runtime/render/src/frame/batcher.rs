//! [`Batcher`]: culls the scene's objects and groups them into instanced batches keyed by
//! (shading, texture, mesh). Its vectors are kept between frames, so a steady scene
//! allocates nothing.

use glam::{Mat4, Vec3};

use super::instance_raw::InstanceRaw;
use crate::frustum::Frustum;
use crate::mesh::MeshHandle;
use crate::render_scene::DrawObject;
use crate::shading_mode::ShadingMode;
use crate::texture::TextureHandle;

/// What objects are grouped by. Ordered so batches of one pipeline are adjacent.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct BatchKey {
    pub(crate) shading: ShadingMode,
    /// Drawn as the missing-texture placeholder (its texture failed to load).
    pub(crate) placeholder: bool,
    /// Texture for textured modes (`None` = white); always `None` for untextured modes.
    pub(crate) texture: Option<TextureHandle>,
    pub(crate) mesh: MeshHandle,
}

/// A run of instances drawn with one call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Batch {
    pub(crate) key: BatchKey,
    pub(crate) first_instance: u32,
    pub(crate) instance_count: u32,
}

/// Model-space bounding sphere of a mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct MeshBounds {
    pub(crate) center: Vec3,
    pub(crate) radius: f32,
}

/// Counts from one [`Batcher::prepare`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct PrepareCounts {
    pub(crate) visible: u32,
    pub(crate) culled: u32,
    /// Objects skipped because their mesh handle is unknown or their transform not finite.
    pub(crate) invalid: u32,
}

/// Reusable culling and batching state.
#[derive(Debug, Default)]
pub(crate) struct Batcher {
    order: Vec<(BatchKey, u32)>,
    instances: Vec<InstanceRaw>,
    batches: Vec<Batch>,
}

impl Batcher {
    /// Culls `objects` against `frustum` (if any) and builds instances and batches. With
    /// `instancing` off every object gets its own batch. Textured objects whose texture is
    /// `missing` (the checker) are batched as placeholders.
    pub(crate) fn prepare(
        &mut self,
        objects: &[DrawObject],
        missing: TextureHandle,
        frustum: Option<&Frustum>,
        bounds: impl Fn(MeshHandle) -> Option<MeshBounds>,
        instancing: bool,
    ) -> PrepareCounts {
        self.order.clear();
        self.instances.clear();
        self.batches.clear();
        let mut counts = PrepareCounts::default();
        for (index, object) in objects.iter().enumerate() {
            let Some(mesh_bounds) = bounds(object.mesh) else {
                counts.invalid += 1;
                continue;
            };
            if !object.transform.is_finite() {
                counts.invalid += 1;
                continue;
            }
            if let Some(frustum) = frustum {
                let (center, radius) = world_sphere(&object.transform, mesh_bounds);
                if !frustum.intersects_sphere(center, radius) {
                    counts.culled += 1;
                    continue;
                }
            }
            let shading = object.material.shading;
            let texture = if shading.uses_texture() {
                object.material.texture
            } else {
                None
            };
            self.order.push((
                BatchKey {
                    shading,
                    placeholder: texture == Some(missing),
                    texture,
                    mesh: object.mesh,
                },
                index as u32,
            ));
        }
        counts.visible = self.order.len() as u32;
        self.order.sort_unstable();

        for &(key, index) in &self.order {
            let object = &objects[index as usize];
            let instance = self.instances.len() as u32;
            self.instances
                .push(InstanceRaw::new(&object.transform, object.material.color));
            match self.batches.last_mut() {
                Some(batch) if instancing && batch.key == key => batch.instance_count += 1,
                _ => self.batches.push(Batch {
                    key,
                    first_instance: instance,
                    instance_count: 1,
                }),
            }
        }
        if counts.invalid > 0 {
            tracing::warn!(
                count = counts.invalid,
                "objects skipped: unknown mesh handle or non-finite transform"
            );
        }
        counts
    }

    pub(crate) fn instances(&self) -> &[InstanceRaw] {
        &self.instances
    }

    pub(crate) fn batches(&self) -> &[Batch] {
        &self.batches
    }
}

/// World-space bounding sphere: centre transformed, radius scaled by the largest axis scale.
fn world_sphere(transform: &Mat4, bounds: MeshBounds) -> (Vec3, f32) {
    let center = transform.transform_point3(bounds.center);
    let scale = transform
        .x_axis
        .truncate()
        .length()
        .max(transform.y_axis.truncate().length())
        .max(transform.z_axis.truncate().length());
    (center, bounds.radius * scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Material;

    fn object(mesh: u32, x: f32, shading: ShadingMode) -> DrawObject {
        DrawObject {
            mesh: MeshHandle(mesh),
            material: Material::color(1.0, 1.0, 1.0).with_shading(shading),
            transform: Mat4::from_translation(Vec3::new(x, 0.0, 0.0)),
        }
    }

    fn unit_bounds(_: MeshHandle) -> Option<MeshBounds> {
        Some(MeshBounds {
            center: Vec3::ZERO,
            radius: 1.0,
        })
    }

    #[test]
    fn objects_sharing_mesh_and_material_form_one_batch() {
        let objects: Vec<_> = (0..100)
            .map(|i| {
                object(
                    i % 2,
                    i as f32,
                    if i % 2 == 0 {
                        ShadingMode::Unlit
                    } else {
                        ShadingMode::LitLow
                    },
                )
            })
            .collect();
        let mut batcher = Batcher::default();
        let counts = batcher.prepare(&objects, TextureHandle(1), None, unit_bounds, true);
        assert_eq!(counts.visible, 100);
        assert_eq!(
            batcher.batches().len(),
            2,
            "batches: {:?}",
            batcher.batches()
        );
        assert_eq!(batcher.instances().len(), 100);
        let counts = batcher.prepare(&objects, TextureHandle(1), None, unit_bounds, false);
        assert_eq!((counts.visible, batcher.batches().len()), (100, 100));
    }

    #[test]
    fn spheres_outside_the_frustum_are_culled() {
        let camera = crate::Camera::perspective_look_at(
            Vec3::new(0.0, 0.0, 10.0),
            Vec3::ZERO,
            1.0,
            0.1,
            100.0,
        );
        let frustum = Frustum::from_view_projection(&camera.view_projection(1.0));
        // In view: x = 0. Behind the camera / far to the side: culled.
        let objects = vec![
            object(0, 0.0, ShadingMode::Unlit),
            object(0, 500.0, ShadingMode::Unlit),
            DrawObject {
                transform: Mat4::from_translation(Vec3::new(0.0, 0.0, 20.0)),
                ..object(0, 0.0, ShadingMode::Unlit)
            },
        ];
        let counts = Batcher::default().prepare(
            &objects,
            TextureHandle(1),
            Some(&frustum),
            unit_bounds,
            true,
        );
        assert_eq!((counts.visible, counts.culled), (1, 2));
    }

    #[test]
    fn unknown_meshes_and_nan_transforms_are_skipped_not_drawn() {
        let mut nan = object(0, 0.0, ShadingMode::Unlit);
        nan.transform.w_axis.x = f32::NAN;
        let objects = vec![object(7, 0.0, ShadingMode::Unlit), nan];
        let counts = Batcher::default().prepare(
            &objects,
            TextureHandle(1),
            None,
            |m| {
                (m.0 == 0).then_some(MeshBounds {
                    center: Vec3::ZERO,
                    radius: 1.0,
                })
            },
            true,
        );
        assert_eq!((counts.visible, counts.invalid), (0, 2));
    }
}
