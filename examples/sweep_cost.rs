//! The cost of a sweep of Q/μP on CONTACT's Carter scene (cases/carter2d_contact.yaml): every
//! run cold and alone (scene, assembly, Newton, as a sweep ran its runs before the sequence
//! solver; nothing written, and once more with each run's files written as `rollbem run` writes
//! them) against the sweep of `rollbem sweep` (src/sweep.rs: the runs ordered by value, one
//! chain per thread on one shared assembly, each warm-started from the last; its table and
//! record written, no per-run files), and against one cold run alone. Two sweeps: 100 values
//! (0, 0.01, …, 0.99) on 100 elements and 1001 values (0 to 0.999 in steps of 0.000999)
//! on 41 elements, each on all threads and on one. Best of `--repeat N` (default 3), all
//! measured one after the other in one process, so their ratios share the machine's load.
//!
//! With `--contact BIN` (CONTACT's executable, built outside the repository; docs/performance.md
//! says how), the same process also times CONTACT on its own benchmark of the Carter scene,
//! `perfc_test/carter2d_100.inp` (1000 cases of creepage; `--contact-inp FILE`, by default
//! `perfc_test/carter2d_100.inp` beside the folder holding BIN's source tree), run as
//! `OMP_NUM_THREADS=1 BIN 2 carter2d_100` in a temporary folder (best of `--repeat`, wall
//! time, its output files included as CONTACT writes them), and prints the ratio of rollbem's
//! 1001-value sweep to it on each thread count. Without `--contact` nothing else runs.
//!
//! Run: `cargo run --release --example sweep_cost [-- --repeat 5] [--contact BIN
//! [--contact-inp FILE]]`. The ratios are in docs/performance.md ("Sweeps").

pub mod common;

use common::{case_path, Table};
use rayon::prelude::*;
use rollbem::sequence::GridReuse;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

/// The value following `flag` on the command line.
fn arg(args: &[String], flag: &str) -> Option<String> {
    args.iter()
        .position(|a| a == flag)
        .and_then(|i| args.get(i + 1))
        .cloned()
}

/// CONTACT's input for the comparison: `--contact-inp`, or `perfc_test/carter2d_100.inp` of
/// the source tree holding the executable (the executable in its `src/` folder, or a link to it).
fn contact_inp(args: &[String], bin: &Path) -> PathBuf {
    if let Some(inp) = arg(args, "--contact-inp") {
        return PathBuf::from(inp);
    }
    let bin = bin.canonicalize().expect("--contact: an existing executable");
    bin.ancestors()
        .skip(1)
        .map(|d| d.join("perfc_test/carter2d_100.inp"))
        .find(|p| p.is_file())
        .expect("perfc_test/carter2d_100.inp beside CONTACT's executable; give --contact-inp FILE")
}

/// CONTACT's run of `inp` (copied into a fresh folder under `dir`) on one thread, as
/// `OMP_NUM_THREADS=1 BIN 2 <stem>`: its wall time [s], its output files written.
fn contact_run(bin: &Path, inp: &Path, dir: &Path) -> f64 {
    let stem = inp.file_stem().and_then(|s| s.to_str()).expect("an input file name");
    std::fs::create_dir_all(dir).expect("a folder for CONTACT");
    std::fs::copy(inp, dir.join(format!("{stem}.inp"))).expect("copy CONTACT's input");
    let t = Instant::now();
    let status = Command::new(bin)
        .args(["2", stem])
        .env("OMP_NUM_THREADS", "1")
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .expect("CONTACT starts");
    let wall = t.elapsed().as_secs_f64();
    assert!(status.success(), "CONTACT ran: {status}");
    let out = std::fs::read_to_string(dir.join(format!("{stem}.out"))).expect("CONTACT's .out");
    assert!(!out.is_empty(), "CONTACT wrote its output");
    wall
}

/// The values of Q/μP: `n` of them from 0 in steps of `step`.
fn ratios(n: usize, step: f64) -> Vec<String> {
    (0..n)
        .map(|k| format!("{}", (k as f64 * step * 1e6).round() / 1e6))
        .collect()
}

