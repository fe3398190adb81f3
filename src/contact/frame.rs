//! The contact's own directions: tractions along the normal and tangent of the contact
//! interface at each node, and the rigid surface speeds of curved bodies (docs/theory.md,
//! "Tractions along the contact").
//!
//! Body models give their flexibility in global axes (the pair convention of
//! [`crate::body`]: loads (P, Q) along y and x, h = the y share of the gap, w = the x share of
//! the relative displacement). A [`ContactFrame`] turns that into the contact's own frame at
//! node i, with ψ_i the angle of the interface's tangent t = (cos ψ, sin ψ) from +x and its
//! normal n = (−sin ψ, cos ψ) (from B into A):
//!
//! * **loads**: the nodal p and q are the pressure and shear per unit length of the interface,
//!   acting along n and t (on A; equal and opposite on B). Body b carries them per unit length
//!   of its own surface, whose slope angle θ_b differs from ψ: its global load is
//!   (P, Q) = s_b (p cos ψ + q sin ψ, q cos ψ − p sin ψ), s_b = cos θ_b / cos ψ (the interface
//!   element dx/cos ψ lies on a body element dx/cos θ_b);
//! * **gap**: the normal shares are measured along n and expressed as the vertical gap that
//!   h0 − δ0 is (so the solver's equations and the load equation P = Σ w_j p_j keep their form):
//!   h' = u·n / cos ψ = h − tan ψ · w;
//! * **slip**: w stays the x share, so the slip is ∂w/∂x as before, plus the rigid part of the
//!   surface speeds along x. A body turning about its centre moves its surface at
//!   V_b·(1 − h_b(x)/R_b) along x (h_b the profile, R_b the signed radius): the rigid slip
//!   k = (1 − h_A/R_A) − (1 − h_B/R_B) at each node, s = σ(ξ + k + ∂w/∂x). At second order in a/R
//!   this makes the slip the difference of the bodies' hoop strains (docs/conformal.md §4:
//!   ∂u_x/∂x = ε_θθ + tan θ·ω, whose rotation term the x-speeds V_b cos θ_b cancel).
//!
//! With ψ = 0, s = 1 and k = 0 ([`ContactFrame::global_axes`]) every transformation is the
//! identity: the half-space model's frame (its bodies are flat), and the `global` option.

use crate::body::{Flexibility, LowRankFlexibility, Side, StrainOperator};
use crate::grid::ContactGrid;
use faer::Mat;
use serde::{Deserialize, Serialize};

/// Which axes the contact tractions act along (case key `contact.traction_axes`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TractionAxes {
    /// Along the normal and tangent of the contact interface (the common normal of the two
    /// surfaces, weighted by the bodies' compliances), with the rigid surface speeds of curved
    /// bodies in the slip; the global axes when a body is a half-space (module docs).
    #[default]
    Contact,
    /// Along the global x and y axes at every node, with uniform rigid speeds (the model of
    /// the paper and of rollbem before this option; kept to measure what the choice changes).
    Global,
}

impl TractionAxes {
    /// Name as written in case files.
    pub fn name(self) -> &'static str {
        match self {
            TractionAxes::Contact => "contact",
            TractionAxes::Global => "global",
        }
    }
}

/// The contact's directions and rigid speeds at the nodes of a grid (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactFrame {
    /// ψ_i: angle of the interface's tangent from +x [rad] (positive where the interface rises
    /// with x).
    pub normal_angle: Vec<f64>,
    /// s_b,i = cos θ_b / cos ψ of body A and B [-]: interface length per body surface length.
    pub arc_scale: [Vec<f64>; 2],
    /// k_i: rigid slip of the surface speeds along x [-] (module docs).
    pub rigid_slip: Vec<f64>,
}

/// Forces the contact tractions exert on body A, in two frames [force/length].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactForces {
    /// Global x component: ∫(q − p tan ψ) dx.
    pub global_x: f64,
    /// Global y component (along the load): ∫(p + q tan ψ) dx.
    pub global_y: f64,
    /// Along the contact's normal: ∫ p ds, ds = dx / cos ψ.
    pub normal: f64,
    /// Along the contact's tangent: ∫ q ds.
    pub tangential: f64,
}

