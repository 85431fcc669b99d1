//! # onyx-physics-bench
//!
//! Side-by-side speed/accuracy comparison of Onyx physics and rapier3d. Each scene in
//! [`scenes`] is built in both engines (through [`engine::Engine`]) and stepped over a sweep
//! of step rates (30/60/120/240 Hz) × substeps (Onyx) or solver iterations (rapier)
//! (1/2/4/8); [`runner`] times and measures each point, [`output`] writes a terminal
//! table, `results.csv`, `summary.md` and one error-vs-cost PNG per scene.
//!
//! Run: `cargo run --release -p onyx-physics-bench -- [--quick] [--scenes a,b] [--out DIR]`.

pub mod engine;
pub mod joint_spec;
pub mod output;
pub mod runner;
pub mod scenes;

use std::path::PathBuf;

pub use runner::{Options, Row};

/// What a run produced.
#[derive(Debug)]
pub struct Report {
    /// Every measured point.
    pub rows: Vec<Row>,
    /// `results.csv`.
    pub csv: PathBuf,
    /// `summary.md`.
    pub markdown: PathBuf,
    /// One PNG per scene.
    pub plots: Vec<PathBuf>,
}

/// Runs the sweep and writes all outputs; `print` echoes the table to stdout.
///
/// # Errors
/// On an unknown scene, or failure writing outputs.
pub fn run(opts: &Options, print: bool) -> anyhow::Result<Report> {
    std::fs::create_dir_all(&opts.out)?;
    if print {
        println!("{}", output::table_header());
    }
    let rows = runner::run_sweep(opts, |r| {
        if print {
            println!("{}", output::table_line(r));
        }
    })?;
    let csv = output::write_csv(&rows, &opts.out)?;
    let markdown = output::write_markdown(&rows, &opts.out, opts.quick)?;
    let mut plots = Vec::new();
    for s in opts.selected()? {
        plots.push(output::write_plot(&rows, s.name(), &opts.out)?);
    }
    Ok(Report {
        rows,
        csv,
        markdown,
        plots,
    })
}
