//! [`Shape::scaled`]: a shape stretched by a scale along its own axes (a transform's scale).

use std::sync::Arc;

use glam::Vec3;

use super::{Capsule, ConvexHull, Cuboid, Shape, Sphere, TriMesh};

/// How far apart the components of a scale may be (relative to the largest) before a shape
/// that only scales uniformly counts it as non-uniform.
pub const UNIFORM_SCALE_TOLERANCE: f32 = 1e-5;

/// A shape scaled by a scale: the shape, and whether the scale asked for a stretch the shape
/// cannot take (a sphere or capsule under a non-uniform scale, scaled uniformly instead).
#[derive(Clone, Debug, PartialEq)]
pub struct ScaledShape {
    /// The scaled shape.
    pub shape: Shape,
    /// The scale was non-uniform and the shape took its largest component instead.
    pub made_uniform: bool,
}

impl Shape {
    /// This shape with its local axes stretched by `scale` (absolute values; a mirrored hull
    /// or mesh is mirrored, with its triangles turned so they still face out).
    ///
    /// Boxes, hulls and triangle meshes take any scale. Spheres and capsules stay round: they
    /// take the largest absolute component (a capsule's length scales with it too), and
    /// [`ScaledShape::made_uniform`] says the scale was not uniform. Half spaces are
    /// unchanged (an infinite plane has no size). A scale of one returns the shape as is,
    /// sharing its hull or mesh.
    ///
    /// # Errors
    /// A hull or mesh that the scale flattens (a zero component) cannot be rebuilt: the
    /// builder's message.
    pub fn scaled(&self, scale: Vec3) -> Result<ScaledShape, String> {
        let uniform = |shape| ScaledShape {
            shape,
            made_uniform: false,
        };
        if scale == Vec3::ONE {
            return Ok(uniform(self.clone()));
        }
        let a = scale.abs();
        let largest = a.max_element();
        let non_uniform = a.max_element() - a.min_element() > UNIFORM_SCALE_TOLERANCE * largest;
        Ok(match self {
            Self::Sphere(s) => ScaledShape {
                shape: Self::Sphere(Sphere {
                    radius: s.radius * largest,
                }),
                made_uniform: non_uniform,
            },
            Self::Capsule(c) => ScaledShape {
                shape: Self::Capsule(Capsule {
                    half_height: c.half_height * largest,
                    radius: c.radius * largest,
                }),
                made_uniform: non_uniform,
            },
            Self::Cuboid(c) => uniform(Self::Cuboid(Cuboid {
                half_extents: c.half_extents * a,
            })),
            Self::HalfSpace(_) => uniform(self.clone()),
            Self::ConvexHull(h) => {
                let points: Vec<Vec3> = h.vertices().iter().map(|v| *v * scale).collect();
                let hull = ConvexHull::from_points(&points).map_err(|e| e.to_string())?;
                uniform(Self::ConvexHull(Arc::new(hull)))
            }
            Self::TriMesh(m) => {
                let vertices = m.vertices().iter().map(|v| *v * scale).collect();
                let mirrored = scale.x * scale.y * scale.z < 0.0;
                let triangles = m
                    .triangles()
                    .iter()
                    .map(|&[i, j, k]| if mirrored { [i, k, j] } else { [i, j, k] })
                    .collect();
                let mesh = TriMesh::new(vertices, triangles).map_err(|e| e.to_string())?;
                uniform(Self::TriMesh(Arc::new(mesh)))
            }
        })
    }
}
