//! Output: terminal table, CSV, Markdown summary and one error-vs-cost PNG per scene.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use plotters::prelude::*;

use onyx_physics::PhysicsPreset;

use crate::engine::{EngineKind, StepSettings};
use crate::runner::Row;
use crate::scenes;

/// Header of the terminal table.
#[must_use]
pub fn table_header() -> String {
    format!(
        "{:<12} {:<7} {:>5} {:>4} {:>7} {:>6} {:>10} {:>12} {:>12}",
        "scene", "engine", "hz", "it", "bodies", "steps", "ms/step", "ms/sim-s", "error"
    )
}

/// One row of the terminal table.
#[must_use]
pub fn table_line(r: &Row) -> String {
    format!(
        "{:<12} {:<7} {:>5} {:>4} {:>7} {:>6} {:>10.4} {:>12.3} {:>12.4e}",
        r.scene,
        r.engine.name(),
        r.settings.hz,
        r.settings.iterations,
        r.bodies,
        r.steps,
        r.ms_per_step,
        r.ms_per_sim_second,
        r.error
    )
}

/// Writes `results.csv`; returns its path.
///
/// # Errors
/// On I/O failure.
pub fn write_csv(rows: &[Row], dir: &Path) -> anyhow::Result<PathBuf> {
    let mut s = String::from(
        "scene,engine,hz,iterations,bodies,steps,ms_per_step,ms_per_sim_second,figure,error,joints\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{}",
            r.scene,
            r.engine.name(),
            r.settings.hz,
            r.settings.iterations,
            r.bodies,
            r.steps,
            r.ms_per_step,
            r.ms_per_sim_second,
            r.figure,
            r.error,
            r.joints
        );
    }
    let p = dir.join("results.csv");
    std::fs::write(&p, s)?;
    Ok(p)
}

/// The Pareto front of `rows` (cost = ms per simulated second, lower error is better):
/// each row on it is cheaper than every row with a lower error. Sorted by cost.
#[must_use]
pub fn pareto<'a>(rows: impl IntoIterator<Item = &'a Row>) -> Vec<&'a Row> {
    let mut v: Vec<&Row> = rows
        .into_iter()
        .filter(|r| r.error.is_finite() && r.ms_per_sim_second.is_finite())
        .collect();
    v.sort_by(|a, b| {
        a.ms_per_sim_second
            .total_cmp(&b.ms_per_sim_second)
            .then(a.error.total_cmp(&b.error))
    });
    let mut best = f64::INFINITY;
    v.into_iter()
        .filter(|r| {
            if r.error < best {
                best = r.error;
                true
            } else {
                false
            }
        })
        .collect()
}

/// Writes `summary.md`; returns its path.
///
/// # Errors
/// On I/O failure.
pub fn write_markdown(rows: &[Row], dir: &Path, quick: bool) -> anyhow::Result<PathBuf> {
    let mut s = String::new();
    let _ = writeln!(s, "# Onyx vs rapier3d: speed/accuracy\n");
    let _ = writeln!(
        s,
        "Mode: {}. Cost is CPU ms per simulated second (ms/step × Hz); `it` is Onyx substeps \
         or rapier solver iterations. Timings are the median per-step time (first step \
         excluded) of repeated runs on this machine; errors are against the analytic answer \
         (or the ideal zero of a drift figure).\n",
        if quick { "quick" } else { "full" }
    );
    write_preset_summary(&mut s, rows);
    let names: Vec<&str> = {
        let mut n: Vec<&str> = Vec::new();
        for r in rows {
            if !n.contains(&r.scene) {
                n.push(r.scene);
            }
        }
        n
    };
    for name in names {
        let metric = scenes::all()
            .iter()
            .find(|s| s.name() == name)
            .map_or("", |s| s.metric());
        let _ = writeln!(s, "## {name}\n\nError: {metric}.\n");
        for e in EngineKind::ALL {
            let front = pareto(rows.iter().filter(|r| r.scene == name && r.engine == e));
            let pts: Vec<String> = front
                .iter()
                .map(|r| {
                    format!(
                        "{} Hz ×{} ({:.3} ms/sim-s, err {:.3e})",
                        r.settings.hz, r.settings.iterations, r.ms_per_sim_second, r.error
                    )
                })
                .collect();
            let _ = writeln!(s, "- Pareto front, {}: {}", e.name(), pts.join("; "));
        }
        let _ = writeln!(
            s,
            "\n| engine | Hz | it | preset | bodies | ms/step | ms/sim-s | error |\n|---|---:|---:|---|---:|---:|---:|---:|"
        );
        for r in rows.iter().filter(|r| r.scene == name) {
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {:.4} | {:.3} | {:.3e} |",
                r.engine.name(),
                r.settings.hz,
                r.settings.iterations,
                preset_at(r.settings).map_or("", PhysicsPreset::name),
                r.bodies,
                r.ms_per_step,
                r.ms_per_sim_second,
                r.error
            );
        }
        write_joint_cost(&mut s, rows, name);
        let details: Vec<String> = rows
            .iter()
            .filter(|r| r.scene == name)
            .filter_map(|r| {
                let d = r.detail.as_ref()?;
                Some(format!(
                    "- {} {} Hz ×{}: {d}",
                    r.engine.name(),
                    r.settings.hz,
                    r.settings.iterations
                ))
            })
            .collect();
        if !details.is_empty() {
            let _ = writeln!(s, "\n{}", details.join("\n"));
        }
        let _ = writeln!(s, "\n![{name}]({name}.png)\n");
    }
    let p = dir.join("summary.md");
    std::fs::write(&p, s)?;
    Ok(p)
}

