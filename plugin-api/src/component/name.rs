//! [`Name`]: a human-readable label for an entity.

use serde::{Deserialize, Serialize};

use super::builtin::{FileRefs, HostRefs};
use crate::{Builtin, InvalidValue};

/// A label shown in the editor's hierarchy and in state dumps. Names need not be unique.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Name(pub String);

impl Name {
    /// A name from anything string-like: `Name::new("crate")`.
    pub fn new(name: impl Into<String>) -> Self {
        Self(name.into())
    }

    /// The name as a string slice.
    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl std::fmt::Display for Name {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl From<&str> for Name {
    fn from(name: &str) -> Self {
        Self::new(name)
    }
}

impl From<String> for Name {
    fn from(name: String) -> Self {
        Self(name)
    }
}

impl Builtin for Name {
    const NAME: &'static str = "Name";
    type File = String;

    fn tool_default() -> Option<Self> {
        Some(Name::new("entity"))
    }

    fn validate(&self, _refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        Ok(())
    }

    fn to_file(&self, _refs: &dyn HostRefs) -> String {
        self.0.clone()
    }

    fn from_file(file: String, _refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        Ok(Name(file))
    }
}
