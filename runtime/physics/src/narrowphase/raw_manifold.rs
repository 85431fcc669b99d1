//! [`RawManifold`]: contact geometry produced by the shape-pair routines, before persistence.

use glam::Vec3;

/// Maximum contact points per manifold.
pub const MAX_MANIFOLD_POINTS: usize = 4;

/// Capacity of the candidate buffer before reduction (clipping a polygon against a polygon).
pub const MAX_CANDIDATE_POINTS: usize = 32;

/// Which point a manifold's reduction to [`MAX_MANIFOLD_POINTS`] starts from
/// ([`RawManifold::reduce`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReduceFrom {
    /// The deepest point: the support that matters most where friction holds the face.
    Deepest,
    /// The point farthest from the points' centre in the normal plane: which points are kept
    /// depends on where they are, not on micro-radians of rocking. For frictionless faces,
    /// which only their geometry holds (as they keep their normal through a small turn,
    /// `FRICTIONLESS_NORMAL_HOLD_ANGLE`).
    Outermost,
}

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

    /// Keeps at most [`MAX_MANIFOLD_POINTS`] points: the first chosen by `from`, the
    /// farthest from it, then the two that enlarge the contact polygon most (area in the
    /// normal plane).
    ///
    /// The face of a box turned on the box under it clips to an octagon, and a face that
    /// rocks by micro-radians changes which corner is deepest each half period. Started from
    /// the deepest point, the kept four change with it, and the face's points (and their
    /// warm-started impulses) swap sides in step with the rocking and feed it: a frictionless
    /// column of ten 1 m boxes, each turned by up to 0.47 rad about the vertical, rocked
    /// apart within 2 s at fast, and three 10 cm boxes so turned and offset within 0.3 s.
    /// Frictionless faces therefore start from the outermost point ([`ReduceFrom::Outermost`];
    /// a planar face's depth is linear over it, so the deepest point is a corner of the
    /// polygon and the largest quadrilateral keeps it or a point beside it). Faces with
    /// friction keep the deepest: started from the outermost, the 100-row pyramid at
    /// balanced slumped 0.689 m on average over ten starts, against 0.662 m from the
    /// deepest (rapier 0.684 m).
    pub fn reduce(&mut self, from: ReduceFrom) {
        let pts = &mut self.points;
        if pts.len() <= MAX_MANIFOLD_POINTS {
            return;
        }
        let n = self.normal;
        let i0 = match from {
            ReduceFrom::Deepest => (0..pts.len())
                .min_by(|&a, &b| pts[a].separation.total_cmp(&pts[b].separation))
                .unwrap_or(0),
            ReduceFrom::Outermost => {
                let centre = pts.iter().map(|p| p.point).sum::<Vec3>() / pts.len() as f32;
                let reach = |p: Vec3| {
                    let d = p - centre;
                    (d - n * d.dot(n)).length_squared()
                };
                (0..pts.len())
                    .max_by(|&a, &b| reach(pts[a].point).total_cmp(&reach(pts[b].point)))
                    .unwrap_or(0)
            }
        };
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
