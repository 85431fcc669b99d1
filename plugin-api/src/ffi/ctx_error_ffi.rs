//! [`CtxErrorFfi`]: a [`CtxError`] flattened into plain data for the boundary.

use abi_stable::{std_types::RString, StableAbi};

use crate::{CtxError, Entity, ParentProblem};

#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CtxErrorKind {
    NoSuchEntity,
    MissingComponent,
    NonFinite,
    InvalidValue,
    InvalidParent,
    Encode,
    Decode,
    Scene,
    Unsupported,
    Invalid,
}

/// [`CtxError`] as plain data: the kind and every value a variant can carry (unused ones
/// empty; entity bits 0 and line 0 stand for none).
#[repr(C)]
#[derive(StableAbi, Clone, Debug)]
pub struct CtxErrorFfi {
    pub kind: CtxErrorKind,
    pub entity: Entity,
    pub other: Entity,
    pub problem: ParentProblem,
    pub component: RString,
    pub field: RString,
    pub message: RString,
    pub path: RString,
    pub line: u32,
    pub column: u32,
}

const NONE: Entity = Entity::from_bits(0);

fn some(entity: Entity) -> Option<Entity> {
    (entity != NONE).then_some(entity)
}

fn number(value: u32) -> Option<u32> {
    (value != 0).then_some(value)
}

impl From<CtxError> for CtxErrorFfi {
    fn from(error: CtxError) -> Self {
        let mut ffi = CtxErrorFfi {
            kind: CtxErrorKind::Invalid,
            entity: NONE,
            other: NONE,
            problem: ParentProblem::Missing,
            component: RString::new(),
            field: RString::new(),
            message: RString::new(),
            path: RString::new(),
            line: 0,
            column: 0,
        };
        match error {
            CtxError::NoSuchEntity { entity } => {
                ffi.kind = CtxErrorKind::NoSuchEntity;
                ffi.entity = entity;
            }
            CtxError::MissingComponent { entity, component } => {
                ffi.kind = CtxErrorKind::MissingComponent;
                ffi.entity = entity;
                ffi.component = component.into();
            }
            CtxError::NonFinite {
                entity,
                component,
                field,
            } => {
                ffi.kind = CtxErrorKind::NonFinite;
                ffi.entity = entity.unwrap_or(NONE);
                ffi.component = component.into();
                ffi.field = field.into();
            }
            CtxError::InvalidValue {
                entity,
                component,
                field,
                message,
            } => {
                ffi.kind = CtxErrorKind::InvalidValue;
                ffi.entity = entity.unwrap_or(NONE);
                ffi.component = component.into();
                ffi.field = field.into();
                ffi.message = message.into();
            }
            CtxError::InvalidParent {
                entity,
                parent,
                problem,
            } => {
                ffi.kind = CtxErrorKind::InvalidParent;
                ffi.entity = entity;
                ffi.other = parent;
                ffi.problem = problem;
            }
            CtxError::Encode { component, message } => {
                ffi.kind = CtxErrorKind::Encode;
                ffi.component = component.into();
                ffi.message = message.into();
            }
            CtxError::Decode { component, message } => {
                ffi.kind = CtxErrorKind::Decode;
                ffi.component = component.into();
                ffi.message = message.into();
            }
            CtxError::Scene {
                path,
                line,
                column,
                message,
            } => {
                ffi.kind = CtxErrorKind::Scene;
                ffi.path = path.into();
                ffi.line = line.unwrap_or(0);
                ffi.column = column.unwrap_or(0);
                ffi.message = message.into();
            }
            CtxError::Unsupported { service } => {
                ffi.kind = CtxErrorKind::Unsupported;
                ffi.message = service.into();
            }
            CtxError::Invalid { message } => {
                ffi.kind = CtxErrorKind::Invalid;
                ffi.message = message.into();
            }
        }
        ffi
    }
}

impl From<CtxErrorFfi> for CtxError {
    fn from(error: CtxErrorFfi) -> Self {
        let CtxErrorFfi {
            kind,
            entity,
            other,
            problem,
            component,
            field,
            message,
            path,
            line,
            column,
        } = error;
        let component = component.into_string();
        let field = field.into_string();
        let message = message.into_string();
        match kind {
            CtxErrorKind::NoSuchEntity => CtxError::NoSuchEntity { entity },
            CtxErrorKind::MissingComponent => CtxError::MissingComponent { entity, component },
            CtxErrorKind::NonFinite => CtxError::NonFinite {
                entity: some(entity),
                component,
                field,
            },
            CtxErrorKind::InvalidValue => CtxError::InvalidValue {
                entity: some(entity),
                component,
                field,
                message,
            },
            CtxErrorKind::InvalidParent => CtxError::InvalidParent {
                entity,
                parent: other,
                problem,
            },
            CtxErrorKind::Encode => CtxError::Encode { component, message },
            CtxErrorKind::Decode => CtxError::Decode { component, message },
            CtxErrorKind::Scene => CtxError::Scene {
                path: path.into_string(),
                line: number(line),
                column: number(column),
                message,
            },
            CtxErrorKind::Unsupported => CtxError::Unsupported { service: message },
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
        let p = Entity::from_bits(9);
        let all = [
            CtxError::NoSuchEntity { entity: e },
            CtxError::MissingComponent {
                entity: e,
                component: "Name".into(),
            },
            CtxError::NonFinite {
                entity: Some(e),
                component: "Transform".into(),
                field: "scale".into(),
            },
            CtxError::NonFinite {
                entity: None,
                component: "Light".into(),
                field: "color".into(),
            },
            CtxError::InvalidValue {
                entity: Some(e),
                component: "Camera".into(),
                field: "near".into(),
                message: "must be > 0 m, got -1".into(),
            },
            CtxError::InvalidParent {
                entity: e,
                parent: p,
                problem: ParentProblem::Descendant,
            },
            CtxError::Encode {
                component: "a".into(),
                message: "b".into(),
            },
            CtxError::Decode {
                component: "c".into(),
                message: "d".into(),
            },
            CtxError::Scene {
                path: "a.ron".into(),
                line: Some(3),
                column: Some(14),
                message: "scene `a.ron` is malformed at line 3, column 14: x".into(),
            },
            CtxError::Scene {
                path: "b.ron".into(),
                line: None,
                column: None,
                message: "could not read scene `b.ron`".into(),
            },
            CtxError::Unsupported {
                service: "open_scene".into(),
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
