//! [`catch_gltf_panics`]: the `gltf` crate (1.4.1) panics on some malformed files instead of
//! returning an error, so every read through it runs behind this guard.
//!
//! Found by the long fuzz run (`onyx-fuzz --formats gltf,glb`, README "Fuzzing"): 52 of
//! 200,000 mutated files panicked inside the crate — its validation indexes `accessors` with
//! a primitive's POSITION index before checking it (`gltf-json/src/mesh.rs`), `Image::source`
//! unwraps a missing buffer view or MIME type, and the primitive readers hit `unreachable!()`
//! for an index or texture-coordinate accessor of a type the validator let through. Until the
//! crate returns errors for these, a panic while reading a glTF file becomes a
//! [`ModelLoadError::Gltf`] naming the file, and the default panic message (a source
//! location in a dependency, no file name) is kept off stderr.

use std::cell::Cell;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;
use std::sync::Once;

use crate::mesh::model_load_error::ModelLoadError;

thread_local! {
    /// Whether this thread is inside [`catch_gltf_panics`].
    static GUARDED: Cell<bool> = const { Cell::new(false) };
}

/// Wraps the process's panic hook once: panics on a guarded thread are not printed (the
/// guard reports them as an error), every other panic goes to the hook as before.
fn quiet_hook_for_guarded_threads() {
    static INSTALL: Once = Once::new();
    INSTALL.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if !GUARDED.with(Cell::get) {
                previous(info);
            }
        }));
    });
}

/// Runs `read` (anything that reads the glTF file at `path` through the `gltf` crate); a
/// panic inside becomes [`ModelLoadError::Gltf`] saying the file is malformed.
pub fn catch_gltf_panics<T>(
    path: &Path,
    read: impl FnOnce() -> Result<T, ModelLoadError>,
) -> Result<T, ModelLoadError> {
    quiet_hook_for_guarded_threads();
    let was = GUARDED.with(|g| g.replace(true));
    let result = catch_unwind(AssertUnwindSafe(read));
    GUARDED.with(|g| g.set(was));
    result.unwrap_or_else(|payload| {
        let detail = payload
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| payload.downcast_ref::<&str>().copied())
            .unwrap_or("no message");
        tracing::debug!(path = %path.display(), detail, "the gltf crate panicked");
        Err(ModelLoadError::Gltf {
            path: path.to_owned(),
            message: format!(
                "it is malformed in a way the glTF reader does not check ({detail}); \
                 re-export it or check it with the Khronos glTF validator"
            ),
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_inside_becomes_an_error_naming_the_file_and_others_still_reach_the_hook() {
        let path = Path::new("broken.glb");
        let error = catch_gltf_panics::<()>(path, || {
            let empty: Vec<u32> = Vec::new();
            let index = empty.len() + 1;
            Err(ModelLoadError::Gltf {
                path: path.to_owned(),
                message: format!("{}", empty[index]),
            })
        })
        .expect_err("the panic is an error");
        let text = error.to_string();
        assert!(text.contains("broken.glb"), "{text}");
        assert!(text.contains("index out of bounds"), "{text}");
        assert!(!GUARDED.with(Cell::get), "the guard is lifted after");
        // Values and errors pass through untouched.
        assert_eq!(catch_gltf_panics(path, || Ok(7)).ok(), Some(7));
    }
}