impl ContactFrame {
    /// The global axes at m nodes: ψ = 0, s = 1, k = 0.
    pub fn global_axes(m: usize) -> Self {
        Self {
            normal_angle: vec![0.0; m],
            arc_scale: [vec![1.0; m], vec![1.0; m]],
            rigid_slip: vec![0.0; m],
        }
    }

    /// Whether the frame is the global axes exactly (every transformation the identity).
    pub fn is_global(&self) -> bool {
        self.normal_angle.iter().all(|&a| a == 0.0)
            && self.arc_scale.iter().flatten().all(|&s| s == 1.0)
            && self.rigid_slip.iter().all(|&k| k == 0.0)
    }

    fn side(side: Side) -> usize {
        match side {
            Side::A => 0,
            Side::B => 1,
        }
    }

    /// The column transformation (p, q) → (P, Q) of one body's blocks at each node j:
    /// (s_j cos ψ_j, s_j sin ψ_j), s the body's arc scale.
    fn column_turn(&self, side: Side) -> (Vec<f64>, Vec<f64>) {
        let s = &self.arc_scale[Self::side(side)];
        self.normal_angle
            .iter()
            .zip(s)
            .map(|(psi, s)| {
                let (sn, c) = psi.sin_cos();
                (s * c, s * sn)
            })
            .unzip()
    }

    /// The global-axes flexibility of one body turned into this frame (module docs).
    pub fn flexibility(&self, mut f: Flexibility, side: Side) -> Flexibility {
        if self.is_global() {
            return f;
        }
        let m = self.normal_angle.len();
        // Per column j: s_j (cos ψ_j, sin ψ_j); per row i: tan ψ_i (hoisted: the transform is
        // O(m²) and ran every trigonometric function m² times).
        let (sc, ss) = self.column_turn(side);
        let tan: Vec<f64> = self.normal_angle.iter().map(|psi| psi.tan()).collect();
        // In place, entry by entry (no new m × m matrices: each costs its page faults on every
        // grid): the column transformation (p, q) → (P, Q) at node j of each pair of blocks,
        // then h' = h − tan ψ_i w at row i with the transformed w.
        for j in 0..m {
            for (i, &t) in tan.iter().enumerate() {
                let (wp, wq) = (f.wp[(i, j)], f.wq[(i, j)]);
                let (wp, wq) = (sc[j] * wp - ss[j] * wq, ss[j] * wp + sc[j] * wq);
                let (hp, hq) = (f.hp[(i, j)], f.hq[(i, j)]);
                f.hp[(i, j)] = (sc[j] * hp - ss[j] * hq) - t * wp;
                f.hq[(i, j)] = (ss[j] * hp + sc[j] * hq) - t * wq;
                f.wp[(i, j)] = wp;
                f.wq[(i, j)] = wq;
            }
        }
        f
    }

