//! Component values as they cross the boundary, and their conversions to plain Rust.

use abi_stable::{
    std_types::{RString, RVec},
    StableAbi,
};

use crate::host::{Blob, BuiltinValue};
use crate::{
    BlobFormat, Camera, Collider, Entity, Light, MeshRenderer, Name, RigidBody, Transform,
};

/// Which built-in component a get or remove asks for.
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BuiltinId {
    Name,
    Transform,
    MeshRenderer,
    Camera,
    Light,
    RigidBody,
    Collider,
}

impl BuiltinId {
    pub fn name(self) -> &'static str {
        match self {
            BuiltinId::Name => "Name",
            BuiltinId::Transform => "Transform",
            BuiltinId::MeshRenderer => "MeshRenderer",
            BuiltinId::Camera => "Camera",
            BuiltinId::Light => "Light",
            BuiltinId::RigidBody => "RigidBody",
            BuiltinId::Collider => "Collider",
        }
    }
}

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

/// A built-in component value.
#[repr(C, u8)]
#[derive(StableAbi, Clone, Debug)]
pub enum BuiltinFfi {
    Name(RString),
    Transform(TransformFfi),
    MeshRenderer(MeshRenderer),
    Camera(Camera),
    Light(Light),
    RigidBody(RigidBody),
    Collider(Collider),
}

impl From<BuiltinValue> for BuiltinFfi {
    fn from(value: BuiltinValue) -> Self {
        match value {
            BuiltinValue::Name(name) => BuiltinFfi::Name(name.0.into()),
            BuiltinValue::Transform(t) => BuiltinFfi::Transform(t.into()),
            BuiltinValue::MeshRenderer(v) => BuiltinFfi::MeshRenderer(v),
            BuiltinValue::Camera(v) => BuiltinFfi::Camera(v),
            BuiltinValue::Light(v) => BuiltinFfi::Light(v),
            BuiltinValue::RigidBody(v) => BuiltinFfi::RigidBody(v),
            BuiltinValue::Collider(v) => BuiltinFfi::Collider(v),
        }
    }
}

impl From<BuiltinFfi> for BuiltinValue {
    fn from(value: BuiltinFfi) -> Self {
        match value {
            BuiltinFfi::Name(name) => BuiltinValue::Name(Name(name.into_string())),
            BuiltinFfi::Transform(t) => BuiltinValue::Transform(t.into()),
            BuiltinFfi::MeshRenderer(v) => BuiltinValue::MeshRenderer(v),
            BuiltinFfi::Camera(v) => BuiltinValue::Camera(v),
            BuiltinFfi::Light(v) => BuiltinValue::Light(v),
            BuiltinFfi::RigidBody(v) => BuiltinValue::RigidBody(v),
            BuiltinFfi::Collider(v) => BuiltinValue::Collider(v),
        }
    }
}

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
