//! [`RawManifold`]: contact geometry produced by the shape-pair routines, before persistence.

use glam::Vec3;

/// Maximum contact points per manifold.
pub const MAX_MANIFOLD_POINTS: usize = 4;

/// Capacity of the candidate buffer before reduction (clipping a polygon against a polygon).
pub const MAX_CANDIDATE_POINTS: usize = 32;

/// One candidate contact: point midway between the surfaces, signed separation along the
/// normal (negative = penetration, metres) and a feature id for warm-start matching
/// (`u32::MAX` = none).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RawPoint {
    /// Contact point in the pair frame.
    pub point: Vec3,
    /// Signed separation along the normal, metres.
    pub separation: f32,
    /// Feature id (`u32::MAX` when the routine has none).
    pub id: u32,
}

/// Contact geometry in the frame handed to the collision routine: unit normal from shape A
/// toward shape B and up to [`MAX_MANIFOLD_POINTS`] points.
#[derive(Clone, Debug, PartialEq)]
pub struct RawManifold {
    /// Unit normal from A to B.
    pub normal: Vec3,
    /// Points (at most [`MAX_MANIFOLD_POINTS`] after [`RawManifold::reduce`]).
    pub points: Vec<RawPoint>,
}

impl RawManifold {
    /// Empty manifold with a normal.
    #[must_use]
    pub fn new(normal: Vec3) -> Self {
        Self {
            normal,
            points: Vec::with_capacity(MAX_MANIFOLD_POINTS),
        }
    }

    /// Single-point manifold.
    #[must_use]
    pub fn single(normal: Vec3, point: Vec3, separation: f32, id: u32) -> Self {
        let mut m = Self::new(normal);
        m.points.push(RawPoint {
            point,
            separation,
            id,
        });
        m
    }

    /// Swaps the roles of A and B (negates the normal).
    pub fn flip(&mut self) {
        self.normal = -self.normal;
    }

    /// Keeps at most [`MAX_MANIFOLD_POINTS`] points: the deepest, the farthest from it, then
    /// the two that enlarge the contact polygon most (area in the normal plane).
    pub fn reduce(&mut self) {
        let pts = &mut self.points;
        if pts.len() <= MAX_MANIFOLD_POINTS {
            return;
        }
        let n = self.normal;
        let i0 = (0..pts.len())
            .min_by(|&a, &b| pts[a].separation.total_cmp(&pts[b].separation))
            .unwrap_or(0);
        let p0 = pts[i0].point;
        let i1 = (0..pts.len())
            .max_by(|&a, &b| {
                pts[a]
                    .point
                    .distance_squared(p0)
                    .total_cmp(&pts[b].point.distance_squared(p0))
            })
            .unwrap_or(0);
        let p1 = pts[i1].point;
        let area = |p: Vec3, a: Vec3, b: Vec3| (a - p).cross(b - p).dot(n);
        let i2 = (0..pts.len())
            .max_by(|&a, &b| {
                area(p0, p1, pts[a].point)
                    .abs()
                    .total_cmp(&area(p0, p1, pts[b].point).abs())
            })
            .unwrap_or(0);
        let p2 = pts[i2].point;
        // Orient the triangle counter-clockwise about n.
        let (q0, q1, q2) = if area(p0, p1, p2) >= 0.0 {
            (p0, p1, p2)
        } else {
            (p0, p2, p1)
        };
        let i3 = (0..pts.len())
            .filter(|&k| k != i0 && k != i1 && k != i2)
            .max_by(|&a, &b| {
                let outside = |p: Vec3| {
                    (-area(q0, q1, p))
                        .max(-area(q1, q2, p))
                        .max(-area(q2, q0, p))
                };
                outside(pts[a].point).total_cmp(&outside(pts[b].point))
            });
        let mut keep = vec![pts[i0], pts[i1], pts[i2]];
        if i1 == i0 || i2 == i0 || i2 == i1 {
            keep.dedup_by(|a, b| a.point == b.point);
        }
        if let Some(i3) = i3 {
            keep.push(pts[i3]);
        }
        keep.truncate(MAX_MANIFOLD_POINTS);
        *pts = keep;
    }
}
