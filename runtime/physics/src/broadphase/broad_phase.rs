//! [`BroadPhase`]: finds new candidate pairs by querying moved proxies against a dynamic tree.

use glam::Vec3;

use crate::aabb::Aabb;

use super::dynamic_tree::DynamicTree;

/// A proxy's fat-box margin is at most this fraction of its smallest half extent (a 0.1 m
/// margin around 0.1 m spheres made each sphere's fat box 8× its volume, and the pile of
/// 8,000 spheres carried ~3× more candidate pairs than touching ones).
pub const AABB_MARGIN_SIZE_FRACTION: f32 = 0.25;

/// The margin used for a proxy of tight box `tight`: `min(margin, fraction × smallest half
/// extent)`.
#[must_use]
pub fn scaled_margin(tight: &Aabb, margin: f32) -> f32 {
    margin.min(AABB_MARGIN_SIZE_FRACTION * tight.half_extents().min_element())
}

/// Proxy tree plus the list of proxies that left their fat box since the last pair search.
///
/// Only moved proxies are queried, so resting or sleeping bodies cost nothing; each query is
/// O(log n), giving O(m log n) per step for m movers (O(n log n) worst case).
#[derive(Clone, Debug, Default)]
pub struct BroadPhase {
    pub(crate) tree: DynamicTree,
    moved: Vec<u32>,
    moved_flag: Vec<bool>,
    /// The proxies the last pair search was for, and the same as flags by proxy id.
    searched: Vec<u32>,
    searched_flag: Vec<bool>,
}

impl BroadPhase {
    /// Adds a proxy for a tight box, enlarged by `margin` (see [`scaled_margin`]); returns
    /// its id.
    pub fn create_proxy(&mut self, tight: Aabb, margin: f32, data: u32) -> u32 {
        let p = self
            .tree
            .insert(tight.expanded(scaled_margin(&tight, margin)), data);
        self.mark_moved(p);
        p
    }

    /// Removes a proxy.
    pub fn destroy_proxy(&mut self, proxy: u32) {
        if let Some(f) = self.moved_flag.get_mut(proxy as usize) {
            if *f {
                *f = false;
                self.moved.retain(|&m| m != proxy);
            }
        }
        self.tree.remove(proxy);
    }

    /// Updates a proxy's tight box; re-inserts (and schedules a pair search) only when it
    /// left its fat box.
    pub fn update_proxy(&mut self, proxy: u32, tight: Aabb, margin: f32, displacement: Vec3) {
        if self
            .tree
            .move_proxy(proxy, tight, scaled_margin(&tight, margin), displacement)
        {
            self.mark_moved(proxy);
        }
    }

    fn mark_moved(&mut self, proxy: u32) {
        let i = proxy as usize;
        if self.moved_flag.len() <= i {
            self.moved_flag.resize(i + 1, false);
        }
        if !self.moved_flag[i] {
            self.moved_flag[i] = true;
            self.moved.push(proxy);
        }
    }

    /// Number of proxies waiting for a pair search.
    #[must_use]
    pub fn moved_count(&self) -> usize {
        self.moved.len()
    }

    /// Appends `(data_a, data_b)` for every pair of overlapping fat boxes where at least one
    /// proxy moved. Pairs may repeat ones that already exist; the caller deduplicates.
    pub fn find_pairs(&mut self, out: &mut Vec<(u32, u32)>) {
        for &p in &self.moved {
            let fat = self.tree.fat_aabb(p);
            let my = self.tree.data(p);
            let flags = &self.moved_flag;
            self.tree.query(&fat, |other, data| {
                // Both moved: only the lower proxy id reports the pair.
                if other != p && !(flags[other as usize] && other < p) {
                    out.push((my, data));
                }
                true
            });
        }
        for &p in &self.searched {
            self.searched_flag[p as usize] = false;
        }
        for &p in &self.moved {
            self.moved_flag[p as usize] = false;
            let i = p as usize;
            if self.searched_flag.len() <= i {
                self.searched_flag.resize(i + 1, false);
            }
            self.searched_flag[i] = true;
        }
        std::mem::swap(&mut self.searched, &mut self.moved);
        self.moved.clear();
    }

    /// Whether the proxy's fat box changed before the last pair search (it moved out of its
    /// fat box, or is new). Two proxies that overlapped when their pair was found and did
    /// not change since still overlap: the narrowphase tests pairs only when this is true
    /// for one of them.
    #[must_use]
    pub fn moved_before_last_search(&self, proxy: u32) -> bool {
        self.searched_flag
            .get(proxy as usize)
            .copied()
            .unwrap_or(false)
    }

    /// Fat box of a proxy.
    #[must_use]
    pub fn fat_aabb(&self, proxy: u32) -> Aabb {
        self.tree.fat_aabb(proxy)
    }

    /// The underlying tree.
    #[must_use]
    pub fn tree(&self) -> &DynamicTree {
        &self.tree
    }
}
