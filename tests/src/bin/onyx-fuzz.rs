//! `onyx-fuzz`: the long mutation run over every format Onyx reads.
//!
//! ```text
//! cargo run --release -p onyx-tests --bin onyx-fuzz -- [--formats scene,obj,...]
//!     [--cases N] [--seed S] [--timeout SECS] [--deep] [--record FILE]
//! ```
//!
//! Cases run in child processes (this binary with `--child`), which say which case starts and
//! how it ended. A child that dies — a signal, an abort — or says nothing for `--timeout`
//! seconds (a hang; it is killed) leaves its case recorded as a recipe (`FORMAT SOURCE SEED
//! CASE`, printed, and appended to `--record FILE`), and a new child goes on from the next
//! case. At the end: one line per format with the cases run, read, refused, panics, signals
//! and hangs. `--deep` also opens every library that passes the host's check with the system
//! loader (children restart every 200 of those: each stays mapped).

use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use onyx_tests::fuzz::{Case, Format, Outcome, Recipe};

const USAGE: &str = "\
usage: onyx-fuzz [--formats scene,obj,mtl,png,jpeg,gltf,glb,library] [--cases N]
                 [--seed S] [--timeout SECS] [--deep] [--record FILE]

Mutates every format Onyx reads and feeds each case to its reader in a child process.
  --formats  which formats (default: all)        --cases    cases per format (100000)
  --seed     the run's seed (1)                   --timeout  seconds before a hang (20)
  --deep     also dlopen libraries that pass the host's check
  --record   append the recipe of each failing case to FILE
Exit status: 0 when no case panicked, died of a signal or hung; 1 otherwise; 2 bad usage.";

struct Options {
    formats: Vec<Format>,
    cases: u64,
    seed: u64,
    timeout: Duration,
    deep: bool,
    record: Option<std::path::PathBuf>,
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--child") {
        std::process::exit(child(&args[1..]));
    }
    let options = match parse(&args) {
        Ok(options) => options,
        Err(message) => {
            eprintln!("onyx-fuzz: {message}");
            std::process::exit(2);
        }
    };
    println!(
        "{:<8} {:>8} {:>8} {:>8} {:>7} {:>7} {:>6} {:>9}",
        "format", "cases", "read", "refused", "panics", "signals", "hangs", "cases/s"
    );
    let mut failures = 0;
    for format in &options.formats {
        failures += run_format(*format, &options);
    }
    std::process::exit(i32::from(failures > 0));
}

fn parse(args: &[String]) -> Result<Options, String> {
    let mut options = Options {
        formats: Format::ALL.to_vec(),
        cases: 100_000,
        seed: 1,
        timeout: Duration::from_secs(20),
        deep: false,
        record: None,
    };
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let mut value = || it.next().ok_or(format!("{arg} needs a value"));
        match arg.as_str() {
            "--formats" => {
                options.formats = value()?
                    .split(',')
                    .map(|f| Format::from_name(f).ok_or(format!("unknown format `{f}`")))
                    .collect::<Result<_, _>>()?;
            }
            "--cases" => options.cases = value()?.parse().map_err(|e| format!("--cases: {e}"))?,
            "--seed" => options.seed = value()?.parse().map_err(|e| format!("--seed: {e}"))?,
            "--timeout" => {
                let secs: f64 = value()?.parse().map_err(|e| format!("--timeout: {e}"))?;
                options.timeout = Duration::from_secs_f64(secs.max(0.1));
            }
            "--deep" => options.deep = true,
            "--record" => options.record = Some(value()?.into()),
            "--help" | "-h" => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            other => return Err(format!("unknown argument `{other}`\n{USAGE}")),
        }
    }
    Ok(options)
}

#[derive(Default)]
struct Counts {
    cases: u64,
    read: u64,
    refused: u64,
    panics: u64,
    signals: u64,
    hangs: u64,
}

