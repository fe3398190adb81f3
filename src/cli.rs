//! Command-line interface: the verbs, their arguments and their help texts.

use clap::{Parser, Subcommand};
use std::path::PathBuf;

/// rollbem — 2D steady rolling contact of elastic cylinders (half-space or BEM bodies),
/// coupled normal–tangential, Coulomb friction, generalized Newton (González & Abascal 2000).
///
/// Exit codes: 0 solved; 1 bad input or usage (the message names the file, key or folder;
/// nothing written); 2 the solver did not converge (summary.json written with converged: false
/// and the residual history); 3 internal error (a bug: please report it; nothing written).
///
/// rollbem never deletes or overwrites a file it did not write: it replaces only its own earlier
/// results (atomically) and refuses an output folder that holds anything else.
#[derive(Debug, Parser)]
#[command(name = "rollbem", version, about, long_about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
    /// Say more on stderr: -v each stage and Newton step with its residual, as it happens;
    /// -vv debugging detail. (Without it, a run that takes over a second shows its progress on
    /// one line, and restarts of the solver are printed as warnings; the environment variable
    /// ROLLBEM_PROGRESS_AFTER=SECONDS changes that second.)
    #[arg(short, long, action = clap::ArgAction::Count, global = true)]
    pub verbose: u8,
    /// Say nothing on stderr but errors (no progress, warnings or notices; the results table
    /// still goes to stdout).
    #[arg(short, long, global = true, conflicts_with = "verbose")]
    pub quiet: bool,
}

impl Cli {
    /// How much to say on stderr: the level of `-q`/`-v`, and progress for a single run.
    pub fn verbosity(&self) -> crate::logging::Verbosity {
        crate::logging::Verbosity {
            level: if self.quiet { -1 } else { self.verbose.min(3) as i8 },
            progress: matches!(self.command, Command::Run { .. }),
        }
    }

    /// The case file of the command, if it has one (named in the internal-error report).
    pub fn case_path(&self) -> Option<&std::path::Path> {
        match &self.command {
            Command::Run { case, .. } | Command::Check { case, .. } | Command::Mesh { case, .. } => Some(case),
            Command::Sweep { case, .. } => case.as_deref(),
            Command::Study { study } => match study {
                StudyCommand::Accuracy { case, .. }
                | StudyCommand::Stability { case, .. }
                | StudyCommand::Shakedown { case, .. } => Some(case),
            },
            Command::Validate => None,
        }
    }
}

