//! Collision shapes: [`Shape`] and one file per primitive; `shape_scale.rs` stretches any
//! of them by a scale ([`Shape::scaled`]).

pub mod capsule;
pub mod convex_core;
pub mod convex_hull;
pub mod cuboid;
pub mod half_space;
pub mod shape_scale;
pub mod sphere;
pub mod tri_mesh;

use std::sync::Arc;

use glam::Vec3;

pub use capsule::Capsule;
pub use convex_core::ConvexCore;
pub use convex_hull::{ConvexHull, HullDimension, HullError, HullFace};
pub use cuboid::Cuboid;
pub use half_space::HalfSpace;
pub use shape_scale::{ScaledShape, UNIFORM_SCALE_TOLERANCE};
pub use sphere::Sphere;
pub use tri_mesh::{TriMesh, TriMeshError};

use crate::aabb::Aabb;
use crate::mass_properties::MassProperties;
use crate::pose::Pose;

/// Half extent used for the bounds of infinite shapes (half spaces), metres.
/// Large but finite so that tree costs stay finite.
pub const INFINITE_EXTENT: f32 = 1.0e18;

/// A collision shape in its collider's local frame.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// Sphere.
    Sphere(Sphere),
    /// Box.
    Cuboid(Cuboid),
    /// Capsule along local Y.
    Capsule(Capsule),
    /// Infinite half space (ground plane).
    HalfSpace(HalfSpace),
    /// Convex polytope (shared).
    ConvexHull(Arc<ConvexHull>),
    /// Static triangle mesh (shared).
    TriMesh(Arc<TriMesh>),
}

impl Shape {
    /// World bounds of the shape placed at `pose`.
    #[must_use]
    pub fn aabb(&self, pose: &Pose) -> Aabb {
        match self {
            Self::Sphere(s) => Aabb::from_center_half(pose.translation, Vec3::splat(s.radius)),
            Self::Cuboid(c) => {
                let m = glam::Mat3::from_quat(pose.rotation);
                let h = c.half_extents;
                let e = m.x_axis.abs() * h.x + m.y_axis.abs() * h.y + m.z_axis.abs() * h.z;
                Aabb::from_center_half(pose.translation, e)
            }
            Self::Capsule(c) => {
                let a = pose.rotation * Vec3::new(0.0, c.half_height, 0.0);
                Aabb::from_center_half(pose.translation, a.abs() + Vec3::splat(c.radius))
            }
            Self::HalfSpace(h) => {
                let n = pose.rotation * h.normal;
                let mut min = Vec3::splat(-INFINITE_EXTENT);
                let mut max = Vec3::splat(INFINITE_EXTENT);
                // Axis-aligned planes get a tight bound on their normal axis.
                for k in 0..3 {
                    if (n[k].abs() - 1.0).abs() < 1e-6 {
                        if n[k] > 0.0 {
                            max[k] = pose.translation[k];
                        } else {
                            min[k] = pose.translation[k];
                        }
                    }
                }
                Aabb::new(min, max)
            }
            Self::ConvexHull(h) => {
                Aabb::from_points(h.vertices().iter().map(|v| pose.transform_point(*v)))
            }
            Self::TriMesh(m) => {
                let b = m.local_aabb();
                let c = pose.transform_point(b.center());
                let mm = glam::Mat3::from_quat(pose.rotation);
                let h = b.half_extents();
                let e = mm.x_axis.abs() * h.x + mm.y_axis.abs() * h.y + mm.z_axis.abs() * h.z;
                Aabb::from_center_half(c, e)
            }
        }
    }

    /// Smallest dimension of a finite shape, metres (a sphere's diameter, a box's shortest
    /// side); `f32::MAX` for half spaces and triangle meshes, which have no body to deform.
    #[must_use]
    pub fn size(&self) -> f32 {
        match self {
            Self::HalfSpace(_) | Self::TriMesh(_) => f32::MAX,
            _ => 2.0 * self.aabb(&Pose::IDENTITY).half_extents().min_element(),
        }
    }

