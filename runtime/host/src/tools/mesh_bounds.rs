//! [`MeshBounds`]: the local shape of every mesh, for picking and outlines — the built-in
//! shapes exactly, a loaded model by its bounding box (read from its file once).

use std::collections::HashMap;
use std::sync::Arc;

use onyx_physics::shape::{Capsule, Cuboid, Shape, Sphere};
use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::tools::Bounds;
use onyx_plugin_api::MeshId;

use crate::assets::AssetRegistry;

/// Half the thickness given to the flat built-in plane, so a ray along it still meets it.
const PLANE_HALF_THICKNESS: f32 = 1e-4;

/// A mesh's shape in its own frame: what a ray is tested against, and its box.
#[derive(Clone, Debug)]
pub struct MeshShape {
    /// The shape, centred on `centre`.
    pub shape: Shape,
    /// Where the shape's centre is in the mesh's frame.
    pub centre: Vec3,
    /// The box around it.
    pub bounds: Bounds,
}

/// The shapes of the meshes asked about so far (a loaded model is read once).
#[derive(Debug, Default)]
pub struct MeshBounds {
    loaded: HashMap<MeshId, Option<Arc<MeshShape>>>,
}

fn centred(shape: Shape, half: Vec3) -> MeshShape {
    MeshShape {
        shape,
        centre: Vec3::ZERO,
        bounds: Bounds {
            min: -half,
            max: half,
        },
    }
}

/// The shape of a built-in mesh (see [`MeshId`]'s constants for their sizes).
fn builtin(mesh: MeshId) -> Option<MeshShape> {
    Some(match mesh {
        MeshId::CUBE | MeshId::CYLINDER => centred(
            Shape::Cuboid(Cuboid {
                half_extents: Vec3::splat(0.5),
            }),
            Vec3::splat(0.5),
        ),
        MeshId::SPHERE => centred(Shape::Sphere(Sphere { radius: 0.5 }), Vec3::splat(0.5)),
        MeshId::PLANE => {
            let half = Vec3::new(0.5, PLANE_HALF_THICKNESS, 0.5);
            centred(Shape::Cuboid(Cuboid { half_extents: half }), half)
        }
        MeshId::CAPSULE => centred(
            Shape::Capsule(Capsule {
                half_height: 0.5,
                radius: 0.5,
            }),
            Vec3::new(0.5, 1.0, 0.5),
        ),
        _ => return None,
    })
}

impl MeshBounds {
    /// The shape of `mesh`: a built-in exactly, a loaded model as its bounding box. `None`
    /// for an id no mesh has, or a model file that cannot be read (the renderer reports it).
    pub fn shape(&mut self, assets: &AssetRegistry, mesh: MeshId) -> Option<Arc<MeshShape>> {
        if let Some(shape) = builtin(mesh) {
            return Some(Arc::new(shape));
        }
        self.loaded
            .entry(mesh)
            .or_insert_with(|| {
                let path = assets.mesh_path(mesh)?;
                let data = onyx_render::mesh::load_obj_geometry(&assets.resolve(path)).ok()?;
                let mut points = data.vertices.iter().map(|v| Vec3::from(v.position));
                let first = points.next()?;
                let (min, max) = points.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p)));
                let half = ((max - min) * 0.5).max(Vec3::splat(PLANE_HALF_THICKNESS));
                Some(Arc::new(MeshShape {
                    shape: Shape::Cuboid(Cuboid { half_extents: half }),
                    centre: (min + max) * 0.5,
                    bounds: Bounds { min, max },
                }))
            })
            .clone()
    }
}
