//! The command line, as clap types.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};
use onyx_runtime::scene::{ImportSettingsFile, NormalsFile, UpAxisFile};

/// Onyx: a 3D application host that runs plugins.
#[derive(Parser, Debug)]
#[command(name = "onyx", version, about, long_about = None)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// Subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Run the host with plugins, in a window or headless.
    Run(RunArgs),
    /// Show the plugin search path and the plugin libraries found in it.
    Plugins,
    /// Create a new plugin crate, ready to build, test and run.
    NewPlugin(NewPluginArgs),
    /// Build plugin crates, run them, and rebuild + hot-reload them as their sources change.
    Dev(DevArgs),
    /// The host process `onyx dev` runs and watches (not for people: `onyx dev` passes it
    /// its own arguments and the libraries it built).
    #[command(name = "dev-host", hide = true)]
    DevHost(DevHostArgs),
}

/// `onyx run`.
#[derive(Args, Debug)]
#[command(after_help = "\
PLUGINS
  --plugin takes a library path (anything with a '/' or ending in the platform's library
  suffix) or a NAME. A NAME is looked up as lib<NAME>.so (.dylib, NAME.dll) in:
    1. each directory of $ONYX_PLUGIN_PATH
    2. the directory of the onyx executable (cargo builds plugins next to it)
    3. $CARGO_TARGET_DIR/{debug,release}, else ./target/{debug,release}
  Plugins are attached in the order given and called in that order each frame.

EXIT STATUS
  0 on a clean run; 1 if a plugin faulted during the run; 2 if the run could not start
  (a plugin or scene failed to load, no display); 3 if the process crashed natively (a
  segfault, an abort, a stack overflow); 4 if a plugin ended the process itself (`exit`)
  during a call. The reason is printed on one line, for 3 and 4 naming the plugin and the
  stage that was running (or the host).

A plugin call still running after --watchdog seconds is reported (log, window title) but
not stopped: native code cannot be interrupted safely.")]
pub struct RunArgs {
    /// What to run and how (shared with `onyx dev`).
    #[command(flatten)]
    pub host: HostArgs,
    /// After the last frame, write every entity and component as JSON to FILE.
    #[arg(long, value_name = "FILE")]
    pub dump_state: Option<PathBuf>,
    /// After the last frame, save the world as a scene file (written atomically).
    #[arg(long, value_name = "FILE")]
    pub save_scene: Option<PathBuf>,
    /// After the last frame, render the world offscreen at --size and save it as a PNG
    /// (windowed or headless; headless needs a GPU or Mesa's CPU Vulkan driver).
    #[arg(long, value_name = "FILE.png")]
    pub screenshot: Option<PathBuf>,
}

/// The host options `onyx run` and `onyx dev` share.
#[derive(Args, Debug)]
pub struct HostArgs {
    /// A plugin to load: a library path or a NAME (repeatable; loaded in order).
    #[arg(long = "plugin", value_name = "PATH|NAME")]
    pub plugins: Vec<String>,
    /// A scene file (RON), or a glTF file (.gltf, .glb) whose node tree becomes the scene,
    /// to load before the first frame.
    #[arg(long, value_name = "FILE")]
    pub scene: Option<PathBuf>,
    /// How a glTF --scene is brought in (a RON scene gives its models' settings in its
    /// `imports` table instead).
    #[command(flatten)]
    pub import: ImportArgs,
    /// Run without a window (and without a GPU): `run` as fast as possible, `dev` in real time.
    #[arg(long)]
    pub headless: bool,
    /// Stop after N frames (without it: until the window is closed or a plugin quits).
    #[arg(long, value_name = "N")]
    pub frames: Option<u64>,
    /// Fixed simulation steps per second [default: the physics preset's, 60 for balanced].
    #[arg(long, value_name = "HZ")]
    pub fixed_hz: Option<f64>,
    /// Physics accuracy preset, instead of the scene's: fast (30 Hz x 2 substeps), balanced
    /// (60 Hz x 4) or precise (120 Hz x 4). It sets the step rate and substeps only; the
    /// scene's other physics settings (gravity, thresholds, caps) stay. See
    /// docs/physics-accuracy.md.
    #[arg(long, value_name = "PRESET")]
    pub physics: Option<onyx_runtime::PhysicsPreset>,
    /// Most fixed steps per frame (the spiral-of-death guard).
    #[arg(long, value_name = "N", default_value_t = 8)]
    pub max_steps: u32,
    /// A setting for a plugin, read in its on_attach (repeatable): `hello.quit_after=10`.
    #[arg(long = "set", value_name = "PLUGIN.KEY=VALUE", value_parser = parse_setting)]
    pub settings: Vec<(String, String, String)>,
    /// Window (and screenshot) size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1280x720", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Present frames as soon as they are drawn instead of waiting for the display's refresh.
    #[arg(long)]
    pub no_vsync: bool,
    /// Multisample anti-aliasing of the window: samples per pixel, 1 (off) or 4. Headless
    /// screenshots never multisample (their output is compared with reference images).
    #[arg(long, value_name = "N", default_value_t = 4, value_parser = clap::value_parser!(u32).range(1..=4))]
    pub msaa: u32,
    /// An equirectangular HDR image (Radiance .hdr) as the sky: it lights the scene and is
    /// drawn behind it, instead of the procedural sky (window and screenshot). A file that
    /// cannot be read is one warning; the procedural sky stays.
    #[arg(long, value_name = "FILE.hdr")]
    pub sky: Option<PathBuf>,
    /// Report a plugin call still running after SECS seconds, and every 10 s while it lasts
    /// (0: off; it is quiet anyway while a debugger is attached).
    #[arg(long, value_name = "SECS", default_value_t = 5.0, value_parser = parse_seconds)]
    pub watchdog: f64,
    /// Keep every old build's library mapped after a reload or an unload (for plugins that
    /// leave threads or callbacks of a C library running after on_detach).
    #[arg(long)]
    pub keep_old_builds: bool,
}

