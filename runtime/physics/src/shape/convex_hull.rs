//! [`ConvexHull`] shape built from a point cloud (incremental hull), with polygon faces.

use std::collections::{HashMap, HashSet};

use glam::{Mat3, Vec3};

use crate::mass_properties::MassProperties;

/// Relative tolerance of the hull builder: a point closer than
/// `HULL_RELATIVE_EPSILON * size` to a face plane counts as on the plane.
/// Bounded: `[1e-6, 1e-2]`; too low keeps noise faces, too high drops real detail.
pub const HULL_RELATIVE_EPSILON: f32 = 1e-4;

/// A point cloud is flat (a polygon, [`HullDimension::Flat`]) only when its thickness is
/// below this fraction of its size: a few f32 roundings. Thin but solid shapes (a wall
/// 10 km wide and 1 cm thick, aspect 10⁶) stay solid; with the face tolerance as the
/// flatness test they were flattened onto one face and lost their thickness.
pub const HULL_FLAT_RELATIVE_EPSILON: f32 = 2e-7;

/// For thin solids the face tolerance is at most this fraction of the thickness (so the
/// two large faces of a slab are never merged into one plane).
pub const HULL_THIN_EPSILON_FRACTION: f32 = 1e-2;

/// Upper bound on input points processed by [`ConvexHull::from_points`]; extra points are
/// ignored (the builder is O(n·faces)). Documented cap, not a silent truncation: see
/// [`HullError::TooManyPoints`].
pub const HULL_MAX_INPUT_POINTS: usize = 65_536;

/// Cosine above which two triangle normals are merged into one polygon face.
pub const HULL_FACE_MERGE_COS: f32 = 0.9999;

/// Why a hull could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HullError {
    /// No input points.
    Empty,
    /// An input coordinate was NaN or infinite.
    NonFinite,
    /// More than [`HULL_MAX_INPUT_POINTS`] points.
    TooManyPoints,
    /// Rounding broke the incremental construction (the surface stopped being a closed
    /// manifold); reported instead of looping or growing without bound.
    NumericallyDegenerate,
}

impl std::fmt::Display for HullError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Empty => write!(f, "convex hull needs at least one point"),
            Self::NonFinite => write!(f, "convex hull input has a non-finite coordinate"),
            Self::NumericallyDegenerate => write!(
                f,
                "convex hull construction failed on near-degenerate input (rounding); \
                 simplify the point cloud"
            ),
            Self::TooManyPoints => {
                write!(
                    f,
                    "convex hull input exceeds {HULL_MAX_INPUT_POINTS} points"
                )
            }
        }
    }
}

impl std::error::Error for HullError {}

/// Dimension of a hull: degenerate inputs give lower-dimensional hulls, never errors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HullDimension {
    /// All points coincide.
    Point,
    /// All points on a line: a segment.
    Segment,
    /// All points on a plane: a flat polygon with two opposite faces.
    Flat,
    /// A solid polytope.
    Solid,
}

/// One planar face: outward normal, plane offset and counter-clockwise vertex loop.
#[derive(Clone, Debug, PartialEq)]
pub struct HullFace {
    /// Outward unit normal.
    pub normal: Vec3,
    /// Plane offset: points `p` on the face satisfy `dot(normal, p) = offset`.
    pub offset: f32,
    /// Vertex indices, counter-clockwise seen from outside.
    pub vertices: Vec<u32>,
}

/// Convex polytope (local frame). Build with [`ConvexHull::from_points`].
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexHull {
    vertices: Vec<Vec3>,
    faces: Vec<HullFace>,
    edges: Vec<(u32, u32)>,
    dimension: HullDimension,
}

