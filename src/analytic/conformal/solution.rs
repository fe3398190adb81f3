//! Solving a disc in a bore for a load or an approach, and what a solution gives: the pressure
//! along the arc and its samples.

// The items and imports of the scene types (a split of one module).
use super::*;

impl DiscInBore {
    /// Scene with the default traction direction (common normal) and resolution.
    pub fn new(roller: Roller, ring: Ring) -> Self {
        Self {
            roller,
            ring,
            direction: TractionDirection::default(),
            rigid_gap: RigidGap::default(),
            resolution: SeriesResolution::default(),
        }
    }

    /// Combined contact modulus E* with 1/E* = (1−ν1²)/E1 + (1−ν2²)/E2 [stress].
    pub fn contact_modulus(&self) -> f64 {
        1.0 / (self.roller.material.plane_strain_compliance() + self.ring.material.plane_strain_compliance())
    }

    /// Effective radius R* with 1/R* = 1/R1 − 1/R2 (internal contact) [length]; infinite for
    /// zero clearance.
    pub fn effective_radius(&self) -> f64 {
        let inv = 1.0 / self.roller.radius - 1.0 / self.ring.bore_radius;
        if inv > 0.0 {
            1.0 / inv
        } else {
            f64::INFINITY
        }
    }

    /// Hertz half-width a = √(4PR*/(πE*)) for the load P [length]; infinite for zero clearance.
    pub fn hertz_half_width(&self, load: f64) -> f64 {
        crate::analytic::hertz_half_width(load, self.effective_radius(), self.contact_modulus())
    }

    /// Solves the contact for the load P > 0 [force/length].
    pub fn solve(&self, load: f64) -> Result<ConformalSolution, ConformalError> {
        if !(load > 0.0 && load.is_finite()) {
            return Err(ConformalError::Load(load));
        }
        let model = Model::new(self)?;
        let hertz = self.hertz_half_width(load);
        let mut theta = if hertz.is_finite() {
            (hertz / model.r2).min(1.0)
        } else {
            1.0
        };
        let mut d = model.clearance;
        if self.rigid_gap == RigidGap::Linear {
            let (th, arc) = model.bounded_arc(theta, d, load)?;
            return Ok(ConformalSolution::new(model, load, th, d, arc));
        }
        // The rigid gap and the pairing depend on d only weakly (δ ≪ R): Newton on d converges
        // in two or three steps.
        for _ in 0..30 {
            let (th, arc) = model.bounded_arc(theta, d, load)?;
            theta = th;
            d += arc.step;
            if arc.step.abs() <= 1e-13 * model.r1 {
                let (th, arc) = model.bounded_arc(theta, d, load)?;
                return Ok(ConformalSolution::new(model, load, th, d, arc));
            }
        }
        Err(ConformalError::NotConverged("centre distance".into()))
    }
}

impl DiscInBore {
    /// Solves the contact for a prescribed approach δ > 0 [length] (zero clearance or not): the
    /// load P with `solve(P).approach` = δ to 1e−12, by Brent's method on ln P.
    pub fn solve_approach(&self, approach: f64) -> Result<ConformalSolution, ConformalError> {
        if !(approach > 0.0 && approach.is_finite()) {
            return Err(ConformalError::Load(approach));
        }
        // A probe load gives the scale: δ grows with P a little faster than linearly (Hertz:
        // δ ∝ P ln(1/P) at small load), so P·δ/δ_probe is a good first guess.
        let probe = 1e-6 * self.contact_modulus() * self.roller.radius;
        let scale = self.solve(probe)?.approach;
        let f = |ln_p: f64| -> f64 {
            match self.solve(ln_p.exp()) {
                Ok(s) => s.approach / approach - 1.0,
                Err(_) => f64::NAN,
            }
        };
        let guess = (probe * approach / scale).ln();
        let (mut lo, mut hi) = (guess - 0.5, guess + 0.5);
        let (mut f_lo, mut f_hi) = (f(lo), f(hi));
        for _ in 0..60 {
            if !(f_lo.is_finite() && f_hi.is_finite()) {
                return Err(ConformalError::ArcTooLarge { max_degrees: 150.0 });
            }
            if f_lo <= 0.0 && f_hi >= 0.0 {
                let ln_p = brent(f, lo, hi, f_lo, f_hi, 1e-13)?;
                return self.solve(ln_p.exp());
            }
            if f_lo > 0.0 {
                (hi, f_hi) = (lo, f_lo);
                lo -= 1.0;
                f_lo = f(lo);
            } else {
                (lo, f_lo) = (hi, f_hi);
                hi += 1.0;
                f_hi = f(hi);
            }
        }
        Err(ConformalError::NotConverged("load for the approach".into()))
    }
}