/// Runs one format's cases in children; returns how many cases failed (panic, signal, hang).
fn run_format(format: Format, options: &Options) -> u64 {
    let corpus = format.corpus();
    if corpus.is_empty() {
        println!(
            "{:<8} skipped: no corpus under {}",
            format.name(),
            format.root().display()
        );
        return 0;
    }
    let started = Instant::now();
    let mut counts = Counts::default();
    let chunk = if options.deep && format == Format::Library {
        200
    } else {
        options.cases
    };
    let mut next = 0u64;
    while next < options.cases {
        let to = (next + chunk).min(options.cases);
        let mut child = Command::new(std::env::current_exe().expect("knows its own path"))
            .args(["--child", format.name()])
            .args(["--seed", &options.seed.to_string()])
            .args(["--from", &next.to_string(), "--to", &to.to_string()])
            .args(options.deep.then_some("--deep"))
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("can start a child");
        let stdout = child.stdout.take().expect("piped");
        let (lines_tx, lines) = mpsc::channel::<String>();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines().map_while(Result::ok) {
                if lines_tx.send(line).is_err() {
                    break;
                }
            }
        });
        let mut running: Option<u64> = None;
        let mut finished_at = next;
        loop {
            match lines.recv_timeout(options.timeout) {
                Ok(line) => {
                    let mut words = line.splitn(3, ' ');
                    match (
                        words.next(),
                        words.next().and_then(|n| n.parse::<u64>().ok()),
                    ) {
                        (Some("case"), Some(n)) => running = Some(n),
                        (Some("done"), Some(n)) => {
                            running = None;
                            finished_at = n + 1;
                            counts.cases += 1;
                            match words.next().unwrap_or("") {
                                "read" => counts.read += 1,
                                "refused" => counts.refused += 1,
                                panic => {
                                    counts.panics += 1;
                                    record(format, &corpus, n, options, panic);
                                }
                            }
                        }
                        _ => {}
                    }
                }
                Err(mpsc::RecvTimeoutError::Timeout) => {
                    let _ = child.kill();
                    let _ = child.wait();
                    if let Some(n) = running {
                        counts.cases += 1;
                        counts.hangs += 1;
                        record(format, &corpus, n, options, "hang");
                        finished_at = n + 1;
                    }
                    break;
                }
                Err(mpsc::RecvTimeoutError::Disconnected) => {
                    let status = child.wait().expect("can wait");
                    if let (Some(n), false) = (running, status.success()) {
                        counts.cases += 1;
                        counts.signals += 1;
                        record(format, &corpus, n, options, &format!("died: {status}"));
                        finished_at = n + 1;
                    }
                    break;
                }
            }
        }
        next = finished_at.max(next + u64::from(finished_at == next));
    }
    let rate = counts.cases as f64 / started.elapsed().as_secs_f64().max(1e-9);
    println!(
        "{:<8} {:>8} {:>8} {:>8} {:>7} {:>7} {:>6} {:>9.0}",
        format.name(),
        counts.cases,
        counts.read,
        counts.refused,
        counts.panics,
        counts.signals,
        counts.hangs,
        rate
    );
    counts.panics + counts.signals + counts.hangs
}

fn record(format: Format, corpus: &[String], case: u64, options: &Options, why: &str) {
    let recipe = Recipe {
        format,
        source: corpus[(case % corpus.len() as u64) as usize].clone(),
        seed: options.seed,
        case,
    };
    println!("  {recipe}    # {why}");
    if let Some(path) = &options.record {
        if let Ok(mut file) = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)
        {
            let _ = writeln!(file, "{recipe}    # {why}");
        }
    }
}

/// `--child FORMAT --seed S --from A --to B [--deep]`: runs cases A..B, saying `case N` before
/// each and `done N read|refused|panic: MESSAGE` after.
fn child(args: &[String]) -> i32 {
    let Some(format) = args.first().and_then(|f| Format::from_name(f)) else {
        return 2;
    };
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
            .and_then(|v| v.parse::<u64>().ok())
            .unwrap_or(0)
    };
    let (seed, from, to) = (value("--seed"), value("--from"), value("--to"));
    let deep = args.iter().any(|a| a == "--deep");
    let corpus = format.corpus();
    let mut cases: Vec<Option<Case>> = corpus.iter().map(|_| None).collect();
    // The readers' own panics are the findings: keep their messages off the terminal.
    std::panic::set_hook(Box::new(|_| {}));
    let stdout = std::io::stdout();
    for n in from..to {
        let index = (n % corpus.len() as u64) as usize;
        if cases[index].is_none() {
            match Case::prepare(format, &corpus[index]) {
                Ok(case) => cases[index] = Some(case),
                Err(_) => continue,
            }
        }
        let Some(case) = &cases[index] else { continue };
        let bytes = format.mutate(&case.original, seed, n);
        let _ = writeln!(stdout.lock(), "case {n}");
        let _ = stdout.lock().flush();
        let result =
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| case.run(&bytes, deep)));
        let word = match result {
            Ok(Outcome::Read) => "read".to_owned(),
            Ok(Outcome::Refused(_)) => "refused".to_owned(),
            Err(payload) => {
                let message = payload
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                    .unwrap_or_default();
                format!("panic: {}", message.replace('\n', " "))
            }
        };
        let _ = writeln!(stdout.lock(), "done {n} {word}");
        let _ = stdout.lock().flush();
    }
    0
}
