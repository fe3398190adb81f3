//! SVG charts of the studies (plotters): the heat maps of the stability map and the
//! error–time chart of the accuracy study. They draw plain data; the studies build it.

pub mod accuracy;
pub mod heatmap;
