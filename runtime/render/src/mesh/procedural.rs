//! Procedural shapes as [`MeshData`] constructors: cube, plane, sphere, cylinder, capsule.
//! All are centred on the origin, Y up, with outward normals and counter-clockwise fronts.

use std::f32::consts::{FRAC_PI_2, PI, TAU};

use glam::{Vec2, Vec3};

use super::mesh_data::MeshData;
use super::vertex::Vertex;

/// Fewest segments around a round shape.
const MIN_SEGMENTS: u32 = 3;
/// Fewest rings from pole to pole.
const MIN_RINGS: u32 = 2;
/// Triangles with less area than this (m²) are dropped (the poles of a sphere).
const DEGENERATE_AREA: f32 = 1e-12;

/// One ring of a surface of revolution.
struct Ring {
    /// Height of the ring (m).
    y: f32,
    /// Distance from the Y axis (m).
    radius: f32,
    /// Normal in the (radial, y) plane.
    normal: Vec2,
    /// Texture v of the ring.
    v: f32,
}

impl MeshData {
    /// An axis-aligned cube with edges of `size` metres; each face maps the whole texture.
    #[must_use]
    pub fn cube(size: f32) -> Self {
        let h = size * 0.5;
        let mut mesh = MeshData::default();
        // (normal, texture-up direction) per face; right = up × normal.
        let faces = [
            (Vec3::X, Vec3::Y),
            (Vec3::NEG_X, Vec3::Y),
            (Vec3::Z, Vec3::Y),
            (Vec3::NEG_Z, Vec3::Y),
            (Vec3::Y, Vec3::NEG_Z),
            (Vec3::NEG_Y, Vec3::Z),
        ];
        for (normal, up) in faces {
            let right = up.cross(normal);
            let base = mesh.vertices.len() as u32;
            let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
            for (x, y) in corners {
                let position = (normal + right * x + up * y) * h;
                let uv = [(x + 1.0) * 0.5, (1.0 - y) * 0.5];
                mesh.vertices
                    .push(Vertex::new(position.to_array(), normal.to_array(), uv));
            }
            mesh.indices
                .extend([base, base + 1, base + 2, base, base + 2, base + 3]);
        }
        mesh.orient_to_normals();
        mesh
    }

    /// A square on the XZ plane facing +Y, `size` metres on a side.
    #[must_use]
    pub fn plane(size: f32) -> Self {
        let h = size * 0.5;
        let n = [0.0, 1.0, 0.0];
        let mut mesh = MeshData {
            vertices: vec![
                Vertex::new([-h, 0.0, h], n, [0.0, 1.0]),
                Vertex::new([h, 0.0, h], n, [1.0, 1.0]),
                Vertex::new([h, 0.0, -h], n, [1.0, 0.0]),
                Vertex::new([-h, 0.0, -h], n, [0.0, 0.0]),
            ],
            indices: vec![0, 1, 2, 0, 2, 3],
        };
        mesh.orient_to_normals();
        mesh
    }

    /// A UV sphere of `radius` metres with `segments` around and `rings` pole to pole.
    #[must_use]
    pub fn sphere(radius: f32, segments: u32, rings: u32) -> Self {
        let rings = rings.max(MIN_RINGS);
        let profile = (0..=rings).map(|i| {
            let theta = PI * i as f32 / rings as f32;
            let normal = Vec2::new(theta.sin(), theta.cos());
            Ring {
                y: radius * normal.y,
                radius: radius * normal.x,
                normal,
                v: i as f32 / rings as f32,
            }
        });
        Self::lathe(profile.collect(), segments)
    }

    /// A cylinder along Y, `height` metres tall, with flat caps.
    #[must_use]
    pub fn cylinder(radius: f32, height: f32, segments: u32) -> Self {
        let h = height * 0.5;
        let side = vec![
            Ring {
                y: h,
                radius,
                normal: Vec2::X,
                v: 0.0,
            },
            Ring {
                y: -h,
                radius,
                normal: Vec2::X,
                v: 1.0,
            },
        ];
        let top = vec![
            Ring {
                y: h,
                radius: 0.0,
                normal: Vec2::Y,
                v: 0.0,
            },
            Ring {
                y: h,
                radius,
                normal: Vec2::Y,
                v: 1.0,
            },
        ];
        let bottom = vec![
            Ring {
                y: -h,
                radius,
                normal: Vec2::NEG_Y,
                v: 0.0,
            },
            Ring {
                y: -h,
                radius: 0.0,
                normal: Vec2::NEG_Y,
                v: 1.0,
            },
        ];
        let mut mesh = Self::lathe(side, segments);
        mesh.append(Self::lathe(top, segments));
        mesh.append(Self::lathe(bottom, segments));
        mesh
    }

    /// A capsule along Y: a cylinder of `height` metres between two hemispheres of `radius`
    /// (total height `height + 2 * radius`).
    #[must_use]
    pub fn capsule(radius: f32, height: f32, segments: u32, rings: u32) -> Self {
        let half_rings = (rings.max(MIN_RINGS) / 2).max(1);
        let h = height * 0.5;
        let total = height + 2.0 * radius;
        let mut profile = Vec::new();
        for (offset, start) in [(h, 0.0), (-h, FRAC_PI_2)] {
            for i in 0..=half_rings {
                let theta = start + FRAC_PI_2 * i as f32 / half_rings as f32;
                let normal = Vec2::new(theta.sin(), theta.cos());
                let y = offset + radius * normal.y;
                let v = if total > 0.0 {
                    (total * 0.5 - y) / total
                } else {
                    0.0
                };
                profile.push(Ring {
                    y,
                    radius: radius * normal.x,
                    normal,
                    v,
                });
            }
        }
        Self::lathe(profile, segments)
    }

