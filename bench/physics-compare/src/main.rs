//! `onyx-physics-bench [--quick] [--scenes a,b] [--rates 30,60] [--iterations 1,4]
//! [--repeats N] [--out DIR] [--no-progress]`: see the crate docs of `onyx_physics_bench`,
//! and `--help` for the scenes.

use std::path::PathBuf;

use clap::{CommandFactory, FromArgMatches, Parser};

/// Onyx physics next to rapier3d on the same scenes, swept over step rate and substeps
/// (Onyx) or solver iterations (rapier): error against the analytic answer or a converged
/// reference, and the cost of each setting.
#[derive(Parser, Debug)]
#[command(name = "onyx-physics-bench", about, long_about = None)]
struct Cli {
    /// Reduced sweep and problem sizes (60 and 120 Hz, 1 and 4 substeps, one repetition).
    #[arg(long)]
    quick: bool,
    /// Only these scenes, by name (comma-separated; all when absent; listed below).
    #[arg(long, value_name = "A,B", value_delimiter = ',')]
    scenes: Option<Vec<String>>,
    /// Step rates swept instead of the mode's, Hz (comma-separated).
    #[arg(long, value_name = "HZ,HZ", value_delimiter = ',')]
    rates: Option<Vec<f32>>,
    /// Substeps (Onyx) / solver iterations (rapier) swept instead of the mode's.
    #[arg(long, value_name = "N,N", value_delimiter = ',')]
    iterations: Option<Vec<u32>>,
    /// Timed repetitions of each run instead of the mode's (the median is taken).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    repeats: Option<u64>,
    /// Folder for results.csv, summary.md and the plots.
    #[arg(long, value_name = "DIR", default_value = "target/physics-compare")]
    out: PathBuf,
    /// No progress bar on stderr.
    #[arg(long)]
    no_progress: bool,
}

/// The scenes `--scenes` takes, one per line with what each measures.
fn scene_list() -> String {
    let mut text = String::from("SCENES\n");
    for scene in onyx_physics_bench::scenes::all() {
        text.push_str(&format!("  {:<18} {}\n", scene.name(), scene.metric()));
    }
    text
}

fn main() -> anyhow::Result<()> {
    let command = Cli::command().after_help(scene_list());
    let cli = Cli::from_arg_matches(&command.get_matches())?;
    let opts = onyx_physics_bench::Options {
        quick: cli.quick,
        scenes: cli.scenes,
        out: cli.out,
        progress: !cli.no_progress,
        rates: cli.rates,
        iterations: cli.iterations,
        repeats: cli.repeats.and_then(|n| usize::try_from(n).ok()),
    };
    let report = onyx_physics_bench::run(&opts, true)?;
    println!(
        "\nwrote {}, {} and {} plot(s) in {}",
        report.csv.display(),
        report.markdown.display(),
        report.plots.len(),
        opts.out.display()
    );
    Ok(())
}
