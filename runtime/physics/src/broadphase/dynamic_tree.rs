//! [`DynamicTree`]: incremental AABB tree with enlarged leaves (insert/remove/move in O(log n)).

use glam::Vec3;

use crate::aabb::Aabb;

const NULL: u32 = u32::MAX;

/// Depth bound of the traversal stacks. The tree is height-balanced (AVL rotations), so
/// 2^(MAX_DEPTH/1.44) leaves fit; deeper trees fall back to a heap stack.
const STACK_DEPTH: usize = 128;

#[derive(Clone, Debug)]
struct Node {
    aabb: Aabb,
    parent: u32,
    child1: u32,
    child2: u32,
    /// Leaf = 0, free = -1.
    height: i32,
    data: u32,
}

impl Node {
    fn is_leaf(&self) -> bool {
        self.child1 == NULL
    }
}

/// Bounding-volume tree of enlarged ("fat") boxes. Leaves carry a user `u32`.
#[derive(Clone, Debug)]
pub struct DynamicTree {
    nodes: Vec<Node>,
    root: u32,
    free: Vec<u32>,
    leaf_count: usize,
}

impl Default for DynamicTree {
    fn default() -> Self {
        Self::new()
    }
}

impl DynamicTree {
    /// Empty tree.
    #[must_use]
    pub fn new() -> Self {
        Self {
            nodes: Vec::new(),
            root: NULL,
            free: Vec::new(),
            leaf_count: 0,
        }
    }

    fn alloc(&mut self) -> u32 {
        let node = Node {
            aabb: Aabb::new(Vec3::ZERO, Vec3::ZERO),
            parent: NULL,
            child1: NULL,
            child2: NULL,
            height: 0,
            data: 0,
        };
        if let Some(i) = self.free.pop() {
            self.nodes[i as usize] = node;
            i
        } else {
            self.nodes.push(node);
            (self.nodes.len() - 1) as u32
        }
    }

    fn release(&mut self, i: u32) {
        self.nodes[i as usize].height = -1;
        self.free.push(i);
    }

    /// Number of leaves.
    #[must_use]
    pub fn len(&self) -> usize {
        self.leaf_count
    }

