//! [`EntityMap`]: per-entity data in a vector indexed by the entity's slot, so systems that
//! look up many entities every step (the physics sync, the transform hierarchy) find them
//! without hashing.

/// A map from live hecs entities to `T`. A slot remembers the full entity (with its
/// generation), so a despawned entity's reused slot is not mistaken for it.
#[derive(Clone, Debug)]
pub struct EntityMap<T> {
    slots: Vec<Option<(hecs::Entity, T)>>,
    len: usize,
}

impl<T> Default for EntityMap<T> {
    fn default() -> Self {
        Self {
            slots: Vec::new(),
            len: 0,
        }
    }
}

impl<T> EntityMap<T> {
    /// Number of entries.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The value of `e`, if any.
    pub fn get(&self, e: hecs::Entity) -> Option<&T> {
        match self.slots.get(e.id() as usize) {
            Some(Some((k, v))) if *k == e => Some(v),
            _ => None,
        }
    }

    /// The value of `e`, mutably.
    pub fn get_mut(&mut self, e: hecs::Entity) -> Option<&mut T> {
        match self.slots.get_mut(e.id() as usize) {
            Some(Some((k, v))) if *k == e => Some(v),
            _ => None,
        }
    }

    /// Sets the value of `e`; returns the value it replaces (of `e` or of a dead entity
    /// that had the slot).
    pub fn insert(&mut self, e: hecs::Entity, value: T) -> Option<T> {
        let i = e.id() as usize;
        if i >= self.slots.len() {
            self.slots.resize_with(i + 1, || None);
        }
        let old = self.slots[i].replace((e, value)).map(|(_, v)| v);
        if old.is_none() {
            self.len += 1;
        }
        old
    }

    /// Removes the value of `e`.
    pub fn remove(&mut self, e: hecs::Entity) -> Option<T> {
        let slot = self.slots.get_mut(e.id() as usize)?;
        match slot {
            Some((k, _)) if *k == e => {
                self.len -= 1;
                slot.take().map(|(_, v)| v)
            }
            _ => None,
        }
    }

    /// Every entry.
    pub fn iter(&self) -> impl Iterator<Item = (hecs::Entity, &T)> {
        self.slots.iter().flatten().map(|(e, v)| (*e, v))
    }

    /// Every entry, values mutable.
    pub fn iter_mut(&mut self) -> impl Iterator<Item = (hecs::Entity, &mut T)> {
        self.slots.iter_mut().flatten().map(|(e, v)| (*e, v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reused_slot_is_not_the_old_entity() {
        let mut world = hecs::World::new();
        let a = world.spawn(());
        let mut map = EntityMap::default();
        map.insert(a, 1);
        assert_eq!(map.get(a), Some(&1));
        world.despawn(a).unwrap();
        let b = world.spawn(());
        assert_eq!(a.id(), b.id(), "hecs reuses the slot");
        assert_eq!(map.get(b), None);
        assert_eq!(map.remove(b), None);
        assert_eq!(map.len(), 1);
        assert_eq!(
            map.insert(b, 2),
            Some(1),
            "the dead entity's value is replaced"
        );
        assert_eq!(map.len(), 1);
        assert_eq!(map.iter().collect::<Vec<_>>(), vec![(b, &2)]);
        assert_eq!(map.remove(b), Some(2));
        assert!(map.is_empty());
    }
}
