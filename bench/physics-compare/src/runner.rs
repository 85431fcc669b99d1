//! The sweep: every scene × engine × setting, timed and measured.

use std::path::PathBuf;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};

use crate::engine::{EngineKind, StepSettings};
use crate::scenes::{self, Reference, Scene, Size};

/// Runner options (the command line).
#[derive(Clone, Debug)]
pub struct Options {
    /// Reduced sweep and sizes.
    pub quick: bool,
    /// Only these scenes (by name); all when `None`.
    pub scenes: Option<Vec<String>>,
    /// Output folder for the CSV, Markdown and PNG files.
    pub out: PathBuf,
    /// Show a progress bar (on stderr).
    pub progress: bool,
    /// Step rates swept instead of the mode's.
    pub rates: Option<Vec<f32>>,
    /// Substeps / iterations swept instead of the mode's.
    pub iterations: Option<Vec<u32>>,
    /// Timed repetitions instead of the mode's.
    pub repeats: Option<usize>,
}

fn list<T: std::str::FromStr>(flag: &str, value: Option<String>) -> anyhow::Result<Vec<T>> {
    let value = value.ok_or_else(|| anyhow::anyhow!("{flag} needs a comma-separated list"))?;
    value
        .split(',')
        .map(|v| {
            v.trim()
                .parse::<T>()
                .map_err(|_| anyhow::anyhow!("{flag}: {v:?} is not a number"))
        })
        .collect()
}

impl Default for Options {
    fn default() -> Self {
        Self {
            quick: false,
            scenes: None,
            out: PathBuf::from("target/physics-compare"),
            progress: true,
            rates: None,
            iterations: None,
            repeats: None,
        }
    }
}

impl Options {
    /// Parses `[--quick] [--scenes a,b] [--out DIR]`.
    ///
    /// # Errors
    /// On an unknown flag or a missing value.
    pub fn parse(args: impl IntoIterator<Item = String>) -> anyhow::Result<Self> {
        let mut o = Self::default();
        let mut it = args.into_iter();
        while let Some(a) = it.next() {
            match a.as_str() {
                "--quick" => o.quick = true,
                "--no-progress" => o.progress = false,
                "--rates" => o.rates = Some(list("--rates", it.next())?),
                "--iterations" => o.iterations = Some(list("--iterations", it.next())?),
                "--repeats" => {
                    let n: Vec<usize> = list("--repeats", it.next())?;
                    o.repeats = n.first().copied().filter(|n| *n > 0);
                }
                "--scenes" => {
                    let v = it
                        .next()
                        .ok_or_else(|| anyhow::anyhow!("--scenes needs a list"))?;
                    o.scenes = Some(v.split(',').map(|s| s.trim().to_string()).collect());
                }
                "--out" => {
                    o.out = PathBuf::from(
                        it.next()
                            .ok_or_else(|| anyhow::anyhow!("--out needs a folder"))?,
                    );
                }
                "-h" | "--help" => {
                    anyhow::bail!(
                        "usage: onyx-physics-bench [--quick] [--scenes a,b] [--rates 30,60] \
                         [--iterations 1,4] [--repeats N] [--out DIR] [--no-progress]\n\
                         scenes: {}",
                        scenes::all()
                            .iter()
                            .map(|s| s.name())
                            .collect::<Vec<_>>()
                            .join(",")
                    )
                }
                other => anyhow::bail!("unknown argument {other:?} (try --help)"),
            }
        }
        Ok(o)
    }

    /// Problem size.
    #[must_use]
    pub fn size(&self) -> Size {
        if self.quick {
            Size::Quick
        } else {
            Size::Full
        }
    }

    /// Step rates swept.
    #[must_use]
    pub fn rates(&self) -> Vec<f32> {
        if let Some(r) = &self.rates {
            return r.clone();
        }
        if self.quick {
            vec![60.0, 120.0]
        } else {
            vec![30.0, 60.0, 120.0, 240.0]
        }
    }

    /// Substeps (Onyx) / solver iterations (rapier) swept.
    #[must_use]
    pub fn iterations(&self) -> Vec<u32> {
        if let Some(i) = &self.iterations {
            return i.clone();
        }
        if self.quick {
            vec![1, 4]
        } else {
            vec![1, 2, 4, 8]
        }
    }

    /// Timed repetitions of each run (median taken).
    #[must_use]
    pub fn repeats(&self) -> usize {
        if let Some(n) = self.repeats {
            return n;
        }
        if self.quick {
            1
        } else {
            3
        }
    }

    /// The selected scenes.
    ///
    /// # Errors
    /// On an unknown scene name.
    pub fn selected(&self) -> anyhow::Result<Vec<&'static dyn Scene>> {
        let all = scenes::all();
        match &self.scenes {
            None => Ok(all),
            Some(names) => names
                .iter()
                .map(|n| {
                    all.iter().copied().find(|s| s.name() == n).ok_or_else(|| {
                        anyhow::anyhow!(
                            "unknown scene {n:?}; known: {}",
                            all.iter().map(|s| s.name()).collect::<Vec<_>>().join(",")
                        )
                    })
                })
                .collect(),
        }
    }
}