/// Every run cold and alone, in parallel; with `files`, each written to its own folder under
/// `dir`. Returns the wall time [s] and the Newton iterations.
fn cold(case: &Path, elements: &str, values: &[String], files: Option<&Path>) -> (f64, usize) {
    let t = Instant::now();
    let iterations: usize = values
        .par_iter()
        .enumerate()
        .map(|(k, v)| {
            let set = [elements.to_string(), format!("load.tangential.ratio={v}")];
            match files {
                Some(dir) => {
                    let r = rollbem::app::run(case, &set, Some(&dir.join(format!("run_{k:04}")))).expect("run");
                    r.report.iterations
                }
                None => rollbem::app::solve_case(case, &set).expect("solves").report.iterations,
            }
        })
        .sum();
    (t.elapsed().as_secs_f64(), iterations)
}

/// The sweep as `rollbem sweep` runs it (table and record only) into `dir`. Returns the wall
/// time [s] and the Newton iterations.
fn swept(case: &Path, elements: &str, values: &[String], dir: &Path) -> (f64, usize) {
    let vary = rollbem::sweep::Vary {
        key: "load.tangential.ratio".into(),
        values: values.to_vec(),
    };
    let t = Instant::now();
    let report = rollbem::sweep::run(case, &[elements.to_string()], &[vary], None, dir, false, false).expect("sweep");
    let wall = t.elapsed().as_secs_f64();
    assert!(report.rows.iter().all(|r| r.status == "ok"), "every run converges");
    let iterations = report.rows.iter().map(|r| r.results[1].parse::<usize>().unwrap()).sum();
    (wall, iterations)
}

/// Best of `repeat` of `f`'s (time, iterations).
fn best(repeat: usize, mut f: impl FnMut() -> (f64, usize)) -> (f64, usize) {
    (0..repeat)
        .map(|_| f())
        .fold((f64::INFINITY, 0), |b, r| if r.0 < b.0 { r } else { b })
}

/// One error-controlled run of Q/μP = `v` at `tolerance` on `case`, from `chain`'s last run
/// (`None`: cold, on the start grid): (elements of the result, Newton iterations, passes), or
/// None when the run failed (its grid reached `contact.grid.max_elements` first).
fn adaptive_run(
    case: &Path,
    tolerance: &str,
    v: &str,
    chain: Option<&mut rollbem::sequence::GridChain>,
) -> Option<Counts> {
    let set = [tolerance.to_string(), format!("load.tangential.ratio={v}")];
    let read = |s: &rollbem::app::Solved| {
        let a = s.adaptation.as_ref().expect("an error-controlled run");
        let iterations = a.steps.iter().map(|p| p.iterations).sum();
        Counts {
            elements: s.problem.grid.n_elements(),
            iterations,
            passes: a.steps.len(),
        }
    };
    match chain {
        None => rollbem::app::solve_case(case, &set).ok().map(|s| read(&s)),
        Some(chain) => {
            let case = rollbem::app::load_case(case, &set).expect("loads");
            let scene = rollbem::scene::Scene::from_case(&case).expect("scene");
            chain.solve_with(scene, Instant::now(), read).ok()
        }
    }
}

/// What one error-controlled run took.
#[derive(Debug, Clone, Copy)]
struct Counts {
    elements: usize,
    iterations: usize,
    passes: usize,
}

