//! [`TransformHierarchy`]: who is whose child, and every child's world pose, recomputed only
//! for the subtrees that changed.

use onyx_plugin_api::glam::Affine3A;
use onyx_plugin_api::{Parent, Transform};

use crate::entity_map::EntityMap;

/// Above this share of dirty nodes, a propagation recomputes every node in one pass over the
/// parents-first order instead of walking each dirty subtree (which first checks that no
/// ancestor is dirty too).
const FULL_PASS_DIRTY_SHARE: usize = 4;

/// One entity with a parent or children (an entity with neither is not a node: its world pose
/// is its local transform).
#[derive(Clone, Debug)]
struct Node {
    parent: Option<hecs::Entity>,
    children: Vec<hecs::Entity>,
    /// Local-to-world, valid after [`TransformHierarchy::propagate`] unless `dirty`.
    world: Affine3A,
    /// Its local transform, or an ancestor's, changed since the last propagation.
    dirty: bool,
}

impl Node {
    fn new() -> Self {
        Self {
            parent: None,
            children: Vec::new(),
            world: Affine3A::IDENTITY,
            dirty: true,
        }
    }
}

/// The scene graph's index over the world's [`Parent`] components, and the world pose of
/// every entity in it.
///
/// The world stays the source of truth: a [`Parent`] component makes a child, a
/// [`Transform`] its local pose. The host tells the hierarchy what changed — a local pose
/// ([`TransformHierarchy::moved`]), a parent ([`TransformHierarchy::attach`],
/// [`TransformHierarchy::detach`]), a despawn, or "anything may have" ([`TransformHierarchy::invalidate`])
/// — and [`TransformHierarchy::propagate`] recomputes the world poses of the changed subtrees
/// only. A frame in which nothing moved costs nothing; an entity in no hierarchy costs
/// nothing ever.
///
/// World poses are affine matrices: a non-uniform scale under a rotated parent shears, which
/// no translation/rotation/scale triple can hold.
#[derive(Debug, Default)]
pub struct TransformHierarchy {
    nodes: EntityMap<Node>,
    /// Nodes marked dirty since the last propagation (may hold despawned entities).
    dirty: Vec<hecs::Entity>,
    /// The index must be rebuilt from the world's `Parent` components.
    stale: bool,
    /// Every node, parents before children, while `order_valid`.
    order: Vec<hecs::Entity>,
    order_valid: bool,
}

impl TransformHierarchy {
    /// An empty hierarchy.
    pub fn new() -> Self {
        Self::default()
    }

    /// Forgets the index: the next [`TransformHierarchy::propagate`] rebuilds it from the
    /// world's `Parent` components and recomputes every world pose (after the world was
    /// replaced, restored, or edited directly).
    pub fn invalidate(&mut self) {
        self.stale = true;
    }

    /// Number of entities with a parent or children.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether no entity has a parent.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The local transform of `entity` changed (or was added or removed).
    pub fn moved(&mut self, entity: hecs::Entity) {
        if let Some(node) = self.nodes.get_mut(entity) {
            if !node.dirty {
                node.dirty = true;
                self.dirty.push(entity);
            }
        }
    }

    /// `child` now has the parent `parent` (its `Parent` component was written). The caller
    /// has checked that this makes no cycle.
    pub fn attach(&mut self, child: hecs::Entity, parent: hecs::Entity) {
        if self
            .nodes
            .get(child)
            .is_some_and(|n| n.parent == Some(parent))
        {
            self.moved(child);
            return;
        }
        self.unlink_from_parent(child);
        self.node(parent).children.push(child);
        let node = self.node(child);
        node.parent = Some(parent);
        node.dirty = true;
        self.dirty.push(child);
        self.order_valid = false;
    }

    /// `child` lost its parent (its `Parent` component was removed).
    pub fn detach(&mut self, child: hecs::Entity) {
        self.unlink_from_parent(child);
        self.moved(child);
        self.forget_if_alone(child);
    }

