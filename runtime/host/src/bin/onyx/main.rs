//! `onyx`: the command line of the Onyx host.

mod cli;
mod crate_graph;
mod dev;
mod logging;
mod new_plugin;

use std::process::ExitCode;

use anyhow::Context as _;
use clap::Parser;
use onyx_runtime::clock::ClockSettings;
use onyx_runtime::fs::write_atomically;
use onyx_runtime::plugins::{plugin_search, PluginSearchPath};
use onyx_runtime::render::{save_png, RenderSystem, ScreenshotError};
use onyx_runtime::window::{run_windowed, WindowOptions};
use onyx_runtime::{Host, HostConfig, PluginStatus, ScenePhysics};

use cli::{Cli, Command, HostArgs, RunArgs};

/// Why `onyx` stopped, with its exit code.
enum Failure {
    /// The run could not start (exit 2).
    Start(anyhow::Error),
    /// The run happened but was not clean (exit 1).
    Run(anyhow::Error),
    /// A host process ended with this status and said why itself (`onyx dev`).
    Reported(u8),
}

fn main() -> ExitCode {
    logging::install();
    let cli = Cli::parse();
    if matches!(cli.command, Command::Run(_) | Command::DevHost(_)) {
        onyx_runtime::watchdog::install_crash_report();
    }
    let result = match cli.command {
        Command::Run(args) => run(args),
        Command::Plugins => {
            list_plugins();
            Ok(())
        }
        Command::NewPlugin(args) => new_plugin::new_plugin(args),
        Command::Dev(args) => dev::dev(args),
        Command::DevHost(args) => dev::dev_host(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Start(e)) => {
            eprintln!("onyx: {e:#}");
            ExitCode::from(2)
        }
        Err(Failure::Run(e)) => {
            eprintln!("onyx: {e:#}");
            ExitCode::from(1)
        }
        Err(Failure::Reported(code)) => ExitCode::from(code),
    }
}

/// The host configuration of `onyx run` and `onyx dev`.
fn host_config(args: &HostArgs) -> HostConfig {
    HostConfig {
        clock: ClockSettings {
            fixed_hz: args.fixed_hz.unwrap_or(60.0),
            max_steps_per_frame: args.max_steps,
            ..Default::default()
        },
        plugin_settings: args.settings.clone(),
        search_path: PluginSearchPath::from_env(),
        // Relative model and texture paths start from the working directory.
        asset_root: Default::default(),
        keep_old_builds: args.keep_old_builds,
        ..HostConfig::default()
    }
}

/// `Err(Failure::Run)` naming every faulted plugin and every other incident, if any.
fn check_faults(host: &Host) -> Result<(), Failure> {
    let faults: Vec<String> = host
        .plugins()
        .iter()
        .filter_map(|p| match p.status() {
            PluginStatus::Faulted { stage, message } => Some(format!(
                "plugin `{}` faulted in {stage}: {message}",
                p.name()
            )),
            PluginStatus::Running => None,
        })
        .chain(host.incidents().iter().cloned())
        .collect();
    if !faults.is_empty() {
        return Err(Failure::Run(anyhow::anyhow!(faults.join("; "))));
    }
    Ok(())
}

/// A host set up as `args` say: `libraries` first, then `--plugin`s in order, then the scene.
fn start_host(args: &HostArgs, libraries: &[std::path::PathBuf]) -> Result<Host, Failure> {
    if args.watchdog > 0.0 {
        onyx_runtime::watchdog::start(onyx_runtime::watchdog::WatchdogSettings {
            limit: std::time::Duration::from_secs_f64(args.watchdog),
            ..Default::default()
        });
    }
    let mut host = Host::new(host_config(args));
    for library in libraries {
        host.load_plugin_file(library)
            .map_err(|e| Failure::Start(anyhow::Error::new(e)))?;
    }
    for spec in &args.plugins {
        host.load_plugin(spec)
            .map_err(|e| Failure::Start(anyhow::Error::new(e)))?;
    }
    if let Some(settings) = args.import.settings() {
        // Checked by the parsers; a RON scene names its models' settings itself.
        let settings = settings
            .settings()
            .map_err(|e| Failure::Start(anyhow::anyhow!(e)))?;
        match &args.scene {
            Some(scene) if onyx_runtime::scene::is_gltf_scene(scene) => {
                host.set_import_settings(scene, settings);
            }
            _ => {
                return Err(Failure::Start(anyhow::anyhow!(
                    "--import-scale, --up-axis and --normals apply to a glTF --scene \
                     (.gltf, .glb); a RON scene gives its models' settings in its `imports` table"
                )))
            }
        }
    }
    if let Some(scene) = &args.scene {
        host.load_scene(scene)
            .map_err(|e| Failure::Start(anyhow::Error::new(e)))?;
    }
    // The command line wins over the scene: its preset replaces the scene's step rate and
    // substeps (and nothing else the scene sets), its rate overrides either.
    let chosen = match (args.physics, host.physics().scene_physics()) {
        (Some(preset), Some(from_scene)) => Some(from_scene.with_preset(preset)),
        (Some(preset), None) => Some(ScenePhysics::preset(preset)),
        (None, Some(from_scene)) => Some(from_scene.clone()),
        (None, None) => None,
    };
    if let Some(mut physics) = chosen {
        physics.fixed_hz = args.fixed_hz.or(physics.fixed_hz);
        physics
            .validate()
            .map_err(|e| Failure::Start(anyhow::anyhow!(e)))?;
        host.set_physics(physics);
    }
    Ok(host)
}

