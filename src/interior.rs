//! Post-processing inside the bodies: what is common to the interior fields of every model.
//!
//! Every body model offers its own interior field through [`crate::body::BodyFields::interior`]:
//! the BEM by Somigliana's identity ([`crate::bem::somigliana`]), the half-space by the Flamant /
//! Boussinesq–Cerruti line-load fields ([`crate::body::flamant`]), a rigid body none. This module
//! holds what they share: the result of one point ([`InteriorSample`]), the grid of points of
//! `output.interior` ([`InteriorField`]) and the invariants written to the outputs. Displacements
//! of a half-plane are measured from its datum (see [`crate::body::flamant`]); their differences
//! are physical.

/// Plane-strain stress at a point [stress]: in-plane σx, σz (z into the body), τxz, and the
/// out-of-plane σy = ν(σx + σz).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlaneStress {
    /// σ along the surface.
    pub sxx: f64,
    /// σ normal to the surface (z into the body).
    pub szz: f64,
    /// Shear τxz.
    pub txz: f64,
    /// Out-of-plane σ (plane strain).
    pub syy: f64,
}

impl PlaneStress {
    /// Principal shear stress τ1 = √(((σx − σz)/2)² + τxz²) [stress].
    pub fn max_shear(&self) -> f64 {
        (0.25 * (self.sxx - self.szz).powi(2) + self.txz * self.txz).sqrt()
    }

    /// von Mises equivalent stress with the plane-strain σy [stress].
    pub fn von_mises(&self) -> f64 {
        let (a, b, c) = (self.sxx, self.szz, self.syy);
        (0.5 * ((a - b).powi(2) + (b - c).powi(2) + (c - a).powi(2)) + 3.0 * self.txz * self.txz).sqrt()
    }
}

/// The fields at one interior point, in the contact frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InteriorValue {
    /// Displacement (u_x, u_y) [length] (for a half-space: from its datum, see the module docs).
    pub displacement: [f64; 2],
    /// (σxx, σyy, σzz, τxy) [stress, tension positive], σzz = ν(σxx + σyy) out of plane.
    pub stress: [f64; 4],
}

/// The result of asking a body model for its fields at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InteriorSample {
    /// The point lies inside the body: its fields.
    Inside(InteriorValue),
    /// The point lies outside the body: nothing to evaluate.
    Outside,
    /// The point lies on the boundary or within the boundary layer
    /// ([`InteriorOptions::boundary_layer`]), where the interior formulas lose accuracy: not
    /// evaluated.
    Boundary,
}

/// Where each point of an [`InteriorField`] lies; written as `status` (CSV: the name; VTK:
/// the code 0 outside, 1 inside, 2 boundary).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointStatus {
    /// Not in the body; fields written as 0.
    Outside,
    /// Evaluated.
    Inside,
    /// On the boundary or within the boundary layer; fields written as 0.
    Boundary,
}

impl PointStatus {
    /// Name in the CSV.
    pub fn name(self) -> &'static str {
        match self {
            PointStatus::Outside => "outside",
            PointStatus::Inside => "inside",
            PointStatus::Boundary => "boundary",
        }
    }

    /// Integer code in VTK files: 0 outside, 1 inside, 2 boundary.
    pub fn code(self) -> i32 {
        match self {
            PointStatus::Outside => 0,
            PointStatus::Inside => 1,
            PointStatus::Boundary => 2,
        }
    }
}

/// Accuracy controls shared by the interior evaluations of all models.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InteriorOptions {
    /// Points inside the body but closer to a boundary element than this fraction of that
    /// element's length (for a half-space: closer to the surface than this fraction of the
    /// contact grid's longest element) are reported as [`InteriorSample::Boundary`] and not
    /// evaluated. Default = 0.05 (docs/validation.md, "Interior stresses", measures
    /// the accuracy down to this distance).
    pub boundary_layer: f64,
    /// Whether the displacements are wanted (a strength assessment needs the stresses only;
    /// models may then skip them and return 0). Default = true.
    pub displacements: bool,
}

impl Default for InteriorOptions {
    fn default() -> Self {
        Self {
            boundary_layer: 0.05,
            displacements: true,
        }
    }
}

/// Interior fields on a grid of points in the contact frame, for output.
#[derive(Debug, Clone)]
pub struct InteriorField {
    /// `A` or `B`.
    pub body: String,
    /// Model of the body (`half_space`, `bem`).
    pub model: String,
    /// Points (x, y) in the contact frame, x fastest [length].
    pub points: Vec<[f64; 2]>,
    /// Number of points along x and y.
    pub shape: [usize; 2],
    /// Where each point lies; only `Inside` points carry values.
    pub status: Vec<PointStatus>,
    /// (σxx, σyy, σzz, τxy) in the contact frame, σzz the plane-strain out-of-plane stress
    /// [stress, tension positive]; 0 at points not inside.
    pub stress: Vec<[f64; 4]>,
    /// (u_x, u_y) in the contact frame [length]; 0 at points not inside.
    pub displacement: Vec<[f64; 2]>,
}

