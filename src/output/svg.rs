//! contact.svg: pressure, shear with the ±μp bounds, and slip along x (plotters, SVG backend).

use crate::error::Error;
use crate::post::ContactSolution;
use plotters::prelude::*;
use std::path::Path;

fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    let pad = 0.05 * (hi - lo).max(1e-300);
    if lo.is_finite() && hi.is_finite() && hi > lo {
        (lo - pad, hi + pad)
    } else {
        (lo.min(0.0) - 1.0, hi.max(0.0) + 1.0)
    }
}

/// Writes the two-panel contact plot.
pub fn write_contact_plot(path: &Path, sol: &ContactSolution, friction: f64, title: &str) -> Result<(), Error> {
    draw(path, sol, friction, title).map_err(|e| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

fn draw(path: &Path, sol: &ContactSolution, mu: f64, title: &str) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (900, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, ("sans-serif", 18))?;
    let (top, bottom) = root.split_vertically(400);
    let x = &sol.x;
    let (x0, x1) = (x[0], x[x.len() - 1]);
    let bound: Vec<f64> = sol.pressure.iter().map(|p| mu * p).collect();
    let (y0, y1) = range(
        sol.pressure
            .iter()
            .chain(&sol.shear)
            .chain(&bound)
            .copied()
            .chain([0.0, -0.0])
            .chain(bound.iter().map(|b| -b)),
    );
    let mut chart = ChartBuilder::on(&top)
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart.configure_mesh().x_desc("x").y_desc("traction").draw()?;
    let series = |v: &[f64]| x.iter().copied().zip(v.iter().copied()).collect::<Vec<_>>();
    chart
        .draw_series(LineSeries::new(series(&sol.pressure), BLUE.stroke_width(2)))?
        .label("pressure p")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE));
    chart
        .draw_series(LineSeries::new(series(&sol.shear), RED.stroke_width(2)))?
        .label("shear q")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RED));
    let neg: Vec<f64> = bound.iter().map(|b| -b).collect();
    chart
        .draw_series(LineSeries::new(series(&bound), BLACK.mix(0.5)))?
        .label("±mu p")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.mix(0.5)));
    chart.draw_series(LineSeries::new(series(&neg), BLACK.mix(0.5)))?;
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()?;

    let in_contact: Vec<usize> = (0..x.len()).filter(|&i| sol.pressure[i] > 0.0).collect();
    let pick = |v: &[f64]| in_contact.iter().map(|&i| (x[i], v[i])).collect::<Vec<_>>();
    let mut slip_values: Vec<f64> = in_contact.iter().map(|&i| sol.slip[i]).collect();
    if let Some(s) = &sol.slip_strain {
        slip_values.extend(in_contact.iter().map(|&i| s[i]));
    }
    let (s0, s1) = range(slip_values.into_iter().chain([0.0]));
    let mut chart = ChartBuilder::on(&bottom)
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, s0..s1)?;
    chart.configure_mesh().x_desc("x").y_desc("slip / |V|").draw()?;
    chart
        .draw_series(LineSeries::new(pick(&sol.slip), GREEN.stroke_width(2)))?
        .label("slip (finite difference)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], GREEN));
    if let Some(s) = &sol.slip_strain {
        chart
            .draw_series(pick(s).into_iter().map(|p| Circle::new(p, 2, MAGENTA.filled())))?
            .label("slip (boundary-integral derivative)")
            .legend(|(x, y)| Circle::new((x + 10, y), 2, MAGENTA.filled()));
    }
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()?;
    root.present()?;
    Ok(())
}
