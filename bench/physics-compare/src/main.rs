//! `onyx-physics-bench [--quick] [--scenes a,b] [--out DIR] [--no-progress]`: see the crate
//! docs of `onyx_physics_bench`.

fn main() -> anyhow::Result<()> {
    let opts = onyx_physics_bench::Options::parse(std::env::args().skip(1))?;
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
