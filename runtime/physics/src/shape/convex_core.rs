//! [`ConvexCore`]: the support-mapped core of a convex shape (its radius kept apart),
//! used by GJK, EPA, CCD and the generic clipping manifold.

use glam::Vec3;

use super::convex_hull::{ConvexHull, HullDimension};

/// Cosine below which a segment counts as perpendicular to a query direction, so both
/// its end points form the supporting feature (used for clipping capsules lying flat).
pub const SEGMENT_FEATURE_COS: f32 = 0.02;

/// Cosine above which a triangle's own face is its supporting feature (below it, an edge
/// or vertex is used), for clipping against triangle meshes.
pub const TRIANGLE_FACE_COS: f32 = 0.7;

/// Convex core in the shape's local frame. A sphere is a `Point` core with a radius, a
/// capsule a `Segment` core with a radius; polytopes have radius zero.
#[derive(Clone, Copy, Debug)]
pub enum ConvexCore<'a> {
    /// The origin.
    Point,
    /// Segment between two points.
    Segment(Vec3, Vec3),
    /// Box with the given half extents.
    Cuboid(Vec3),
    /// Convex hull.
    Hull(&'a ConvexHull),
    /// Single triangle (corner order gives the face normal `(b-a)×(c-a)`).
    Triangle([Vec3; 3]),
}

impl ConvexCore<'_> {
    /// Largest distance of the core's points from its frame origin, metres.
    #[must_use]
    pub fn reach(&self) -> f32 {
        match self {
            Self::Point => 0.0,
            Self::Segment(a, b) => a.length().max(b.length()),
            Self::Cuboid(h) => h.length(),
            Self::Hull(h) => h.vertices().iter().map(|v| v.length()).fold(0.0, f32::max),
            Self::Triangle(t) => t.iter().map(|v| v.length()).fold(0.0, f32::max),
        }
    }

    /// Point of the core farthest along `d` (local frame).
    #[inline]
    #[must_use]
    pub fn support(&self, d: Vec3) -> Vec3 {
        match self {
            Self::Point => Vec3::ZERO,
            Self::Segment(a, b) => {
                if a.dot(d) >= b.dot(d) {
                    *a
                } else {
                    *b
                }
            }
            Self::Cuboid(h) => Vec3::new(
                if d.x >= 0.0 { h.x } else { -h.x },
                if d.y >= 0.0 { h.y } else { -h.y },
                if d.z >= 0.0 { h.z } else { -h.z },
            ),
            Self::Hull(hull) => hull.support(d),
            Self::Triangle(t) => {
                let (da, db, dc) = (t[0].dot(d), t[1].dot(d), t[2].dot(d));
                if da >= db && da >= dc {
                    t[0]
                } else if db >= dc {
                    t[1]
                } else {
                    t[2]
                }
            }
        }
    }

    /// Supporting feature along unit `d`: writes its vertices (local frame, counter-clockwise
    /// around the returned normal for faces) into `out` and returns the face normal when the
    /// feature is a polygon of three or more vertices.
    pub fn support_feature(&self, d: Vec3, out: &mut Vec<Vec3>) -> Option<Vec3> {
        out.clear();
        match self {
            Self::Point => {
                out.push(Vec3::ZERO);
                None
            }
            Self::Segment(a, b) => {
                let axis = (*b - *a).normalize_or_zero();
                if axis.dot(d).abs() < SEGMENT_FEATURE_COS {
                    out.push(*a);
                    out.push(*b);
                } else {
                    out.push(self.support(d));
                }
                None
            }
            Self::Cuboid(h) => {
                let ad = d.abs();
                let axis = if ad.x >= ad.y && ad.x >= ad.z {
                    0
                } else if ad.y >= ad.z {
                    1
                } else {
                    2
                };
                let s = if d[axis] >= 0.0 { 1.0 } else { -1.0 };
                let mut n = Vec3::ZERO;
                n[axis] = s;
                let u = (axis + 1) % 3;
                let v = (axis + 2) % 3;
                // CCW around n: (u,v) order flips with the sign.
                let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
                for &(cu, cv) in &corners {
                    let mut p = Vec3::ZERO;
                    p[axis] = s * h[axis];
                    p[u] = cu * h[u];
                    p[v] = cv * h[v] * s;
                    out.push(p);
                }
                Some(n)
            }
            Self::Hull(hull) => match hull.dimension() {
                HullDimension::Point => {
                    out.push(hull.vertices()[0]);
                    None
                }
                HullDimension::Segment => {
                    let v = hull.vertices();
                    Self::Segment(v[0], v[1]).support_feature(d, out)
                }
                HullDimension::Flat | HullDimension::Solid => {
                    let fi = hull.best_face(d)?;
                    let f = &hull.faces()[fi];
                    out.extend(f.vertices.iter().map(|&i| hull.vertices()[i as usize]));
                    Some(f.normal)
                }
            },
            Self::Triangle(t) => {
                let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
                let c = n.dot(d);
                if c.abs() > TRIANGLE_FACE_COS {
                    if c >= 0.0 {
                        out.extend_from_slice(t);
                        Some(n)
                    } else {
                        out.extend([t[0], t[2], t[1]]);
                        Some(-n)
                    }
                } else {
                    let s = self.support(d);
                    out.push(s);
                    let sd = s.dot(d);
                    // Second vertex if the edge is nearly perpendicular to d.
                    for p in t {
                        if *p != s && (sd - p.dot(d)) < SEGMENT_FEATURE_COS * (*p - s).length() {
                            out.push(*p);
                            break;
                        }
                    }
                    None
                }
            }
        }
    }
}
