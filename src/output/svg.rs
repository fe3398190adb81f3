//! contact.svg: the contact of a run as a rolling-contact engineer reads it (plotters, SVG
//! backend). Two panels over x, stick zones shaded blue and slip zones orange in both:
//!
//! * tractions: the pressure p on the left axis and the shear q with the friction bounds ±μp on
//!   the right axis, whose scale is μ times the left one (so q fills the panel at any μ, and
//!   ±μp lies on p and its mirror image); each slip zone labelled with an arrow for the direction
//!   in which A slips relative to B; the rolling direction and the leading edge marked; for a
//!   run with a rolling speed (a viscoelastic body's) also the trailing edge and the pressure
//!   centre, with F_r and F_r/P in the header;
//! * slip velocity over |V|: the finite-difference slip and, where the models give it, the
//!   boundary-integral slip, with a zero line and ticks that include 0.
//!
//! Units on every axis, from the case's `units`.

use crate::error::Error;
use crate::post::rolling_resistance::RollingResistance;
use crate::post::{ContactSolution, NodeState};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// What the plot shows and how it is labelled.
#[derive(Debug, Clone, Copy)]
pub struct ContactPlot<'a> {
    /// The solution.
    pub solution: &'a ContactSolution,
    /// Coulomb friction coefficient μ [-].
    pub friction: f64,
    /// σ = sgn(V): −1 when rolling in +x (the leading edge at +a), +1 when rolling in −x.
    pub flow_sign: f64,
    /// The case's title.
    pub title: &'a str,
    /// The length unit (`mm`).
    pub length_unit: &'a str,
    /// The stress unit (`N/mm^2`).
    pub stress_unit: &'a str,
    /// The force-per-length unit (`N/mm`).
    pub force_unit: &'a str,
    /// The rolling resistance to show (F_r, F_r/P, the pressure centre and both contact
    /// edges): that of a run with a rolling speed, where the bodies dissipate; None for an
    /// elastic run, whose plot stays as it was.
    pub rolling_resistance: Option<&'a RollingResistance>,
}

/// Height of the header [px].
const HEADER: u32 = 104;
/// What the rolling resistance's line adds to the header and to the image [px].
const RESISTANCE_LINE: u32 = 20;