/// Import settings for a glTF file given as `--scene`: the node tree is scaled and turned as
/// one piece at its root; the normals apply to each of its meshes.
#[derive(Args, Debug, Default)]
pub struct ImportArgs {
    /// Uniform scale of a glTF --scene (0.01 for a file in centimetres), applied once at
    /// its root, so node positions scale with the meshes. Must be > 0.
    #[arg(long, value_name = "FACTOR", value_parser = parse_scale)]
    pub import_scale: Option<f32>,
    /// Which axis of a glTF --scene points up: y (glTF's own) or z (turned to Y up as one
    /// piece, at its root).
    #[arg(long, value_name = "AXIS", value_parser = parse_up_axis)]
    pub up_axis: Option<UpAxisFile>,
    /// Normals generated for the meshes of a glTF --scene that lack them: smooth, flat, or
    /// a crease angle in degrees (0 to 180; edges sharper stay sharp) [default: 45].
    #[arg(long, value_name = "smooth|flat|DEGREES", value_parser = parse_normals)]
    pub normals: Option<NormalsFile>,
}

impl ImportArgs {
    /// The settings asked for, `None` when no option was given.
    pub fn settings(&self) -> Option<ImportSettingsFile> {
        (self.import_scale.is_some() || self.up_axis.is_some() || self.normals.is_some()).then(
            || ImportSettingsFile {
                scale: self.import_scale,
                up_axis: self.up_axis.unwrap_or_default(),
                normals: self.normals.unwrap_or_default(),
            },
        )
    }
}

/// `onyx new-plugin`.
#[derive(Args, Debug)]
#[command(after_help = "\
The crate depends on this Onyx checkout's onyx-plugin-api (and, for its tests, on
onyx-runtime) by absolute path: the checkout `onyx` was built from, or $ONYX_SOURCE_DIR
when set (the root of an Onyx repository). Its Cargo.lock starts as a copy of the
checkout's, so the plugin builds against the dependency versions the host was built with.
It has its own [workspace] table, so it builds wherever it is.

EXIT STATUS
  0 when the crate was created; 2 when NAME is not a valid crate name, DIR/NAME exists
  and is not empty, or the files cannot be written. The reason is printed on one line.")]
pub struct NewPluginArgs {
    /// The crate's name (letters, digits, `-` and `_`, starting with a letter).
    #[arg(value_name = "NAME")]
    pub name: String,
    /// Directory to create the crate in (as DIR/NAME).
    #[arg(long, value_name = "DIR", default_value = ".")]
    pub path: PathBuf,
}

