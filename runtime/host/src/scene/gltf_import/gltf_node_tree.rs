//! [`NodeTree`]: the nodes of a glTF file's scene, walked once: who is whose parent, in which
//! order they are met, and the name each entity gets (unique among its siblings, so an
//! animation can find its target by the path of names below the imported root).

use std::collections::{HashMap, HashSet};

/// Deeper node chains than this are not walked (a malformed file's cycle or a chain made to
/// exhaust the stack).
pub const MAX_NODE_DEPTH: usize = 256;

/// The nodes of the default scene (else the first scene, else every node no other names as
/// a child), each met once.
pub struct NodeTree {
    /// Node indices in the order met, parents before children.
    pub order: Vec<usize>,
    /// The parent of each node met (`None`: a root of the scene), by node index.
    pub parent: HashMap<usize, Option<usize>>,
    /// The entity name of each node met: its own name, else `node N`; a name a sibling
    /// already has gets ` (node N)` added.
    pub names: HashMap<usize, String>,
}

impl NodeTree {
    /// Walks the scene of `document`. A node named twice (a cycle, or a child of two
    /// parents, which glTF forbids) is kept under the first parent met.
    pub fn new(document: &gltf::Document) -> Self {
        let roots: Vec<gltf::Node<'_>> = match document
            .default_scene()
            .or_else(|| document.scenes().next())
        {
            Some(scene) => scene.nodes().collect(),
            None => {
                let children: HashSet<usize> = document
                    .nodes()
                    .flat_map(|n| n.children().map(|c| c.index()).collect::<Vec<_>>())
                    .collect();
                document
                    .nodes()
                    .filter(|n| !children.contains(&n.index()))
                    .collect()
            }
        };
        let mut tree = Self {
            order: Vec::new(),
            parent: HashMap::new(),
            names: HashMap::new(),
        };
        let mut taken: HashMap<Option<usize>, HashSet<String>> = HashMap::new();
        // Depth-first, children in file order.
        let mut stack: Vec<(gltf::Node<'_>, Option<usize>, usize)> =
            roots.into_iter().rev().map(|n| (n, None, 0)).collect();
        while let Some((node, parent, depth)) = stack.pop() {
            let index = node.index();
            if depth > MAX_NODE_DEPTH || tree.parent.contains_key(&index) {
                continue;
            }
            let siblings = taken.entry(parent).or_default();
            let mut name = node
                .name()
                .filter(|n| !n.is_empty())
                .map_or_else(|| format!("node {index}"), str::to_owned);
            if !siblings.insert(name.clone()) {
                name = format!("{name} (node {index})");
                siblings.insert(name.clone());
            }
            tree.order.push(index);
            tree.parent.insert(index, parent);
            tree.names.insert(index, name);
            let children: Vec<_> = node.children().collect();
            stack.extend(
                children
                    .into_iter()
                    .rev()
                    .map(|c| (c, Some(index), depth + 1)),
            );
        }
        tree
    }

    /// The names from the scene's root down to `node` (the path an animation's channel uses
    /// to find its entity below the imported root); `None` for a node not in the scene.
    pub fn path_of(&self, node: usize) -> Option<Vec<String>> {
        let mut path = Vec::new();
        let mut at = Some(node);
        while let Some(index) = at {
            path.push(self.names.get(&index)?.clone());
            at = *self.parent.get(&index)?;
        }
        path.reverse();
        Some(path)
    }
}
