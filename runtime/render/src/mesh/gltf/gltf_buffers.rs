//! [`load_buffers`] and [`image_bytes`]: the bytes a glTF document points at.

use std::path::Path;

use base64::Engine as _;

use crate::asset_io::{read_asset_file, resolve_referenced_path, MAX_ASSET_FILE_BYTES};

/// Every buffer of `document`, in index order: the GLB `BIN` chunk, a `data:` URI or a file
/// beside the model. Errors are sentences naming the buffer.
pub fn load_buffers(
    document: &gltf::Document,
    blob: Option<&[u8]>,
    folder: &Path,
) -> Result<Vec<Vec<u8>>, String> {
    document
        .buffers()
        .map(|buffer| {
            let mut bytes = match buffer.source() {
                gltf::buffer::Source::Bin => blob.map(<[u8]>::to_vec).ok_or_else(|| {
                    format!(
                        "buffer {} is the GLB binary chunk, which the file does not have",
                        buffer.index()
                    )
                })?,
                gltf::buffer::Source::Uri(uri) => uri_bytes(uri, folder)
                    .map_err(|e| format!("buffer {} ({}): {e}", buffer.index(), short(uri)))?,
            };
            if bytes.len() < buffer.length() {
                return Err(format!(
                    "buffer {} holds {} bytes, the file says {}; the model is truncated",
                    buffer.index(),
                    bytes.len(),
                    buffer.length()
                ));
            }
            bytes.truncate(buffer.length());
            Ok(bytes)
        })
        .collect()
}

/// The encoded bytes of an image: a buffer view, a `data:` URI or a file.
pub(crate) fn image_bytes(
    image: &gltf::Image<'_>,
    buffers: &[Vec<u8>],
    folder: &Path,
) -> Result<Vec<u8>, String> {
    match image.source() {
        gltf::image::Source::View { view, .. } => {
            let data = buffers
                .get(view.buffer().index())
                .ok_or_else(|| format!("image {} names a missing buffer", image.index()))?;
            data.get(view.offset()..view.offset() + view.length())
                .map(<[u8]>::to_vec)
                .ok_or_else(|| format!("image {} lies outside its buffer", image.index()))
        }
        gltf::image::Source::Uri { uri, .. } => uri_bytes(uri, folder),
    }
}

/// Where an image URI points, when it is a file (for naming it and caching by path).
pub(crate) fn image_file(image: &gltf::Image<'_>, folder: &Path) -> Option<std::path::PathBuf> {
    match image.source() {
        gltf::image::Source::Uri { uri, .. } if !uri.starts_with("data:") => {
            Some(resolve_referenced_path(folder, &percent_decode(uri)))
        }
        _ => None,
    }
}

fn uri_bytes(uri: &str, folder: &Path) -> Result<Vec<u8>, String> {
    if let Some(rest) = uri.strip_prefix("data:") {
        let Some((_, data)) = rest.split_once(";base64,") else {
            return Err("a data: URI that is not base64".to_owned());
        };
        return base64::engine::general_purpose::STANDARD
            .decode(data.trim())
            .map_err(|e| format!("its base64 data is damaged ({e})"));
    }
    let path = resolve_referenced_path(folder, &percent_decode(uri));
    read_asset_file(&path, MAX_ASSET_FILE_BYTES).map_err(|e| e.to_string())
}

/// `%20` and friends in a relative URI.
fn percent_decode(uri: &str) -> String {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = |b: u8| (b as char).to_digit(16);
        match (
            bytes[i],
            bytes.get(i + 1).copied().and_then(hex),
            bytes.get(i + 2).copied().and_then(hex),
        ) {
            (b'%', Some(h), Some(l)) => {
                out.push((h * 16 + l) as u8);
                i += 3;
            }
            (b, _, _) => {
                out.push(b);
                i += 1;
            }
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

fn short(uri: &str) -> String {
    if uri.len() > 60 {
        format!(
            "{}…",
            &uri[..uri.char_indices().nth(60).map_or(uri.len(), |(i, _)| i)]
        )
    } else {
        uri.to_owned()
    }
}