/// `onyx dev`.
#[derive(Args, Debug)]
#[command(after_help = "\
THE DEV LOOP
  Each crate is built with `cargo build` (the compiler's messages are shown as usual) and its
  cdylib is loaded. Then its src/ directory, Cargo.toml and build.rs are watched: after a
  change (and 200 ms without another), the crate is rebuilt in the background while frames
  go on, one build per crate at a time (a change during a build starts another after it).
  When the library file has been rewritten, the host reloads the plugin at the start of a
  frame: save_state -> load_state into the new build, the world untouched. A build that fails
  prints the compiler's errors; the previous build keeps running. Builds honour
  CARGO_TARGET_DIR and the crate's own cargo configuration.

  The host runs in a process of its own. If it crashes (a segfault, an abort, a plugin
  calling exit: its one `onyx:` line says which plugin and stage), `onyx dev` says so and
  keeps watching: the next good build starts the host again.

EXIT STATUS
  0 when the run ends (window closed, a plugin quit, --frames reached); 1 if a plugin is
  faulted at the end; 2 if it could not start (a first build failed, a crate has no cdylib,
  a plugin or scene failed to load, no display). The reason is printed on one line.
  3 and 4 are as for `onyx run` (a native crash; a plugin called `exit`).")]
pub struct DevArgs {
    /// A plugin crate's directory (repeatable): built, loaded, rebuilt and reloaded on change.
    #[arg(long = "plugin-crate", value_name = "DIR", required = true)]
    pub plugin_crates: Vec<PathBuf>,
    /// What else to run and how (shared with `onyx run`; `--plugin` libraries are reloaded
    /// when their file changes, but not built).
    #[command(flatten)]
    pub host: HostArgs,
}

/// `onyx dev-host`: `onyx dev`'s arguments, and the libraries its first builds made.
#[derive(Args, Debug)]
pub struct DevHostArgs {
    /// A plugin library built by `onyx dev` (repeatable; loaded first, in order).
    #[arg(long = "library", value_name = "PATH")]
    pub libraries: Vec<PathBuf>,
    /// The arguments `onyx dev` was given.
    #[command(flatten)]
    pub dev: DevArgs,
}

fn parse_setting(text: &str) -> Result<(String, String, String), String> {
    let (target, value) = text
        .split_once('=')
        .ok_or_else(|| format!("`{text}` is not PLUGIN.KEY=VALUE (no `=`)"))?;
    let (plugin, key) = target
        .split_once('.')
        .ok_or_else(|| format!("`{target}` is not PLUGIN.KEY (no `.`)"))?;
    if plugin.is_empty() || key.is_empty() {
        return Err(format!("`{text}`: plugin and key must not be empty"));
    }
    Ok((plugin.to_owned(), key.to_owned(), value.to_owned()))
}

fn parse_seconds(text: &str) -> Result<f64, String> {
    let seconds: f64 = text.parse().map_err(|e| format!("`{text}`: {e}"))?;
    if !seconds.is_finite() || seconds < 0.0 {
        return Err(format!("`{text}` is not a number of seconds (0 or more)"));
    }
    Ok(seconds)
}

fn parse_scale(text: &str) -> Result<f32, String> {
    let scale: f32 = text.parse().map_err(|e| format!("`{text}`: {e}"))?;
    if !(scale.is_finite() && scale > 0.0) {
        return Err(format!("`{text}` is not a scale (a number > 0)"));
    }
    Ok(scale)
}

fn parse_up_axis(text: &str) -> Result<UpAxisFile, String> {
    match text.to_ascii_lowercase().as_str() {
        "y" => Ok(UpAxisFile::Y),
        "z" => Ok(UpAxisFile::Z),
        _ => Err(format!("`{text}` is not an up axis (y or z)")),
    }
}

fn parse_normals(text: &str) -> Result<NormalsFile, String> {
    match text.to_ascii_lowercase().as_str() {
        "smooth" => Ok(NormalsFile::Smooth),
        "flat" => Ok(NormalsFile::Flat),
        degrees => match degrees.parse::<f32>() {
            Ok(d) if (0.0..=180.0).contains(&d) => Ok(NormalsFile::Crease(d)),
            _ => Err(format!(
                "`{text}` is not smooth, flat or a crease angle (0 to 180 degrees)"
            )),
        },
    }
}

fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let (w, h) = text
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("`{text}` is not WIDTHxHEIGHT"))?;
    let w: u32 = w.parse().map_err(|e| format!("width `{w}`: {e}"))?;
    let h: u32 = h.parse().map_err(|e| format!("height `{h}`: {e}"))?;
    if w == 0 || h == 0 {
        return Err("width and height must be at least 1".into());
    }
    Ok((w, h))
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn cli_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn settings_and_sizes_parse_or_explain() {
        assert_eq!(
            parse_setting("hello.quit_after=3").unwrap(),
            ("hello".into(), "quit_after".into(), "3".into())
        );
        assert!(parse_setting("hello=3").unwrap_err().contains("PLUGIN.KEY"));
        assert_eq!(parse_size("640x480").unwrap(), (640, 480));
        assert!(parse_size("640").is_err() && parse_size("0x5").is_err());
        assert_eq!(parse_seconds("2.5").unwrap(), 2.5);
        assert!(parse_seconds("-1").is_err() && parse_seconds("inf").is_err());
    }

    #[test]
    fn import_options_parse_or_explain() {
        let cli = Cli::try_parse_from([
            "onyx",
            "run",
            "--scene",
            "m.glb",
            "--import-scale",
            "0.01",
            "--up-axis",
            "Z",
            "--normals",
            "30",
        ])
        .unwrap_or_else(|e| panic!("{e}"));
        let Command::Run(run) = cli.command else {
            panic!("not run: {:?}", cli.command)
        };
        assert_eq!(
            run.host.import.settings(),
            Some(ImportSettingsFile {
                scale: Some(0.01),
                up_axis: UpAxisFile::Z,
                normals: NormalsFile::Crease(30.0),
            })
        );
        assert_eq!(ImportArgs::default().settings(), None);
        assert!(parse_scale("0").is_err() && parse_scale("-2").is_err());
        assert!(parse_up_axis("x").unwrap_err().contains("y or z"));
        assert_eq!(parse_normals("Flat"), Ok(NormalsFile::Flat));
        assert!(parse_normals("200").is_err() && parse_normals("round").is_err());
    }
}
