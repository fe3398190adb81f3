//! What the docs say is true: they cite only what the repository holds
//! ([`no_external_references`]), the source keeps the rules of docs/architecture.md
//! ([`architecture`]), and the numbers they quote are the numbers the report programs print:
//! every table of
//! docs/*.md that a program in examples/ prints is compared here, cell by cell, with what the
//! program prints now (within the rounding of the printed digits, see [`markdown`]), and the
//! numbers the prose repeats from those tables are checked against them. A change of the
//! solver that moves a quoted number fails here until the page is regenerated with the
//! program; a page edited by hand fails too.
//!
//! Times are not compared (they depend on the machine and its load).

// Each report is a program of its own and declares the shared examples/common/mod.rs itself;
// compiled together here, that file is one module per report.
#![allow(clippy::duplicate_mod)]

#[allow(dead_code)]
#[path = "../../examples/adaptive_report.rs"]
mod adaptive_report;
mod architecture;
#[allow(dead_code)]
#[path = "../../examples/bem_tolerance_matrix.rs"]
mod bem_tolerance_matrix;
#[allow(dead_code)]
#[path = "../../examples/body_mesh_report.rs"]
mod body_mesh_report;
#[path = "../common/mod.rs"]
mod common;
#[allow(dead_code)]
#[path = "../../examples/conformal_report.rs"]
mod conformal_report;
#[allow(dead_code)]
#[path = "../../examples/effectivity_matrix.rs"]
mod effectivity_matrix;
#[allow(dead_code)]
#[path = "../../examples/error_vs_time.rs"]
mod error_vs_time;
#[allow(dead_code)]
#[path = "../../examples/fixed_grid_report.rs"]
mod fixed_grid_report;
#[allow(dead_code)]
#[path = "../../examples/friction_limits.rs"]
mod friction_limits;
#[allow(dead_code)]
#[path = "../../examples/hbem_report.rs"]
mod hbem_report;
mod markdown;
#[allow(dead_code)]
#[path = "../../examples/methods_perf.rs"]
mod methods_perf;
#[allow(dead_code)]
#[path = "../../examples/model_error_table.rs"]
mod model_error_table;
mod no_external_references;
#[allow(dead_code)]
#[path = "../../examples/oscillating_report.rs"]
mod oscillating_report;
mod outputs;
#[allow(dead_code)]
#[path = "../../examples/parametric_report.rs"]
mod parametric_report;
#[allow(dead_code)]
#[path = "../../examples/perf_report.rs"]
mod perf_report;
mod readme;
#[allow(dead_code)]
#[path = "../../examples/strength_report.rs"]
mod strength_report;
#[allow(dead_code)]
#[path = "../../examples/validation_report.rs"]
mod validation_report;
#[allow(dead_code)]
#[path = "../../examples/viscoelastic_report.rs"]
mod viscoelastic_report;

use markdown::{assert_table, cell_mismatch, number_after, page, Printed, Rows};

/// The page's table of the same header holds every printed row and no other.
fn assert_same(page_name: &str, t: &validation_report::common::Table) {
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table(page_name, printed, Rows::All, &[], (&[], 0.0));
}

/// A number the prose quotes (right after `before`) is the printed one.
fn assert_quoted(page_name: &str, before: &str, printed: &str) {
    let quoted = number_after(&page(page_name), before);
    if let Some(why) = cell_mismatch(&quoted, printed) {
        panic!("{page_name}, after `{before}`: {why}");
    }
}

/// A cell of a printed table: the column `column` of the row whose first cell is `row`.
fn cell<'a>(header: &[String], rows: &'a [Vec<String>], row: &str, column: &str) -> &'a str {
    let j = header.iter().position(|h| h == column).expect("a column of the table");
    &rows.iter().find(|r| r[0] == row).expect("a row of the table")[j]
}

/// The number of a percentage cell ("1.46 %" → "1.46").
fn percent(cell: &str) -> &str {
    cell.trim().trim_end_matches('%').trim()
}

/// docs/strength.md: the sliding Hertz contact against McEwen, Tresca in-plane against three
/// principal stresses, and Carter's partial slip on the half-space and the true geometry.
#[test]
fn strength_tables() {
    let rows = strength_report::sliding_rows();
    for t in [
        strength_report::sliding_table(&rows),
        strength_report::tresca_table(),
        strength_report::partial_slip_table(),
    ] {
        let printed = Printed {
            header: &t.header,
            rows: &t.rows,
        };
        assert_table("strength.md", printed, Rows::All, &[], (&[], 0.0));
    }
}

