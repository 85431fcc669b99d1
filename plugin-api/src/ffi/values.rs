//! Component values as they cross the boundary, and their conversions to plain Rust.

use abi_stable::{
    std_types::{RString, RVec},
    StableAbi,
};

use crate::host::Blob;
use crate::{BlobFormat, BuiltinValue, Entity, GlobalTransform, Name, Transform};

/// A [`Transform`] passed by value: plain floats (translation, rotation xyzw, scale), so no
/// SIMD type travels through an `extern "C"` signature.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct TransformFfi(pub [f32; 10]);

impl From<Transform> for TransformFfi {
    fn from(t: Transform) -> Self {
        let (p, r, s) = (t.translation, t.rotation, t.scale);
        Self([p.x, p.y, p.z, r.x, r.y, r.z, r.w, s.x, s.y, s.z])
    }
}

impl From<TransformFfi> for Transform {
    fn from(TransformFfi(v): TransformFfi) -> Self {
        Transform {
            translation: glam::Vec3::new(v[0], v[1], v[2]),
            rotation: glam::Quat::from_xyzw(v[3], v[4], v[5], v[6]),
            scale: glam::Vec3::new(v[7], v[8], v[9]),
        }
    }
}

/// A [`Name`] as it crosses.
pub type NameFfi = RString;

impl From<Name> for RString {
    fn from(name: Name) -> Self {
        name.0.into()
    }
}

impl From<RString> for Name {
    fn from(name: RString) -> Self {
        Name(name.into_string())
    }
}

macro_rules! define_builtin_ffi {
    ($($id:ident => $key:ident: $ty:ty as $ffi:ty),* $(,)?) => {
        /// A built-in component value as it crosses: each in its boundary form.
        #[repr(C, u8)]
        #[derive(StableAbi, Clone, Debug)]
        pub enum BuiltinFfi {
            $($id($ffi),)*
        }

        impl From<BuiltinValue> for BuiltinFfi {
            fn from(value: BuiltinValue) -> Self {
                match value {
                    $(BuiltinValue::$id(v) => BuiltinFfi::$id(<$ffi>::from(v)),)*
                }
            }
        }

        impl From<BuiltinFfi> for BuiltinValue {
            fn from(value: BuiltinFfi) -> Self {
                match value {
                    $(BuiltinFfi::$id(v) => BuiltinValue::$id(<$ty>::from(v)),)*
                }
            }
        }
    };
}

crate::for_each_builtin!(define_builtin_ffi);

/// A named plugin component.
#[repr(C)]
#[derive(StableAbi, Clone, Debug)]
pub struct BlobFfi {
    pub name: RString,
    pub format: BlobFormat,
    pub bytes: RVec<u8>,
}

impl From<Blob> for BlobFfi {
    fn from(blob: Blob) -> Self {
        Self {
            name: blob.name.into(),
            format: blob.format,
            bytes: blob.bytes.into(),
        }
    }
}

impl From<BlobFfi> for Blob {
    fn from(blob: BlobFfi) -> Self {
        Self {
            name: blob.name.into_string(),
            format: blob.format,
            bytes: blob.bytes.into_vec(),
        }
    }
}

/// One row of a plugin-component query.
#[repr(C)]
#[derive(StableAbi, Clone, Debug)]
pub struct EntityBlobFfi {
    pub entity: Entity,
    pub format: BlobFormat,
    pub bytes: RVec<u8>,
}

/// Every component of one entity, as `components_of` answers.
#[repr(C)]
#[derive(StableAbi, Clone, Debug, Default)]
pub struct ComponentsFfi {
    pub builtins: RVec<BuiltinFfi>,
    pub blobs: RVec<BlobFfi>,
}

/// A [`GlobalTransform`] as plain floats: the three axis columns, then the translation.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct GlobalTransformFfi(pub [f32; 12]);

impl From<GlobalTransform> for GlobalTransformFfi {
    fn from(g: GlobalTransform) -> Self {
        let a = g.0;
        let mut v = [0.0; 12];
        for (i, column) in [
            a.matrix3.x_axis,
            a.matrix3.y_axis,
            a.matrix3.z_axis,
            a.translation,
        ]
        .into_iter()
        .enumerate()
        {
            v[i * 3..i * 3 + 3].copy_from_slice(&column.to_array());
        }
        Self(v)
    }
}

impl From<GlobalTransformFfi> for GlobalTransform {
    fn from(GlobalTransformFfi(v): GlobalTransformFfi) -> Self {
        let column = |i: usize| glam::Vec3A::new(v[i * 3], v[i * 3 + 1], v[i * 3 + 2]);
        GlobalTransform(glam::Affine3A {
            matrix3: glam::Mat3A::from_cols(column(0), column(1), column(2)),
            translation: column(3),
        })
    }
}
