//! The collocation model of one contact: the rim kernels of both bodies, the pressure series on
//! the arc, and the arc found by Brent's method (the module docs of [`super`]).

// The items and imports of the scene types (a split of one module).
use super::*;

impl Model {
    pub(super) fn new(scene: &DiscInBore) -> Result<Self, ConformalError> {
        let (r1, r2) = (scene.roller.radius, scene.ring.bore_radius);
        if !(r1 > 0.0 && r2 >= r1 && r2 < 2.0 * r1) {
            return Err(ConformalError::Fit { roller: r1, bore: r2 });
        }
        let res = scene.resolution;
        if res.pressure_terms < 2 || res.truncation.is_some_and(|m| m < 16) {
            return Err(ConformalError::Resolution {
                terms: res.pressure_terms,
                modes: res.truncation,
            });
        }
        let roller = Annulus::new(scene.roller.shaft_radius, r1, scene.roller.material, LoadedRim::Outer)?;
        let ring = Annulus::new(r2, scene.ring.rim_radius, scene.ring.material, LoadedRim::Inner)?;
        let (c1, c2) = (
            scene.roller.material.plane_strain_compliance(),
            scene.ring.material.plane_strain_compliance(),
        );
        let (roller_modes, ring_modes) = match res.truncation {
            Some(m) => (roller.compliances(m), ring.compliances(m)),
            None => (Vec::new(), Vec::new()),
        };
        Ok(Self {
            r1,
            r2,
            clearance: r2 - r1,
            ring_share: c2 / (c1 + c2),
            direction: scene.direction,
            terms: res.pressure_terms,
            quadrature: res.quadrature,
            truncation: res.truncation,
            roller_kernel: RimKernel::new(&roller),
            ring_kernel: RimKernel::new(&ring),
            roller_modes,
            ring_modes,
        })
    }

    /// Pairing of the bore point θ for the centre distance d (eq. C1–C2).
    pub(super) fn pair(&self, theta: f64, d: f64) -> Pair {
        let (st, ct) = theta.sin_cos();
        let root = (self.r1 * self.r1 - d * d * st * st).max(0.0).sqrt();
        let s = d * ct + root;
        let ds_dtheta = -d * st - d * d * st * ct / root;
        let ds_dd = ct - d * st * st / root;
        // Roller point X = s e_r(θ); θ1 = arg(X − O1); dθ1/dθ = ((X − O1) × X')/|X − O1|².
        let (x, y) = (s * ct - d, s * st);
        let theta1 = y.atan2(x);
        let (xp, yp) = (ds_dtheta * ct - s * st, ds_dtheta * st + s * ct);
        let dtheta1 = (x * yp - y * xp) / (x * x + y * y);
        let psi = match self.direction {
            TractionDirection::CommonNormal => theta + self.ring_share * (theta1 - theta),
            TractionDirection::LoadLine => 0.0,
        };
        Pair {
            theta,
            theta1,
            dtheta1,
            s,
            ds_dd,
            psi,
        }
    }

    /// Nodes of the product-integration rule for the arc θc: 3K + 40, plus what the
    /// remainder series of the shaft and the rim need across the arc.
    fn rule_size(&self, theta_c: f64, d: f64) -> usize {
        if self.quadrature > 0 {
            return self.quadrature;
        }
        let span = theta_c.max(self.pair(theta_c, d).theta1.abs());
        let rest = self
            .roller_kernel
            .remainder_modes()
            .max(self.ring_kernel.remainder_modes());
        3 * self.terms + 40 + (1.5 * rest as f64 * span).ceil() as usize
    }

    pub(super) fn displacements(&self, theta_c: f64, d: f64, targets: &[Pair]) -> RimDisplacements {
        match self.truncation {
            None => self.kernel_displacements(theta_c, d, targets),
            Some(m) => self.fourier_displacements(theta_c, d, targets, m),
        }
    }

