//! [`UnionFind`]: disjoint sets of solver bodies, for the sleep stage's islands and the
//! jointed groups whose mass damps the contacts under them.

/// Disjoint sets over `0..n` with path splitting; a union keeps the smaller root, so the
/// root of a set does not depend on the order of the unions within it.
#[derive(Debug, Default)]
pub(crate) struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    /// `n` singleton sets.
    pub(crate) fn new(n: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
        }
    }

    /// Back to `n` singleton sets, keeping the allocation.
    pub(crate) fn reset(&mut self, n: usize) {
        self.parent.clear();
        self.parent.extend(0..n as u32);
    }

    /// The root of `x`'s set.
    pub(crate) fn find(&mut self, mut x: u32) -> u32 {
        let parent = &mut self.parent;
        while parent[x as usize] != x {
            let p = parent[x as usize];
            parent[x as usize] = parent[p as usize];
            x = p;
        }
        x
    }

    /// Joins the sets of `a` and `b`.
    pub(crate) fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.parent[ra.max(rb) as usize] = ra.min(rb);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unions_join_sets_under_their_smallest_member() {
        let mut sets = UnionFind::new(6);
        sets.union(3, 5);
        sets.union(5, 1);
        sets.union(4, 2);
        let roots: Vec<u32> = (0..6).map(|i| sets.find(i)).collect();
        assert_eq!(roots, vec![0, 1, 2, 1, 2, 1]);
    }
}