/// The verbs.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Solve a case: print a summary table and write summary.json, contact.csv, contact.svg.
    ///
    /// Example: rollbem run cases/carter_051.yaml --set contact.friction=0.2
    Run {
        /// Case file (YAML; see cases/README.md for the keys).
        case: PathBuf,
        /// Output folder (default: output.dir of the case, relative to the case file).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Override a case value by its dotted key path, e.g. --set load.tangential.ratio=0.84
        /// or --set contact.grid.elements=81. Repeatable.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
        set: Vec<String>,
        /// Replace an earlier result in the output folder even if files of it were changed
        /// since rollbem wrote them (without it, such a file stops the run before it solves).
        /// The case's own inputs (case file, meshes) are never replaced.
        #[arg(long)]
        force: bool,
    },
    /// Run a case over the Cartesian product of parameter values, in parallel.
    ///
    /// Example (the paper's variable-friction study, Figs 7–9):
    /// rollbem sweep cases/variable_mu_qp_0075.yaml --vary contact.friction=0.1,0.2,0.3,0.4,0.8
    ///
    /// Writes sweep.csv (varied values, status, forces, creepage, zones, timings; a row added as
    /// each run finishes) and sweep.json (what sweep this is); with --per-run-files also one
    /// folder per run (run_0000, …, each what `rollbem run` writes) and sweep.pvd (the runs'
    /// contact lines as ParaView time steps). A failed run is recorded as failed and the others
    /// go on; exit code 2 if any run failed (3 if one hit an internal error). An interrupted
    /// sweep is continued with --resume.
    /// Runs that vary only loads (load.*), contact.friction or solver settings share one
    /// assembly of the bodies and start from the solution of their neighbour in the varied
    /// values (runs are ordered by value, each thread taking a contiguous chain); runs that
    /// change the grid (a normal load on a grid sized by its Hertz contact, contact.grid.*),
    /// the bodies or the materials, and error-controlled runs, build their own.
    /// Large sweeps: `--shard K/N` runs the K-th of N deterministic slices (one per Slurm array
    /// task), then `rollbem sweep --merge DIR... --out DIR` joins the shards.
    Sweep {
        /// Case file (not with --merge: the shards' records say what sweep they are).
        #[arg(required_unless_present = "merge", conflicts_with = "merge")]
        case: Option<PathBuf>,
        /// key.path=v1,v2,... — values for one case key (read as YAML, like --set). Repeatable:
        /// the runs are the Cartesian product, the first --vary varying slowest (at most
        /// 10 000 000 runs).
        #[arg(long = "vary", value_name = "KEY.PATH=V1,V2,...", conflicts_with = "merge")]
        vary: Vec<String>,
        /// Fixed overrides applied to every run. Repeatable.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE", conflicts_with = "merge")]
        set: Vec<String>,
        /// Output folder (default: the case's output folder with `_sweep` appended).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Run only slice K of N (1 <= K <= N) of the runs; writes sweep_shard_K_of_N.csv.
        #[arg(long, value_name = "K/N", conflicts_with = "merge")]
        shard: Option<String>,
        /// Join the sweep_shard_*.csv files of these folders into --out (default: the first).
        /// Refused (exit 1) unless they make one complete sweep: every shard 1..N, all of the
        /// same case, --set and --vary, each with all its runs.
        #[arg(long, num_args = 1.., value_name = "DIR")]
        merge: Vec<PathBuf>,
        /// Continue an interrupted sweep (or shard) in --out: keep the runs its table records as
        /// done, run only the missing and failed ones. The table must belong to the same sweep
        /// (case, --set, --vary, shards).
        #[arg(long, conflicts_with = "merge")]
        resume: bool,
        /// Write each run's folder (run_NNNN: summary.json, contact.csv, contact.svg, VTK files)
        /// and sweep.pvd; by default only the sweep's table and record are written.
        #[arg(long, conflicts_with = "merge")]
        per_run_files: bool,
        /// Runs at once (default 0: one per core). More than the machine's cores are capped to
        /// them with a warning; more than 1024 is refused (exit 1).
        #[arg(long, default_value_t = 0, conflicts_with = "merge")]
        jobs: usize,
    },
    /// Solve the built-in reference problems (Hertz, Carter, dissimilar regimes, free-rolling
    /// limits) and print each measured error against its closed form and limit; exit code 2 if
    /// any fails. docs/validation.md has the full tables.
    Validate,
    /// Studies over many runs of a case's scene: speed against accuracy of the body
    /// models, and where each solution method converges (parallel, with a progress bar).
    Study {
        /// Which study.
        #[command(subcommand)]
        study: StudyCommand,
    },
    /// Validate a case without solving: print the bodies, materials, Hertz estimates (a, p0),
    /// the grid spacing, the Carter stick-zone estimate and model advice.
    ///
    /// The model advice estimates the half-space model's error on this scene from measured
    /// tables (rollers on shafts by a/R, cover layers by b/a; docs/choosing-a-model.md) and says
    /// whether it meets --tolerance or the BEM true geometry is needed, with the cost of each.
    Check {
        /// Case file.
        case: PathBuf,
        /// Override a case value (as for `run`). Repeatable.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
        set: Vec<String>,
        /// Accuracy you need, as a fraction of p0 (pressure) and μp0 (shear): 0.01 is 1 %.
        #[arg(long, default_value_t = 0.01)]
        tolerance: f64,
        /// Also estimate the grid's discretisation error: solves the case's steady problem on
        /// its fixed grid and on the grid halved (what `rollbem run` reports as error_estimate;
        /// 1.5–4 times a run's time) and warns when the estimate exceeds --tolerance.
        #[arg(long)]
        estimate: bool,
    },
    /// Write the meshes rollbem generates for a case's `geometry:` bodies as Gmsh files.
    ///
    /// A `bem` body may give `geometry:` (a roller on a shaft, a ring, a covered roller, a
    /// block; cases/README.md) instead of a Gmsh `mesh:`; rollbem then meshes it itself, with
    /// its contact elements sized from the Hertz contact (the case's contact.grid) or matched
    /// to the other body's mesh. This writes exactly the mesh `rollbem run` would solve on, as
    /// A.msh and B.msh (Gmsh MSH 4.1 ASCII, the bodies without `geometry:` left out): open them
    /// in Gmsh to look at them, or give one to a case's `mesh:` key (it reads back to the same
    /// mesh, groups `contact`, `free`, `shaft`, ... included).
    ///
    /// The families (lengths in the case's unit; the groups besides `contact`, the one held
    /// fixed by default marked, the others free; `boundaries:` may change them):
    ///
    /// - geometry: {roller: {radius: 150, shaft: 15}}: free, shaft (fixed)
    ///
    /// - geometry: {ring: {bore: 50, rim: 65}}: bore, rim (fixed)
    ///
    /// - geometry: {covered_roller: {radius: 100, cover_thickness: 5, core: rigid}}: free, bonded (fixed)
    ///
    /// - geometry: {block: {width: 80, depth: 40}} with the body's radius: free, far (fixed)
    ///
    /// Example: rollbem mesh cases/fig14_geometry.yaml --out meshes_fig14
    Mesh {
        /// Case file with at least one `geometry:` body.
        case: PathBuf,
        /// Output folder (default: the case's output folder with `_mesh` appended).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Override a case value (as for `run`), e.g. --set load.normal.force=800. Repeatable.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
        set: Vec<String>,
        /// Replace earlier meshes in the output folder even if they were changed since rollbem
        /// wrote them. A mesh the case reads (`mesh:`) is never replaced.
        #[arg(long)]
        force: bool,
    },
}

