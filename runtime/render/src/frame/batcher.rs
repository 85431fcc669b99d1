//! [`Batcher`]: culls the scene's objects against the camera and every shadow view, writes
//! each object that any view sees once ([`ObjectRaw`]), and groups each view's objects into
//! instanced batches: opaque and masked ones by key, blended ones back to front. Its vectors
//! are kept between frames, so a steady scene allocates nothing.

use glam::{Mat4, Vec3};

use super::batch_key::{AlphaClass, BatchKey, KeyTable, MaterialMaps, ShadowKey};
use super::object_raw::ObjectRaw;
use crate::frustum::Frustum;
use crate::mesh::MeshHandle;
use crate::model_material::AlphaMode;
use crate::render_scene::DrawObject;
use crate::texture::TextureHandle;

/// A run of instances drawn with one call: `key` numbers a [`BatchKey`] (camera) or a
/// [`ShadowKey`] (shadow views); instances `first_instance..+instance_count` of the index
/// buffer name the objects.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Batch {
    pub(crate) key: u32,
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
    /// Objects the camera sees.
    pub(crate) visible: u32,
    /// Objects no view sees.
    pub(crate) culled: u32,
    /// Objects skipped because their mesh handle is unknown or their transform not finite.
    pub(crate) invalid: u32,
    /// Blended objects the camera sees.
    pub(crate) blended: u32,
    /// Instances drawn by all shadow views together.
    pub(crate) shadow_instances: u32,
}

/// What one frame is culled and batched for.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FrameViews<'a> {
    /// The camera position: object positions are made relative to it.
    pub(crate) origin: Vec3,
    /// The camera's culling volume (camera-relative), `None` to draw everything.
    pub(crate) camera: Option<&'a Frustum>,
    /// Direction the camera looks (for back-to-front order of blended objects).
    pub(crate) forward: Vec3,
    /// Each shadow view's volume (camera-relative).
    pub(crate) shadows: &'a [Frustum],
    /// The texture standing for failed ones (drawn as the placeholder).
    pub(crate) missing: TextureHandle,
    /// Group objects into instanced draws (else one draw per object).
    pub(crate) instancing: bool,
}

/// Reusable culling and batching state.
#[derive(Debug, Default)]
pub(crate) struct Batcher {
    objects: Vec<ObjectRaw>,
    indices: Vec<u32>,
    keys: KeyTable<BatchKey>,
    shadow_keys: KeyTable<ShadowKey>,
    /// Per camera key, its shadow key (filled as met).
    shadow_key_of: Vec<Option<u32>>,
    camera_entries: Vec<(u32, u32)>,
    blended: Vec<(f32, u32, u32)>,
    shadow_entries: Vec<Vec<(u32, u32)>>,
    camera_batches: Vec<Batch>,
    shadow_batches: Vec<Vec<Batch>>,
    counts: Vec<u32>,
    rank: Vec<u32>,
    order: Vec<u32>,
}

