//! `onyx new-plugin NAME [--path DIR]`: scaffolds a plugin crate in `DIR/NAME`.
//!
//! The crate depends on this checkout's `onyx-plugin-api` (and, as a dev-dependency, on
//! `onyx-runtime` for a headless test) by absolute path. The checkout is the one this binary
//! was built from (`CARGO_MANIFEST_DIR` at compile time), or `$ONYX_SOURCE_DIR` when set.
//! Its `Cargo.lock` is seeded from the checkout's, so the plugin resolves the same versions
//! of the dependencies it shares with the host (abi_stable above all).

use std::path::{Path, PathBuf};

use anyhow::{anyhow, Context as _};
use onyx_runtime::plugins::plugin_search::library_file_name;

use crate::cli::NewPluginArgs;
use crate::Failure;

/// The environment variable naming the Onyx checkout a new plugin depends on.
pub const SOURCE_DIR_VAR: &str = "ONYX_SOURCE_DIR";

const CARGO_TOML: &str = include_str!("templates/Cargo.toml.tmpl");
const LIB_RS: &str = include_str!("templates/lib.rs.tmpl");
const README_MD: &str = include_str!("templates/README.md.tmpl");
const GITIGNORE: &str = include_str!("templates/gitignore.tmpl");

/// Names a crate cannot take: Rust keywords, the standard crates, what the plugin depends on,
/// and names Windows reserves for devices.
const RESERVED: &[&str] = &[
    "abstract",
    "alloc",
    "as",
    "async",
    "await",
    "become",
    "box",
    "break",
    "const",
    "continue",
    "core",
    "crate",
    "do",
    "dyn",
    "else",
    "enum",
    "extern",
    "false",
    "final",
    "fn",
    "for",
    "gen",
    "if",
    "impl",
    "in",
    "let",
    "loop",
    "macro",
    "match",
    "mod",
    "move",
    "mut",
    "override",
    "priv",
    "proc_macro",
    "pub",
    "ref",
    "return",
    "self",
    "serde",
    "static",
    "std",
    "struct",
    "super",
    "test",
    "trait",
    "true",
    "try",
    "type",
    "typeof",
    "unsafe",
    "unsized",
    "use",
    "virtual",
    "where",
    "while",
    "yield",
    "onyx_plugin_api",
    "onyx_runtime",
    "con",
    "prn",
    "aux",
    "nul",
    "com1",
    "com2",
    "com3",
    "com4",
    "com5",
    "com6",
    "com7",
    "com8",
    "com9",
    "lpt1",
    "lpt2",
    "lpt3",
    "lpt4",
    "lpt5",
    "lpt6",
    "lpt7",
    "lpt8",
    "lpt9",
];

/// Type names the generated `lib.rs` already uses: a plugin type may not shadow them.
const TAKEN_TYPE_NAMES: &[&str] = &[
    "AttachInfo",
    "Camera",
    "Ctx",
    "CtxError",
    "Deserialize",
    "Entity",
    "HeadlessHost",
    "Light",
    "Material",
    "MeshId",
    "MeshRenderer",
    "Name",
    "Option",
    "Plugin",
    "PluginError",
    "Quat",
    "Result",
    "Serialize",
    "Transform",
    "Vec",
    "Vec3",
];

/// Runs `onyx new-plugin`.
pub fn new_plugin(args: NewPluginArgs) -> Result<(), Failure> {
    scaffold(&args.name, &args.path).map_err(Failure::Start)?;
    let dir = args.path.join(&args.name);
    let lib = library_file_name(&args.name);
    println!("created plugin crate `{}` in {}", args.name, dir.display());
    println!();
    println!("  cd {}", dir.display());
    println!("  cargo build                                  # -> target/debug/{lib}");
    println!("  cargo test                                   # runs it in a headless host");
    println!("  onyx run --plugin target/debug/{lib}");
    println!("  onyx dev --plugin-crate .                    # rebuild + hot reload on save");
    Ok(())
}