impl ConformalSolution {
    /// `d` is the centre distance of the pairing; the approach is d + Δd − ΔR (Δd = 0 when the
    /// exact iteration has converged).
    fn new(model: Model, load: f64, theta_c: f64, d: f64, arc: Arc) -> Self {
        let pair = model.pair(theta_c, d);
        let mut sol = Self {
            load,
            half_angle: theta_c,
            roller_half_angle: pair.theta1,
            half_width: model.r1 * pair.theta1,
            approach: d + arc.step - model.clearance,
            peak_pressure: 0.0,
            edge_residual: arc.edge,
            model,
            coefficients: arc.coefficients,
            centre_distance: d,
            step: arc.step,
        };
        sol.peak_pressure = sol.find_peak();
        sol
    }

    /// Pressure per unit bore arc length at the bore angle θ [stress]; zero outside the arc.
    /// The edge coefficient left by the root search (~1e−12) is removed so that p(±θc) = 0.
    pub fn pressure(&self, theta: f64) -> f64 {
        let t = theta.abs() / self.half_angle;
        if t >= 1.0 {
            return 0.0;
        }
        let v = chebyshev_even(t, self.coefficients.len());
        let num: f64 =
            v.iter().zip(&self.coefficients).map(|(a, b)| a * b).sum::<f64>() - self.coefficients.iter().sum::<f64>();
        num / (1.0 - t * t).sqrt()
    }

    /// `count` samples of the pressure from the contact centre to the edge, on both bodies.
    pub fn pressure_profile(&self, count: usize) -> Vec<PressureSample> {
        let last = count.max(2) - 1;
        (0..=last)
            .map(|i| self.sample(self.half_angle * i as f64 / last as f64))
            .collect()
    }

    /// The pressure and the paired positions at the bore angle θ.
    pub fn sample(&self, theta: f64) -> PressureSample {
        let pr = self.model.pair(theta, self.centre_distance);
        let p = self.pressure(theta);
        PressureSample {
            ring_angle: theta,
            roller_angle: pr.theta1,
            ring_arc: self.model.r2 * theta,
            roller_arc: self.model.r1 * pr.theta1,
            pressure: p,
            roller_pressure: p * self.model.r2 / (self.model.r1 * pr.dtheta1),
            direction: pr.psi,
        }
    }

    /// Deformed gap along the traction direction between the bore at θ and its paired roller
    /// point [length]: zero (to the resolution) on the arc, positive outside it.
    pub fn gap(&self, theta: f64) -> f64 {
        let pr = self.model.pair(theta, self.centre_distance);
        let disp = self.model.displacements(self.half_angle, self.centre_distance, &[pr]);
        let elastic: f64 = self
            .model
            .elastic_gap(&disp, 0, &pr)
            .iter()
            .zip(&self.coefficients)
            .map(|(g, c)| g * c)
            .sum();
        let rigid = self.model.r2 - pr.s - self.step * pr.ds_dd;
        rigid * (pr.psi - pr.theta).cos() + elastic
    }

    /// Radial displacements (outwards positive) of the bore at θ and of the roller at the
    /// paired angle θ1(θ) [length], relative to the fixed rim and the shaft.
    pub fn radial_displacements(&self, theta: f64) -> (f64, f64) {
        let pr = self.model.pair(theta, self.centre_distance);
        let disp = self.model.displacements(self.half_angle, self.centre_distance, &[pr]);
        let dot = |m: &DMatrix<f64>| {
            (0..self.coefficients.len())
                .map(|j| m[(j, 0)] * self.coefficients[j])
                .sum()
        };
        (dot(&disp.ring_r), dot(&disp.roller_r))
    }

    fn find_peak(&self) -> f64 {
        let n = 400;
        let (mut best, mut at) = (0.0, 0.0);
        for i in 0..n {
            let th = self.half_angle * i as f64 / n as f64;
            let p = self.pressure(th);
            if p > best {
                best = p;
                at = th;
            }
        }
        // Golden-section refinement around the best sample.
        let h = self.half_angle / n as f64;
        let (mut a, mut b) = ((at - h).max(0.0), (at + h).min(self.half_angle));
        let g = 0.5 * (5.0_f64.sqrt() - 1.0);
        for _ in 0..60 {
            let (c, d) = (b - g * (b - a), a + g * (b - a));
            if self.pressure(c) > self.pressure(d) {
                b = d;
            } else {
                a = c;
            }
        }
        best.max(self.pressure(0.5 * (a + b)))
    }
}
