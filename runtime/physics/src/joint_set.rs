//! [`JointSet`]: flat generational storage of joints, and which body pairs they keep from
//! colliding.

use std::collections::HashMap;

use crate::body_handle::BodyHandle;
use crate::handle_set::HandleSet;
use crate::joint::Joint;
use crate::joint_handle::JointHandle;

/// The key of an unordered pair of body slots.
fn pair_key(a: u32, b: u32) -> u64 {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    u64::from(hi) << 32 | u64::from(lo)
}

/// All joints of a world, addressed by [`JointHandle`] (broken ones included until removed):
/// a [`HandleSet`] (through `Deref`: `get`, `len`, `iter`, …) plus the body pairs the joints
/// keep from colliding.
#[derive(Clone, Debug, Default)]
pub struct JointSet {
    joints: HandleSet<JointHandle, Joint>,
    /// Body-slot pairs joined by joints that do not let them collide, with how many.
    no_collide: HashMap<u64, u32>,
}

impl std::ops::Deref for JointSet {
    type Target = HandleSet<JointHandle, Joint>;
    fn deref(&self) -> &Self::Target {
        &self.joints
    }
}

impl std::ops::DerefMut for JointSet {
    fn deref_mut(&mut self) -> &mut Self::Target {
        &mut self.joints
    }
}

impl JointSet {
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
