//! [`TriMesh`]: static triangle mesh (level geometry) with its own bounding-volume tree.

use glam::Vec3;

use crate::aabb::Aabb;

/// Triangles per BVH leaf. Bounded `[1, 16]`: lower means deeper trees, higher more tests per leaf.
pub const TRIMESH_LEAF_SIZE: usize = 4;

/// Why a mesh could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriMeshError {
    /// No triangles.
    Empty,
    /// An index points past the vertex list.
    IndexOutOfRange,
    /// A vertex coordinate is NaN or infinite.
    NonFinite,
}

impl std::fmt::Display for TriMeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Empty => write!(f, "triangle mesh has no triangles"),
            Self::IndexOutOfRange => write!(f, "triangle index out of range"),
            Self::NonFinite => write!(f, "triangle mesh vertex is not finite"),
        }
    }
}

impl std::error::Error for TriMeshError {}

#[derive(Clone, Debug, PartialEq)]
struct Node {
    aabb: Aabb,
    /// Leaf: first triangle in `order`; inner: index of the left child (right = left + 1).
    start: u32,
    /// Leaf: triangle count (> 0); inner: 0.
    count: u32,
}

/// Static triangle mesh in the local frame. Triangles are one-sided for nothing:
/// contacts use the triangle normal `(b - a) × (c - a)` only for degenerate fallbacks.
/// Meant for fixed bodies; on a dynamic body it contributes no mass.
#[derive(Clone, Debug, PartialEq)]
pub struct TriMesh {
    vertices: Vec<Vec3>,
    triangles: Vec<[u32; 3]>,
    nodes: Vec<Node>,
    order: Vec<u32>,
}