/// The points of the grid [x0, x1, nx] × [y0, y1, ny] (contact frame, x fastest).
pub fn grid_points(x: [f64; 3], y: [f64; 3]) -> Vec<[f64; 2]> {
    let (nx, ny) = (x[2] as usize, y[2] as usize);
    let at = |v: [f64; 3], n: usize, k: usize| v[0] + (v[1] - v[0]) * k as f64 / (n - 1).max(1) as f64;
    (0..ny)
        .flat_map(|j| (0..nx).map(move |i| [at(x, nx, i), at(y, ny, j)]))
        .collect()
}

impl InteriorField {
    /// Collects the samples of a model at `points` (an nx × ny grid, x fastest).
    pub fn from_samples(
        body: &str,
        model: &str,
        shape: [usize; 2],
        points: Vec<[f64; 2]>,
        samples: &[InteriorSample],
    ) -> Self {
        let mut f = Self {
            body: body.to_string(),
            model: model.to_string(),
            shape,
            status: Vec::with_capacity(points.len()),
            stress: Vec::with_capacity(points.len()),
            displacement: Vec::with_capacity(points.len()),
            points,
        };
        for s in samples {
            let (status, v) = match s {
                InteriorSample::Inside(v) => (PointStatus::Inside, *v),
                InteriorSample::Outside => (PointStatus::Outside, InteriorValue::ZERO),
                InteriorSample::Boundary => (PointStatus::Boundary, InteriorValue::ZERO),
            };
            f.status.push(status);
            f.stress.push(v.stress);
            f.displacement.push(v.displacement);
        }
        f
    }

    /// Numbers of points (inside, outside, in the boundary layer).
    pub fn counts(&self) -> [usize; 3] {
        let n = |s: PointStatus| self.status.iter().filter(|&&x| x == s).count();
        [
            n(PointStatus::Inside),
            n(PointStatus::Outside),
            n(PointStatus::Boundary),
        ]
    }
}

/// A maximum over the evaluated points of an [`InteriorField`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Peak {
    /// The value [stress].
    pub value: f64,
    /// Where: x [length], contact frame.
    pub x: f64,
    /// Where: y [length], contact frame.
    pub y: f64,
}

/// What summary.json and the run table say about the interior grid.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct InteriorSummary {
    /// `A` or `B`.
    pub body: String,
    /// The body's model.
    pub model: String,
    /// Points of the grid.
    pub points: usize,
    /// Points evaluated (status `inside`).
    pub inside: usize,
    /// Points outside the body.
    pub outside: usize,
    /// Points within the boundary layer.
    pub boundary: usize,
    /// Largest principal shear stress τ1 over the evaluated points (null if none).
    pub max_shear: Option<Peak>,
    /// Largest von Mises stress over the evaluated points (null if none).
    pub max_von_mises: Option<Peak>,
}

impl InteriorField {
    /// Counts and maxima of the grid.
    pub fn summary(&self) -> InteriorSummary {
        let [inside, outside, boundary] = self.counts();
        let peak = |which: fn((f64, f64)) -> f64| {
            self.points
                .iter()
                .zip(&self.stress)
                .zip(&self.status)
                .filter(|(_, &st)| st == PointStatus::Inside)
                .map(|((p, s), _)| Peak {
                    value: which(invariants(s)),
                    x: p[0],
                    y: p[1],
                })
                .max_by(|a, b| a.value.total_cmp(&b.value))
        };
        InteriorSummary {
            body: self.body.clone(),
            model: self.model.clone(),
            points: self.points.len(),
            inside,
            outside,
            boundary,
            max_shear: peak(|(_, ms)| ms),
            max_von_mises: peak(|(vm, _)| vm),
        }
    }
}

impl InteriorValue {
    /// All fields zero (written at points that are not evaluated).
    pub const ZERO: Self = Self {
        displacement: [0.0; 2],
        stress: [0.0; 4],
    };
}

/// von Mises and principal shear of a (σxx, σyy, σzz, τxy) stress.
pub fn invariants(s: &[f64; 4]) -> (f64, f64) {
    let ps = PlaneStress {
        sxx: s[0],
        szz: s[1],
        syy: s[2],
        txz: s[3],
    };
    (ps.von_mises(), ps.max_shear())
}
