//! [`Blob`]: a plugin component as the host stores it.

use crate::BlobFormat;

/// A named plugin component: its encoding and bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Blob {
    /// The component's name ([`Component::NAME`](crate::Component::NAME)).
    pub name: String,
    /// How `bytes` are encoded.
    pub format: BlobFormat,
    /// The encoded value.
    pub bytes: Vec<u8>,
}