    /// `entity` was despawned. Its children must have been detached (or despawned) first.
    pub fn despawned(&mut self, entity: hecs::Entity) {
        self.unlink_from_parent(entity);
        if let Some(node) = self.nodes.remove(entity) {
            for child in node.children {
                if let Some(c) = self.nodes.get_mut(child) {
                    c.parent = None;
                }
                self.moved(child);
                self.forget_if_alone(child);
            }
        }
        self.order_valid = false;
    }

    /// The parent of `entity` in the index.
    pub fn parent(&self, entity: hecs::Entity) -> Option<hecs::Entity> {
        self.nodes.get(entity).and_then(|n| n.parent)
    }

    /// The children of `entity`, in the order they were attached.
    pub fn children(&self, entity: hecs::Entity) -> &[hecs::Entity] {
        self.nodes.get(entity).map_or(&[], |n| &n.children)
    }

    /// `entity` and all its descendants, parents before children.
    pub fn subtree(&self, entity: hecs::Entity) -> Vec<hecs::Entity> {
        let mut out = vec![entity];
        let mut i = 0;
        while i < out.len() {
            out.extend_from_slice(self.children(out[i]));
            i += 1;
        }
        out
    }

    /// The world pose of `entity` as of the last propagation; `local` is its transform (its
    /// world pose when it is in no hierarchy).
    pub fn world_of(&self, entity: hecs::Entity, local: &Transform) -> Affine3A {
        match self.nodes.get(entity) {
            Some(node) => node.world,
            None => local.affine(),
        }
    }

    /// The cached world pose of `entity`, if it is in a hierarchy.
    pub fn cached_world(&self, entity: hecs::Entity) -> Option<Affine3A> {
        self.nodes.get(entity).map(|n| n.world)
    }

    /// Whether the next propagation has work to do.
    pub fn needs_propagation(&self) -> bool {
        self.stale || !self.dirty.is_empty()
    }

    /// Rebuilds the index from `world` if it was invalidated (world poses are recomputed
    /// at the next propagation).
    pub fn refresh_index(&mut self, world: &hecs::World) {
        if self.stale {
            self.rebuild(world);
        }
    }

    /// Brings every world pose up to date with `world`: rebuilds the index when it was
    /// invalidated, else recomputes the subtrees that changed. Nothing changed: no work.
    pub fn propagate(&mut self, world: &hecs::World) {
        self.refresh_index(world);
        if self.dirty.is_empty() {
            return;
        }
        let locals = world.view::<&Transform>();
        let local = |e: hecs::Entity| locals.get(e).map_or(Affine3A::IDENTITY, |t| t.affine());
        if self.dirty.len() * FULL_PASS_DIRTY_SHARE > self.nodes.len() {
            self.full_pass(local);
            return;
        }
        let dirty = std::mem::take(&mut self.dirty);
        let mut stack = Vec::new();
        for &entity in &dirty {
            if !self.nodes.get(entity).is_some_and(|n| n.dirty) || self.ancestor_dirty(entity) {
                continue; // done already, despawned, or its dirty ancestor's pass covers it
            }
            stack.push(entity);
            while let Some(e) = stack.pop() {
                let parent_world = self.parent_world(e);
                let Some(node) = self.nodes.get_mut(e) else {
                    continue;
                };
                node.world = parent_world * local(e);
                node.dirty = false;
                stack.extend_from_slice(&node.children);
            }
        }
        self.dirty = dirty;
        self.dirty.clear();
    }

    fn full_pass(&mut self, local: impl Fn(hecs::Entity) -> Affine3A) {
        if !self.order_valid {
            self.rebuild_order();
        }
        for &e in &self.order {
            let parent_world = self.parent_world(e);
            if let Some(node) = self.nodes.get_mut(e) {
                node.world = parent_world * local(e);
                node.dirty = false;
            }
        }
        self.dirty.clear();
    }

    fn parent_world(&self, entity: hecs::Entity) -> Affine3A {
        self.parent(entity)
            .and_then(|p| self.nodes.get(p))
            .map_or(Affine3A::IDENTITY, |p| p.world)
    }