/// The sky `--sky` names (the procedural one without it).
fn sky(args: &HostArgs) -> onyx_render::Sky {
    args.sky
        .clone()
        .map_or_else(onyx_render::Sky::default, onyx_render::Sky::image)
}

/// The window `args` ask for, titled `title`.
fn window_options(args: &HostArgs, title: &str) -> WindowOptions {
    WindowOptions {
        title: title.to_owned(),
        size: args.size,
        frames: args.frames,
        vsync: !args.no_vsync,
        msaa_samples: args.msaa,
        sky: sky(args),
        ..Default::default()
    }
}

fn run(run_args: RunArgs) -> Result<(), Failure> {
    let args = &run_args.host;
    let mut host = start_host(args, &[])?;

    let (frames, render) = if args.headless {
        let dt = host.clock_mut().fixed_delta();
        let mut frames = 0u64;
        while args.frames.is_none_or(|n| frames < n) {
            frames += 1;
            if host.frame(dt).quit {
                break;
            }
        }
        (frames, None)
    } else {
        let options = window_options(args, "Onyx");
        let summary =
            run_windowed(&mut host, options).map_err(|e| Failure::Start(anyhow::Error::new(e)))?;
        (summary.frames, summary.render)
    };
    if let Some(path) = &run_args.screenshot {
        screenshot(&mut host, render, args, path)?;
    }
    host.shutdown();
    tracing::info!(frames, ticks = host.time().ticks, "run finished");

    if let Some(path) = &run_args.dump_state {
        let text = serde_json::to_string_pretty(&host.dump_state())
            .context("could not serialize the state dump")
            .map_err(Failure::Run)?;
        write_atomically(path, text.as_bytes())
            .with_context(|| format!("could not write the state dump to `{}`", path.display()))
            .map_err(Failure::Run)?;
    }
    if let Some(path) = &run_args.save_scene {
        host.save_scene(path)
            .map_err(|e| Failure::Run(anyhow::Error::new(e)))?;
    }
    check_faults(&host)
}

/// Renders the world offscreen (with the window's renderer when there was one) and saves it.
/// A size the GPU cannot draw is refused like a bad argument (exit 2); any other failure is
/// a failed run (exit 1).
fn screenshot(
    host: &mut Host,
    render: Option<RenderSystem>,
    args: &HostArgs,
    path: &std::path::Path,
) -> Result<(), Failure> {
    let (width, height) = args.size;
    let run_error = |e: anyhow::Error| Failure::Run(e);
    let mut system = match render {
        Some(system) => system,
        None => RenderSystem::new_headless(RenderSystem::offscreen_settings().with_sky(sky(args)))
            .map_err(|e| run_error(e.into()))?,
    };
    let image = host
        .render_image(&mut system, width, height)
        .map_err(|e| match e {
            ScreenshotError::TooLarge { .. } => Failure::Start(e.into()),
            other => run_error(other.into()),
        })?;
    save_png(&image, path).map_err(|e| run_error(e.into()))?;
    tracing::info!(path = %path.display(), width, height, "screenshot saved");
    Ok(())
}

/// Libraries of the test suite's fixture plugins (`tests/fixtures/`) are named so; `onyx
/// plugins` does not list them.
const TEST_FIXTURE_PREFIX: &str = "fixture_";

fn list_plugins() {
    let search = PluginSearchPath::from_env();
    println!("plugin search path (first match wins):");
    let mut fixtures = 0;
    for dir in search.dirs() {
        println!("  {}", dir.display());
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        let mut found: Vec<String> = entries
            .filter_map(|e| e.ok())
            .map(|e| e.path())
            .filter(|p| {
                p.file_name()
                    .and_then(|n| n.to_str())
                    .is_some_and(|n| n.ends_with(std::env::consts::DLL_SUFFIX))
            })
            .map(|p| plugin_search::name_from_path(&p))
            .collect();
        let all = found.len();
        found.retain(|name| !name.starts_with(TEST_FIXTURE_PREFIX));
        fixtures += all - found.len();
        found.sort();
        for name in found {
            println!("    {name}");
        }
    }
    if fixtures > 0 {
        println!("({fixtures} test fixture libraries, {TEST_FIXTURE_PREFIX}*, not listed)");
    }
}