impl Batcher {
    /// Culls `objects` for every view and builds objects, indices and batches.
    pub(crate) fn prepare(
        &mut self,
        objects: &[DrawObject],
        views: &FrameViews<'_>,
        bounds: impl Fn(MeshHandle) -> Option<MeshBounds>,
    ) -> PrepareCounts {
        self.objects.clear();
        self.indices.clear();
        self.keys.clear();
        self.shadow_keys.clear();
        self.shadow_key_of.clear();
        self.camera_entries.clear();
        self.blended.clear();
        self.camera_batches.clear();
        let shadow_views = views.shadows.len();
        self.shadow_entries.resize_with(shadow_views, Vec::new);
        self.shadow_batches.resize_with(shadow_views, Vec::new);
        for list in &mut self.shadow_entries {
            list.clear();
        }
        for list in &mut self.shadow_batches {
            list.clear();
        }
        let mut counts = PrepareCounts::default();
        for object in objects {
            let Some(mesh_bounds) = bounds(object.mesh) else {
                counts.invalid += 1;
                continue;
            };
            if !object.transform.is_finite() {
                counts.invalid += 1;
                continue;
            }
            let (center, radius) = relative_sphere(&object.transform, views.origin, mesh_bounds);
            let in_camera = views
                .camera
                .is_none_or(|f| f.intersects_sphere(center, radius));
            let material = &object.material;
            let blended = material.is_blended();
            let casts = !blended && material.shading.casts_shadows();
            let mut shadow_mask = 0u64;
            if casts {
                for (i, frustum) in views.shadows.iter().enumerate() {
                    if frustum.intersects_sphere(center, radius) {
                        shadow_mask |= 1 << i;
                    }
                }
            }
            if !in_camera && shadow_mask == 0 {
                counts.culled += 1;
                continue;
            }
            let slot = self.objects.len() as u32;
            self.objects
                .push(ObjectRaw::new(&object.transform, views.origin, material));
            let key = self.keys.id(batch_key(object, views.missing));
            if in_camera {
                if blended {
                    let depth = center.dot(views.forward);
                    self.blended.push((depth, key, slot));
                } else {
                    self.camera_entries.push((key, slot));
                }
            }
            if shadow_mask != 0 {
                // The shadow key follows from the camera key: ask the table once per key.
                if self.shadow_key_of.len() <= key as usize {
                    self.shadow_key_of.resize(key as usize + 1, None);
                }
                let key = *self.shadow_key_of[key as usize]
                    .get_or_insert_with(|| self.shadow_keys.id(shadow_key(&self.keys.get(key))));
                let mut mask = shadow_mask;
                while mask != 0 {
                    let view = mask.trailing_zeros() as usize;
                    self.shadow_entries[view].push((key, slot));
                    mask &= mask - 1;
                }
            }
        }
        counts.blended = self.blended.len() as u32;
        counts.visible = self.camera_entries.len() as u32 + counts.blended;

        // Camera: opaque and masked grouped by key (in key order), then blended far to near.
        rank_keys(self.keys.keys(), &mut self.rank, &mut self.order);
        group_by_key(
            &self.camera_entries,
            &self.rank,
            &self.order,
            views.instancing,
            &mut self.counts,
            &mut self.indices,
            &mut self.camera_batches,
        );
        self.blended
            .sort_unstable_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
        for &(_, key, slot) in &self.blended {
            let first = self.indices.len() as u32;
            self.indices.push(slot);
            match self.camera_batches.last_mut() {
                Some(batch)
                    if views.instancing
                        && batch.key == key
                        && batch.first_instance + batch.instance_count == first
                        && self.keys.get(key).alpha == AlphaClass::Blend =>
                {
                    batch.instance_count += 1;
                }
                _ => self.camera_batches.push(Batch {
                    key,
                    first_instance: first,
                    instance_count: 1,
                }),
            }
        }

        rank_keys(self.shadow_keys.keys(), &mut self.rank, &mut self.order);
        for view in 0..shadow_views {
            counts.shadow_instances += self.shadow_entries[view].len() as u32;
            group_by_key(
                &self.shadow_entries[view],
                &self.rank,
                &self.order,
                views.instancing,
                &mut self.counts,
                &mut self.indices,
                &mut self.shadow_batches[view],
            );
        }
        if counts.invalid > 0 {
            tracing::warn!(
                count = counts.invalid,
                "objects skipped: unknown mesh handle or non-finite transform"
            );
        }
        counts
    }

    /// Every object some view sees, camera-relative.
    pub(crate) fn objects(&self) -> &[ObjectRaw] {
        &self.objects
    }

    /// Object slots, per instance, of every view's batches.
    pub(crate) fn indices(&self) -> &[u32] {
        &self.indices
    }

    /// The camera's batches: opaque, masked, then blended back to front.
    pub(crate) fn batches(&self) -> &[Batch] {
        &self.camera_batches
    }

    /// The batches of shadow view `view`.
    pub(crate) fn shadow_batches(&self, view: usize) -> &[Batch] {
        self.shadow_batches.get(view).map_or(&[], Vec::as_slice)
    }

    /// The camera key numbered `id`.
    pub(crate) fn key(&self, id: u32) -> BatchKey {
        self.keys.get(id)
    }

    /// The shadow key numbered `id`.
    pub(crate) fn shadow_key(&self, id: u32) -> ShadowKey {
        self.shadow_keys.get(id)
    }
}