    /// Adds `alpha` times the bodies' low-rank changes of flexibility (global axes; each with
    /// the side of its body) to `f`, a flexibility in this frame: the transformation of
    /// [`Self::flexibility`], which is linear, applied to each change's right factors (the
    /// columns) and, for h' = h − tan ψ_i w', to its left factor (the rows). The factors of all
    /// changes are stacked, so that each block takes one product, made by the global
    /// parallelism (on a final grid of 1554 nodes the six thin products of each body, one after
    /// the other, cost half the check's assembly), and no m × m matrix is made beyond the sums
    /// into `f`.
    pub fn add_low_rank(&self, f: &mut Flexibility, changes: &[(&LowRankFlexibility, Side)], alpha: f64) {
        if changes.is_empty() {
            return;
        }
        let m = self.normal_angle.len();
        let turned = self.normal_angle.iter().any(|&a| a != 0.0);
        let tan: Vec<f64> = self.normal_angle.iter().map(|a| a.tan()).collect();
        // Each change's columns turned: (p, q) → (P, Q) at column j,
        // P = s(cos ψ p − sin ψ q), Q = s(sin ψ p + cos ψ q).
        let rights: Vec<[Mat<f64>; 4]> = changes
            .iter()
            .map(|(change, side)| {
                let (sc, ss) = self.column_turn(*side);
                let [hp, hq, wp, wq] = &change.right;
                let combined = |a: &Mat<f64>, ca: &[f64], b: &Mat<f64>, cb: &[f64], sign: f64| {
                    Mat::from_fn(a.nrows(), m, |l, j| ca[j] * a[(l, j)] + sign * cb[j] * b[(l, j)])
                };
                [
                    combined(hp, &sc, hq, &ss, -1.0),
                    combined(hp, &ss, hq, &sc, 1.0),
                    combined(wp, &sc, wq, &ss, -1.0),
                    combined(wp, &ss, wq, &sc, 1.0),
                ]
            })
            .collect();
        let ranks: Vec<usize> = changes.iter().map(|(c, _)| c.left.ncols()).collect();
        let rank: usize = ranks.iter().sum();
        // Rows: every change's left factor, and for the h blocks after them −tan ψ_i times it.
        let h_rank = if turned { 2 * rank } else { rank };
        let left = Mat::from_fn(m, h_rank, |i, l| {
            let (l, scale) = if l < rank { (l, 1.0) } else { (l - rank, -tan[i]) };
            let (k, c) = column_of(&ranks, l);
            scale * changes[k].0.left[(i, c)]
        });
        // Columns: each change's right factor of the block, and for the h blocks the w block's
        // of the same load after them.
        let stacked = |block: usize, with: Option<usize>| {
            let rows = if with.is_some() { h_rank } else { rank };
            Mat::from_fn(rows, m, |l, j| {
                let (l, block) = if l < rank {
                    (l, block)
                } else {
                    (l - rank, with.unwrap_or(block))
                };
                let (k, c) = column_of(&ranks, l);
                rights[k][block][(c, j)]
            })
        };
        let w = |block| turned.then_some(block);
        let par = faer::get_global_parallelism();
        let add = |dst: &mut Mat<f64>, lhs: faer::MatRef<'_, f64>, rhs: &Mat<f64>| {
            faer::linalg::matmul::matmul(dst.as_mut(), faer::Accum::Add, lhs, rhs, alpha, par);
        };
        add(&mut f.hp, left.as_ref(), &stacked(0, w(2)));
        add(&mut f.hq, left.as_ref(), &stacked(1, w(3)));
        let left_w = left.as_ref().subcols(0, rank);
        add(&mut f.wp, left_w, &stacked(2, None));
        add(&mut f.wq, left_w, &stacked(3, None));
    }

    /// The global-axes surface-strain operator of one body turned into this frame (columns
    /// only: the slip stays ∂w/∂x), in place.
    pub fn strain(&self, mut op: StrainOperator, side: Side) -> StrainOperator {
        if self.is_global() {
            return op;
        }
        let s = &self.arc_scale[Self::side(side)];
        for (j, (psi, s)) in self.normal_angle.iter().zip(s).enumerate() {
            let (sn, c) = psi.sin_cos();
            for i in 0..op.p.nrows() {
                let (p, q) = (op.p[(i, j)], op.q[(i, j)]);
                op.p[(i, j)] = s * (c * p - sn * q);
                op.q[(i, j)] = s * (sn * p + c * q);
            }
        }
        op
    }

    /// [`Self::global_loads`] as one-column matrices, the loads a body model's
    /// [`crate::body::BodyModel::displacements`] and `strain_at` take.
    pub fn global_load_columns(&self, side: Side, p: &[f64], q: &[f64]) -> (Mat<f64>, Mat<f64>) {
        let (pg, qg) = self.global_loads(side, p, q);
        let column = |v: &[f64]| Mat::from_fn(v.len(), 1, |i, _| v[i]);
        (column(&pg), column(&qg))
    }

    /// The nodal loads (P, Q) that body `side` carries in global axes (pair convention: P
    /// along y, Q along x, per unit length of its own surface) for the contact's nodal p, q.
    pub fn global_loads(&self, side: Side, p: &[f64], q: &[f64]) -> (Vec<f64>, Vec<f64>) {
        if self.is_global() {
            return (p.to_vec(), q.to_vec());
        }
        let s = &self.arc_scale[Self::side(side)];
        (0..p.len())
            .map(|j| {
                let (sn, c) = self.normal_angle[j].sin_cos();
                (s[j] * (p[j] * c + q[j] * sn), s[j] * (q[j] * c - p[j] * sn))
            })
            .unzip()
    }

    /// The forces of the nodal p, q on body A, globally and along the contact.
    pub fn forces(&self, grid: &ContactGrid, p: &[f64], q: &[f64]) -> ContactForces {
        let tan: Vec<f64> = self.normal_angle.iter().map(|a| a.tan()).collect();
        let sec: Vec<f64> = self.normal_angle.iter().map(|a| 1.0 / a.cos()).collect();
        let of = |f: &dyn Fn(usize) -> f64| grid.integrate(&(0..p.len()).map(f).collect::<Vec<_>>());
        ContactForces {
            global_x: of(&|j| q[j] - p[j] * tan[j]),
            global_y: of(&|j| p[j] + q[j] * tan[j]),
            normal: of(&|j| p[j] * sec[j]),
            tangential: of(&|j| q[j] * sec[j]),
        }
    }
}