impl ConvexHull {
    /// Builds the convex hull of `points` (e.g. the vertices of an OBJ mesh).
    ///
    /// Coplanar, collinear or coincident inputs produce [`HullDimension::Flat`],
    /// [`HullDimension::Segment`] or [`HullDimension::Point`] hulls.
    ///
    /// # Errors
    /// [`HullError`] on empty, non-finite or oversized input.
    pub fn from_points(points: &[Vec3]) -> Result<Self, HullError> {
        if points.is_empty() {
            return Err(HullError::Empty);
        }
        if points.len() > HULL_MAX_INPUT_POINTS {
            return Err(HullError::TooManyPoints);
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(HullError::NonFinite);
        }
        let (lo, hi) = points.iter().fold((points[0], points[0]), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
        let size = (hi - lo).max_element().max(
            points
                .iter()
                .map(|p| p.abs().max_element())
                .fold(0.0, f32::max)
                * 1e-3,
        );
        let eps = (size * HULL_RELATIVE_EPSILON).max(f32::MIN_POSITIVE);

        // Initial simplex from extreme points.
        let i0 = (0..points.len())
            .min_by(|&a, &b| points[a].x.total_cmp(&points[b].x))
            .unwrap_or(0);
        let i1 = argmax(points, |p| p.distance_squared(points[i0]));
        if points[i1].distance(points[i0]) <= eps {
            return Ok(Self::degenerate(vec![points[i0]], HullDimension::Point));
        }
        let axis = (points[i1] - points[i0]).normalize();
        let i2 = argmax(points, |p| {
            let d = *p - points[i0];
            (d - axis * d.dot(axis)).length_squared()
        });
        let d2 = points[i2] - points[i0];
        if (d2 - axis * d2.dot(axis)).length() <= eps {
            return Ok(Self::degenerate(
                vec![points[i0], points[i1]],
                HullDimension::Segment,
            ));
        }
        let plane_n = (points[i1] - points[i0])
            .cross(points[i2] - points[i0])
            .normalize();
        let i3 = argmax(points, |p| (*p - points[i0]).dot(plane_n).abs());
        let thickness = (points[i3] - points[i0]).dot(plane_n).abs();
        if thickness <= (size * HULL_FLAT_RELATIVE_EPSILON).max(f32::MIN_POSITIVE) {
            return Ok(Self::flat(points, points[i0], plane_n, eps));
        }
        let eps = eps.min(thickness * HULL_THIN_EPSILON_FRACTION);
        Self::solid(points, [i0, i1, i2, i3], eps)
    }

    fn degenerate(vertices: Vec<Vec3>, dimension: HullDimension) -> Self {
        let edges = if vertices.len() == 2 {
            vec![(0, 1)]
        } else {
            vec![]
        };
        Self {
            vertices,
            faces: Vec::new(),
            edges,
            dimension,
        }
    }

    fn flat(points: &[Vec3], origin: Vec3, n: Vec3, eps: f32) -> Self {
        let (u, v) = any_orthonormal_pair(n);
        let mut pts2: Vec<(f32, f32, Vec3)> = points
            .iter()
            .map(|p| {
                let d = *p - origin;
                (d.dot(u), d.dot(v), *p)
            })
            .collect();
        pts2.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        // Andrew's monotone chain.
        let cross = |o: &(f32, f32, Vec3), a: &(f32, f32, Vec3), b: &(f32, f32, Vec3)| {
            (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
        };
        let tol = eps * eps;
        let mut lower: Vec<(f32, f32, Vec3)> = Vec::new();
        for p in &pts2 {
            while lower.len() >= 2
                && cross(&lower[lower.len() - 2], &lower[lower.len() - 1], p) <= tol
            {
                lower.pop();
            }
            lower.push(*p);
        }
        let mut upper: Vec<(f32, f32, Vec3)> = Vec::new();
        for p in pts2.iter().rev() {
            while upper.len() >= 2
                && cross(&upper[upper.len() - 2], &upper[upper.len() - 1], p) <= tol
            {
                upper.pop();
            }
            upper.push(*p);
        }
        lower.pop();
        upper.pop();
        lower.extend(upper);
        let vertices: Vec<Vec3> = lower.iter().map(|p| p.2).collect();
        let count = vertices.len() as u32;
        if count < 3 {
            return Self::degenerate(vertices, HullDimension::Segment);
        }
        // Loop is CCW around u × v.
        let nn = u.cross(v);
        let loop_ccw: Vec<u32> = (0..count).collect();
        let offset = nn.dot(vertices[0]);
        let faces = vec![
            HullFace {
                normal: nn,
                offset,
                vertices: loop_ccw.clone(),
            },
            HullFace {
                normal: -nn,
                offset: -offset,
                vertices: loop_ccw.iter().rev().copied().collect(),
            },
        ];
        let edges = (0..count).map(|i| (i, (i + 1) % count)).collect();
        Self {
            vertices,
            faces,
            edges,
            dimension: HullDimension::Flat,
        }
    }

    fn solid(points: &[Vec3], init: [usize; 4], eps: f32) -> Result<Self, HullError> {
        #[derive(Clone)]
        struct Tri {
            v: [usize; 3],
            n: Vec3,
            d: f32,
            alive: bool,
        }
        let make = |a: usize, b: usize, c: usize| -> Tri {
            let n = (points[b] - points[a])
                .cross(points[c] - points[a])
                .normalize_or_zero();
            Tri {
                v: [a, b, c],
                n,
                d: n.dot(points[a]),
                alive: true,
            }
        };
        let [a, b, c, d] = init;
        let mut tris = Vec::new();
        let centroid = (points[a] + points[b] + points[c] + points[d]) * 0.25;
        for (x, y, z) in [(a, b, c), (a, c, d), (a, d, b), (b, d, c)] {
            let mut t = make(x, y, z);
            if t.n.dot(centroid) - t.d > 0.0 {
                t = make(x, z, y);
            }
            tris.push(t);
        }
        // Directed edge -> the live triangle that owns it. Each edge of a closed surface has
        // exactly one owner and its reverse one other, which is how neighbours are found.
        let mut owner: HashMap<(usize, usize), usize> = HashMap::new();
        for (ti, t) in tris.iter().enumerate() {
            for k in 0..3 {
                owner.insert((t.v[k], t.v[(k + 1) % 3]), ti);
            }
        }
        // A hull of n points has at most 2n - 4 triangles; more means rounding broke it.
        let max_alive = 2 * points.len() + 8;
        let mut alive = tris.len();
        let mut visible: Vec<usize> = Vec::new();
        let mut seen: HashSet<usize> = HashSet::new();
        let mut horizon: Vec<(usize, usize)> = Vec::new();
        for (pi, p) in points.iter().enumerate() {
            if init.contains(&pi) {
                continue;
            }
            // Start from the face that sees the point best, then grow the visible region
            // through neighbours only, so it is connected and its border is one closed loop.
            // Neighbours within `eps` of the point's plane join it too: leaving such a
            // nearly-coplanar face as an island inside the region would pinch the surface.
            let mut best = None;
            let mut best_dist = eps;
            for (ti, t) in tris.iter().enumerate() {
                let dist = t.n.dot(*p) - t.d;
                if t.alive && dist > best_dist {
                    best_dist = dist;
                    best = Some(ti);
                }
            }
            let Some(start) = best else { continue };
            visible.clear();
            seen.clear();
            horizon.clear();
            let mut stack = vec![start];
            seen.insert(start);
            while let Some(ti) = stack.pop() {
                visible.push(ti);
                let v = tris[ti].v;
                for k in 0..3 {
                    let (ea, eb) = (v[k], v[(k + 1) % 3]);
                    match owner.get(&(eb, ea)) {
                        Some(&ni) if tris[ni].alive && tris[ni].n.dot(*p) - tris[ni].d > -eps => {
                            if seen.insert(ni) {
                                stack.push(ni);
                            }
                        }
                        _ => horizon.push((ea, eb)),
                    }
                }
            }
            for &ti in &visible {
                let v = tris[ti].v;
                for k in 0..3 {
                    owner.remove(&(v[k], v[(k + 1) % 3]));
                }
                tris[ti].alive = false;
            }
            alive -= visible.len();
            for &(ea, eb) in &horizon {
                let ti = tris.len();
                tris.push(make(ea, eb, pi));
                owner.insert((ea, eb), ti);
                owner.insert((eb, pi), ti);
                owner.insert((pi, ea), ti);
            }
            alive += horizon.len();
            if alive > max_alive {
                return Err(HullError::NumericallyDegenerate);
            }
        }
        // The surface is closed: every live edge has its reverse, and T = 2V - 4.
        debug_assert!(
            tris.iter()
                .filter(|t| t.alive)
                .all(|t| (0..3).all(|k| owner.contains_key(&(t.v[(k + 1) % 3], t.v[k])))),
            "convex hull surface is not closed"
        );
        tris.retain(|t| t.alive && t.n != Vec3::ZERO);

        // Compact vertices.
        let mut remap = vec![u32::MAX; points.len()];
        let mut vertices = Vec::new();
        for t in &tris {
            for &vi in &t.v {
                if remap[vi] == u32::MAX {
                    remap[vi] = vertices.len() as u32;
                    vertices.push(points[vi]);
                }
            }
        }
        // Merge coplanar triangles into polygon faces.
        let mut assigned = vec![false; tris.len()];
        let mut faces = Vec::new();
        for i in 0..tris.len() {
            if assigned[i] {
                continue;
            }
            let n = tris[i].n;
            let dd = tris[i].d;
            let mut ids: Vec<u32> = Vec::new();
            let mut nsum = Vec3::ZERO;
            for j in i..tris.len() {
                if !assigned[j]
                    && tris[j].n.dot(n) > HULL_FACE_MERGE_COS
                    && (tris[j].d - dd).abs() <= eps * 4.0
                {
                    assigned[j] = true;
                    nsum += tris[j].n;
                    for &vi in &tris[j].v {
                        let r = remap[vi];
                        if !ids.contains(&r) {
                            ids.push(r);
                        }
                    }
                }
            }
            let normal = nsum.normalize_or(n);
            let c = ids.iter().map(|&k| vertices[k as usize]).sum::<Vec3>() / ids.len() as f32;
            let (u, v) = any_orthonormal_pair(normal);
            ids.sort_by(|&x, &y| {
                let px = vertices[x as usize] - c;
                let py = vertices[y as usize] - c;
                let ax = px.dot(v).atan2(px.dot(u));
                let ay = py.dot(v).atan2(py.dot(u));
                ax.total_cmp(&ay)
            });
            let offset = ids
                .iter()
                .map(|&k| normal.dot(vertices[k as usize]))
                .fold(f32::MIN, f32::max);
            faces.push(HullFace {
                normal,
                offset,
                vertices: ids,
            });
        }
        let mut edge_set: HashSet<(u32, u32)> = HashSet::new();
        for f in &faces {
            let n = f.vertices.len();
            for k in 0..n {
                let (x, y) = (f.vertices[k], f.vertices[(k + 1) % n]);
                edge_set.insert((x.min(y), x.max(y)));
            }
        }
        let mut edges: Vec<(u32, u32)> = edge_set.into_iter().collect();
        edges.sort_unstable();
        Ok(Self {
            vertices,
            faces,
            edges,
            dimension: HullDimension::Solid,
        })
    }

    /// Hull vertices (local frame, metres).
    #[must_use]
    pub fn vertices(&self) -> &[Vec3] {
        &self.vertices
    }

    /// Polygon faces (empty for point and segment hulls; two opposite faces for flat hulls).
    #[must_use]
    pub fn faces(&self) -> &[HullFace] {
        &self.faces
    }

    /// Unique edges as vertex index pairs.
    #[must_use]
    pub fn edges(&self) -> &[(u32, u32)] {
        &self.edges
    }

    /// Point, segment, flat or solid.
    #[must_use]
    pub fn dimension(&self) -> HullDimension {
        self.dimension
    }

    /// Vertex farthest along `dir`.
    #[inline]
    #[must_use]
    pub fn support(&self, dir: Vec3) -> Vec3 {
        let mut best = self.vertices[0];
        let mut best_d = best.dot(dir);
        for v in &self.vertices[1..] {
            let d = v.dot(dir);
            if d > best_d {
                best_d = d;
                best = *v;
            }
        }
        best
    }

    /// Index of the face whose normal is most aligned with `dir`, if any.
    #[must_use]
    pub fn best_face(&self, dir: Vec3) -> Option<usize> {
        let mut best = None;
        let mut best_d = f32::MIN;
        for (i, f) in self.faces.iter().enumerate() {
            let d = f.normal.dot(dir);
            if d > best_d {
                best_d = d;
                best = Some(i);
            }
        }
        best
    }

    /// Mass properties for density `rho` (kg/m³). Non-solid hulls have zero mass.
    #[must_use]
    pub fn mass_properties(&self, rho: f32) -> MassProperties {
        if self.dimension != HullDimension::Solid {
            return MassProperties::ZERO;
        }
        // Tetrahedra from an interior reference point to each face triangle fan.
        let r = self.vertices.iter().sum::<Vec3>() / self.vertices.len() as f32;
        let mut vol = 0.0;
        let mut com = Vec3::ZERO;
        // Second moments about r: integral of x_i x_j.
        let mut cov = Mat3::ZERO;
        for f in &self.faces {
            let v0 = self.vertices[f.vertices[0] as usize] - r;
            for k in 1..f.vertices.len().saturating_sub(1) {
                let v1 = self.vertices[f.vertices[k] as usize] - r;
                let v2 = self.vertices[f.vertices[k + 1] as usize] - r;
                let det = v0.dot(v1.cross(v2));
                let tv = det / 6.0;
                vol += tv;
                com += (v0 + v1 + v2) * (tv / 4.0);
                // Canonical tetra covariance scaled by det: (1/120) * (sum v v^T + (sum v)(sum v)^T).
                let s = v0 + v1 + v2;
                let c = crate::mass_properties::outer(v0, v0)
                    + crate::mass_properties::outer(v1, v1)
                    + crate::mass_properties::outer(v2, v2)
                    + crate::mass_properties::outer(s, s);
                cov += c * (det / 120.0);
            }
        }
        if vol <= f32::EPSILON {
            return MassProperties::ZERO;
        }
        let m = rho * vol;
        let c_rel = com / vol;
        // Covariance about the centre of mass.
        let cov_com = cov * rho - crate::mass_properties::outer(c_rel, c_rel) * m;
        let tr = cov_com.x_axis.x + cov_com.y_axis.y + cov_com.z_axis.z;
        let inertia = Mat3::from_diagonal(Vec3::splat(tr)) - cov_com;
        MassProperties {
            mass: m,
            local_com: r + c_rel,
            inertia,
        }
    }
}

fn argmax(points: &[Vec3], f: impl Fn(&Vec3) -> f32) -> usize {
    let mut best = 0;
    let mut bv = f32::MIN;
    for (i, p) in points.iter().enumerate() {
        let v = f(p);
        if v > bv {
            bv = v;
            best = i;
        }
    }
    best
}

/// Two unit vectors orthogonal to `n` and to each other, with `u × v = n`.
#[must_use]
pub(crate) fn any_orthonormal_pair(n: Vec3) -> (Vec3, Vec3) {
    let u = n.any_orthonormal_vector();
    let v = n.cross(u);
    (u, v)
}