/// For a scene with joints: each preset's cost per joint per step, µs (the whole step,
/// contacts included, divided by the joints), Onyx next to rapier.
fn write_joint_cost(s: &mut String, rows: &[Row], scene: &str) {
    let mut parts = Vec::new();
    for p in PhysicsPreset::ALL {
        let cost = |e: EngineKind| {
            rows.iter()
                .find(|r| r.scene == scene && r.engine == e && preset_at(r.settings) == Some(p))
                .filter(|r| r.joints > 0)
                .map(|r| 1e3 * r.ms_per_step / r.joints as f64)
        };
        if let (Some(o), Some(r)) = (cost(EngineKind::Onyx), cost(EngineKind::Rapier)) {
            parts.push(format!(
                "{} onyx {o:.3} µs, rapier {r:.3} µs ({:.2}×)",
                p.name(),
                o / r
            ));
        }
    }
    if !parts.is_empty() {
        let _ = writeln!(
            s,
            "\nCost per joint per step (whole step / joints): {}.",
            parts.join("; ")
        );
    }
}

/// The Onyx preset whose step rate and substeps are `s`, if any.
#[must_use]
pub fn preset_at(s: StepSettings) -> Option<PhysicsPreset> {
    PhysicsPreset::ALL
        .into_iter()
        .find(|&p| StepSettings::of_preset(p) == s)
}

/// The "Presets" section: per scene, each preset's cost and error in Onyx next to rapier at
/// the same step rate and iteration count, with the cost ratio.
fn write_preset_summary(s: &mut String, rows: &[Row]) {
    let presets: Vec<PhysicsPreset> = PhysicsPreset::ALL
        .into_iter()
        .filter(|p| rows.iter().any(|r| preset_at(r.settings) == Some(*p)))
        .collect();
    if presets.is_empty() {
        return;
    }
    let _ = writeln!(
        s,
        "## Presets\n\nEach preset is one point of the sweep; rapier is run at the same step \
         rate with as many solver iterations as Onyx has substeps. Cost in ms per simulated \
         second; `×` is Onyx cost / rapier cost (below 1: Onyx is faster).\n"
    );
    let mut header = String::from("| scene |");
    let mut rule = String::from("|---|");
    for p in &presets {
        let _ = write!(
            header,
            " {0} onyx ms | {0} onyx err | {0} rapier ms | {0} rapier err | {0} × |",
            p.name()
        );
        rule.push_str("---:|---:|---:|---:|---:|");
    }
    let _ = writeln!(s, "{header}\n{rule}");
    let mut names: Vec<&str> = Vec::new();
    for r in rows {
        if !names.contains(&r.scene) {
            names.push(r.scene);
        }
    }
    for name in names {
        let _ = write!(s, "| {name} |");
        for p in &presets {
            let find = |e: EngineKind| {
                rows.iter()
                    .find(|r| r.scene == name && r.engine == e && preset_at(r.settings) == Some(*p))
            };
            match (find(EngineKind::Onyx), find(EngineKind::Rapier)) {
                (Some(o), Some(r)) => {
                    let _ = write!(
                        s,
                        " {:.3} | {:.3e} | {:.3} | {:.3e} | {:.2} |",
                        o.ms_per_sim_second,
                        o.error,
                        r.ms_per_sim_second,
                        r.error,
                        o.ms_per_sim_second / r.ms_per_sim_second
                    );
                }
                _ => s.push_str(" | | | | |"),
            }
        }
        s.push('\n');
    }
    s.push('\n');
}