impl TriMesh {
    /// Builds a mesh from vertices and triangle indices.
    ///
    /// # Errors
    /// [`TriMeshError`] for empty, out-of-range or non-finite input.
    pub fn new(vertices: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> Result<Self, TriMeshError> {
        if triangles.is_empty() {
            return Err(TriMeshError::Empty);
        }
        if vertices.iter().any(|v| !v.is_finite()) {
            return Err(TriMeshError::NonFinite);
        }
        if triangles
            .iter()
            .any(|t| t.iter().any(|&i| i as usize >= vertices.len()))
        {
            return Err(TriMeshError::IndexOutOfRange);
        }
        let mut mesh = Self {
            vertices,
            triangles,
            nodes: Vec::new(),
            order: Vec::new(),
        };
        mesh.build();
        Ok(mesh)
    }

    fn tri_aabb(&self, t: u32) -> Aabb {
        let [a, b, c] = self.triangle(t as usize);
        Aabb::from_points([a, b, c])
    }

    fn build(&mut self) {
        self.order = (0..self.triangles.len() as u32).collect();
        let centers: Vec<Vec3> = (0..self.triangles.len())
            .map(|i| {
                let [a, b, c] = self.triangle(i);
                (a + b + c) / 3.0
            })
            .collect();
        self.nodes.push(Node {
            aabb: Aabb::new(Vec3::ZERO, Vec3::ZERO),
            start: 0,
            count: 0,
        });
        // Explicit stack: (node, start, end).
        let mut stack = vec![(0usize, 0usize, self.order.len())];
        while let Some((node, start, end)) = stack.pop() {
            let mut aabb = self.tri_aabb(self.order[start]);
            for &t in &self.order[start + 1..end] {
                aabb = aabb.union(&self.tri_aabb(t));
            }
            self.nodes[node].aabb = aabb;
            if end - start <= TRIMESH_LEAF_SIZE {
                self.nodes[node].start = start as u32;
                self.nodes[node].count = (end - start) as u32;
                continue;
            }
            let ext = aabb.max - aabb.min;
            let axis = if ext.x >= ext.y && ext.x >= ext.z {
                0
            } else if ext.y >= ext.z {
                1
            } else {
                2
            };
            let mid = (start + end) / 2;
            self.order[start..end].select_nth_unstable_by(mid - start, |&x, &y| {
                centers[x as usize][axis].total_cmp(&centers[y as usize][axis])
            });
            let left = self.nodes.len();
            self.nodes.push(Node {
                aabb,
                start: 0,
                count: 0,
            });
            self.nodes.push(Node {
                aabb,
                start: 0,
                count: 0,
            });
            self.nodes[node].start = left as u32;
            self.nodes[node].count = 0;
            stack.push((left, start, mid));
            stack.push((left + 1, mid, end));
        }
    }

    /// Vertices (local frame).
    #[must_use]
    pub fn vertices(&self) -> &[Vec3] {
        &self.vertices
    }

    /// Triangle index triples.
    #[must_use]
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Corner positions of triangle `i`.
    #[inline]
    #[must_use]
    pub fn triangle(&self, i: usize) -> [Vec3; 3] {
        let t = self.triangles[i];
        [
            self.vertices[t[0] as usize],
            self.vertices[t[1] as usize],
            self.vertices[t[2] as usize],
        ]
    }

    /// Bounds of the whole mesh (local frame).
    #[must_use]
    pub fn local_aabb(&self) -> Aabb {
        self.nodes[0].aabb
    }

    /// Calls `f` with every triangle whose bounds overlap `aabb` (local frame).
    pub fn for_each_in_aabb(&self, aabb: &Aabb, mut f: impl FnMut(usize)) {
        let mut stack = [0u32; 64];
        let mut sp = 1;
        while sp > 0 {
            sp -= 1;
            let n = &self.nodes[stack[sp] as usize];
            if !n.aabb.intersects(aabb) {
                continue;
            }
            if n.count > 0 {
                for &t in &self.order[n.start as usize..(n.start + n.count) as usize] {
                    if self.tri_aabb(t).intersects(aabb) {
                        f(t as usize);
                    }
                }
            } else if sp + 2 <= stack.len() {
                stack[sp] = n.start;
                stack[sp + 1] = n.start + 1;
                sp += 2;
            }
        }
    }

    /// Closest ray hit `(t, triangle, normal)` with `t` in `[0, max_t]` (local frame).
    /// The normal faces against the ray.
    #[must_use]
    pub fn cast_ray(&self, origin: Vec3, dir: Vec3, max_t: f32) -> Option<(f32, usize, Vec3)> {
        let inv = dir.recip();
        let mut best: Option<(f32, usize, Vec3)> = None;
        let mut stack = [0u32; 64];
        let mut sp = 1;
        while sp > 0 {
            sp -= 1;
            let n = &self.nodes[stack[sp] as usize];
            let limit = best.map_or(max_t, |b| b.0);
            if n.aabb.ray_entry(origin, inv, limit).is_none() {
                continue;
            }
            if n.count > 0 {
                for &t in &self.order[n.start as usize..(n.start + n.count) as usize] {
                    let [a, b, c] = self.triangle(t as usize);
                    if let Some(hit) = ray_triangle(origin, dir, a, b, c) {
                        if hit <= best.map_or(max_t, |b| b.0) {
                            let mut nrm = (b - a).cross(c - a).normalize_or_zero();
                            if nrm.dot(dir) > 0.0 {
                                nrm = -nrm;
                            }
                            best = Some((hit, t as usize, nrm));
                        }
                    }
                }
            } else if sp + 2 <= stack.len() {
                stack[sp] = n.start;
                stack[sp + 1] = n.start + 1;
                sp += 2;
            }
        }
        best
    }
}

/// Möller–Trumbore, two-sided: `t >= 0` of the hit, if any.
#[must_use]
pub(crate) fn ray_triangle(o: Vec3, d: Vec3, a: Vec3, b: Vec3, c: Vec3) -> Option<f32> {
    let e1 = b - a;
    let e2 = c - a;
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det.abs() < 1e-12 {
        return None;
    }
    let inv = 1.0 / det;
    let s = o - a;
    let u = s.dot(p) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = d.dot(q) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(q) * inv;
    (t >= 0.0).then_some(t)
}