    /// Mass properties for density `rho` (kg/m³), in the shape frame. Half spaces and
    /// triangle meshes have none.
    #[must_use]
    pub fn mass_properties(&self, rho: f32) -> MassProperties {
        match self {
            Self::Sphere(s) => MassProperties::sphere(rho, s.radius),
            Self::Cuboid(c) => MassProperties::cuboid(rho, c.half_extents),
            Self::Capsule(c) => MassProperties::capsule(rho, c.half_height, c.radius),
            Self::ConvexHull(h) => h.mass_properties(rho),
            Self::HalfSpace(_) | Self::TriMesh(_) => MassProperties::ZERO,
        }
    }

    /// Radius of the smallest ball about the shape's origin that holds it, metres; `None`
    /// for half spaces and triangle meshes.
    #[must_use]
    pub(crate) fn bounding_radius(&self) -> Option<f32> {
        self.convex_core()
            .map(|(core, radius)| core.reach() + radius)
    }

    /// Convex core and radius, for convex shapes.
    #[must_use]
    pub fn convex_core(&self) -> Option<(ConvexCore<'_>, f32)> {
        match self {
            Self::Sphere(s) => Some((ConvexCore::Point, s.radius)),
            Self::Cuboid(c) => Some((ConvexCore::Cuboid(c.half_extents), 0.0)),
            Self::Capsule(c) => {
                let (a, b) = c.segment();
                Some((ConvexCore::Segment(a, b), c.radius))
            }
            Self::ConvexHull(h) => Some((ConvexCore::Hull(h), 0.0)),
            Self::HalfSpace(_) | Self::TriMesh(_) => None,
        }
    }

    /// Local-frame ray cast: `(t, normal)` of the first surface hit with `t` in `[0, max_t]`.
    /// A ray starting inside a solid shape hits at `t = 0` with normal `-dir`.
    #[must_use]
    pub fn cast_local_ray(&self, o: Vec3, d: Vec3, max_t: f32) -> Option<(f32, Vec3)> {
        match self {
            Self::Sphere(s) => ray_sphere(o, d, Vec3::ZERO, s.radius, max_t),
            Self::Cuboid(c) => ray_box(o, d, c.half_extents, max_t),
            Self::Capsule(c) => ray_capsule(o, d, c, max_t),
            Self::HalfSpace(h) => {
                let dist = h.normal.dot(o);
                if dist <= 0.0 {
                    return Some((0.0, -d));
                }
                let dn = h.normal.dot(d);
                if dn >= 0.0 {
                    return None;
                }
                let t = -dist / dn;
                (t <= max_t).then_some((t, h.normal))
            }
            Self::ConvexHull(h) => ray_hull(o, d, h, max_t),
            Self::TriMesh(m) => m.cast_ray(o, d, max_t).map(|(t, _, n)| (t, n)),
        }
    }
}

fn ray_sphere(o: Vec3, d: Vec3, c: Vec3, r: f32, max_t: f32) -> Option<(f32, Vec3)> {
    let m = o - c;
    let cc = m.dot(m) - r * r;
    if cc <= 0.0 {
        return Some((0.0, -d));
    }
    let a = d.dot(d);
    let b = m.dot(d);
    if b >= 0.0 || a <= 0.0 {
        return None;
    }
    let disc = b * b - a * cc;
    if disc < 0.0 {
        return None;
    }
    let t = (-b - disc.sqrt()) / a;
    if t > max_t {
        return None;
    }
    Some((t, (m + d * t).normalize_or(-d)))
}

