//! OBJ + MTL, read tolerantly: any encoding, Windows paths, texture options, concave
//! polygons, smoothing groups, and every oddity real exporters write warned once with its
//! line rather than refused.
//!
//! - `obj_document`: the statements of the file, indices resolved and checked.
//! - `mtl_library`: MTL text into [`crate::ModelMaterial`]s.
//! - `texture_map`: a `map_*` statement's options and file name.
//! - `polygon`: ear clipping of one face.
//! - `obj_builder`: faces into single-indexed meshes with normals and UVs.
//! - `obj_loader`: the file into a [`crate::ModelSource`] (the entry point).

mod mtl_library;
mod obj_builder;
mod obj_document;
mod obj_loader;
mod polygon;
mod texture_map;

pub(crate) use obj_loader::load_obj_source;
