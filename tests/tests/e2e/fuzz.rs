//! The bounded mutation run: a few thousand mutated files through every reader — scenes (then
//! frames and a save), OBJ, MTL, PNG, JPEG, glTF, GLB, and the library check the host runs
//! before the system loader. No reader may panic or take long; refusing is fine. Every
//! recorded failing case (`tests/fuzz-regressions.txt`) is replayed. The long run is the
//! `onyx-fuzz` binary (README, "Fuzzing").

use std::time::{Duration, Instant};

use onyx_tests::fuzz::{Case, Format, Outcome, Recipe};

/// The bounded run's seed: fixed, so a failure here is a recipe to keep.
const SEED: u64 = 0x0_4e_79_78;
/// No single case may take longer than this (a debug build on a loaded two-core machine)…
const SLOW_CASE: Duration = Duration::from_secs(5);
/// …or, for a source file that is slow to read intact (Avocado's three 2048² textures in a
/// debug build), than this many times what reading the intact file took in the same run: a
/// mutation that makes a reader several times slower than the real file is a defect, while
/// the machine's load moves both alike.
const SLOW_FACTOR: u32 = 4;

fn cases_for(format: Format) -> u64 {
    match format {
        Format::Scene => 400,
        Format::Obj | Format::Gltf | Format::Library => 300,
        Format::Mtl => 200,
        Format::Png => 600,
        Format::Jpeg | Format::Glb => 120,
    }
}

/// A case's time budget: [`SLOW_CASE`], or [`SLOW_FACTOR`] × the intact file's read time.
fn budget(case: &Case) -> Duration {
    let started = Instant::now();
    let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        case.run(&case.original, false)
    }));
    SLOW_CASE.max(started.elapsed() * SLOW_FACTOR)
}

/// Runs one case; `Err` with what went wrong if it panicked or took longer than `budget`.
fn run_case(
    format: Format,
    case: &Case,
    bytes: &[u8],
    budget: Duration,
) -> Result<Outcome, String> {
    let started = Instant::now();
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| case.run(bytes, false)));
    let took = started.elapsed();
    match result {
        Ok(_) if took > budget => Err(format!("took {took:.1?} (budget {budget:.1?})")),
        Ok(outcome) => Ok(outcome),
        Err(payload) => Err(format!(
            "panicked: {}",
            payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                .unwrap_or_default()
        ))
        .map_err(|e| format!("{} {e}", format.name())),
    }
}

#[test]
fn every_reader_survives_a_few_thousand_mutated_files() {
    let mut failures = Vec::new();
    let mut table = Vec::new();
    for format in Format::ALL {
        let corpus = format.corpus();
        if corpus.is_empty() {
            eprintln!(
                "{}: skipped, no corpus under {} (the shared fixtures, or the plugin libraries \
                 the README's test command builds)",
                format.name(),
                format.root().display()
            );
            continue;
        }
        let mut cases: Vec<Option<(Case, Duration)>> = corpus.iter().map(|_| None).collect();
        let (mut read, mut refused) = (0u32, 0u32);
        let started = Instant::now();
        for n in 0..cases_for(format) {
            let index = (n % corpus.len() as u64) as usize;
            let (case, budget) = cases[index].get_or_insert_with(|| {
                let case =
                    Case::prepare(format, &corpus[index]).expect("the corpus file can be copied");
                let budget = budget(&case);
                (case, budget)
            });
            let bytes = format.mutate(&case.original, SEED, n);
            match run_case(format, case, &bytes, *budget) {
                Ok(Outcome::Read) => read += 1,
                Ok(Outcome::Refused(_)) => refused += 1,
                Err(why) => {
                    let recipe = Recipe {
                        format,
                        source: corpus[index].clone(),
                        seed: SEED,
                        case: n,
                    };
                    failures.push(format!("{recipe}    # {why}"));
                }
            }
        }
        table.push(format!(
            "{:<8} {:>5} cases: {read:>5} read, {refused:>5} refused, {:.1?}",
            format.name(),
            cases_for(format),
            started.elapsed()
        ));
    }
    eprintln!("{}", table.join("\n"));
    assert!(
        failures.is_empty(),
        "cases that panicked or hung (add them to tests/fuzz-regressions.txt once fixed):\n{}",
        failures.join("\n")
    );
}

#[test]
fn recorded_failing_cases_stay_fixed() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz-regressions.txt");
    let text = std::fs::read_to_string(&path).expect("tests/fuzz-regressions.txt exists");
    let mut failed = Vec::new();
    for line in text.lines() {
        let Some(recipe) = Recipe::parse(line) else {
            continue;
        };
        let recipe = recipe.unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        if !recipe.format.root().join(&recipe.source).is_file() {
            eprintln!("{recipe}: skipped, its source file is absent");
            continue;
        }
        let case = Case::prepare(recipe.format, &recipe.source).expect("the source can be copied");
        let bytes = recipe
            .format
            .mutate(&case.original, recipe.seed, recipe.case);
        if let Err(why) = run_case(recipe.format, &case, &bytes, budget(&case)) {
            failed.push(format!("{recipe}: {why}"));
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}
