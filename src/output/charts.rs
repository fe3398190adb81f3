//! SVG charts of the studies (plotters): the heat maps of the stability map, the
//! error–time chart of the accuracy study, the shakedown map and the
//! history of a transient run. They draw plain data; the studies build it.

pub mod accuracy;
pub mod heatmap;
pub mod residual;
pub mod shakedown;
pub mod transient;

use crate::error::Error;
use plotters::coord::CoordTranslate;
use plotters::prelude::*;
use std::path::Path;

/// The charts' drawing result: plotters' errors of any backend, boxed.
type Drawn = Result<(), Box<dyn std::error::Error>>;

/// The outcome of drawing the chart at `path`, a drawing error turned into the crate's output
/// error naming the file (every chart's `write`).
fn written(path: &Path, drawn: Drawn) -> Result<(), Error> {
    drawn.map_err(|e| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

/// Draws the chart's legend at `position` in the style every chart shares: a black border on a
/// light background (85 % white), so that the curves beneath stay visible.
fn draw_legend<'a, 'b: 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, SVGBackend<'b>, CT>,
    position: SeriesLabelPosition,
) -> Drawn {
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.85))
        .position(position)
        .draw()?;
    Ok(())
}

/// The legend key of a line series: a 20-pixel stroke in `style`, at the legend entry's
/// backend coordinates (pixels).
fn line_key(style: impl Into<ShapeStyle>) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    let style = style.into();
    move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style)
}
