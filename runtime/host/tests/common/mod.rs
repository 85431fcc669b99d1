//! Shared helpers of the host's integration tests.

#![allow(dead_code)] // each test binary uses a different subset

use std::path::PathBuf;

/// The Khronos glTF samples in `../shared/fixtures/gltf/`, or `None` when they are absent
/// (the test then skips, saying so).
pub fn gltf_samples() -> Option<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/fixtures/gltf");
    if dir.is_dir() {
        Some(dir)
    } else {
        eprintln!(
            "skipped: {} is absent (../shared/fixtures not beside the checkout)",
            dir.display()
        );
        None
    }
}