    /// Sweeps a profile of rings around the Y axis.
    fn lathe(profile: Vec<Ring>, segments: u32) -> Self {
        let segments = segments.max(MIN_SEGMENTS);
        let mut mesh = MeshData::default();
        let columns = segments + 1;
        for ring in &profile {
            for j in 0..=segments {
                let u = j as f32 / segments as f32;
                let (sin, cos) = (u * TAU).sin_cos();
                let position = [ring.radius * cos, ring.y, -ring.radius * sin];
                let normal = Vec3::new(ring.normal.x * cos, ring.normal.y, -ring.normal.x * sin)
                    .normalize_or(Vec3::Y);
                mesh.vertices
                    .push(Vertex::new(position, normal.to_array(), [u, ring.v]));
            }
        }
        for i in 0..profile.len().saturating_sub(1) as u32 {
            for j in 0..segments {
                let a = i * columns + j;
                let b = a + columns;
                mesh.indices.extend([a, b, b + 1, a, b + 1, a + 1]);
            }
        }
        mesh.orient_to_normals();
        mesh
    }

    /// Appends another mesh's triangles.
    fn append(&mut self, other: MeshData) {
        let base = self.vertices.len() as u32;
        self.vertices.extend(other.vertices);
        self.indices
            .extend(other.indices.into_iter().map(|i| i + base));
    }

    /// Drops zero-area triangles and flips any triangle whose winding disagrees with its
    /// vertex normals, so every front face is counter-clockwise seen from outside.
    fn orient_to_normals(&mut self) {
        let vertices = &self.vertices;
        let mut kept = Vec::with_capacity(self.indices.len());
        for tri in self.indices.chunks_exact(3) {
            let [a, b, c] = [tri[0], tri[1], tri[2]];
            let p = |i: u32| Vec3::from(vertices[i as usize].position);
            let n = |i: u32| Vec3::from(vertices[i as usize].normal);
            let face = (p(b) - p(a)).cross(p(c) - p(a));
            if face.length_squared() * 0.25 < DEGENERATE_AREA * DEGENERATE_AREA {
                continue;
            }
            if face.dot(n(a) + n(b) + n(c)) >= 0.0 {
                kept.extend([a, b, c]);
            } else {
                kept.extend([a, c, b]);
            }
        }
        self.indices = kept;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shapes() -> Vec<(&'static str, MeshData)> {
        vec![
            ("cube", MeshData::cube(1.0)),
            ("plane", MeshData::plane(2.0)),
            ("sphere", MeshData::sphere(0.5, 16, 8)),
            ("cylinder", MeshData::cylinder(0.5, 1.0, 12)),
            ("capsule", MeshData::capsule(0.5, 1.0, 12, 8)),
        ]
    }

    #[test]
    fn every_shape_is_valid_and_faces_point_outward() {
        for (name, mesh) in shapes() {
            assert!(mesh.is_valid(), "{name} is not a valid mesh");
            let (center, _) = mesh.bounding_sphere();
            for tri in mesh.indices.chunks_exact(3) {
                let p: Vec<Vec3> = tri
                    .iter()
                    .map(|&i| Vec3::from(mesh.vertices[i as usize].position))
                    .collect();
                let face = (p[1] - p[0]).cross(p[2] - p[0]);
                let centroid = (p[0] + p[1] + p[2]) / 3.0;
                // Convex shapes: the front face points away from the centre.
                assert!(
                    face.dot(centroid - center) >= -1e-6,
                    "{name}: triangle {tri:?} faces inward (face normal {face}, centroid {centroid})"
                );
            }
        }
    }

    #[test]
    fn shapes_have_the_documented_size() {
        let (c, r) = MeshData::cube(2.0).bounding_sphere();
        assert!(
            c.length() < 1e-6 && (r - 3f32.sqrt()).abs() < 1e-5,
            "cube: centre {c}, radius {r}"
        );
        let (c, r) = MeshData::sphere(0.5, 16, 8).bounding_sphere();
        assert!(
            c.length() < 1e-5 && (r - 0.5).abs() < 1e-5,
            "sphere: centre {c}, radius {r}"
        );
        let (c, r) = MeshData::capsule(0.5, 1.0, 12, 8).bounding_sphere();
        assert!(
            c.length() < 1e-5 && (r - 1.0).abs() < 1e-5,
            "capsule: centre {c}, radius {r} (expected 1.0)"
        );
    }

    #[test]
    fn smooth_normals_of_a_sphere_point_outward() {
        let mut sphere = MeshData::sphere(1.0, 16, 8);
        sphere.compute_smooth_normals();
        for v in &sphere.vertices {
            let p = Vec3::from(v.position);
            let n = Vec3::from(v.normal);
            assert!(
                n.dot(p.normalize()) > 0.9,
                "normal {n} at {p} does not point outward"
            );
        }
    }
}