/// Writes the plot to `path`.
pub fn write_contact_plot(path: &Path, plot: &ContactPlot) -> Result<(), Error> {
    draw(path, plot).map_err(|e| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

const STICK: RGBColor = RGBColor(70, 130, 220);
const SLIP: RGBColor = RGBColor(245, 150, 40);
const PRESSURE: RGBColor = RGBColor(20, 60, 170);
const SHEAR: RGBColor = RGBColor(200, 30, 30);
const SLIP_LINE: RGBColor = RGBColor(20, 130, 60);
const HBEM: RGBColor = RGBColor(150, 40, 160);
const FONT: &str = "sans-serif";

/// `^2`, `^3` of a unit label as superscripts.
fn pretty(unit: &str) -> String {
    unit.replace("^2", "²").replace("^3", "³")
}

/// Ticks at multiples of a 1, 2 or 5 × 10^k step covering [lo, hi] with about `n` intervals:
/// (step, ticks). 0 is a tick whenever it lies in the range.
pub fn nice_ticks(lo: f64, hi: f64, n: usize) -> (f64, Vec<f64>) {
    let span = (hi - lo).abs().max(f64::MIN_POSITIVE);
    let raw = span / n.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    let ticks = (first..=last)
        .map(|k| if k == 0 { 0.0 } else { k as f64 * step })
        .collect();
    (step, ticks)
}

/// A tick label with the digits its step needs: `0`, `0.25`, `-4e-4`, `1.5e-3`.
pub fn tick_label(v: f64, step: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if (1e-3..1e5).contains(&step) {
        let decimals = (-step.log10().floor()).max(0.0) as usize + 1;
        let s = format!("{v:.decimals$}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        };
        return s;
    }
    // Scientific with the digits the step needs relative to the value.
    let digits = ((v.abs().log10().floor() - step.log10().floor()).max(0.0) as usize).min(6);
    let s = format!("{v:.digits$e}");
    s.replace(".0e", "e")
}

/// Range [lo, hi] padded by 6 % of its span (1 either side when empty or flat).
fn padded(lo: f64, hi: f64) -> (f64, f64) {
    if lo.is_finite() && hi.is_finite() && hi > lo {
        let pad = 0.06 * (hi - lo);
        (lo - pad, hi + pad)
    } else {
        let v = if lo.is_finite() { lo } else { 0.0 };
        (v - 1.0, v + 1.0)
    }
}

/// The zones to shade: (x0, x1, state, slip direction sign).
fn shaded_zones(sol: &ContactSolution) -> Vec<(f64, f64, NodeState, i32)> {
    sol.zones
        .iter()
        .filter(|z| z.state != NodeState::Open)
        .map(|z| (z.x0, z.x1, z.state, z.direction.map_or(0, |d| i32::from(d.sign()))))
        .collect()
}

fn zone_colour(state: NodeState) -> RGBAColor {
    match state {
        NodeState::Slip => SLIP.mix(0.22),
        _ => STICK.mix(0.16),
    }
}

/// A linear axis with the ticks we choose ([`nice_ticks`]: 0 among them), where plotters' own
/// choice may skip 0.
#[derive(Debug, Clone)]
struct Ticked {
    range: (f64, f64),
    ticks: Vec<f64>,
}

impl Ticked {
    fn new((lo, hi): (f64, f64), intervals: usize) -> (Self, f64) {
        let (step, ticks) = nice_ticks(lo, hi, intervals);
        (Self { range: (lo, hi), ticks }, step)
    }

    fn scaled(&self, factor: f64, intervals: usize) -> (Self, f64) {
        Self::new((factor * self.range.0, factor * self.range.1), intervals)
    }
}

impl Ranged for Ticked {
    type ValueType = f64;
    type FormatOption = DefaultFormatting;

    fn range(&self) -> std::ops::Range<f64> {
        self.range.0..self.range.1
    }

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        let (a, b) = self.range;
        let t = (v - a) / (b - a);
        (limit.0 as f64 + t * (limit.1 - limit.0) as f64).round() as i32
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.ticks.clone()
        }
    }
}

/// A panel: x against a y with chosen ticks.
type Panel<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, Ticked>>;

/// Shades every zone over the chart's whole height.
fn shade(
    chart: &mut Panel<'_, '_>,
    zones: &[(f64, f64, NodeState, i32)],
    (y0, y1): (f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    chart.draw_series(
        zones
            .iter()
            .map(|&(a, b, state, _)| Rectangle::new([(a, y0), (b, y1)], zone_colour(state).filled())),
    )?;
    Ok(())
}

/// A panel's grid, axis titles and tick labels: x in `length` over [x0, x1], y ticks at `step`.
fn draw_axes(
    chart: &mut Panel<'_, '_>,
    y_desc: &str,
    step: f64,
    length: &str,
    (x0, x1): (f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    chart
        .configure_mesh()
        .x_desc(format!("x [{length}]"))
        .y_desc(y_desc)
        .y_label_formatter(&|v| tick_label(*v, step))
        .x_label_formatter(&|v| tick_label(*v, nice_ticks(x0, x1, 10).0))
        .light_line_style(WHITE.mix(0.0))
        .bold_line_style(BLACK.mix(0.08))
        .axis_desc_style((FONT, 15))
        .label_style((FONT, 13))
        .draw()?;
    Ok(())
}

fn draw(path: &Path, plot: &ContactPlot) -> Result<(), Box<dyn std::error::Error>> {
    let sol = plot.solution;
    let (length, stress) = (pretty(plot.length_unit), pretty(plot.stress_unit));
    let extra = plot.rolling_resistance.map_or(0, |_| RESISTANCE_LINE);
    let root = SVGBackend::new(path, (1000, 840 + extra)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(HEADER + extra);
    header(&head, plot)?;
    let (top, rest) = body.split_vertically(420);
    let (slip_legend, bottom) = rest.split_vertically(30);
    let x = &sol.x;
    let (x0, x1) = (x[0], x[x.len() - 1]);
    let zones = shaded_zones(sol);
    let mu = plot.friction;

    // Tractions: p on the left axis, q and ±μp on the right at μ times the scale.
    let p_max = sol.pressure.iter().fold(0.0_f64, |a, &b| a.max(b));
    let q_max = sol.shear.iter().fold(0.0_f64, |a, &b| a.max(b.abs()));
    let scale = if mu > 0.0 { mu } else { 1.0 };
    let reach = p_max.max(q_max / scale);
    let reach = if reach > 0.0 { reach } else { 1.0 };
    let signed_shear = mu > 0.0 || q_max > 0.0;
    let (l0, l1) = if signed_shear {
        (-1.08 * reach, 1.18 * reach)
    } else {
        (-0.05 * reach, 1.18 * reach)
    };
    let (left, step) = Ticked::new((l0, l1), 8);
    let (right, rstep) = left.scaled(scale, 8);
    let mut chart = ChartBuilder::on(&top)
        .margin_left(10)
        .margin_right(10)
        .margin_top(8)
        .x_label_area_size(42)
        .y_label_area_size(80)
        .right_y_label_area_size(80)
        .build_cartesian_2d(x0..x1, left)?
        .set_secondary_coord(x0..x1, right);
    shade(&mut chart, &zones, (l0, l1))?;
    draw_axes(&mut chart, &format!("pressure p [{stress}]"), step, &length, (x0, x1))?;
    chart
        .configure_secondary_axes()
        .y_desc(if mu > 0.0 {
            format!("shear q, ±μp [{stress}]   (scale: μ × left)")
        } else {
            format!("shear q [{stress}]")
        })
        .y_label_formatter(&|v| tick_label(*v, rstep))
        .axis_desc_style((FONT, 15).into_font().color(&SHEAR))
        .label_style((FONT, 13))
        .draw()?;
    chart.draw_series(LineSeries::new([(x0, 0.0), (x1, 0.0)], BLACK.mix(0.6)))?;
    let series = |v: &[f64]| x.iter().copied().zip(v.iter().copied()).collect::<Vec<_>>();
    if mu > 0.0 {
        let bound: Vec<f64> = sol.pressure.iter().map(|p| mu * p).collect();
        let neg: Vec<f64> = bound.iter().map(|b| -b).collect();
        let dashed = ShapeStyle::from(BLACK.mix(0.75)).stroke_width(1);
        chart.draw_secondary_series(DashedLineSeries::new(series(&bound), 6, 4, dashed))?;
        chart.draw_secondary_series(DashedLineSeries::new(series(&neg), 6, 4, dashed))?;
    }
    chart.draw_series(LineSeries::new(series(&sol.pressure), PRESSURE.stroke_width(2)))?;
    chart.draw_secondary_series(LineSeries::new(series(&sol.shear), SHEAR.stroke_width(2)))?;
    label_zones(&mut chart, &zones, (x0, x1), l1)?;
    mark_leading_edge(&mut chart, sol, plot.flow_sign, (l0, l1))?;
    if let Some(r) = plot.rolling_resistance {
        mark_asymmetry(&mut chart, r, (l0, l1))?;
    }
    let mut entries = vec![
        (Sample::Line(PRESSURE, 2), "pressure p (left axis)".to_string()),
        (Sample::Line(SHEAR, 2), "shear q on A (right axis)".to_string()),
    ];
    if mu > 0.0 {
        entries.push((
            Sample::Dashed(BLACK.mix(0.75)),
            "±μp, the friction bounds (right axis)".to_string(),
        ));
    }
    legend_row(&head, (90, 88 + extra as i32), &entries)?;
    let mut entries = vec![(
        Sample::Line(SLIP_LINE, 2),
        "slip (finite difference, as solved)".to_string(),
    )];
    if sol.slip_strain.is_some() {
        entries.push((Sample::Dot(HBEM), "slip (boundary-integral derivative)".to_string()));
    }
    legend_row(&slip_legend, (90, 18), &entries)?;
    slip_panel(&bottom, plot, &zones, (x0, x1))?;
    root.present()?;
    Ok(())
}

/// What a legend entry shows.
#[derive(Debug, Clone, Copy)]
enum Sample {
    /// A line of this colour and width.
    Line(RGBColor, u32),
    /// A dashed line.
    Dashed(RGBAColor),
    /// A dot.
    Dot(RGBColor),
}

/// A legend as one row of entries from pixel (x, y) of `area` (outside the panels: it hides no
/// curve).
fn legend_row(
    area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
    (mut x, y): (i32, i32),
    entries: &[(Sample, String)],
) -> Result<(), Box<dyn std::error::Error>> {
    let style = (FONT, 13)
        .into_font()
        .color(&BLACK)
        .pos(Pos::new(HPos::Left, VPos::Center));
    for (sample, label) in entries {
        match *sample {
            Sample::Line(c, w) => area.draw(&PathElement::new(vec![(x, y), (x + 26, y)], c.stroke_width(w)))?,
            Sample::Dashed(c) => {
                for k in 0..3 {
                    area.draw(&PathElement::new(vec![(x + 10 * k, y), (x + 10 * k + 6, y)], c))?;
                }
            }
            Sample::Dot(c) => area.draw(&Circle::new((x + 13, y), 3, c.filled()))?,
        }
        area.draw(&Text::new(label.clone(), (x + 32, y), style.clone()))?;
        let (w, _) = area.estimate_text_size(label, &style)?;
        x += 32 + w as i32 + 28;
    }
    Ok(())
}

/// Title, the loads and the rolling direction.
fn header(
    area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
    plot: &ContactPlot,
) -> Result<(), Box<dyn std::error::Error>> {
    let sol = plot.solution;
    area.draw(&Text::new(
        plot.title.to_string(),
        (20, 10),
        (FONT, 19).into_font().style(FontStyle::Bold),
    ))?;
    let force = pretty(plot.force_unit);
    let ratio = if plot.friction > 0.0 && sol.normal_force > 0.0 {
        format!(
            ",  Q/μP = {:.3}",
            sol.tangential_force / (plot.friction * sol.normal_force)
        )
    } else {
        String::new()
    };
    let loads = format!(
        "μ = {},  P = {:.5} {force},  Q = {:.5} {force}{ratio},  creepage ξ = {:.4e}",
        plot.friction, sol.normal_force, sol.tangential_force, sol.creep
    );
    area.draw(&Text::new(loads, (20, 38), (FONT, 14)))?;
    let (arrow, edge) = if plot.flow_sign < 0.0 {
        ("→", "+x")
    } else {
        ("←", "−x")
    };
    let rolling = format!(
        "rolling direction {arrow}  (the contact moves in {edge} over the bodies; leading edge on the {edge} side)"
    );
    area.draw(&Text::new(
        rolling,
        (20, 58),
        (FONT, 14).into_font().color(&BLACK.mix(0.8)),
    ))?;
    if let Some(r) = plot.rolling_resistance {
        let length = pretty(plot.length_unit);
        let resistance = format!(
            "F_r = {:.4e} {force},  F_r/P = {:.4e};  pressure centre {:+.4e} {length} towards the leading \
             edge;  trailing edge {:+.4}, leading edge {:+.4} {length}",
            r.force, r.coefficient, r.pressure_centre, r.trailing_edge, r.leading_edge
        );
        area.draw(&Text::new(
            resistance,
            (20, 78),
            (FONT, 13).into_font().color(&PRESSURE),
        ))?;
    }
    let legend = "shaded: stick (blue), slip (orange, arrow: direction in which A slips relative to B)";
    let right = Pos::new(HPos::Right, VPos::Top);
    area.draw(&Text::new(
        legend,
        (980, 58),
        (FONT, 12).into_font().color(&BLACK.mix(0.7)).pos(right),
    ))?;
    Ok(())
}

/// `stick` and `slip →` above each zone wide enough for its label.
fn label_zones(
    chart: &mut Panel<'_, '_>,
    zones: &[(f64, f64, NodeState, i32)],
    (x0, x1): (f64, f64),
    top: f64,
) -> Result<(), Box<dyn std::error::Error>> {
    let centre = Pos::new(HPos::Center, VPos::Top);
    let span = x1 - x0;
    let labels = zones
        .iter()
        .filter(|z| (z.1 - z.0) > 0.025 * span)
        .map(|&(a, b, state, dir)| {
            let wide = (b - a) > 0.07 * span;
            let text = match (state, dir, wide) {
                (NodeState::Slip, d, true) if d > 0 => "slip →",
                (NodeState::Slip, d, true) if d < 0 => "← slip",
                (NodeState::Slip, d, false) if d > 0 => "→",
                (NodeState::Slip, d, false) if d < 0 => "←",
                (NodeState::Slip, _, _) => "slip",
                (_, _, true) => "stick",
                _ => "",
            };
            let colour = if state == NodeState::Slip {
                RGBColor(170, 90, 0)
            } else {
                RGBColor(30, 70, 150)
            };
            Text::new(
                text,
                (0.5 * (a + b), top),
                (FONT, 15).into_font().color(&colour).pos(centre),
            )
        });
    chart.draw_series(labels)?;
    Ok(())
}

/// A dotted vertical line at the leading edge of the contact, labelled.
fn mark_leading_edge(
    chart: &mut Panel<'_, '_>,
    sol: &ContactSolution,
    flow_sign: f64,
    (y0, y1): (f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    let Some([a, b]) = sol.contact_extent() else {
        return Ok(());
    };
    let (edge, pos) = if flow_sign < 0.0 {
        (b, Pos::new(HPos::Right, VPos::Top))
    } else {
        (a, Pos::new(HPos::Left, VPos::Top))
    };
    let style = ShapeStyle::from(BLACK.mix(0.55)).stroke_width(1);
    let label = Marker {
        text: "leading edge ",
        height: 0.88,
        colour: BLACK.mix(0.7),
        pos,
    };
    vertical_marker(chart, edge, (y0, y1), (2, 4), style, label)
}

/// A label of a [`vertical_marker`]: its text, its height as a fraction of the panel's, its
/// colour and its anchor.
struct Marker<'a, C: Color> {
    text: &'a str,
    height: f64,
    colour: C,
    pos: Pos,
}

/// A dashed vertical line at `x` over the panel's height (`dash`: dash and gap lengths [px]),
/// and its label.
fn vertical_marker<C: Color>(
    chart: &mut Panel<'_, '_>,
    x: f64,
    (y0, y1): (f64, f64),
    (dash, gap): (u32, u32),
    style: ShapeStyle,
    label: Marker<'_, C>,
) -> Result<(), Box<dyn std::error::Error>> {
    chart.draw_series(DashedLineSeries::new([(x, y0), (x, y1)], dash, gap, style))?;
    chart.draw_series(std::iter::once(Text::new(
        label.text.to_string(),
        (x, y0 + label.height * (y1 - y0)),
        (FONT, 12).into_font().color(&label.colour).pos(label.pos),
    )))?;
    Ok(())
}

/// The trailing edge (dotted, like the leading edge) and the pressure centre (dashed, in the
/// pressure's colour) of a run's rolling resistance, labelled.
fn mark_asymmetry(
    chart: &mut Panel<'_, '_>,
    r: &RollingResistance,
    (y0, y1): (f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    // The pressure centre is measured from x = 0 towards the leading edge.
    let leading = if r.leading_edge >= r.trailing_edge { 1.0 } else { -1.0 };
    let (inward, outward) = if leading > 0.0 {
        (HPos::Left, HPos::Right)
    } else {
        (HPos::Right, HPos::Left)
    };
    let grey = ShapeStyle::from(BLACK.mix(0.55)).stroke_width(1);
    let trailing = Marker {
        text: " trailing edge ",
        height: 0.88,
        colour: BLACK.mix(0.7),
        pos: Pos::new(inward, VPos::Top),
    };
    vertical_marker(chart, r.trailing_edge, (y0, y1), (2, 4), grey, trailing)?;
    let style = ShapeStyle::from(PRESSURE.mix(0.8)).stroke_width(1);
    let centre = Marker {
        text: " pressure centre ",
        height: 0.80,
        colour: PRESSURE,
        pos: Pos::new(outward, VPos::Top),
    };
    vertical_marker(chart, leading * r.pressure_centre, (y0, y1), (8, 4), style, centre)
}

/// The slip velocity over |V| at the nodes in contact.
fn slip_panel(
    area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
    plot: &ContactPlot,
    zones: &[(f64, f64, NodeState, i32)],
    (x0, x1): (f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    let sol = plot.solution;
    let x = &sol.x;
    let in_contact: Vec<usize> = (0..x.len()).filter(|&i| sol.state[i] != NodeState::Open).collect();
    let pick = |v: &[f64]| in_contact.iter().map(|&i| (x[i], v[i])).collect::<Vec<_>>();
    let hbem = sol.slip_strain.as_ref().filter(|s| s.iter().all(|v| v.is_finite()));
    let values = in_contact
        .iter()
        .map(|&i| sol.slip[i])
        .chain(hbem.into_iter().flat_map(|s| in_contact.iter().map(move |&i| s[i])))
        .chain([0.0]);
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    let (s0, s1) = padded(lo, hi);
    let (axis, step) = Ticked::new((s0, s1), 6);
    let mut chart = ChartBuilder::on(area)
        .margin_left(10)
        .margin_right(90)
        .margin_top(10)
        .margin_bottom(6)
        .x_label_area_size(42)
        .y_label_area_size(80)
        .build_cartesian_2d(x0..x1, axis)?;
    shade(&mut chart, zones, (s0, s1))?;
    let length = pretty(plot.length_unit);
    draw_axes(
        &mut chart,
        "slip s = velocity of A rel. to B / |V| [-]",
        step,
        &length,
        (x0, x1),
    )?;
    chart.draw_series(LineSeries::new([(x0, 0.0), (x1, 0.0)], BLACK.stroke_width(1)))?;
    chart.draw_series(LineSeries::new(pick(&sol.slip), SLIP_LINE.stroke_width(2)))?;
    if let Some(s) = hbem {
        chart.draw_series(pick(s).into_iter().map(|p| Circle::new(p, 2, HBEM.filled())))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_include_zero_and_cover_the_range() {
        for (lo, hi) in [(-1.3e-3, 2.0e-4), (-0.07, 0.9), (-1200.0, 1350.0), (3e-5, 4e-4)] {
            let (step, ticks) = nice_ticks(lo, hi, 6);
            assert!(ticks.len() >= 3, "{lo}..{hi}: {ticks:?}");
            assert!(ticks.iter().all(|t| *t >= lo && *t <= hi));
            assert!(ticks.windows(2).all(|w| ((w[1] - w[0]) - step).abs() < 1e-9 * step));
            if lo < 0.0 && hi > 0.0 {
                assert!(ticks.contains(&0.0), "{lo}..{hi}: {ticks:?}");
            }
        }
    }

    #[test]
    fn tick_labels_are_short() {
        assert_eq!(tick_label(0.0, 2e-4), "0");
        assert_eq!(tick_label(-4e-4, 2e-4), "-4e-4");
        assert_eq!(tick_label(1.5e-3, 5e-4), "1.5e-3");
        assert_eq!(tick_label(0.25, 0.05), "0.25");
        assert_eq!(tick_label(-0.4, 0.2), "-0.4");
        assert_eq!(tick_label(1200.0, 200.0), "1200");
    }
}
