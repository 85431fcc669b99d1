//! [`EntityList`]: every entity with its name, fetched in one call.

use crate::Entity;

/// Every entity of the world with its [`Name`](crate::Name) (empty when it has none) and its
/// parent, in entity order. Names are kept in one string, so listing 10,000 entities costs a
/// few allocations, not 10,000.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EntityList {
    pub(crate) entities: Vec<Entity>,
    pub(crate) name_ends: Vec<u32>,
    pub(crate) names: String,
    pub(crate) parents: Vec<u32>,
}

impl EntityList {
    /// The parent row of a row without a parent.
    pub const NO_PARENT: u32 = u32::MAX;

    /// Builds a list from `(entity, name)` rows (hosts use this).
    pub fn from_rows<'a>(rows: impl IntoIterator<Item = (Entity, &'a str)>) -> Self {
        let mut list = Self::default();
        for (entity, name) in rows {
            list.push(entity, name);
        }
        list
    }

    /// Appends one row.
    pub fn push(&mut self, entity: Entity, name: &str) {
        self.entities.push(entity);
        self.names.push_str(name);
        self.name_ends.push(self.names.len() as u32);
        self.parents.push(Self::NO_PARENT);
    }

    /// Makes row `parent` the parent of row `row` (hosts use this; rows out of range are
    /// ignored).
    pub fn set_parent(&mut self, row: usize, parent: usize) {
        if parent < self.entities.len() {
            if let Some(slot) = self.parents.get_mut(row) {
                *slot = parent as u32;
            }
        }
    }

    /// The row of the parent of row `index` (`None` for a root or an index out of range).
    pub fn parent(&self, index: usize) -> Option<usize> {
        let parent = *self.parents.get(index)?;
        (parent != Self::NO_PARENT).then_some(parent as usize)
    }

    /// Number of entities.
    pub fn len(&self) -> usize {
        self.entities.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.entities.is_empty()
    }

    /// The entities, in order.
    pub fn entities(&self) -> &[Entity] {
        &self.entities
    }

    /// The name of row `index` (`""` for an unnamed entity or an index out of range).
    pub fn name(&self, index: usize) -> &str {
        let Some(&end) = self.name_ends.get(index) else {
            return "";
        };
        let start = if index == 0 {
            0
        } else {
            self.name_ends[index - 1]
        };
        self.names.get(start as usize..end as usize).unwrap_or("")
    }

    /// `(entity, name)` for every row.
    pub fn iter(&self) -> impl Iterator<Item = (Entity, &str)> + '_ {
        self.entities
            .iter()
            .enumerate()
            .map(|(i, e)| (*e, self.name(i)))
    }
}
