//! [`Bundle`]: a set of components spawned together.

use super::component_type::BundleParts;
use crate::{ComponentType, CtxError};

/// Components to spawn an entity with: one [`ComponentType`] or a tuple of up to eight.
///
/// `ctx.spawn((Name::new("crate"), Transform::from_xyz(0.0, 2.0, 0.0)))`
pub trait Bundle {
    #[doc(hidden)]
    fn write_to(self, parts: &mut BundleParts) -> Result<(), CtxError>;
}

impl<T: ComponentType> Bundle for T {
    fn write_to(self, parts: &mut BundleParts) -> Result<(), CtxError> {
        ComponentType::write_to(self, parts)
    }
}

macro_rules! tuple_bundle {
    ($($t:ident),+) => {
        impl<$($t: ComponentType),+> Bundle for ($($t,)+) {
            #[allow(non_snake_case)]
            fn write_to(self, parts: &mut BundleParts) -> Result<(), CtxError> {
                let ($($t,)+) = self;
                $(ComponentType::write_to($t, parts)?;)+
                Ok(())
            }
        }
    };
}

impl Bundle for () {
    fn write_to(self, _parts: &mut BundleParts) -> Result<(), CtxError> {
        Ok(())
    }
}
tuple_bundle!(A);
tuple_bundle!(A, B);
tuple_bundle!(A, B, C);
tuple_bundle!(A, B, C, D);
tuple_bundle!(A, B, C, D, E);
tuple_bundle!(A, B, C, D, E, F);
tuple_bundle!(A, B, C, D, E, F, G);
tuple_bundle!(A, B, C, D, E, F, G, H);