/// One measured point: scene × engine × setting.
#[derive(Clone, Debug)]
pub struct Row {
    /// Scene name.
    pub scene: &'static str,
    /// Engine.
    pub engine: EngineKind,
    /// Step setting.
    pub settings: StepSettings,
    /// Bodies in the scene.
    pub bodies: usize,
    /// Joints in the scene.
    pub joints: usize,
    /// Steps per run.
    pub steps: usize,
    /// Median ms per step (first step of each run excluded; median over repeats).
    pub ms_per_step: f64,
    /// CPU ms per simulated second (`ms_per_step × hz`).
    pub ms_per_sim_second: f64,
    /// The scene's raw figure.
    pub figure: f64,
    /// Error against the analytic answer or the converged reference.
    pub error: f64,
    /// What else the last run showed ([`crate::scenes::Trial::detail`]).
    pub detail: Option<String>,
}

/// Outcome of one run: timing and figure.
struct Measured {
    ms_per_step: f64,
    figure: f64,
    detail: Option<String>,
    bodies: usize,
    joints: usize,
    steps: usize,
}

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Builds and runs `scene` once in `engine` at `s`.
fn run_once(scene: &dyn Scene, engine: EngineKind, s: StepSettings, size: Size) -> Measured {
    let mut e = engine.create(s);
    let mut trial = scene.build(e.as_mut(), s, size);
    let steps = scene.steps(s, size);
    let mut times = Vec::with_capacity(steps);
    for _ in 0..steps {
        let t = Instant::now();
        e.step();
        times.push(t.elapsed().as_secs_f64() * 1e3);
        trial.observe(e.as_ref());
    }
    // First step excluded (pair creation, allocation).
    let ms = if times.len() > 1 {
        median(&mut times[1..])
    } else {
        median(&mut times)
    };
    Measured {
        ms_per_step: ms,
        figure: trial.figure(e.as_ref()),
        detail: trial.detail(e.as_ref()),
        bodies: e.len(),
        joints: e.joint_count(),
        steps,
    }
}

/// Runs the whole sweep. `on_row` sees each row as it is produced.
///
/// # Errors
/// On an unknown scene name.
pub fn run_sweep(opts: &Options, mut on_row: impl FnMut(&Row)) -> anyhow::Result<Vec<Row>> {
    let scenes = opts.selected()?;
    let size = opts.size();
    let rates = opts.rates();
    let iters = opts.iterations();
    let settings: Vec<StepSettings> = rates
        .iter()
        .flat_map(|&hz| {
            iters
                .iter()
                .map(move |&it| StepSettings { hz, iterations: it })
        })
        .collect();
    let converged = scenes
        .iter()
        .filter(|s| s.reference() == Reference::Converged)
        .count();
    let total = (scenes.len() * settings.len() * opts.repeats() + converged) * 2;
    let pb = if opts.progress {
        ProgressBar::new(total as u64)
    } else {
        ProgressBar::hidden()
    };
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} {elapsed} {msg}") {
        pb.set_style(style);
    }
    let mut rows = Vec::new();
    for scene in scenes {
        let mut references = Vec::new();
        for engine in EngineKind::ALL {
            let reference = if scene.reference() == Reference::Converged {
                pb.set_message(format!("{} {} reference", scene.name(), engine.name()));
                let r = run_once(scene, engine, StepSettings::REFERENCE, size).figure;
                pb.inc(1);
                Some(r)
            } else {
                None
            };
            references.push(reference);
        }
        // Per setting, each repeat runs both engines back to back, so a machine that slows
        // down or speeds up during the sweep (other jobs, clocks) weighs on both alike.
        let mut scene_rows: Vec<Vec<Row>> = EngineKind::ALL.iter().map(|_| Vec::new()).collect();
        for &s in &settings {
            let mut ms: Vec<Vec<f64>> = EngineKind::ALL.iter().map(|_| Vec::new()).collect();
            let mut last: Vec<Option<Measured>> = EngineKind::ALL.iter().map(|_| None).collect();
            for _ in 0..opts.repeats() {
                for (e, &engine) in EngineKind::ALL.iter().enumerate() {
                    pb.set_message(format!(
                        "{} {} {} Hz x{}",
                        scene.name(),
                        engine.name(),
                        s.hz,
                        s.iterations
                    ));
                    let m = run_once(scene, engine, s, size);
                    ms[e].push(m.ms_per_step);
                    last[e] = Some(m);
                    pb.inc(1);
                }
            }
            for (e, &engine) in EngineKind::ALL.iter().enumerate() {
                let m = last[e].take().expect("at least one repeat");
                let ms_per_step = median(&mut ms[e]);
                let error = match references[e] {
                    Some(r) => (m.figure - r).abs(),
                    None => m.figure,
                };
                scene_rows[e].push(Row {
                    scene: scene.name(),
                    engine,
                    settings: s,
                    bodies: m.bodies,
                    joints: m.joints,
                    steps: m.steps,
                    ms_per_step,
                    ms_per_sim_second: ms_per_step * f64::from(s.hz),
                    figure: m.figure,
                    error,
                    detail: m.detail,
                });
            }
        }
        // Rows in the table's order: one engine's settings, then the other's.
        for row in scene_rows.into_iter().flatten() {
            on_row(&row);
            rows.push(row);
        }
    }
    pb.finish_and_clear();
    Ok(rows)
}
