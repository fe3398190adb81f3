//! SVG charts of the studies (plotters): the heat maps of the stability map, the
//! error–time chart of the accuracy study, the shakedown map and the
//! history of a transient run. They draw plain data; the studies build it.

pub mod accuracy;
pub mod heatmap;
pub mod residual;
pub mod shakedown;
pub mod transient;
