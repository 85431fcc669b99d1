//! [`PluginLibrary`]: an opened plugin library, checked for version and layout, and the
//! image it keeps mapped.

use std::path::Path;
use std::sync::Arc;

use abi_stable::library::{
    lib_header_from_raw_library, LibraryError as AbiError, RawLibrary, RootModule,
};
use abi_stable::sabi_types::VersionNumber;

use crate::__ffi::PluginModuleRef;
use crate::host::{CallError, LibraryError, PluginInstance};

/// The mapped image of a library file, shared by its [`PluginLibrary`] and every
/// [`PluginInstance`] built from it (their vtables and code live in it).
///
/// Dropping the last handle does **not** unmap it: an image is handed back to the system
/// loader only by [`PluginLibrary::close`], when the host knows nothing from it can run
/// again. Until then it is leaked, as abi_stable does with every library it opens.
pub(crate) struct LibraryImage {
    raw: Option<RawLibrary>,
}

impl Drop for LibraryImage {
    fn drop(&mut self) {
        if let Some(raw) = self.raw.take() {
            // Not closed on purpose: keep the image mapped for the rest of the process.
            std::mem::forget(raw);
        }
    }
}

/// A plugin library opened from disk. The dynamic loader hands back the already-mapped
/// image for a path it has opened, so a hot reload opens each new build from a fresh path.
/// An old build's image stays mapped unless the host closes it ([`PluginLibrary::close`]).
pub struct PluginLibrary {
    module: PluginModuleRef,
    image: Arc<LibraryImage>,
    built_against: String,
}

impl std::fmt::Debug for PluginLibrary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PluginLibrary")
            .field("name", &self.name())
            .field("version", &self.version())
            .finish()
    }
}

fn version_of(strings: abi_stable::sabi_types::VersionStrings) -> String {
    match VersionNumber::new(strings) {
        Ok(v) => v.to_string(),
        Err(_) => format!("{strings}"),
    }
}

impl PluginLibrary {
    /// Opens the library at `path` and checks that it is an Onyx plugin built against a
    /// compatible onyx-plugin-api: same version (major, and minor while 0.x) and the same
    /// type layouts. Opening runs the library's initialisers but no plugin code.
    ///
    /// Each path is opened at most once per process (the dynamic loader returns the same
    /// image for the same path): to load a new build, copy it to a new path first.
    pub fn open(path: &Path) -> Result<Self, LibraryError> {
        let raw = RawLibrary::load_at(path).map_err(map_error)?;
        match Self::check(&raw) {
            Ok((module, built_against)) => Ok(Self {
                module,
                image: Arc::new(LibraryImage { raw: Some(raw) }),
                built_against,
            }),
            Err(error) => {
                // Its initialisers ran and it may have registered anything: a library that
                // is refused stays mapped, like every library before `close` existed.
                std::mem::forget(raw);
                Err(error)
            }
        }
    }

    fn check(raw: &RawLibrary) -> Result<(PluginModuleRef, String), LibraryError> {
        // SAFETY: the header points into the image `raw` holds open; the module taken from
        // it is kept next to that image (`PluginLibrary::image`) and never outlives it.
        let header = unsafe { lib_header_from_raw_library(raw) }.map_err(map_error)?;
        let host = <PluginModuleRef as RootModule>::VERSION_STRINGS;
        let built = header.version_strings();
        // abi_stable accepts a 0.x library with a *newer* minor; Onyx requires the same
        // major (and the same minor while 0.x) in both directions.
        let compatible = match (VersionNumber::new(host), VersionNumber::new(built)) {
            (Ok(h), Ok(b)) => h.major == b.major && (h.major != 0 || h.minor == b.minor),
            _ => false,
        };
        if !compatible {
            return Err(LibraryError::IncompatibleVersion {
                built_against: version_of(built),
                host: version_of(host),
            });
        }
        let module = header
            .init_root_module::<PluginModuleRef>()
            .map_err(map_error)?;
        Ok((module, version_of(built)))
    }

    /// The onyx-plugin-api version the library was built against (the same major and, while
    /// 0.x, minor as [`API_VERSION`](crate::host::API_VERSION); the patch may differ).
    pub fn api_version(&self) -> &str {
        &self.built_against
    }

    /// The plugin's name (its crate name).
    pub fn name(&self) -> &str {
        self.module.plugin_name().as_str()
    }

    /// The plugin crate's version.
    pub fn version(&self) -> &str {
        self.module.plugin_version().as_str()
    }

    /// Builds a fresh plugin object (runs the plugin's constructor, panics caught).
    pub fn instantiate(&self) -> Result<PluginInstance, CallError> {
        let make = self.module.new_plugin();
        let object = make().into_result().map_err(CallError::from)?;
        Ok(PluginInstance::from_library(object, self.image.clone()))
    }

    /// Hands the library back to the system loader, which unmaps it — unless something
    /// still pins it there: glibc keeps an image whose thread-local destructors are still
    /// pending (a thread the library started and that has not ended, a thread-local with a
    /// destructor it filled on a thread that still runs). Whether it left memory is for the
    /// caller to check. Returns the library again while a [`PluginInstance`] built from it
    /// is alive.
    ///
    /// # Safety
    ///
    /// Nothing from the library may run or be read after this: no object from it (checked),
    /// no thread it started still running its code outside Rust's std (raw `pthread_create`,
    /// a C library's threads), no pointer into it kept anywhere — callbacks or signal
    /// handlers it installed, `'static` data it handed out.
    pub unsafe fn close(self) -> Result<(), Self> {
        match Arc::try_unwrap(self.image) {
            Ok(mut image) => {
                // dlclose: the loader runs the library's finalisers and unmaps it.
                drop(image.raw.take());
                Ok(())
            }
            Err(image) => Err(Self {
                module: self.module,
                image,
                built_against: self.built_against,
            }),
        }
    }
}

fn map_error(error: AbiError) -> LibraryError {
    match error {
        AbiError::OpenError { err, .. } => LibraryError::Open {
            reason: err.to_string(),
        },
        AbiError::GetSymbolError { .. } => LibraryError::MissingRootSymbol,
        AbiError::IncompatibleVersionNumber {
            expected_version,
            actual_version,
            ..
        } => LibraryError::IncompatibleVersion {
            built_against: actual_version.to_string(),
            host: expected_version.to_string(),
        },
        AbiError::AbiInstability(details) => LibraryError::IncompatibleLayout {
            details: details.to_string(),
        },
        AbiError::InvalidAbiHeader(header) => LibraryError::IncompatibleAbiStable {
            details: format!("{header:?}"),
        },
        AbiError::InvalidCAbi { expected, found } => LibraryError::IncompatibleAbiStable {
            details: format!("C ABI mismatch: expected {expected}, found {found}"),
        },
        other => LibraryError::InitFailed {
            message: other.to_string(),
        },
    }
}
