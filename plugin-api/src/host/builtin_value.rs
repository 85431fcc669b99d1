//! [`BuiltinValue`]: a built-in component value, for hosts.

use crate::host::BuiltinId;
use crate::{Name, Transform};

/// One built-in component with its value.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum BuiltinValue {
    /// A [`Name`].
    Name(Name),
    /// A [`Transform`].
    Transform(Transform),
}

impl BuiltinValue {
    /// Which built-in component this is.
    pub fn id(&self) -> BuiltinId {
        match self {
            BuiltinValue::Name(_) => BuiltinId::Name,
            BuiltinValue::Transform(_) => BuiltinId::Transform,
        }
    }
}
