//! [`JointSet`]: flat generational storage of joints, and which body pairs they keep from
//! colliding.

use std::collections::HashMap;

use crate::arena::Arena;
use crate::body_handle::BodyHandle;
use crate::joint::Joint;
use crate::joint_handle::JointHandle;

/// The key of an unordered pair of body slots.
fn pair_key(a: u32, b: u32) -> u64 {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    u64::from(hi) << 32 | u64::from(lo)
}

/// All joints of a world, addressed by [`JointHandle`].
#[derive(Clone, Debug, Default)]
pub struct JointSet {
    pub(crate) arena: Arena<Joint>,
    /// Body-slot pairs joined by joints that do not let them collide, with how many.
    no_collide: HashMap<u64, u32>,
}

impl JointSet {
    /// Joint behind a handle, if still alive.
    #[must_use]
    pub fn get(&self, h: JointHandle) -> Option<&Joint> {
        self.arena.get(h.index(), h.generation())
    }

    /// Number of joints (broken ones included until removed).
    #[must_use]
    pub fn len(&self) -> usize {
        self.arena.len()
    }

    /// True when there are no joints.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.arena.len() == 0
    }

    /// Iterates `(handle, joint)`.
    pub fn iter(&self) -> impl Iterator<Item = (JointHandle, &Joint)> {
        self.arena
            .iter()
            .map(|(i, g, j)| (JointHandle::from_parts(i, g), j))
    }

    /// Whether a joint keeps the bodies in slots `a` and `b` from colliding.
    #[inline]
    pub(crate) fn keeps_apart(&self, a: u32, b: u32) -> bool {
        !self.no_collide.is_empty() && self.no_collide.contains_key(&pair_key(a, b))
    }

    /// Counts a joint between `a` and `b` that does not let them collide (`add`), or no
    /// longer does (removed, broken).
    pub(crate) fn count_no_collide(&mut self, a: Option<BodyHandle>, b: BodyHandle, add: bool) {
        let Some(a) = a else {
            return;
        };
        let key = pair_key(a.index(), b.index());
        if add {
            *self.no_collide.entry(key).or_insert(0) += 1;
        } else if let Some(n) = self.no_collide.get_mut(&key) {
            *n -= 1;
            if *n == 0 {
                self.no_collide.remove(&key);
            }
        }
    }
}