/// The studies.
#[derive(Debug, Subcommand)]
pub enum StudyCommand {
    /// Error against wall time of each body model the scene allows, at a ladder of grids.
    ///
    /// The case's cylinders are solved with the analytic half-space model, with BEM blocks
    /// standing in for half-spaces (paper Fig. 2) and with BEM rollers of their true radius on
    /// rigid shafts, each at 11 … 321 contact elements. Errors are measured against Carter
    /// (similar bodies, Q/μP given) or Hertz (Q = 0), else against the finest true-geometry run
    /// (stated in the output). Writes accuracy.csv, accuracy.json and accuracy.svg (error
    /// against time on log–log axes, one curve per model, the Pareto front drawn).
    ///
    /// Example: rollbem study accuracy cases/carter_051.yaml --quick
    Accuracy {
        /// Case file: its materials, radii, friction and load define the scene.
        case: PathBuf,
        /// Output folder (default: the case's output folder with `_accuracy` appended).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Override a case value (as for `run`). Repeatable.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
        set: Vec<String>,
        /// The short ladder 11, 21, 41 contact elements and tolerances 1e-2, 1e-3 (under a
        /// minute), as CI runs it.
        #[arg(long, conflicts_with = "ladder")]
        quick: bool,
        /// Contact elements of each rung, e.g. --ladder 21,41,81 (default 11,21,41,81,161,321).
        #[arg(long, value_delimiter = ',')]
        ladder: Vec<usize>,
        /// Models to run: half_space, half_space_block, true_geometry, half_space_adaptive
        /// (the half-space on error-controlled grids, one run per --tolerances) (default all).
        #[arg(long, value_delimiter = ',')]
        models: Vec<String>,
        /// Tolerances of the half_space_adaptive runs (contact.grid.tolerance), e.g.
        /// --tolerances 1e-3,1e-4 (default 1e-2,1e-3,1e-4,1e-5; --quick: 1e-2,1e-3).
        #[arg(long, value_delimiter = ',')]
        tolerances: Vec<f64>,
        /// A measured error–time curve drawn on the chart for comparison: CSV
        /// `label,error,time_s` with `#` provenance lines, e.g. docs/data/contact_carter2d.csv
        /// (CONTACT on cases/carter2d_contact.yaml).
        #[arg(long, value_name = "FILE")]
        reference_curve: Option<PathBuf>,
        /// Shaft radius over roller radius of the true-geometry rollers.
        #[arg(long, default_value_t = 0.1)]
        shaft_ratio: f64,
        /// Runs at once (default: one per core). --jobs 1 gives undisturbed timings.
        #[arg(long, default_value_t = 0)]
        jobs: usize,
    },
    /// Johnson's shakedown map for the case's criterion, with the case's points on it.
    ///
    /// The map: first yield and the shakedown limit (Melan) of a Hertz line contact under a
    /// sliding traction q = μp, as p0/k against the traction coefficient 0 … 0.5, from
    /// McEwen's closed-form stresses (Johnson, Contact Mechanics, 1985, §9.4, Fig. 9.12): below
    /// first yield the contact stays elastic, between the curves it shakes down, above the
    /// limit it ratchets (at the surface where the surface governs) or, for a hardening
    /// material, shakes down plastically. The case is solved with its strength assessment
    /// (`output.strength`; von Mises if the case has none, its materials need `yield:`) and each
    /// body is drawn at its |Q|/P and p_max/k, with the loads of its own first yield and
    /// shakedown limit from its own stresses (partial slip, dissimilar bodies and the true
    /// geometry move them off the map's curves).
    ///
    /// Example: rollbem study shakedown cases/carter_051.yaml --vary load.tangential.ratio=0.3,0.6,0.9
    ///
    /// Writes shakedown_map.csv, shakedown_points.csv and shakedown.svg; docs/strength.md.
    Shakedown {
        /// Case file (e.g. cases/carter_051.yaml).
        case: PathBuf,
        /// Output folder (default: the case's output folder with `_shakedown` appended).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Override a case value (as for `run`). Repeatable.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
        set: Vec<String>,
        /// Solve the case once per value of one key, e.g. load.tangential.ratio=0.3,0.6,0.9:
        /// one point per value and body.
        #[arg(long, value_name = "KEY.PATH=V1,V2,...")]
        vary: Option<String>,
    },
    /// Convergence map of every solution method: newton (Φ), newton_psi, newton_plain,
    /// norm_tang, gauss_seidel, over 2D slices through the case.
    ///
    /// Slices: friction μ 0.05–10 × Q/μP −1…1 (incl. ±0.99) for each Dundurs β in {0, 0.144,
    /// 0.288, 0.45} (set through A's material against B's); penalty scale c 1e-3–1e3 × Q/μP at
    /// β = 0.288; grid 11–161 elements × element type (constant, continuous and discontinuous
    /// quadratic); friction × element type at β = 0.288 with the traction ripple. The friction,
    /// penalty and ripple slices use a ±4a grid of 65 elements (large μβ moves the contact).
    /// Cells with |Q/μP| ≥ 1 have no steady rolling solution: marked n/a, not solved. Each
    /// method gets its budget: 100 Newton steps (per restart), 100 NORM/TANG pairs, 20 000
    /// Gauss–Seidel sweeps. About a minute and a half on 2 cores (--quick: 2 s; docs/stability.md).
    ///
    /// Example: rollbem study stability cases/carter_051.yaml --quick
    ///
    /// Writes stability.csv (one row per cell and method: status, iterations, residual, solve
    /// time, ripple, creepage), summary.txt and img/*.svg heat maps (one per slice and method,
    /// one overview per slice). Exit code 0 when the default method (newton) converged in every
    /// cell with a solution, 2 otherwise, 1 for bad input. docs/stability.md reads the map.
    Stability {
        /// Base case file (e.g. cases/carter_051.yaml).
        case: PathBuf,
        /// Small ladder for CI: 3 frictions, 7 load ratios, β = 0 and 0.288, 11 and 21 elements
        /// (seconds instead of minutes).
        #[arg(long)]
        quick: bool,
        /// Output folder (default: the case's output folder with `_stability` appended).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Fixed overrides of the base case, as for `run`. Repeatable.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
        set: Vec<String>,
    },
}