    /// True when the tree has no leaves.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.leaf_count == 0
    }

    /// Fat box of a leaf.
    #[must_use]
    pub fn fat_aabb(&self, proxy: u32) -> Aabb {
        self.nodes[proxy as usize].aabb
    }

    /// User data of a leaf.
    #[must_use]
    pub fn data(&self, proxy: u32) -> u32 {
        self.nodes[proxy as usize].data
    }

    /// Inserts a leaf with the given (already enlarged) box; returns its proxy id.
    pub fn insert(&mut self, fat: Aabb, data: u32) -> u32 {
        let leaf = self.alloc();
        self.nodes[leaf as usize].aabb = fat;
        self.nodes[leaf as usize].data = data;
        self.insert_leaf(leaf);
        self.leaf_count += 1;
        leaf
    }

    /// Removes a leaf.
    pub fn remove(&mut self, proxy: u32) {
        self.remove_leaf(proxy);
        self.release(proxy);
        self.leaf_count -= 1;
    }

    /// Moves a leaf if `tight` left its fat box; the new fat box is `tight` grown by `margin`
    /// and stretched by `displacement` (predicted motion). Returns true when the leaf moved.
    pub fn move_proxy(&mut self, proxy: u32, tight: Aabb, margin: f32, displacement: Vec3) -> bool {
        if self.nodes[proxy as usize].aabb.contains(&tight) {
            return false;
        }
        self.remove_leaf(proxy);
        let mut fat = tight.expanded(margin);
        fat.min += displacement.min(Vec3::ZERO);
        fat.max += displacement.max(Vec3::ZERO);
        self.nodes[proxy as usize].aabb = fat;
        self.insert_leaf(proxy);
        true
    }

    fn insert_leaf(&mut self, leaf: u32) {
        if self.root == NULL {
            self.root = leaf;
            self.nodes[leaf as usize].parent = NULL;
            return;
        }
        let leaf_box = self.nodes[leaf as usize].aabb;
        // Descend choosing the cheaper child by the perimeter heuristic.
        let mut index = self.root;
        while !self.nodes[index as usize].is_leaf() {
            let n = &self.nodes[index as usize];
            let (c1, c2) = (n.child1, n.child2);
            let area = n.aabb.perimeter();
            let combined = n.aabb.union(&leaf_box).perimeter();
            let cost = 2.0 * combined;
            let inherit = 2.0 * (combined - area);
            let child_cost = |c: u32| {
                let cb = &self.nodes[c as usize];
                let u = leaf_box.union(&cb.aabb).perimeter();
                if cb.is_leaf() {
                    u + inherit
                } else {
                    u - cb.aabb.perimeter() + inherit
                }
            };
            let cost1 = child_cost(c1);
            let cost2 = child_cost(c2);
            if cost < cost1 && cost < cost2 {
                break;
            }
            index = if cost1 < cost2 { c1 } else { c2 };
        }
        let sibling = index;
        let old_parent = self.nodes[sibling as usize].parent;
        let new_parent = self.alloc();
        {
            let sb = self.nodes[sibling as usize].aabb;
            let sh = self.nodes[sibling as usize].height;
            let np = &mut self.nodes[new_parent as usize];
            np.parent = old_parent;
            np.aabb = leaf_box.union(&sb);
            np.height = sh + 1;
            np.child1 = sibling;
            np.child2 = leaf;
        }
        if old_parent != NULL {
            let op = &mut self.nodes[old_parent as usize];
            if op.child1 == sibling {
                op.child1 = new_parent;
            } else {
                op.child2 = new_parent;
            }
        } else {
            self.root = new_parent;
        }
        self.nodes[sibling as usize].parent = new_parent;
        self.nodes[leaf as usize].parent = new_parent;
        self.refit_from(new_parent);
    }

    fn refit_from(&mut self, mut index: u32) {
        while index != NULL {
            index = self.balance(index);
            let (c1, c2) = {
                let n = &self.nodes[index as usize];
                (n.child1, n.child2)
            };
            let h = 1 + self.nodes[c1 as usize]
                .height
                .max(self.nodes[c2 as usize].height);
            let b = self.nodes[c1 as usize]
                .aabb
                .union(&self.nodes[c2 as usize].aabb);
            let n = &mut self.nodes[index as usize];
            n.height = h;
            n.aabb = b;
            index = n.parent;
        }
    }

    fn remove_leaf(&mut self, leaf: u32) {
        if leaf == self.root {
            self.root = NULL;
            return;
        }
        let parent = self.nodes[leaf as usize].parent;
        let grand = self.nodes[parent as usize].parent;
        let sibling = if self.nodes[parent as usize].child1 == leaf {
            self.nodes[parent as usize].child2
        } else {
            self.nodes[parent as usize].child1
        };
        if grand != NULL {
            let g = &mut self.nodes[grand as usize];
            if g.child1 == parent {
                g.child1 = sibling;
            } else {
                g.child2 = sibling;
            }
            self.nodes[sibling as usize].parent = grand;
            self.release(parent);
            self.refit_from(grand);
        } else {
            self.root = sibling;
            self.nodes[sibling as usize].parent = NULL;
            self.release(parent);
        }
    }

    /// AVL-style rotation when the children's heights differ by more than one.
    /// Returns the index now at `a`'s position.
    fn balance(&mut self, a: u32) -> u32 {
        let na = &self.nodes[a as usize];
        if na.is_leaf() || na.height < 2 {
            return a;
        }
        let (b, c) = (na.child1, na.child2);
        let bal = self.nodes[c as usize].height - self.nodes[b as usize].height;
        if bal > 1 {
            self.rotate_up(a, c, b)
        } else if bal < -1 {
            self.rotate_up(a, b, c)
        } else {
            a
        }
    }

    /// Promotes the taller child `up` of `a` (other child `keep`); returns `up`.
    fn rotate_up(&mut self, a: u32, up: u32, keep: u32) -> u32 {
        let (f, g) = {
            let n = &self.nodes[up as usize];
            (n.child1, n.child2)
        };
        let a_parent = self.nodes[a as usize].parent;
        // `up` takes `a`'s place.
        self.nodes[up as usize].child1 = a;
        self.nodes[up as usize].parent = a_parent;
        self.nodes[a as usize].parent = up;
        if a_parent != NULL {
            let p = &mut self.nodes[a_parent as usize];
            if p.child1 == a {
                p.child1 = up;
            } else {
                p.child2 = up;
            }
        } else {
            self.root = up;
        }
        // The taller grandchild stays under `up`, the shorter goes to `a`.
        let (stay, go) = if self.nodes[f as usize].height > self.nodes[g as usize].height {
            (f, g)
        } else {
            (g, f)
        };
        self.nodes[up as usize].child2 = stay;
        if self.nodes[a as usize].child1 == up {
            self.nodes[a as usize].child1 = go;
        } else {
            self.nodes[a as usize].child2 = go;
        }
        self.nodes[go as usize].parent = a;
        let ab = self.nodes[keep as usize]
            .aabb
            .union(&self.nodes[go as usize].aabb);
        let ah = 1 + self.nodes[keep as usize]
            .height
            .max(self.nodes[go as usize].height);
        self.nodes[a as usize].aabb = ab;
        self.nodes[a as usize].height = ah;
        let ub = ab.union(&self.nodes[stay as usize].aabb);
        let uh = 1 + ah.max(self.nodes[stay as usize].height);
        self.nodes[up as usize].aabb = ub;
        self.nodes[up as usize].height = uh;
        up
    }

    /// Calls `f(proxy, data)` for each leaf whose fat box overlaps `aabb`; stop early by
    /// returning false.
    pub fn query(&self, aabb: &Aabb, mut f: impl FnMut(u32, u32) -> bool) {
        if self.root == NULL {
            return;
        }
        let mut stack: Vec<u32> = Vec::with_capacity(STACK_DEPTH);
        stack.push(self.root);
        while let Some(i) = stack.pop() {
            let n = &self.nodes[i as usize];
            if !n.aabb.intersects(aabb) {
                continue;
            }
            if n.is_leaf() {
                if !f(i, n.data) {
                    return;
                }
            } else {
                stack.push(n.child1);
                stack.push(n.child2);
            }
        }
    }

    /// Calls `f(proxy, data)` for leaves whose fat box the ray `origin + t dir`, `t <= max_t`,
    /// crosses. `f` returns the new `max_t` (return the old one to keep going, a negative
    /// value to stop).
    pub fn ray_query(
        &self,
        origin: Vec3,
        dir: Vec3,
        max_t: f32,
        mut f: impl FnMut(u32, u32) -> f32,
    ) {
        if self.root == NULL {
            return;
        }
        let inv = dir.recip();
        let mut max_t = max_t;
        let mut stack: Vec<u32> = Vec::with_capacity(STACK_DEPTH);
        stack.push(self.root);
        while let Some(i) = stack.pop() {
            let n = &self.nodes[i as usize];
            if n.aabb.ray_entry(origin, inv, max_t).is_none() {
                continue;
            }
            if n.is_leaf() {
                max_t = f(i, n.data);
                if max_t < 0.0 {
                    return;
                }
            } else {
                stack.push(n.child1);
                stack.push(n.child2);
            }
        }
    }

    /// Height of the tree (0 for a single leaf or empty tree).
    #[must_use]
    pub fn height(&self) -> i32 {
        if self.root == NULL {
            0
        } else {
            self.nodes[self.root as usize].height
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    impl DynamicTree {
        /// Checks parent links, heights and box containment; returns the leaf count.
        fn validate(&self) -> usize {
            if self.root == NULL {
                return 0;
            }
            assert_eq!(self.nodes[self.root as usize].parent, NULL);
            let mut leaves = 0;
            let mut stack = vec![self.root];
            let mut seen = 0;
            while let Some(i) = stack.pop() {
                seen += 1;
                assert!(seen <= self.nodes.len(), "cycle in tree");
                let n = &self.nodes[i as usize];
                assert!(n.height >= 0, "free node {i} reachable");
                if n.is_leaf() {
                    assert_eq!(n.height, 0);
                    leaves += 1;
                    continue;
                }
                let (c1, c2) = (n.child1, n.child2);
                assert_ne!(c1, i);
                assert_ne!(c2, i);
                assert_eq!(
                    self.nodes[c1 as usize].parent, i,
                    "child1 parent link of {i}"
                );
                assert_eq!(
                    self.nodes[c2 as usize].parent, i,
                    "child2 parent link of {i}"
                );
                let h1 = self.nodes[c1 as usize].height;
                let h2 = self.nodes[c2 as usize].height;
                assert_eq!(n.height, 1 + h1.max(h2), "height of {i}");
                assert!(n.aabb.contains(&self.nodes[c1 as usize].aabb));
                assert!(n.aabb.contains(&self.nodes[c2 as usize].aabb));
                stack.push(c1);
                stack.push(c2);
            }
            leaves
        }
    }

    #[test]
    fn default_tree_is_empty() {
        let mut t = DynamicTree::default();
        t.insert(Aabb::new(Vec3::ZERO, Vec3::ONE), 0);
        t.insert(Aabb::new(Vec3::ONE, Vec3::splat(2.0)), 1);
        assert_eq!(t.validate(), 2);
    }

    #[test]
    fn random_insert_move_remove_keeps_tree_valid() {
        let mut seed = 12345u64;
        let mut rnd = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 33) as f32) / (1u64 << 31) as f32
        };
        let mut t = DynamicTree::new();
        let mut live: Vec<u32> = Vec::new();
        for step in 0..3000 {
            let r = rnd();
            if r < 0.4 || live.len() < 3 {
                let c = Vec3::new(rnd() * 100.0, rnd() * 100.0, rnd() * 100.0);
                let b = Aabb::from_center_half(c, Vec3::splat(rnd() + 0.1));
                live.push(t.insert(b.expanded(0.1), step));
            } else if r < 0.8 {
                let k = (rnd() * live.len() as f32) as usize % live.len();
                let c = Vec3::new(rnd() * 100.0, rnd() * 100.0, rnd() * 100.0);
                let b = Aabb::from_center_half(c, Vec3::splat(0.5));
                t.move_proxy(live[k], b, 0.1, Vec3::ZERO);
            } else {
                let k = (rnd() * live.len() as f32) as usize % live.len();
                t.remove(live.swap_remove(k));
            }
            assert_eq!(t.validate(), live.len(), "leaf count after step {step}");
        }
        assert!(
            t.height() < 40,
            "tree height {} too large for {} leaves",
            t.height(),
            live.len()
        );
    }
}