fn batch_key(object: &DrawObject, missing: TextureHandle) -> BatchKey {
    let material = &object.material;
    let shading = material.shading;
    let maps = if shading.uses_texture() {
        MaterialMaps {
            base_color: material.texture,
            metallic_roughness: material.metallic_roughness_texture,
            normal: material.normal_texture,
            occlusion: material.occlusion_texture,
            emissive: material.emissive_texture,
        }
    } else {
        MaterialMaps::default()
    };
    let alpha = if shading.uses_alpha() {
        match material.alpha_mode {
            AlphaMode::Opaque => AlphaClass::Opaque,
            AlphaMode::Mask { .. } => AlphaClass::Mask,
            AlphaMode::Blend => AlphaClass::Blend,
        }
    } else {
        AlphaClass::Opaque
    };
    BatchKey {
        alpha,
        shading,
        placeholder: maps.base_color == Some(missing),
        double_sided: material.double_sided,
        maps,
        mesh: object.mesh,
    }
}

/// What a shadow pass groups an object of camera key `key` by (a function of it: the same
/// mesh, sidedness and, for masked ones, the base colour map).
fn shadow_key(key: &BatchKey) -> ShadowKey {
    let masked = key.alpha == AlphaClass::Mask;
    ShadowKey {
        masked,
        double_sided: key.double_sided,
        mask_texture: if masked { key.maps.base_color } else { None },
        mesh: key.mesh,
    }
}

/// `rank[id]`: the place of key `id` in key order; `order[rank]`: the id at that place.
fn rank_keys<K: Ord>(keys: &[K], rank: &mut Vec<u32>, order: &mut Vec<u32>) {
    order.clear();
    order.extend(0..keys.len() as u32);
    order.sort_unstable_by(|&a, &b| keys[a as usize].cmp(&keys[b as usize]));
    rank.clear();
    rank.resize(keys.len(), 0);
    for (place, &id) in order.iter().enumerate() {
        rank[id as usize] = place as u32;
    }
}

/// Appends the slots of `entries` to `indices` grouped by key in key order (a counting sort:
/// linear in the entries), one batch per key (or per entry without instancing).
fn group_by_key(
    entries: &[(u32, u32)],
    rank: &[u32],
    order: &[u32],
    instancing: bool,
    counts: &mut Vec<u32>,
    indices: &mut Vec<u32>,
    batches: &mut Vec<Batch>,
) {
    if entries.is_empty() {
        return;
    }
    counts.clear();
    counts.resize(order.len() + 1, 0);
    for &(key, _) in entries {
        counts[rank[key as usize] as usize + 1] += 1;
    }
    for i in 1..counts.len() {
        counts[i] += counts[i - 1];
    }
    let base = indices.len();
    for (place, &id) in order.iter().enumerate() {
        let (start, end) = (counts[place], counts[place + 1]);
        if end == start {
            continue;
        }
        if instancing {
            batches.push(Batch {
                key: id,
                first_instance: (base as u32) + start,
                instance_count: end - start,
            });
        } else {
            batches.extend((start..end).map(|i| Batch {
                key: id,
                first_instance: base as u32 + i,
                instance_count: 1,
            }));
        }
    }
    indices.resize(base + entries.len(), 0);
    for &(key, slot) in entries {
        let place = rank[key as usize] as usize;
        indices[base + counts[place] as usize] = slot;
        counts[place] += 1;
    }
}