/// The change and its own column of column `l` of changes of ranks `ranks`, stacked.
fn column_of(ranks: &[usize], mut l: usize) -> (usize, usize) {
    for (k, &r) in ranks.iter().enumerate() {
        if l < r {
            return (k, l);
        }
        l -= r;
    }
    unreachable!("a column within the stacked ranks")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    fn frame(m: usize) -> ContactFrame {
        let psi: Vec<f64> = (0..m).map(|i| 0.2 * (i as f64 / (m - 1) as f64 - 0.5)).collect();
        ContactFrame {
            arc_scale: [
                psi.iter().map(|a| (1.3 * a).cos() / a.cos()).collect(),
                psi.iter().map(|a| (0.7 * a).cos() / a.cos()).collect(),
            ],
            rigid_slip: vec![0.0; m],
            normal_angle: psi,
        }
    }

    /// Each block of `got` equal to `want`'s to rounding, entry by entry.
    fn assert_close(got: [&Mat<f64>; 4], want: [&Mat<f64>; 4], what: &str) {
        for (g, w) in got.iter().zip(want) {
            for j in 0..w.ncols() {
                for i in 0..w.nrows() {
                    assert!(
                        (g[(i, j)] - w[(i, j)]).abs() <= 1e-13 * w[(i, j)].abs().max(1.0),
                        "{what} ({i}, {j})"
                    );
                }
            }
        }
    }

    /// A low-rank change added in the frame ([`ContactFrame::add_low_rank`]) is the change of
    /// the transformed flexibility: frame(F + UR) − frame(F) to rounding, on both sides (their
    /// arc scales differ) of a frame turned by up to 0.1 rad, one side at a time and both at once;
    /// and a change of zero adds nothing.
    #[test]
    fn a_low_rank_change_is_turned_into_the_frame_as_the_whole_flexibility_is() {
        let (m, r) = (7, 3);
        let block = |a: f64, b: f64| Mat::from_fn(m, m, |i, j| a + b * ((i * 5 + 3 * j) % 11) as f64);
        let f = Flexibility {
            hp: block(1.0, 0.1),
            hq: block(0.3, -0.05),
            wp: block(-0.2, 0.02),
            wq: block(0.8, 0.07),
        };
        let change = LowRankFlexibility {
            left: Mat::from_fn(m, r, |i, l| ((i + 1) as f64).powi(l as i32) / 7.0),
            right: [0.5, -0.3, 0.2, 0.9].map(|c| Mat::from_fn(r, m, |l, j| c * (1.0 + (l * 4 + j) as f64 * 0.1))),
        };
        // F + UR, the change made dense.
        let plus_dense = |c: &LowRankFlexibility| {
            let dense = |k: usize| &c.left * &c.right[k];
            Flexibility {
                hp: &f.hp + dense(0),
                hq: &f.hq + dense(1),
                wp: &f.wp + dense(2),
                wq: &f.wq + dense(3),
            }
        };
        let plus = plus_dense(&change);
        let fr = frame(m);
        for side in [Side::A, Side::B] {
            let want = fr.flexibility(plus.clone(), side);
            let mut got = fr.flexibility(f.clone(), side);
            fr.add_low_rank(&mut got, &[(&change, side)], 1.0);
            assert_close(
                [&got.hp, &got.hq, &got.wp, &got.wq],
                [&want.hp, &want.hq, &want.wp, &want.wq],
                &format!("{side:?}"),
            );
        }
        // Both sides' changes at once (ranks 3 and 2): the sum of each side's.
        let other = LowRankFlexibility {
            left: Mat::from_fn(m, 2, |i, l| (0.3 * (i + l) as f64).cos()),
            right: [0.1, 0.4, -0.6, 0.25].map(|c| Mat::from_fn(2, m, |l, j| c * (j as f64 - 2.0 * l as f64))),
        };
        let plus_other = plus_dense(&other);
        let pair = |a: Flexibility, b: Flexibility| [&a.hp + &b.hp, &a.hq + &b.hq, &a.wp + &b.wp, &a.wq + &b.wq];
        let want = pair(fr.flexibility(plus, Side::A), fr.flexibility(plus_other, Side::B));
        let got = {
            let [hp, hq, wp, wq] = pair(fr.flexibility(f.clone(), Side::A), fr.flexibility(f.clone(), Side::B));
            let mut got = Flexibility { hp, hq, wp, wq };
            fr.add_low_rank(&mut got, &[(&change, Side::A), (&other, Side::B)], 1.0);
            [got.hp, got.hq, got.wp, got.wq]
        };
        assert_close(got.each_ref(), want.each_ref(), "both sides");
        let zero = LowRankFlexibility {
            left: change.left.clone(),
            right: std::array::from_fn(|_| Mat::zeros(r, m)),
        };
        let mut same = fr.flexibility(f.clone(), Side::A);
        fr.add_low_rank(&mut same, &[(&zero, Side::A)], 1.0);
        assert_eq!(same.hp, fr.flexibility(f, Side::A).hp);
    }

    /// The transformed flexibility is what the module docs say, entry by entry: apply it to
    /// (p, q) and compare with the displacements of the global loads, measured along n.
    #[test]
    fn flexibility_in_the_contact_frame_is_the_global_one_seen_along_n() {
        let m = 5;
        let f = Flexibility {
            hp: Mat::from_fn(m, m, |i, j| 1.0 + (i * 7 + j) as f64 * 0.1),
            hq: Mat::from_fn(m, m, |i, j| 0.3 - (i + 2 * j) as f64 * 0.05),
            wp: Mat::from_fn(m, m, |i, j| -0.2 + (3 * i + j) as f64 * 0.02),
            wq: Mat::from_fn(m, m, |i, j| 0.8 + (i as f64 - j as f64).abs() * 0.1),
        };
        let fr = frame(m);
        let (p, q) = ([1.0, 2.0, 3.0, 2.5, 0.5], [0.1, -0.2, 0.3, 0.0, 0.2]);
        for side in [Side::A, Side::B] {
            let local = fr.flexibility(f.clone(), side);
            let (gp, gq) = fr.global_loads(side, &p, &q);
            let (h, w) = (f.normal(&gp, &gq), f.tangential(&gp, &gq));
            let (h2, w2) = (local.normal(&p, &q), local.tangential(&p, &q));
            for i in 0..m {
                let t = fr.normal_angle[i].tan();
                assert!((h2[i] - (h[i] - t * w[i])).abs() < 1e-13);
                assert!((w2[i] - w[i]).abs() < 1e-13);
            }
        }
        let id = ContactFrame::global_axes(m);
        assert!(id.is_global() && id.flexibility(f.clone(), Side::A).hp == f.hp);
    }

    /// A uniform pressure on a symmetric arc: the forces add up as geometry says.
    #[test]
    fn forces_of_a_pressure_on_an_arc() {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 40, -1.0, 1.0);
        let m = grid.n_nodes();
        // Interface y = x²/2R, R = 2: tan ψ = x/R, ds = √(1 + x²/R²) dx.
        let r = 2.0;
        let fr = ContactFrame {
            normal_angle: grid.nodes.iter().map(|x| (x / r).atan()).collect(),
            arc_scale: [vec![1.0; m], vec![1.0; m]],
            rigid_slip: vec![0.0; m],
        };
        let f = fr.forces(&grid, &vec![1.0; m], &vec![0.0; m]);
        assert!(f.global_x.abs() < 1e-14 && (f.global_y - 2.0).abs() < 1e-14);
        // ∫_{-1}^{1} √(1 + x²/4) dx = 2.0805...
        let exact = 0.5 * 5f64.sqrt() + 2.0 * (0.5 + 0.5 * 5f64.sqrt()).ln();
        assert!((f.normal - exact).abs() < 1e-6, "{} vs {exact}", f.normal);
    }
}