/// Checks that `name` can name a crate (and a plugin). Returns the reason when it cannot.
pub fn validate_name(name: &str) -> Result<(), String> {
    if name.is_empty() {
        return Err("the plugin name is empty".into());
    }
    if name.len() > 64 {
        return Err(format!(
            "`{name}` is not a valid crate name: longer than 64 characters"
        ));
    }
    if let Some(bad) = name
        .chars()
        .find(|c| !(c.is_ascii_alphanumeric() || *c == '-' || *c == '_'))
    {
        return Err(format!(
            "`{name}` is not a valid crate name: `{bad}` is not allowed \
             (use ASCII letters, digits, `-` and `_`)"
        ));
    }
    if !name.starts_with(|c: char| c.is_ascii_alphabetic()) {
        return Err(format!(
            "`{name}` is not a valid crate name: it must start with a letter"
        ));
    }
    let normalized = name.to_ascii_lowercase().replace('-', "_");
    if RESERVED.contains(&normalized.as_str()) {
        return Err(format!(
            "`{name}` is not a valid crate name: it is a Rust keyword or a reserved name"
        ));
    }
    Ok(())
}

/// `my-plugin` → `MyPlugin` (suffixed with `Plugin` if it would shadow a name in `lib.rs`).
fn type_name(name: &str) -> String {
    let mut out = String::new();
    for word in name.split(['-', '_']).filter(|w| !w.is_empty()) {
        let mut chars = word.chars();
        if let Some(first) = chars.next() {
            out.push(first.to_ascii_uppercase());
            out.extend(chars);
        }
    }
    if TAKEN_TYPE_NAMES.contains(&out.as_str()) {
        out.push_str("Plugin");
    }
    out
}

