//! [`PluginLibrary`]: an opened plugin library, checked for version and layout.

use std::path::Path;

use abi_stable::library::{lib_header_from_path, LibraryError as AbiError, RootModule};
use abi_stable::sabi_types::VersionNumber;

use crate::__ffi::PluginModuleRef;
use crate::host::{CallError, LibraryError, PluginInstance};

/// A plugin library opened from disk. Libraries are never unloaded: abi_stable leaks them by
/// design, and glibc keeps any image that registered a thread-local destructor, so a hot
/// reload opens each new build from a fresh path and leaves the old image mapped.
#[derive(Clone, Copy)]
pub struct PluginLibrary {
    module: PluginModuleRef,
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
        let header = lib_header_from_path(path).map_err(map_error)?;
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
        Ok(Self { module })
    }

    /// The plugin's name (its crate name).
    pub fn name(&self) -> &'static str {
        self.module.plugin_name().as_str()
    }

    /// The plugin crate's version.
    pub fn version(&self) -> &'static str {
        self.module.plugin_version().as_str()
    }

    /// Builds a fresh plugin object (runs the plugin's constructor, panics caught).
    pub fn instantiate(&self) -> Result<PluginInstance, CallError> {
        let make = self.module.new_plugin();
        let object = make().into_result().map_err(CallError::from)?;
        Ok(PluginInstance::from_object(object))
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
