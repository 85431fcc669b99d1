//! Smoke test of the harness: the `--quick` path on three scenes produces CSV rows, a
//! Markdown summary and PNG plots with finite figures. No timing asserts.

use onyx_physics_bench::{run, Options, Report};

/// A `--quick` run with `args`, writing into `dir`.
fn quick_run(dir: &tempfile::TempDir, args: &[&str]) -> Report {
    let opts = Options::parse(
        ["--quick", "--no-progress"]
            .iter()
            .chain(args)
            .map(|s| (*s).to_string())
            .chain(["--out".to_string(), dir.path().display().to_string()]),
    )
    .expect("options parse");
    run(&opts, false).expect("quick run")
}

#[test]
fn quick_run_writes_csv_markdown_and_plots_with_finite_figures() {
    let dir = tempfile::tempdir().expect("temp dir");
    let report = quick_run(&dir, &["--scenes", "free_fall,stack,tunneling"]);

    // 3 scenes × 2 engines × (2 rates × 2 iteration counts).
    assert_eq!(report.rows.len(), 24, "rows: {}", report.rows.len());
    for r in &report.rows {
        assert!(
            r.error.is_finite() && r.figure.is_finite() && r.ms_per_step.is_finite(),
            "non-finite figure in {r:?}"
        );
        assert!(r.ms_per_step >= 0.0 && r.bodies > 0 && r.steps > 0, "{r:?}");
    }

    let csv = std::fs::read_to_string(&report.csv).expect("csv");
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 25, "CSV header + 24 rows, got {}", lines.len());
    assert!(lines[0].starts_with("scene,engine,hz,iterations"));
    for l in &lines[1..] {
        assert_eq!(l.split(',').count(), 11, "CSV row {l:?}");
    }

    let md = std::fs::read_to_string(&report.markdown).expect("markdown");
    for s in [
        "## free_fall",
        "## stack",
        "## tunneling",
        "Pareto front, onyx",
    ] {
        assert!(md.contains(s), "summary.md lacks {s:?}");
    }

    assert_eq!(report.plots.len(), 3);
    for p in &report.plots {
        let bytes = std::fs::read(p).expect("png");
        assert!(
            bytes.len() > 1000 && bytes.starts_with(b"\x89PNG"),
            "{} is not a PNG ({} bytes)",
            p.display(),
            bytes.len()
        );
    }

    // The analytic free-fall error of semi-implicit Euler is g·t·dt/2 (0.16 m at 60 Hz, one
    // substep): a sanity check that the harness measures what it says, loose bound.
    let ff = report
        .rows
        .iter()
        .find(|r| r.scene == "free_fall" && r.settings.hz == 60.0 && r.settings.iterations == 1)
        .expect("free_fall row");
    assert!(
        ff.error < 0.2,
        "free-fall error {} m, expected < 0.2",
        ff.error
    );
}

#[test]
fn unknown_scene_is_an_error() {
    let opts = Options::parse(["--scenes".to_string(), "nope".to_string()]).expect("parses");
    assert!(opts.selected().is_err());
}

#[test]
fn degenerate_hulls_report_gjk_and_epa_iterations_and_failures() {
    let dir = tempfile::tempdir().expect("temp dir");
    let report = quick_run(
        &dir,
        &[
            "--scenes",
            "degenerate_hulls",
            "--rates",
            "60",
            "--iterations",
            "4",
        ],
    );
    let onyx = report
        .rows
        .iter()
        .find(|r| r.engine.name() == "onyx")
        .expect("an onyx row");
    let detail = onyx
        .detail
        .as_deref()
        .expect("onyx reports its narrowphase");
    assert!(detail.starts_with("GJK "), "{detail}");
    let runs: u64 = detail["GJK ".len()..]
        .split(' ')
        .next()
        .and_then(|n| n.parse().ok())
        .expect("a GJK run count");
    assert!(
        runs > 0,
        "hulls resting on a ground ran no GJK query: {detail}"
    );
    assert!(
        report
            .rows
            .iter()
            .all(|r| r.engine.name() == "onyx" || r.detail.is_none()),
        "rapier reports no narrowphase tally"
    );
    let md = std::fs::read_to_string(&report.markdown).expect("markdown");
    assert!(
        md.contains("- onyx 60 Hz ×4: GJK "),
        "summary.md lacks the tally"
    );
}