/// Registers a system sans-serif font for plot text; false when none is found (plots are
/// then drawn without text).
fn font_ready() -> bool {
    static READY: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *READY.get_or_init(|| {
        const CANDIDATES: [&str; 4] = [
            "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
            "/usr/share/fonts/TTF/DejaVuSans.ttf",
            "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
            "/System/Library/Fonts/Supplemental/Arial.ttf",
        ];
        for c in CANDIDATES {
            if let Ok(bytes) = std::fs::read(c) {
                let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
                if plotters::style::register_font("sans-serif", FontStyle::Normal, bytes).is_ok() {
                    return true;
                }
            }
        }
        false
    })
}

const FLOOR: f64 = 1e-9;

/// Writes `SCENE.png` (error vs cost, log-log, both engines, Pareto fronts as lines);
/// returns its path.
///
/// # Errors
/// On I/O or drawing failure.
pub fn write_plot(rows: &[Row], scene: &str, dir: &Path) -> anyhow::Result<PathBuf> {
    let p = dir.join(format!("{scene}.png"));
    let pts: Vec<&Row> = rows
        .iter()
        .filter(|r| r.scene == scene && r.error.is_finite() && r.ms_per_sim_second > 0.0)
        .collect();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for r in &pts {
        x0 = x0.min(r.ms_per_sim_second);
        x1 = x1.max(r.ms_per_sim_second);
        y0 = y0.min(r.error.max(FLOOR));
        y1 = y1.max(r.error.max(FLOOR));
    }
    if pts.is_empty() {
        (x0, x1, y0, y1) = (0.1, 1.0, FLOOR, 1.0);
    }
    let (x0, x1) = (x0 / 1.5, x1 * 1.5);
    let (y0, y1) = (y0 / 3.0, y1 * 3.0);
    let text = font_ready();
    {
        let root = BitMapBackend::new(&p, (900, 600)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut b = ChartBuilder::on(&root);
        b.margin(20);
        if text {
            b.caption(format!("{scene}: error vs cost"), ("sans-serif", 24))
                .x_label_area_size(45)
                .y_label_area_size(80);
        }
        let mut chart = b.build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())?;
        let mut mesh = chart.configure_mesh();
        if text {
            mesh.x_desc("CPU ms per simulated second")
                .y_desc("error")
                .x_labels(6)
                .x_label_formatter(&|v| format!("{v:.3}"))
                .y_label_formatter(&|v| format!("{v:.0e}"));
        } else {
            mesh.x_labels(0).y_labels(0);
        }
        mesh.draw()?;
        for (e, color) in [(EngineKind::Onyx, BLUE), (EngineKind::Rapier, RED)] {
            let mine: Vec<&Row> = pts.iter().copied().filter(|r| r.engine == e).collect();
            let front = pareto(mine.iter().copied());
            let s = chart.draw_series(LineSeries::new(
                front
                    .iter()
                    .map(|r| (r.ms_per_sim_second, r.error.max(FLOOR))),
                color.stroke_width(2),
            ))?;
            if text {
                s.label(e.name()).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
            }
            chart.draw_series(mine.iter().map(|r| {
                Circle::new((r.ms_per_sim_second, r.error.max(FLOOR)), 4, color.filled())
            }))?;
        }
        if text {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()?;
        }
        root.present()?;
    }
    Ok(p)
}
