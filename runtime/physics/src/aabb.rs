//! [`Aabb`]: axis-aligned bounding box.

use glam::Vec3;

/// Axis-aligned bounding box in metres; `min <= max` component-wise when valid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Minimum corner.
    pub min: Vec3,
    /// Maximum corner.
    pub max: Vec3,
}

impl Aabb {
    /// Builds a box from its corners.
    #[must_use]
    pub fn new(min: Vec3, max: Vec3) -> Self {
        Self { min, max }
    }

    /// Box centred at `center` with half extents `half`.
    #[must_use]
    pub fn from_center_half(center: Vec3, half: Vec3) -> Self {
        Self {
            min: center - half,
            max: center + half,
        }
    }

    /// Smallest box holding every point (an empty iterator gives a degenerate box at the origin).
    #[must_use]
    pub fn from_points(points: impl IntoIterator<Item = Vec3>) -> Self {
        let mut it = points.into_iter();
        let Some(first) = it.next() else {
            return Self::new(Vec3::ZERO, Vec3::ZERO);
        };
        let mut b = Self::new(first, first);
        for p in it {
            b.min = b.min.min(p);
            b.max = b.max.max(p);
        }
        b
    }

    /// True when the boxes overlap (touching counts).
    #[inline]
    #[must_use]
    pub fn intersects(&self, other: &Aabb) -> bool {
        self.min.cmple(other.max).all() && other.min.cmple(self.max).all()
    }

    /// True when `other` lies entirely inside `self`.
    #[inline]
    #[must_use]
    pub fn contains(&self, other: &Aabb) -> bool {
        self.min.cmple(other.min).all() && other.max.cmple(self.max).all()
    }

    /// True when the point is inside or on the boundary.
    #[inline]
    #[must_use]
    pub fn contains_point(&self, p: Vec3) -> bool {
        self.min.cmple(p).all() && p.cmple(self.max).all()
    }

    /// Smallest box holding both.
    #[inline]
    #[must_use]
    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// Box grown by `margin` on every side.
    #[inline]
    #[must_use]
    pub fn expanded(&self, margin: f32) -> Aabb {
        Aabb {
            min: self.min - Vec3::splat(margin),
            max: self.max + Vec3::splat(margin),
        }
    }

    /// Sum of the edge lengths times 4, halved: the "perimeter" used as tree cost.
    #[inline]
    #[must_use]
    pub fn perimeter(&self) -> f32 {
        let d = self.max - self.min;
        2.0 * (d.x + d.y + d.z)
    }

    /// Centre point.
    #[inline]
    #[must_use]
    pub fn center(&self) -> Vec3 {
        (self.min + self.max) * 0.5
    }

    /// Half extents.
    #[inline]
    #[must_use]
    pub fn half_extents(&self) -> Vec3 {
        (self.max - self.min) * 0.5
    }

    /// Slab test: the entry parameter `t` in `[0, max_t]` of the ray `origin + t * dir`, if it hits.
    #[must_use]
    pub fn ray_entry(&self, origin: Vec3, inv_dir: Vec3, max_t: f32) -> Option<f32> {
        let t1 = (self.min - origin) * inv_dir;
        let t2 = (self.max - origin) * inv_dir;
        // NaN from 0 * inf (origin on a slab plane, axis-parallel ray) is dropped by min/max.
        let tmin = t1.min(t2).max_element().max(0.0);
        let tmax = t1.max(t2).min_element().min(max_t);
        (tmin <= tmax).then_some(tmin)
    }
}