    fn ancestor_dirty(&self, entity: hecs::Entity) -> bool {
        let mut at = self.parent(entity);
        while let Some(e) = at {
            let Some(node) = self.nodes.get(e) else {
                return false;
            };
            if node.dirty {
                return true;
            }
            at = node.parent;
        }
        false
    }

    fn rebuild_order(&mut self) {
        self.order.clear();
        let roots = self
            .nodes
            .iter()
            .filter(|(_, n)| n.parent.is_none())
            .map(|(e, _)| e);
        self.order.extend(roots);
        let mut i = 0;
        while i < self.order.len() {
            let e = self.order[i];
            if let Some(node) = self.nodes.get(e) {
                self.order.extend_from_slice(&node.children);
            }
            i += 1;
        }
        self.order_valid = true;
    }

    /// Rebuilds the index from the world's `Parent` components. A parent that does not exist
    /// and an edge that would close a cycle are ignored (with a warning): the world was
    /// edited past the checks (`Host::world_mut`).
    fn rebuild(&mut self, world: &hecs::World) {
        self.nodes = EntityMap::default();
        self.dirty.clear();
        self.order_valid = false;
        self.stale = false;
        let mut edges: Vec<(hecs::Entity, hecs::Entity)> = world
            .query::<(hecs::Entity, &Parent)>()
            .iter()
            .filter_map(|(child, parent)| {
                let parent = crate::entity_id::to_hecs(parent.0);
                match parent {
                    Some(p) if world.contains(p) && p != child => Some((child, p)),
                    _ => {
                        tracing::warn!(
                            entity = %crate::entity_id::to_api(child),
                            "its Parent names an entity that does not exist; treated as a root"
                        );
                        None
                    }
                }
            })
            .collect();
        // Attach in a stable order (by entity), so children keep a deterministic order.
        edges.sort_by_key(|(child, _)| child.to_bits());
        for (child, parent) in edges {
            if self.is_ancestor_or_self(child, parent) {
                tracing::warn!(
                    entity = %crate::entity_id::to_api(child),
                    "its Parent would close a cycle; treated as a root"
                );
                continue;
            }
            self.attach(child, parent);
        }
        // Every node is recomputed: mark them all.
        let all: Vec<hecs::Entity> = self.nodes.iter().map(|(e, _)| e).collect();
        for e in all {
            if let Some(node) = self.nodes.get_mut(e) {
                node.dirty = true;
            }
        }
        self.dirty = self.nodes.iter().map(|(e, _)| e).collect();
    }

    /// Whether `ancestor` is `entity` or one of its ancestors in the index.
    fn is_ancestor_or_self(&self, ancestor: hecs::Entity, entity: hecs::Entity) -> bool {
        let mut at = Some(entity);
        while let Some(e) = at {
            if e == ancestor {
                return true;
            }
            at = self.parent(e);
        }
        false
    }

    fn node(&mut self, entity: hecs::Entity) -> &mut Node {
        if self.nodes.get(entity).is_none() {
            self.nodes.insert(entity, Node::new());
            self.dirty.push(entity);
            self.order_valid = false;
        }
        self.nodes
            .get_mut(entity)
            .expect("the node was inserted just above")
    }

    fn unlink_from_parent(&mut self, child: hecs::Entity) {
        let Some(parent) = self.nodes.get_mut(child).and_then(|n| n.parent.take()) else {
            return;
        };
        if let Some(p) = self.nodes.get_mut(parent) {
            p.children.retain(|c| *c != child);
        }
        self.forget_if_alone(parent);
        self.order_valid = false;
    }

    fn forget_if_alone(&mut self, entity: hecs::Entity) {
        if self
            .nodes
            .get(entity)
            .is_some_and(|n| n.parent.is_none() && n.children.is_empty())
        {
            self.nodes.remove(entity);
            self.order_valid = false;
        }
    }
}