fn ray_box(o: Vec3, d: Vec3, h: Vec3, max_t: f32) -> Option<(f32, Vec3)> {
    if o.abs().cmple(h).all() {
        return Some((0.0, -d));
    }
    let mut tmin = 0.0f32;
    let mut tmax = max_t;
    let mut n = Vec3::ZERO;
    for k in 0..3 {
        if d[k].abs() < 1e-12 {
            if o[k].abs() > h[k] {
                return None;
            }
            continue;
        }
        let inv = 1.0 / d[k];
        let mut t1 = (-h[k] - o[k]) * inv;
        let mut t2 = (h[k] - o[k]) * inv;
        let mut s = -1.0;
        if t1 > t2 {
            std::mem::swap(&mut t1, &mut t2);
            s = 1.0;
        }
        if t1 > tmin {
            tmin = t1;
            n = Vec3::ZERO;
            n[k] = s;
        }
        tmax = tmax.min(t2);
        if tmin > tmax {
            return None;
        }
    }
    Some((tmin, n))
}

fn ray_capsule(o: Vec3, d: Vec3, c: &Capsule, max_t: f32) -> Option<(f32, Vec3)> {
    let (a, b) = c.segment();
    let r = c.radius;
    // Inside test.
    let cl = Vec3::new(0.0, o.y.clamp(-c.half_height, c.half_height), 0.0);
    if o.distance_squared(cl) <= r * r {
        return Some((0.0, -d));
    }
    let mut best: Option<(f32, Vec3)> = None;
    let mut consider = |hit: Option<(f32, Vec3)>| {
        if let Some(h) = hit {
            if best.is_none_or(|b| h.0 < b.0) {
                best = Some(h);
            }
        }
    };
    consider(ray_sphere(o, d, a, r, max_t));
    consider(ray_sphere(o, d, b, r, max_t));
    // Infinite cylinder around Y restricted to |y| <= hh.
    let (ox, oz, dx, dz) = (o.x, o.z, d.x, d.z);
    let qa = dx * dx + dz * dz;
    if qa > 1e-12 {
        let qb = ox * dx + oz * dz;
        let qc = ox * ox + oz * oz - r * r;
        let disc = qb * qb - qa * qc;
        if disc >= 0.0 {
            let t = (-qb - disc.sqrt()) / qa;
            if t >= 0.0 && t <= max_t {
                let p = o + d * t;
                if p.y.abs() <= c.half_height {
                    consider(Some((t, Vec3::new(p.x, 0.0, p.z).normalize_or(-d))));
                }
            }
        }
    }
    best
}

fn ray_hull(o: Vec3, d: Vec3, h: &ConvexHull, max_t: f32) -> Option<(f32, Vec3)> {
    if h.dimension() != HullDimension::Solid {
        if h.dimension() == HullDimension::Flat {
            let f = &h.faces()[0];
            let dn = f.normal.dot(d);
            if dn.abs() < 1e-12 {
                return None;
            }
            let t = (f.offset - f.normal.dot(o)) / dn;
            if !(0.0..=max_t).contains(&t) {
                return None;
            }
            let p = o + d * t;
            let vs = &f.vertices;
            for k in 0..vs.len() {
                let a = h.vertices()[vs[k] as usize];
                let b = h.vertices()[vs[(k + 1) % vs.len()] as usize];
                if (b - a).cross(p - a).dot(f.normal) < -1e-6 {
                    return None;
                }
            }
            return Some((t, if dn < 0.0 { f.normal } else { -f.normal }));
        }
        return None;
    }
    let mut tmin = 0.0f32;
    let mut tmax = max_t;
    let mut n = -d;
    for f in h.faces() {
        let num = f.offset - f.normal.dot(o);
        let den = f.normal.dot(d);
        if den.abs() < 1e-12 {
            if num < 0.0 {
                return None;
            }
            continue;
        }
        let t = num / den;
        if den < 0.0 {
            if t > tmin {
                tmin = t;
                n = f.normal;
            }
        } else {
            tmax = tmax.min(t);
        }
        if tmin > tmax {
            return None;
        }
    }
    Some((tmin, n))
}