/// docs/validation.md: the fixed grids' estimates against the shipped cases' true errors.
#[test]
fn validation_fixed_grid_table() {
    let t = fixed_grid_report::table();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("validation.md", printed, Rows::All, &[], (&[], 0.0));
}

#[test]
fn validation_hertz_table() {
    assert_same("validation.md", &validation_report::hertz());
}

#[test]
fn validation_carter_table() {
    assert_same("validation.md", &validation_report::carter());
}

/// Φ and Ψ converge to the same solution of the discrete problem, so their differences are
/// round-off: the page and the report must both show them below 1e-12 (their digits change
/// with any reordering of the arithmetic).
#[test]
fn validation_phi_psi_table() {
    let t = validation_report::phi_psi();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    let noise = ["max |p_Φ − p_Ψ|/p_max", "max |q_Φ − q_Ψ|/max|q|"];
    assert_table("validation.md", printed, Rows::All, &[], (&noise, 1e-12));
}

/// Every method converges to the default Newton's solution of the same discrete problem: the
/// differences are round-off (Gauss–Seidel stops on the common residual 1e-10, so its shear
/// differs by up to its stopping tolerance): compared below 1e-9, the other cells exactly.
#[test]
fn validation_methods_table() {
    let t = validation_report::methods();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    let noise = ["max Δq / μp0", "max Δp / p0"];
    assert_table("validation.md", printed, Rows::All, &[], (&noise, 1e-9));
}

/// docs/validation.md, "Parametric bodies": each family against its Gmsh twin.
#[test]
fn validation_parametric_table() {
    let t = parametric_report::parametric();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("validation.md", printed, Rows::All, &[], (&[], 0.0));
}

/// docs/validation.md, "The body mesh's error": the coarse roller's estimate against the
/// truth, and the shipped fig14 meshes' estimate.
#[test]
fn validation_body_mesh_table() {
    let t = body_mesh_report::body_mesh();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("validation.md", printed, Rows::All, &[], (&[], 0.0));
}

/// The rows of the BEM tolerance matrix that the tests repeat (the whole table takes half an
/// hour: `cargo run --release --example bem_tolerance_matrix`); times are not compared.
#[test]
fn validation_bem_tolerance_table() {
    let runs: Vec<(String, f64)> = bem_tolerance_matrix::TESTED
        .iter()
        .map(|(name, t)| (name.to_string(), *t))
        .collect();
    let t = bem_tolerance_matrix::table_of(&runs);
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table(
        "validation.md",
        printed,
        Rows::Printed { key: 2 },
        &["time [s]"],
        (&[], 0.0),
    );
}

#[test]
fn validation_regimes_table() {
    assert_same("validation.md", &validation_report::regimes());
}

/// docs/viscoelastic.md: CONTACT's visc_cylindr, Hunter's exact solution, the convergence.
#[test]
fn viscoelastic_tables() {
    for t in [
        viscoelastic_report::contact_comparison(),
        viscoelastic_report::hunter(),
        viscoelastic_report::convergence(),
        viscoelastic_report::covered_roller_energy(),
    ] {
        let printed = Printed {
            header: &t.header,
            rows: &t.rows,
        };
        assert_table("viscoelastic.md", printed, Rows::All, &[], (&[], 0.0));
    }
}

#[test]
fn validation_free_rolling_table() {
    assert_same("validation.md", &validation_report::free_rolling());
}

#[test]
fn validation_variable_friction_table() {
    assert_same("validation.md", &validation_report::variable_friction());
}

/// docs/theory.md: what the traction axes change on every shipped case (the half-space cases
/// not at all).
#[test]
fn traction_axes_table() {
    let t = conformal_report::traction_axes_effect();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("theory.md", printed, Rows::All, &[], (&[], 0.0));
}

/// docs/conformal.md §6: the roller-in-a-ring-bore cases, BEM and half-space.
#[test]
fn bore_table() {
    let rows = conformal_report::bore_runs();
    let t = conformal_report::bore_table(&rows);
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("conformal.md", printed, Rows::All, &[], (&[], 0.0));
}