    /// Closed-form kernels and product integration (eq. C6–C9).
    fn kernel_displacements(&self, theta_c: f64, d: f64, targets: &[Pair]) -> RimDisplacements {
        let k = self.terms;
        let rule = ChebyshevRule::new(self.rule_size(theta_c, d));
        let sources: Vec<Pair> = rule.nodes.iter().map(|&t| self.pair(theta_c * t, d)).collect();
        let tractions: Vec<[f64; 4]> = sources.iter().map(|p| p.tractions(self.r2 / self.r1)).collect();
        let basis: Vec<Vec<f64>> = rule.nodes.iter().map(|&t| chebyshev_even(t, k)).collect();
        let nt = targets.len();
        let mut out = RimDisplacements {
            ring_r: DMatrix::zeros(k, nt),
            ring_t: DMatrix::zeros(k, nt),
            roller_r: DMatrix::zeros(k, nt),
            roller_t: DMatrix::zeros(k, nt),
        };
        let reg = rule.regular_weight();
        let factor = theta_c / PI;
        for (col, tg) in targets.iter().enumerate() {
            let t = tg.theta / theta_c;
            let (wl, ws) = (rule.log_weights(t), rule.sign_weights(t));
            for body in 0..2 {
                let (kern, target_angle) = if body == 0 {
                    (&self.ring_kernel, tg.theta)
                } else {
                    (&self.roller_kernel, tg.theta1)
                };
                let (mut ur, mut ut) = (vec![0.0; k], vec![0.0; k]);
                for (i, src) in sources.iter().enumerate() {
                    let (source_angle, slope) = if body == 0 {
                        (src.theta, theta_c)
                    } else {
                        (src.theta1, theta_c * src.dtheta1)
                    };
                    let u = target_angle - source_angle;
                    let dt = t - rule.nodes[i];
                    // ln|u| = ln|t − τ| + ln|u/(t − τ)|, the second smooth (its limit ln|dΘ/dτ|).
                    let ratio = if dt.abs() > 1e-12 {
                        (u / dt).abs().ln()
                    } else {
                        slope.abs().ln()
                    };
                    let [rr, rs, tt] = kern.eval(u);
                    let w = |x: kernel::Split| wl[i] * x.ln + ws[i] * x.sgn + reg * (x.ln * ratio + x.smooth);
                    let (wrr, wrs, wtt) = (w(rr), w(rs), w(tt));
                    let (sig, tau) = if body == 0 {
                        (tractions[i][0], tractions[i][1])
                    } else {
                        (tractions[i][2], tractions[i][3])
                    };
                    let (a, b) = (wrr * sig - wrs * tau, wrs * sig + wtt * tau);
                    for j in 0..k {
                        ur[j] += a * basis[i][j];
                        ut[j] += b * basis[i][j];
                    }
                }
                let (mr, mt) = if body == 0 {
                    (&mut out.ring_r, &mut out.ring_t)
                } else {
                    (&mut out.roller_r, &mut out.roller_t)
                };
                for j in 0..k {
                    mr[(j, col)] = factor * ur[j];
                    mt[(j, col)] = factor * ut[j];
                }
            }
        }
        out
    }

    /// Plain Fourier series to mode M: traction amplitudes by Gauss–Chebyshev quadrature (even
    /// integrands: the positive half of the rule), then Σ C_n (T_n, S_n) (cos, sin) nθ.
    fn fourier_displacements(&self, theta_c: f64, d: f64, targets: &[Pair], m: usize) -> RimDisplacements {
        let k = self.terms;
        let theta1_c = self.pair(theta_c, d).theta1.abs();
        // cos(nθc τ)·T_2j needs a rule exact to degree ~ Mθc + 2K.
        let half = ((m as f64 * theta_c.max(theta1_c) + 2.0 * k as f64) / 4.0).ceil() as usize + 24;
        let q = 2 * half;
        let nodes: Vec<f64> = (1..=half)
            .map(|i| ((2 * i - 1) as f64 * PI / (2 * q) as f64).cos())
            .collect();
        let w = 2.0 * PI / q as f64;
        let mut basis = DMatrix::zeros(k, half);
        let mut comp = vec![[0.0; 4]; half];
        let mut trig2 = [DMatrix::zeros(half, m + 1), DMatrix::zeros(half, m + 1)];
        let mut trig1 = [DMatrix::zeros(half, m + 1), DMatrix::zeros(half, m + 1)];
        for (i, &t) in nodes.iter().enumerate() {
            let pr = self.pair(theta_c * t, d);
            for (j, v) in chebyshev_even(t, k).into_iter().enumerate() {
                basis[(j, i)] = v;
            }
            comp[i] = pr.tractions(self.r2 / self.r1);
            fill_trig(&mut trig2, i, pr.theta);
            fill_trig(&mut trig1, i, pr.theta1);
        }
        let scale = theta_c * w / PI;
        let project = |c: usize, tr: &DMatrix<f64>| {
            let mut b = basis.clone();
            for (i, ci) in comp.iter().enumerate() {
                b.column_mut(i).scale_mut(ci[c] * scale);
            }
            let mut out = b * tr;
            // Mode 0 is the mean: 1/(2π) instead of 1/π.
            out.column_mut(0).scale_mut(0.5);
            out
        };
        let (t2, s2, t1, s1) = (
            project(0, &trig2[0]),
            project(1, &trig2[1]),
            project(2, &trig1[0]),
            project(3, &trig1[1]),
        );
        let amplitudes = |comps: &[ModeCompliance], t: &DMatrix<f64>, s: &DMatrix<f64>| {
            let (mut u, mut v) = (DMatrix::zeros(k, m + 1), DMatrix::zeros(k, m + 1));
            for (n, c) in comps.iter().enumerate() {
                for j in 0..k {
                    let (un, vn) = c.displacement(t[(j, n)], s[(j, n)]);
                    u[(j, n)] = un;
                    v[(j, n)] = if n == 0 { 0.0 } else { vn };
                }
            }
            (u, v)
        };
        let (u2, v2) = amplitudes(&self.ring_modes, &t2, &s2);
        let (u1, v1) = amplitudes(&self.roller_modes, &t1, &s1);
        let nt = targets.len();
        let mut cos2 = DMatrix::zeros(m + 1, nt);
        let mut sin2 = DMatrix::zeros(m + 1, nt);
        let mut cos1 = DMatrix::zeros(m + 1, nt);
        let mut sin1 = DMatrix::zeros(m + 1, nt);
        for (col, p) in targets.iter().enumerate() {
            fill_trig_column(&mut cos2, &mut sin2, col, p.theta);
            fill_trig_column(&mut cos1, &mut sin1, col, p.theta1);
        }
        RimDisplacements {
            ring_r: &u2 * &cos2,
            ring_t: &v2 * &sin2,
            roller_r: &u1 * &cos1,
            roller_t: &v1 * &sin1,
        }
    }