/// `path` as a TOML basic string.
fn toml_string(path: &Path) -> String {
    let text = path.to_string_lossy();
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => out.push_str(&format!("\\u{:04X}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The Onyx checkout new plugins depend on: `$ONYX_SOURCE_DIR`, else the one `onyx` was
/// built from. Checked to hold `plugin-api/` and `runtime/host/`.
pub fn source_dir() -> anyhow::Result<PathBuf> {
    let (dir, from) = match std::env::var_os(SOURCE_DIR_VAR) {
        Some(dir) if !dir.is_empty() => (PathBuf::from(dir), format!("${SOURCE_DIR_VAR}")),
        _ => (
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."),
            "the checkout `onyx` was built from".to_owned(),
        ),
    };
    let dir = std::path::absolute(&dir).unwrap_or(dir);
    let dir = dir.canonicalize().unwrap_or(dir);
    for member in ["plugin-api", "runtime/host"] {
        if !dir.join(member).join("Cargo.toml").is_file() {
            return Err(anyhow!(
                "`{}` ({from}) is not an Onyx checkout: it has no {member}/Cargo.toml; \
                 set {SOURCE_DIR_VAR} to the root of one",
                dir.display()
            ));
        }
    }
    Ok(dir)
}

/// Writes the crate `name` into `parent/name`.
pub fn scaffold(name: &str, parent: &Path) -> anyhow::Result<()> {
    validate_name(name).map_err(|reason| anyhow!(reason))?;
    let dir = parent.join(name);
    if dir.exists() {
        let empty_dir = dir.is_dir()
            && std::fs::read_dir(&dir)
                .with_context(|| format!("cannot read `{}`", dir.display()))?
                .next()
                .is_none();
        if !empty_dir {
            return Err(anyhow!(
                "`{}` already exists and is not an empty directory; choose another name or --path",
                dir.display()
            ));
        }
    }
    let source = source_dir()?;
    let lib_name = name.replace('-', "_");
    let fill = |template: &str| {
        template
            .replace("{{crate_name}}", name)
            .replace("{{lib_name}}", &lib_name)
            .replace("{{type_name}}", &type_name(name))
            .replace("{{lib_file}}", &library_file_name(name))
            .replace("{{source_dir}}", &source.display().to_string())
            .replace(
                "{{plugin_api_path}}",
                &toml_string(&source.join("plugin-api")),
            )
            .replace(
                "{{runtime_path}}",
                &toml_string(&source.join("runtime").join("host")),
            )
    };
    std::fs::create_dir_all(dir.join("src"))
        .with_context(|| format!("cannot create `{}`", dir.display()))?;
    let mut files = vec![
        ("Cargo.toml", fill(CARGO_TOML)),
        ("src/lib.rs", fill(LIB_RS)),
        ("README.md", fill(README_MD)),
        (".gitignore", fill(GITIGNORE)),
    ];
    // Same dependency versions as the host; cargo drops what the plugin does not use.
    if let Ok(lock) = std::fs::read_to_string(source.join("Cargo.lock")) {
        files.push(("Cargo.lock", lock));
    }
    for (file, text) in files {
        let path = dir.join(file);
        std::fs::write(&path, text)
            .with_context(|| format!("cannot write `{}`", path.display()))?;
    }
    // Line breaks depend on the name's length: let rustfmt settle them when it is there.
    let _ = std::process::Command::new("rustfmt")
        .args(["--edition", "2021"])
        .arg(dir.join("src/lib.rs"))
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status();
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_checked_with_a_reason() {
        for good in ["bouncer", "my-plugin", "my_plugin2", "A"] {
            assert_eq!(validate_name(good), Ok(()), "{good}");
        }
        for (bad, why) in [
            ("", "empty"),
            ("2d", "start with a letter"),
            ("-x", "start with a letter"),
            ("has space", "` ` is not allowed"),
            ("caf\u{e9}", "is not allowed"),
            ("fn", "keyword"),
            ("onyx-runtime", "reserved"),
        ] {
            let reason = validate_name(bad).unwrap_err();
            assert!(reason.contains(why), "{bad}: {reason}");
        }
    }

    #[test]
    fn type_names_are_camel_case_and_do_not_shadow() {
        assert_eq!(type_name("my-plugin_x"), "MyPluginX");
        assert_eq!(type_name("bouncer"), "Bouncer");
        assert_eq!(type_name("plugin"), "PluginPlugin");
        assert_eq!(type_name("transform"), "TransformPlugin");
        assert_eq!(type_name("camera"), "CameraPlugin");
    }

    #[test]
    fn paths_become_toml_strings() {
        assert_eq!(toml_string(Path::new("/a/b")), "\"/a/b\"");
        assert_eq!(toml_string(Path::new("C:\\x\"y")), "\"C:\\\\x\\\"y\"");
    }

    /// The generated crate builds with this workspace's settings, so that it can share the
    /// checkout's target directory (and reuse every dependency already compiled there).
    #[test]
    fn the_template_builds_with_the_workspace_profile() {
        let workspace =
            std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../Cargo.toml"))
                .unwrap();
        let profile = &workspace[workspace.find("\n[profile.").expect("a [profile] table")..];
        for line in profile.lines().map(str::trim) {
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            assert!(
                CARGO_TOML.lines().any(|l| l.trim() == line),
                "the template's Cargo.toml lacks `{line}` from the workspace's profile"
            );
        }
    }

    #[test]
    fn templates_have_no_unfilled_placeholders() {
        let dir = tempfile::tempdir().unwrap();
        scaffold("demo-thing", dir.path()).unwrap();
        for file in ["Cargo.toml", "src/lib.rs", "README.md"] {
            let text = std::fs::read_to_string(dir.path().join("demo-thing").join(file)).unwrap();
            assert!(!text.contains("{{"), "{file}: {text}");
        }
        let lib = std::fs::read_to_string(dir.path().join("demo-thing/src/lib.rs")).unwrap();
        assert!(lib.contains("pub struct DemoThing"));
        assert!(lib.contains("add_plugin(\"demo_thing\", DemoThing::default())"));
        let err = scaffold("demo-thing", dir.path()).unwrap_err().to_string();
        assert!(err.contains("already exists"), "{err}");
    }
}