/// docs/hbem.md: Carter with true rollers (the error table), Fig. 4's nodes (a selection of
/// the printed rows), and the friction check of the shipped cases; the prose of hbem.md and
/// validation.md repeats some of them.
#[test]
fn hbem_tables_and_quoted_numbers() {
    let carter = common_solve("carter_051_true");
    let t = hbem_report::carter_errors(&carter);
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("hbem.md", printed, Rows::All, &[], (&[], 0.0));
    let (hbem_slip, fd_slip) = (&t.rows[0][1], &t.rows[1][1]);
    assert_quoted("validation.md", "largest slip: HBEM slip", percent(hbem_slip));
    assert_quoted(
        "validation.md",
        "in the slip zone (finite differences",
        percent(fd_slip.split('(').next().unwrap_or_default()),
    );

    let fig4 = common_solve("fig4_true_geometry");
    let t = hbem_report::node_table(&fig4, false);
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("hbem.md", printed, Rows::Selection { key: 1 }, &[], (&[], 0.0));

    let t = hbem_report::check_table();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("hbem.md", printed, Rows::All, &[], (&[], 0.0));
    let stick = r"max \|s_hbem\| at stick nodes";
    let slip = r"max \|s_hbem − s\| at slip nodes";
    let fig4_stick = percent(cell(&t.header, &t.rows, "fig4_true_geometry", stick));
    assert_quoted("hbem.md", "In the stick zone the HBEM slip is at most", fig4_stick);
    assert_quoted("validation.md", "stick nodes ≤", fig4_stick);
    let hs = "dissimilar_beta0288_075 (Fig. 4)";
    let (hs_stick, hs_slip) = (
        percent(cell(&t.header, &t.rows, hs, stick)),
        percent(cell(&t.header, &t.rows, hs, slip)),
    );
    assert_quoted("hbem.md", "stick nodes at most", hs_stick);
    assert_quoted("hbem.md", "slip nodes differ by at most", hs_slip);
    assert_quoted("validation.md", "closed-form derivative):", hs_stick);
}

fn common_solve(name: &str) -> rollbem::app::Solved {
    hbem_report::common::solve(name, &[] as &[&str])
}

/// docs/choosing-a-model.md's three tables, and the constants of src/advice.rs that
/// `rollbem check` interpolates: the report prints them to four figures, so the constants must
/// be the measured values within half a unit of their fourth figure.
#[test]
fn model_error_tables_and_advice_constants() {
    let rollers = model_error_table::rollers();
    let t = model_error_table::roller_table(&rollers);
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("choosing-a-model.md", printed, Rows::All, &[], (&[], 0.0));
    assert_eq!(rollers.len(), rollbem::advice::ROLLER_ERROR.len());
    for (r, &(a_over_r, p, q)) in rollers.iter().zip(&rollbem::advice::ROLLER_ERROR) {
        assert_eq!(r.a_over_r, a_over_r);
        assert_four_figures(p, r.pressure, "ROLLER_ERROR pressure");
        assert_four_figures(q, r.shear, "ROLLER_ERROR shear");
    }
    let internal = model_error_table::internal();
    let t = model_error_table::internal_table(&internal);
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("choosing-a-model.md", printed, Rows::All, &[], (&[], 0.0));
    assert_eq!(internal.len(), rollbem::advice::INTERNAL_ERROR.len());
    for (r, &(a_over_r, p, q)) in internal.iter().zip(&rollbem::advice::INTERNAL_ERROR) {
        assert_eq!(r.a_over_r, a_over_r);
        assert_four_figures(p, r.pressure, "INTERNAL_ERROR pressure");
        assert_four_figures(q, r.shear, "INTERNAL_ERROR shear");
    }
    let layers = model_error_table::layers();
    let t = model_error_table::layer_table(&layers);
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("choosing-a-model.md", printed, Rows::All, &[], (&[], 0.0));
    assert_eq!(layers.len(), rollbem::advice::LAYER_ERROR.len());
    for (r, &(b_over_a, p)) in layers.iter().zip(&rollbem::advice::LAYER_ERROR) {
        assert_eq!(r.b_over_a, b_over_a);
        assert_four_figures(p, r.pressure, "LAYER_ERROR pressure");
    }
}