/// CPU time [s] this process has used (user and system, from /proc/self/stat; 10 ms ticks):
/// the work of a one-thread chain, without the time it waited while other processes ran.
fn cpu_seconds() -> f64 {
    let stat = std::fs::read_to_string("/proc/self/stat").expect("/proc/self/stat");
    // The fields after the command name (which is in parentheses and may hold spaces).
    let rest = &stat[stat.rfind(')').expect("a command name") + 2..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    // utime and stime are fields 14 and 15 of the whole line, 12 and 13 after the name.
    let ticks: f64 = fields[11].parse::<f64>().unwrap() + fields[12].parse::<f64>().unwrap();
    ticks / 100.0
}

/// One way of running the error-controlled sweep, timed: wall and CPU time [s], and each
/// run's counts (None: failed).
struct Timed {
    wall: f64,
    cpu: f64,
    runs: Vec<Option<Counts>>,
}

/// The row of `t` against the cold runs' CPU time `cold_cpu` [s].
fn adaptive_row(label: &str, threads: usize, start: &str, t: &Timed, cold_cpu: f64) -> Vec<String> {
    let all = &t.runs;
    let runs: Vec<Counts> = all.iter().flatten().copied().collect();
    let n = runs.len().max(1) as f64;
    let mean = |f: fn(&Counts) -> usize| runs.iter().map(f).sum::<usize>() as f64 / n;
    let max = runs.iter().map(|r| r.elements).max().unwrap_or(0);
    let counted = |text: String| if all.is_empty() { "—".to_string() } else { text };
    vec![
        label.to_string(),
        threads.to_string(),
        start.to_string(),
        format!("{:.3}", t.wall),
        format!("{:.2}", t.cpu),
        format!("{:.2}", cold_cpu / t.cpu),
        counted(format!("{:.0}, {max}", mean(|r| r.elements))),
        counted(format!("{:.2}", mean(|r| r.passes))),
        counted(format!("{:.1}", mean(|r| r.iterations))),
        counted((all.len() - runs.len()).to_string()),
    ]
}

/// The error-controlled sweep: `values` of Q/μP on carter2d_contact.yaml at `tolerance`, on
/// one thread: every run cold (from the start grid) against one chain of runs each started
/// warm from the last one's solution, on its final grid merged 0, 1, 2 and 4 levels or on the
/// start grid (src/sequence.rs, `GridChain`), and the sweep of `rollbem sweep` on all threads.
/// The ways take turns, `repeat` rounds (the unmerged grid, ten times slower, in the first
/// only), each the best of its rounds by CPU time: the process's CPU time of a one-thread
/// chain leaves out the time other processes held the cores.
fn adaptive(case: &Path, tolerance: f64, values: &[String], repeat: usize, dir: &Path) -> Table {
    let tol = format!("contact.grid.tolerance={tolerance:e}");
    let mut table = Table::new(&[
        "error-controlled sweep",
        "threads",
        "start of each run",
        "wall [s]",
        "CPU [s]",
        "cold / this, CPU",
        "elements a run (mean, max)",
        "passes a run",
        "iterations a run",
        "runs failed",
    ]);
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a pool");
    let chain_of = |reuse: Option<GridReuse>| {
        let mut chain = reuse.map(rollbem::sequence::GridChain::new);
        let (t, c) = (Instant::now(), cpu_seconds());
        let runs: Vec<_> = values
            .iter()
            .map(|v| adaptive_run(case, &tol, v, chain.as_mut()))
            .collect();
        Timed {
            wall: t.elapsed().as_secs_f64(),
            cpu: cpu_seconds() - c,
            runs,
        }
    };
    let mut ways: Vec<(String, Option<GridReuse>, Option<Timed>)> = vec![("cold: the start grid".into(), None, None)];
    for merged in [0, 1, 2, 4] {
        let start = format!("last run's grid, merged {merged}×");
        ways.push((start, Some(GridReuse::LastGrid { merged }), None));
    }
    ways.push((
        "start grid, warm from the last run".into(),
        Some(GridReuse::StartGrid),
        None,
    ));
    for round in 0..repeat {
        for (_, reuse, best) in ways.iter_mut() {
            if round > 0 && *reuse == Some(GridReuse::LastGrid { merged: 0 }) {
                continue;
            }
            let t = one.install(|| chain_of(*reuse));
            if best.as_ref().is_none_or(|b| t.cpu < b.cpu) {
                *best = Some(t);
            }
        }
    }
    let label = format!("{} values of Q/μP, tolerance {tolerance:e}", values.len());
    let cold_cpu = ways[0].2.as_ref().expect("timed").cpu;
    for (start, _, best) in &ways {
        table.push(adaptive_row(&label, 1, start, best.as_ref().expect("timed"), cold_cpu));
    }
    let mut k = 0;
    let mut sweep = Timed {
        wall: f64::INFINITY,
        cpu: f64::INFINITY,
        runs: Vec::new(),
    };
    for _ in 0..repeat {
        k += 1;
        let c = cpu_seconds();
        let (wall, _) = swept(case, &tol, values, &dir.join(format!("adaptive_{k}")));
        let cpu = cpu_seconds() - c;
        if cpu < sweep.cpu {
            sweep = Timed {
                wall,
                cpu,
                runs: Vec::new(),
            };
        }
    }
    table.push(adaptive_row(
        &label,
        rayon::current_num_threads(),
        "rollbem sweep",
        &sweep,
        cold_cpu,
    ));
    table
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let repeat = arg(&args, "--repeat").and_then(|v| v.parse().ok()).unwrap_or(3);
    if args.iter().any(|a| a == "--adaptive") {
        let case = case_path("carter2d_contact");
        let tmp = tempfile::tempdir().expect("a temporary folder");
        let n: usize = arg(&args, "--values").and_then(|v| v.parse().ok()).unwrap_or(20);
        let values = ratios(n, 0.95 / (n - 1) as f64);
        let tolerance = arg(&args, "--tolerance").and_then(|v| v.parse().ok()).unwrap_or(1e-4);
        print!("{}", adaptive(&case, tolerance, &values, repeat, tmp.path()).markdown());
        return;
    }
    let contact = arg(&args, "--contact").map(|bin| {
        let bin = PathBuf::from(bin);
        let inp = contact_inp(&args, &bin);
        (bin, inp)
    });
    // rollbem's 1001-value sweep on each thread count, for the comparison with CONTACT.
    let mut carter = Vec::new();
    let case = case_path("carter2d_contact");
    let tmp = tempfile::tempdir().expect("a temporary folder");
    let mut table = Table::new(&[
        "sweep",
        "threads",
        "one cold run [s]",
        "cold runs, files [s]",
        "cold runs [s]",
        "shared + warm [s]",
        "cold / shared",
        "shared / one run",
        "iterations a run cold / warm",
    ]);
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a pool");
    for (n, step, elements) in [(100, 0.01, 100), (1001, 0.000999, 41)] {
        let values = ratios(n, step);
        let el = format!("contact.grid.elements={elements}");
        for threads in [rayon::current_num_threads(), 1] {
            let run = || {
                let single = best(repeat, || cold(&case, &el, &values[40..41], None));
                let files = if n <= 100 {
                    let dir = tmp.path().join(format!("files_{n}_{threads}"));
                    Some(best(1, || cold(&case, &el, &values, Some(&dir))))
                } else {
                    None
                };
                let c = best(repeat, || cold(&case, &el, &values, None));
                let mut k = 0;
                let s = best(repeat, || {
                    k += 1;
                    swept(
                        &case,
                        &el,
                        &values,
                        &tmp.path().join(format!("sweep_{n}_{threads}_{k}")),
                    )
                });
                (single, files, c, s)
            };
            let (single, files, c, s) = if threads == 1 { one.install(run) } else { run() };
            if n == 1001 {
                carter.push((threads, s.0));
            }
            table.push(vec![
                format!("{n} values, {elements} elements"),
                threads.to_string(),
                format!("{:.4}", single.0),
                files.map_or("—".into(), |f| format!("{:.3}", f.0)),
                format!("{:.3}", c.0),
                format!("{:.3}", s.0),
                format!("{:.1}", c.0 / s.0),
                format!("{:.1}", s.0 / single.0),
                format!("{:.2} / {:.2}", c.1 as f64 / n as f64, s.1 as f64 / n as f64),
            ]);
        }
    }
    print!("{}", table.markdown());
    if let Some((bin, inp)) = contact {
        let mut k = 0;
        let (t_contact, _) = best(repeat, || {
            k += 1;
            (contact_run(&bin, &inp, &tmp.path().join(format!("contact_{k}"))), 0)
        });
        let mut side = Table::new(&["program: Carter cases", "threads", "wall time [s]", "rollbem / CONTACT"]);
        side.push(vec![
            "CONTACT: carter2d_100.inp, 1000 creepages, 111 elements".into(),
            "1".into(),
            format!("{t_contact:.3}"),
            "1".into(),
        ]);
        for (threads, t) in carter {
            side.push(vec![
                "rollbem sweep: 1001 values of Q/μP, 41 elements".into(),
                threads.to_string(),
                format!("{t:.3}"),
                format!("1/{:.1}", t_contact / t),
            ]);
        }
        println!();
        print!("{}", side.markdown());
    }
}