/// Camera-relative bounding sphere: centre transformed (translation made relative first, so
/// a far object keeps its precision), radius scaled by the largest axis scale.
fn relative_sphere(transform: &Mat4, origin: Vec3, bounds: MeshBounds) -> (Vec3, f32) {
    let offset = transform.w_axis.truncate() - origin;
    let center = offset + transform.transform_vector3(bounds.center);
    let scale_sq = transform
        .x_axis
        .truncate()
        .length_squared()
        .max(transform.y_axis.truncate().length_squared())
        .max(transform.z_axis.truncate().length_squared());
    (center, bounds.radius * scale_sq.sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Material;
    use crate::shading_mode::ShadingMode;

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

    fn views(instancing: bool) -> FrameViews<'static> {
        FrameViews {
            origin: Vec3::ZERO,
            camera: None,
            forward: Vec3::NEG_Z,
            shadows: &[],
            missing: TextureHandle(1),
            instancing,
        }
    }

    #[test]
    fn objects_sharing_mesh_and_material_form_one_batch() {
        let objects: Vec<_> = (0..100)
            .map(|i| {
                let shading = if i % 2 == 0 {
                    ShadingMode::Unlit
                } else {
                    ShadingMode::LitLow
                };
                object(i % 2, i as f32, shading)
            })
            .collect();
        let mut batcher = Batcher::default();
        let counts = batcher.prepare(&objects, &views(true), unit_bounds);
        assert_eq!(counts.visible, 100);
        assert_eq!(
            batcher.batches().len(),
            2,
            "batches: {:?}",
            batcher.batches()
        );
        assert_eq!(
            (batcher.objects().len(), batcher.indices().len()),
            (100, 100)
        );
        // Each batch names only objects of its own key.
        for batch in batcher.batches() {
            let key = batcher.key(batch.key);
            let range = batch.first_instance as usize
                ..(batch.first_instance + batch.instance_count) as usize;
            for &slot in &batcher.indices()[range] {
                assert_eq!(objects[slot as usize].material.shading, key.shading);
            }
        }
        let counts = batcher.prepare(&objects, &views(false), unit_bounds);
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
        let frustum = Frustum::from_view_projection(
            &(camera.projection.culling_matrix(1.0) * camera.rotation_view()),
        );
        let objects = vec![
            object(0, 0.0, ShadingMode::Unlit),
            object(0, 500.0, ShadingMode::Unlit),
            DrawObject {
                transform: Mat4::from_translation(Vec3::new(0.0, 0.0, 20.0)),
                ..object(0, 0.0, ShadingMode::Unlit)
            },
        ];
        let views = FrameViews {
            origin: camera.position,
            camera: Some(&frustum),
            ..views(true)
        };
        let counts = Batcher::default().prepare(&objects, &views, unit_bounds);
        assert_eq!((counts.visible, counts.culled), (1, 2));
    }

    /// An object outside the camera's view still casts into a shadow view that sees it.
    #[test]
    fn shadow_views_keep_casters_the_camera_does_not_see() {
        let nothing =
            Frustum::from_view_projection(&Mat4::from_translation(Vec3::new(0.0, 0.0, 1.0e6)));
        let everything = Frustum::from_view_projection(&Mat4::from_scale(Vec3::splat(1.0e-6)));
        let objects = vec![object(0, 0.0, ShadingMode::Lit)];
        let shadows = [everything];
        let views = FrameViews {
            camera: Some(&nothing),
            shadows: &shadows,
            ..views(true)
        };
        let mut batcher = Batcher::default();
        let counts = batcher.prepare(&objects, &views, unit_bounds);
        assert_eq!(
            (counts.visible, counts.culled, counts.shadow_instances),
            (0, 0, 1)
        );
        assert_eq!(batcher.shadow_batches(0).len(), 1);
        assert!(batcher.batches().is_empty());
    }

    #[test]
    fn blended_objects_come_last_from_far_to_near() {
        let glass = |z: f32| DrawObject {
            transform: Mat4::from_translation(Vec3::new(0.0, 0.0, z)),
            material: Material::color(1.0, 1.0, 1.0)
                .with_alpha(0.5)
                .with_alpha_mode(AlphaMode::Blend),
            mesh: MeshHandle(0),
        };
        let objects = vec![
            glass(-1.0),
            object(0, 0.0, ShadingMode::Lit),
            glass(-5.0),
            glass(-3.0),
        ];
        let mut batcher = Batcher::default();
        let counts = batcher.prepare(&objects, &views(true), unit_bounds);
        assert_eq!((counts.visible, counts.blended), (4, 3));
        let batches = batcher.batches();
        assert_eq!(batcher.key(batches[0].key).alpha, AlphaClass::Opaque);
        let depths: Vec<f32> = batcher.indices()[1..]
            .iter()
            .map(|&slot| batcher.objects()[slot as usize].z())
            .collect();
        assert_eq!(depths, vec![-5.0, -3.0, -1.0], "far to near");
    }

    #[test]
    fn unknown_meshes_and_nan_transforms_are_skipped_not_drawn() {
        let mut nan = object(0, 0.0, ShadingMode::Unlit);
        nan.transform.w_axis.x = f32::NAN;
        let objects = vec![object(7, 0.0, ShadingMode::Unlit), nan];
        let counts = Batcher::default().prepare(&objects, &views(true), |m| {
            (m.0 == 0).then_some(MeshBounds {
                center: Vec3::ZERO,
                radius: 1.0,
            })
        });
        assert_eq!((counts.visible, counts.invalid), (0, 2));
    }
}
