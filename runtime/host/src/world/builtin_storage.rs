//! Built-in components in hecs, by id or by value: each is stored as its own type, and these
//! functions reach any of them through the one list (`onyx_plugin_api::BuiltinId`).

use onyx_plugin_api::{Builtin, BuiltinFn, BuiltinId, BuiltinValue, BuiltinVisitor};

/// Inserts (or replaces) `value` on `e`, which must exist.
pub fn insert(world: &mut hecs::World, e: hecs::Entity, value: &BuiltinValue) {
    struct Insert<'w>(&'w mut hecs::World, hecs::Entity);
    impl BuiltinVisitor for Insert<'_> {
        type Output = ();
        fn call<T: Builtin>(&mut self, value: &T) {
            // `e` exists (the caller checked), so inserting cannot fail.
            let _ = self.0.insert_one(self.1, value.clone());
        }
    }
    value.visit(&mut Insert(world, e));
}

/// Adds `value` to an entity being built (one archetype move for all its components).
pub fn add_to(builder: &mut hecs::EntityBuilder, value: &BuiltinValue) {
    struct Add<'b>(&'b mut hecs::EntityBuilder);
    impl BuiltinVisitor for Add<'_> {
        type Output = ();
        fn call<T: Builtin>(&mut self, value: &T) {
            self.0.add(value.clone());
        }
    }
    value.visit(&mut Add(builder));
}

/// The built-in `id` of `e`, if it has one.
pub fn get(world: &hecs::World, e: hecs::Entity, id: BuiltinId) -> Option<BuiltinValue> {
    struct Get<'w>(&'w hecs::World, hecs::Entity);
    impl BuiltinFn for Get<'_> {
        type Output = Option<BuiltinValue>;
        fn call<T: Builtin>(&mut self) -> Self::Output {
            let value = self.0.get::<&T>(self.1).ok()?;
            Some(T::clone(&value).into_value())
        }
    }
    id.dispatch(&mut Get(world, e))
}

/// Removes the built-in `id` from `e`; whether it had one.
pub fn remove(world: &mut hecs::World, e: hecs::Entity, id: BuiltinId) -> bool {
    struct Remove<'w>(&'w mut hecs::World, hecs::Entity);
    impl BuiltinFn for Remove<'_> {
        type Output = bool;
        fn call<T: Builtin>(&mut self) -> bool {
            self.0.remove_one::<T>(self.1).is_ok()
        }
    }
    id.dispatch(&mut Remove(world, e))
}

/// Every built-in of `e`, in list order.
pub fn all_of(world: &hecs::World, e: hecs::Entity) -> Vec<BuiltinValue> {
    BuiltinId::ALL
        .iter()
        .filter_map(|id| get(world, e, *id))
        .collect()
}
