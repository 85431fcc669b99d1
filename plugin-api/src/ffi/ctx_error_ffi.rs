//! [`CtxErrorFfi`]: a [`CtxError`] flattened into plain data for the boundary.

use abi_stable::{std_types::RString, StableAbi};

use crate::{CtxError, Entity};

#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CtxErrorKind {
    NoSuchEntity,
    MissingComponent,
    NonFinite,
    Encode,
    Decode,
    Invalid,
}

/// [`CtxError`] as plain data.
#[repr(C)]
#[derive(StableAbi, Clone, Debug)]
pub struct CtxErrorFfi {
    pub kind: CtxErrorKind,
    pub entity: Entity,
    pub component: RString,
    pub message: RString,
}

impl From<CtxError> for CtxErrorFfi {
    fn from(error: CtxError) -> Self {
        let none = Entity::from_bits(0);
        let (kind, entity, component, message) = match error {
            CtxError::NoSuchEntity { entity } => (
                CtxErrorKind::NoSuchEntity,
                entity,
                String::new(),
                String::new(),
            ),
            CtxError::MissingComponent { entity, component } => (
                CtxErrorKind::MissingComponent,
                entity,
                component,
                String::new(),
            ),
            CtxError::NonFinite { entity, component } => {
                (CtxErrorKind::NonFinite, entity, component, String::new())
            }
            CtxError::Encode { component, message } => {
                (CtxErrorKind::Encode, none, component, message)
            }
            CtxError::Decode { component, message } => {
                (CtxErrorKind::Decode, none, component, message)
            }
            CtxError::Invalid { message } => (CtxErrorKind::Invalid, none, String::new(), message),
        };
        Self {
            kind,
            entity,
            component: component.into(),
            message: message.into(),
        }
    }
}

impl From<CtxErrorFfi> for CtxError {
    fn from(error: CtxErrorFfi) -> Self {
        let CtxErrorFfi {
            kind,
            entity,
            component,
            message,
        } = error;
        let component = component.into_string();
        let message = message.into_string();
        match kind {
            CtxErrorKind::NoSuchEntity => CtxError::NoSuchEntity { entity },
            CtxErrorKind::MissingComponent => CtxError::MissingComponent { entity, component },
            CtxErrorKind::NonFinite => CtxError::NonFinite { entity, component },
            CtxErrorKind::Encode => CtxError::Encode { component, message },
            CtxErrorKind::Decode => CtxError::Decode { component, message },
            CtxErrorKind::Invalid => CtxError::Invalid { message },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variant_survives_the_round_trip() {
        let e = Entity::from_bits(7);
        let all = [
            CtxError::NoSuchEntity { entity: e },
            CtxError::MissingComponent {
                entity: e,
                component: "Name".into(),
            },
            CtxError::NonFinite {
                entity: e,
                component: "Transform".into(),
            },
            CtxError::Encode {
                component: "a".into(),
                message: "b".into(),
            },
            CtxError::Decode {
                component: "c".into(),
                message: "d".into(),
            },
            CtxError::Invalid {
                message: "nope".into(),
            },
        ];
        for error in all {
            assert_eq!(CtxError::from(CtxErrorFfi::from(error.clone())), error);
        }
    }
}