    /// Elastic part of the gap along n at target `col`, per pressure term (eq. C4).
    pub(super) fn elastic_gap(&self, disp: &RimDisplacements, col: usize, p: &Pair) -> Vec<f64> {
        let (sn2, cn2) = (p.psi - p.theta).sin_cos();
        let (sn1, cn1) = (p.psi - p.theta1).sin_cos();
        (0..self.terms)
            .map(|j| {
                disp.ring_r[(j, col)] * cn2 + disp.ring_t[(j, col)] * sn2
                    - disp.roller_r[(j, col)] * cn1
                    - disp.roller_t[(j, col)] * sn1
            })
            .collect()
    }

    /// Solves the arc problem for the half-angle θc, linearised about the centre distance d.
    fn arc(&self, theta_c: f64, d: f64, load: f64) -> Arc {
        let k = self.terms;
        // Collocation at the positive roots of T_2K.
        let colloc: Vec<Pair> = (0..k)
            .map(|m| self.pair(theta_c * ((2 * m + 1) as f64 * PI / (4 * k) as f64).cos(), d))
            .collect();
        let disp = self.displacements(theta_c, d, &colloc);
        let mut a = DMatrix::zeros(k + 1, k + 1);
        let mut b = DVector::zeros(k + 1);
        for (m, p) in colloc.iter().enumerate() {
            for (j, g) in self.elastic_gap(&disp, m, p).into_iter().enumerate() {
                a[(m, j)] = g;
            }
            // Rigid gap (R2 − s(d + Δd))·cos(ψ − θ), linear in the step Δd (eq. C4).
            let cn2 = (p.psi - p.theta).cos();
            a[(m, k)] = -p.ds_dd * cn2;
            b[m] = -(self.r2 - p.s) * cn2;
        }
        // Load: P = ∫ p cos ψ R2 dθ (eq. C5), Gauss–Chebyshev (even integrand, positive half).
        let half = 2 * k + 16;
        let w = PI / half as f64;
        for i in 1..=half {
            let t = ((2 * i - 1) as f64 * PI / (4 * half) as f64).cos();
            let pr = self.pair(theta_c * t, d);
            for (j, v) in chebyshev_even(t, k).into_iter().enumerate() {
                a[(k, j)] += self.r2 * theta_c * w * v * pr.psi.cos();
            }
        }
        b[k] = load;
        let x = a
            .lu()
            .solve(&b)
            .unwrap_or_else(|| DVector::from_element(k + 1, f64::NAN));
        let coefficients: Vec<f64> = x.iter().take(k).copied().collect();
        let edge = coefficients.iter().sum::<f64>() * self.r2 * theta_c / load;
        Arc {
            coefficients,
            step: x[k],
            edge,
        }
    }