/// `constant`, written with four significant figures, is `measured` rounded (one unit of the
/// fourth figure: a rounding of the measured value either side of a boundary).
fn assert_four_figures(constant: f64, measured: f64, what: &str) {
    let unit = 10f64.powi(constant.abs().log10().floor() as i32 - 3);
    assert!(
        (constant - measured).abs() <= unit,
        "{what}: src/advice.rs has {constant:e}, the report measures {measured:.4e}"
    );
}

/// docs/validation.md: error-controlled grids against Carter and Hertz, without the times.
#[test]
fn validation_adaptive_table() {
    let t = adaptive_report::table();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("validation.md", printed, Rows::All, &["time [s]"], (&[], 0.0));
}

/// docs/validation.md: the effectivity matrix of the error estimate, without the times; and
/// docs/theory.md's constants table quotes its span (lowest and highest effectivity) of p, q
/// and ξ over the whole matrix.
#[test]
fn validation_effectivity_matrix_table() {
    let t = effectivity_matrix::table();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("validation.md", printed, Rows::All, &["time [s]"], (&[], 0.0));
    let span = |column: &str| {
        let j = t
            .header
            .iter()
            .position(|h| h == column)
            .expect("a column of the table");
        let values = t.rows.iter().filter_map(|r| r[j].parse::<f64>().ok());
        let (lo, hi) = values.fold((f64::INFINITY, 0.0_f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
        (format!("{lo:.2}"), format!("{hi:.2}"))
    };
    for (column, before) in [
        ("effectivity p", "over the matrix they lie in "),
        ("effectivity q", "second order; over the matrix "),
        ("effectivity ξ", "the difference itself; over the matrix "),
    ] {
        let (lo, hi) = span(column);
        assert_quoted("theory.md", before, &lo);
        let quoted_lo = number_after(&page("theory.md"), before);
        assert_quoted("theory.md", &format!("{before}{quoted_lo}–"), &hi);
    }
}

/// docs/validation.md: error-controlled grids of BEM rollers, without the times.
#[test]
fn validation_adaptive_true_geometry_table() {
    let t = adaptive_report::true_geometry_table();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("validation.md", printed, Rows::All, &["time [s]"], (&[], 0.0));
}

/// docs/performance.md: uniform against error-controlled grids, without the times.
#[test]
fn performance_error_vs_time_table() {
    let mut t = error_vs_time::common::Table::new(&error_vs_time::HEADER);
    for (label, set) in error_vs_time::runs() {
        t.push(error_vs_time::row(
            &label,
            &error_vs_time::common::solve("carter2d_contact", &set),
            None,
        ));
    }
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("performance.md", printed, Rows::All, &["whole process [s]"], (&[], 0.0));
}

/// docs/performance.md: the carter2d table without its times.
#[test]
fn performance_carter2d_table() {
    let mut t = perf_report::common::Table::new(&perf_report::HEADER);
    for n in perf_report::ELEMENTS {
        t.push(perf_report::row(n, &perf_report::solve_grid(n, "second_order"), None));
    }
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    let times = ["assembly [ms]", "solve [ms]", "per iteration [ms]", "whole process [s]"];
    assert_table("performance.md", printed, Rows::All, &times, (&[], 0.0));
}

/// docs/performance.md: the methods table without its times. A difference from Newton below
/// 1e-9 μp0 is the methods' common stopping tolerance (scaled residual 1e-10), not a number to
/// reproduce digit by digit.
#[test]
fn performance_methods_table() {
    let t = methods_perf::table(&[21, 41, 81, 161], |_| 1);
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    let noise = ["max |Δq| vs newton (μp0)"];
    assert_table("performance.md", printed, Rows::All, &["solve [ms]"], (&noise, 1e-9));
}

/// docs/performance.md, "Solver cost at the friction limits": the ladder at 41 and 81 elements
/// (the page's second table, 161–481 elements, takes minutes and is checked by running the
/// program).
#[test]
fn performance_friction_limits_table() {
    let t = friction_limits::table("case", &[41, 81]);
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("performance.md", printed, Rows::All, &["solve [s]"], (&[], 0.0));
}

/// docs/transient.md, "Oscillating normal load": amplitude and phase of Q(s) against λ/a.
#[test]
fn transient_oscillating_table() {
    let t = oscillating_report::table();
    let printed = Printed {
        header: &t.header,
        rows: &t.rows,
    };
    assert_table("transient.md", printed, Rows::All, &[], (&[], 0.0));
}