    /// Half-angle whose pressure is bounded (edge coefficient zero), by bracketing and Brent.
    pub(super) fn bounded_arc(&self, guess: f64, d: f64, load: f64) -> Result<(f64, Arc), ConformalError> {
        let f = |th: f64| self.arc(th, d, load).edge;
        let max_angle = 150.0_f64.to_radians();
        let (mut lo, mut hi) = (guess, guess);
        let (mut f_lo, mut f_hi) = (f(lo), f(lo));
        if !f_lo.is_finite() {
            return Err(ConformalError::NotConverged(format!(
                "singular arc system at θc = {guess}"
            )));
        }
        // Too small an arc needs a compressive edge singularity (positive coefficient).
        while f_hi > 0.0 {
            lo = hi;
            f_lo = f_hi;
            hi = (hi * 1.25).min(max_angle);
            f_hi = f(hi);
            if hi >= max_angle && f_hi > 0.0 {
                return Err(ConformalError::ArcTooLarge {
                    max_degrees: max_angle.to_degrees(),
                });
            }
        }
        while f_lo < 0.0 {
            hi = lo;
            f_hi = f_lo;
            lo /= 1.25;
            f_lo = f(lo);
            if lo < 1e-7 {
                return Err(ConformalError::NotConverged("no contact arc above 1e−7 rad".into()));
            }
        }
        let theta = brent(f, lo, hi, f_lo, f_hi, 1e-14)?;
        Ok((theta, self.arc(theta, d, load)))
    }
}

/// T_0(t), T_2(t), …, T_{2(k−1)}(t).
pub(super) fn chebyshev_even(t: f64, k: usize) -> Vec<f64> {
    let mut out = Vec::with_capacity(k);
    let (mut prev, mut cur) = (1.0, t);
    out.push(1.0);
    for n in 2..2 * k - 1 {
        let next = 2.0 * t * cur - prev;
        prev = cur;
        cur = next;
        if n % 2 == 0 {
            out.push(cur);
        }
    }
    out
}

/// Row i of the (cos nθ, sin nθ) tables, n = 0..=M, by the rotation recurrence.
fn fill_trig(tables: &mut [DMatrix<f64>; 2], i: usize, theta: f64) {
    let (st, ct) = theta.sin_cos();
    let (mut c, mut s) = (1.0, 0.0);
    for n in 0..tables[0].ncols() {
        tables[0][(i, n)] = c;
        tables[1][(i, n)] = s;
        (c, s) = (c * ct - s * st, s * ct + c * st);
    }
}

/// Column m of the (cos nθ, sin nθ) tables, n = 0..=M.
fn fill_trig_column(cos: &mut DMatrix<f64>, sin: &mut DMatrix<f64>, m: usize, theta: f64) {
    let (st, ct) = theta.sin_cos();
    let (mut c, mut s) = (1.0, 0.0);
    for n in 0..cos.nrows() {
        cos[(n, m)] = c;
        sin[(n, m)] = s;
        (c, s) = (c * ct - s * st, s * ct + c * st);
    }
}

/// Brent's root finder on a bracket [a, b] with f(a)·f(b) < 0, to the absolute tolerance `tol`.
pub(super) fn brent(f: impl Fn(f64) -> f64, a: f64, b: f64, fa: f64, fb: f64, tol: f64) -> Result<f64, ConformalError> {
    let (mut a, mut b, mut fa, mut fb) = (a, b, fa, fb);
    if fa.abs() < fb.abs() {
        std::mem::swap(&mut a, &mut b);
        std::mem::swap(&mut fa, &mut fb);
    }
    let (mut c, mut fc) = (a, fa);
    let mut mflag = true;
    let mut d = 0.0;
    for _ in 0..200 {
        if fb == 0.0 || (b - a).abs() < tol * b.abs().max(1e-300) {
            return Ok(b);
        }
        let mut s = if fa != fc && fb != fc {
            a * fb * fc / ((fa - fb) * (fa - fc))
                + b * fa * fc / ((fb - fa) * (fb - fc))
                + c * fa * fb / ((fc - fa) * (fc - fb))
        } else {
            b - fb * (b - a) / (fb - fa)
        };
        let lo = (3.0 * a + b) / 4.0;
        let out_of_range = !((s > lo.min(b)) && (s < lo.max(b)));
        if out_of_range
            || (mflag && (s - b).abs() >= (b - c).abs() / 2.0)
            || (!mflag && (s - b).abs() >= (c - d).abs() / 2.0)
        {
            s = 0.5 * (a + b);
            mflag = true;
        } else {
            mflag = false;
        }
        let fs = f(s);
        if !fs.is_finite() {
            return Err(ConformalError::NotConverged(format!(
                "non-finite edge coefficient at θc = {s}"
            )));
        }
        d = c;
        c = b;
        fc = fb;
        if fa * fs < 0.0 {
            b = s;
            fb = fs;
        } else {
            a = s;
            fa = fs;
        }
        if fa.abs() < fb.abs() {
            std::mem::swap(&mut a, &mut b);
            std::mem::swap(&mut fa, &mut fb);
        }
    }
    Err(ConformalError::NotConverged("Brent on the contact half-angle".into()))
}
