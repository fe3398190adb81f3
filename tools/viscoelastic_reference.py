#!/usr/bin/env python3
"""Independent reference for frictionless steady rolling over a viscoelastic (SLS) half-plane.

Two solvers that share no code with rollbem and none with each other beyond the material data:

* ``exact``: Hunter's (1961) route. The SLS law u - L u' = (W - L eps W')/G_r, taken along the
  material path (L = V tau_c, eps = G_r/G_g, ' = d/dx in the contact frame), is local, so inside
  the contact it turns the known indentation u = delta - x^2/(2R) into a first-order ODE for the
  unit-modulus elastic displacement W: W' = G_r ((1-eps) L - x)/R + B exp(x/(L eps)). The airfoil
  equation for p with that right-hand side is inverted in Chebyshev series; exp(k t) expands in
  modified Bessel functions I_n(k). With x = m + c cos(phi) the pressure is
  p = sum_n beta_n sin(n phi). Three scalar conditions remain (p bounded at both edges, the load,
  and the leading-edge condition that u there is the one the material brings from ahead), solved
  for the centre m, the half-width c and B. The only numerics: scaled Bessel functions by Miller's
  recurrence, one integral by composite Gauss-Legendre, and root finding; its error is estimated
  by repeating with twice the quadrature nodes and Bessel terms.

* ``grid``: the same SLS law integrated in closed form. Its bounded solution is
  u = (eps W + (1 - eps) D)/G_r with D(x) = (1/L) int_0^inf exp(-t/L) W(x + t) dt, and for a
  piecewise-constant pressure on a uniform grid both W and D have closed-form kernels
  (x ln|x| - x and its exponential average, through the exponential integral E1/Ei). The
  frictionless contact (p >= 0, gap >= 0, complementarity) is solved by an active-set iteration
  under load control; its error is estimated by refining the grid.

Both treat two identical SLS cylinders as one SLS half-plane with twice the compliance pressed by
a rigid cylinder of radius R* = R1 R2/(R1 + R2) (quasi-identical bodies: the normal problem is
frictionless). Sign convention: the contact moves in +x over the body, material enters at the
leading edge x_lead and leaves at the trailing edge x_trail; x_p (pressure centre) is positive
towards the leading edge and F_r/P = x_p/R* is the rolling-resistance coefficient (the energy
dissipated per unit distance rolled over P).

Usage:
  viscoelastic_reference.py --write tests/data/viscoelastic_reference.csv
  viscoelastic_reference.py --check tests/data/viscoelastic_reference.csv
      (exit 1 on a difference from the table or docs/viscoelastic-reference.md's generated
      tables, or if a limit against Hertz is off)
  viscoelastic_reference.py --convergence      (grid solver on 3 grids against the exact solution)
  viscoelastic_reference.py --self-test        (limits tau_c -> 0 and tau_c -> inf against Hertz)
  viscoelastic_reference.py --pressure f9_r1   (a row's exact pressure as x,p CSV)
--write also rewrites the generated tables of docs/viscoelastic-reference.md.

Units: N, mm, s (stresses in N/mm^2, loads per unit length in N/mm). numpy only.
"""

import os
import sys

# tools/ holds an inspect.py of its own that would shadow the standard library's (which
# dataclasses and numpy import) when this file is run as a script: drop the script's folder.
_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != _HERE]

# One BLAS thread: the systems are small (threads only contend on a busy machine) and the
# results stay bit-for-bit the same from run to run, as --check needs.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import math  # noqa: E402
from dataclasses import dataclass  # noqa: E402

try:
    import numpy as np  # noqa: E402
except ImportError:  # the system Python may lack it; CI's venv has it
    sys.exit("viscoelastic_reference.py needs numpy: pip install -r tools/requirements.txt")

EULER = 0.57721566490153286060651209008240243

# --------------------------------------------------------------------------------------------
# material and case


@dataclass(frozen=True)
class Case:
    """One rolling case as an equivalent rigid cylinder on one SLS half-plane.

    g_glassy, g_rubbery: shear moduli [N/mm^2] of the equivalent half-plane (for two identical
    bodies: half of each body's); nu: Poisson's ratio; radius: R* [mm]; load: P [N/mm];
    l_creep: V tau_c [mm] (0: purely rubbery, inf: purely glassy).
    """

    group: str
    name: str
    g_glassy: float
    g_rubbery: float
    nu: float
    radius: float
    load: float
    l_creep: float

    @property
    def eps(self):
        """G_r/G_g = tau_e/tau_c (1/(1+f))."""
        return self.g_rubbery / self.g_glassy

    def hertz_half_width(self, g):
        """Hertz half-width a = sqrt(4 P R/(pi E*)), E* = 2 G/(1 - nu) (rigid on elastic)."""
        return math.sqrt(2.0 * self.load * self.radius * (1.0 - self.nu) / (math.pi * g))


def hertz(case, g):
    """Hertz's line contact for shear modulus g: (half-width, p_max)."""
    a = case.hertz_half_width(g)
    return a, 2.0 * case.load / (math.pi * a)


# --------------------------------------------------------------------------------------------
# exponential integrals (no scipy): the generalised E1(z) = -gamma - ln|z| - sum (-z)^k/(k k!)
# (for z < 0 this is -Ei(-z), the principal value)


def _e1_series_part(z):
    """-sum_{k>=1} (-z)^k/(k k!), used for |z| <= 2 (cancellation stays below 1e-14 there)."""
    term = np.ones_like(z)
    s = np.zeros_like(z)
    for k in range(1, 40):
        term = term * (-z) / k
        s -= term / k
    return s


def _exp_e1(z):
    """e^z E1(z) for z > 2: the continued fraction 1/(z+1- 1/(z+3- 4/(z+5- ...))), backwards."""
    f = np.zeros_like(z)
    for n in range(80, 0, -1):
        f = n * n / (z + 2 * n + 1 - f)
    return 1.0 / (z + 1 - f)


def _expm_ei(y):
    """e^-y Ei(y) for y > 2: the (positive) power series up to 40, the asymptotic series above."""
    out = np.empty_like(y)
    small = y <= 40.0
    ys = y[small]
    a = np.ones_like(ys)
    s = np.zeros_like(ys)
    for k in range(1, 160):
        a = a * ys / k
        s += a / k
    out[small] = np.exp(-ys) * (EULER + np.log(ys) + s)
    yl = y[~small]
    t = np.ones_like(yl)
    s = np.ones_like(yl)
    for k in range(1, 40):  # smallest term 40!/40^40 ~ 7e-17
        t = t * k / yl
        s += t
    out[~small] = s / yl
    return out


def _phi(z):
    """Phi(z) = ln|z| + gamma + e^z E1(z), finite at 0 (Phi(0) = 0); z real, nonzero."""
    z = np.asarray(z, float)
    out = np.empty_like(z)
    mid = np.abs(z) <= 2.0
    zm = z[mid]
    # ln|z| + gamma + e^z(-gamma - ln|z| + S) written without the cancellation at small z
    out[mid] = -(np.log(np.abs(zm)) + EULER) * np.expm1(zm) + np.exp(zm) * _e1_series_part(zm)
    pos = z > 2.0
    out[pos] = np.log(z[pos]) + EULER + _exp_e1(z[pos])
    neg = z < -2.0
    out[neg] = np.log(-z[neg]) + EULER - _expm_ei(-z[neg])
    return out


def _f_log(x):
    """F(x) = x ln|x| - x, the integral of ln|x| (F(0) = 0)."""
    x = np.asarray(x, float)
    out = -x.copy()
    nz = x != 0.0
    out[nz] += x[nz] * np.log(np.abs(x[nz]))
    return out


def _f_log_delayed(x, lc):
    """(1/L) int_0^inf exp(-t/L) F(x + t) dt - L (ln L - gamma) = F(x) + L Phi(x/L).

    By parts: F(x) + int e^{-t/L} ln|x+t| dt = F(x) + L ln|x| + L e^{x/L} E1(x/L); the constant
    L (ln L - gamma) is dropped (a uniform displacement, absorbed by the approach).
    """
    return _f_log(x) + lc * _phi(np.asarray(x, float) / lc)


# --------------------------------------------------------------------------------------------
# the grid solver


def grid_matrix(case, xl, xr, n):
    """Collocation matrix u_i = sum_j A_ij p_j [mm per N/mm^2] on n uniform cells of [xl, xr].

    u is the surface displacement into the body (positive under pressure), collocated at the
    cell centres, for piecewise-constant pressure. A is Toeplitz (depends on i - j only).
    """
    h = (xr - xl) / n
    d = np.arange(-(n - 1), n) * h  # x_i - c_j
    k_el = _f_log(d + h / 2) - _f_log(d - h / 2)  # int over cell of ln|x - s| ds
    eps, lc = case.eps, case.l_creep
    if lc == 0.0:
        k_del = k_el
    elif math.isinf(lc):
        k_del = np.zeros_like(k_el)  # the delayed part is a constant: absorbed by the approach
    else:
        k_del = _f_log_delayed(d + h / 2, lc) - _f_log_delayed(d - h / 2, lc)
    kern = -(1.0 - case.nu) / (math.pi * case.g_rubbery) * (eps * k_el + (1.0 - eps) * k_del)
    i = np.arange(n)
    return kern[i[:, None] - i[None, :] + n - 1], xl + (i + 0.5) * h, h


def grid_contact(case, xl, xr, n, guess=None):
    """Active-set solution of the frictionless contact under load control on one grid.

    guess: (x_trail, x_lead) to start the active set from. Returns (p per cell, cell centres,
    h, approach, gap). Raises RuntimeError if the iteration
    cycles or the contact reaches the window's ends.
    """
    a_mat, xc, h = grid_matrix(case, xl, xr, n)
    prof = xc**2 / (2.0 * case.radius)
    if guess is None:
        active = np.abs(xc - 0.5 * (xl + xr)) < 0.3 * (xr - xl)
    else:  # a coarser grid's contact: the iteration then settles in a few steps
        active = (xc > guess[0]) & (xc < guess[1])
    seen, cautious = {active.tobytes()}, False
    for it in range(2000):
        idx = np.flatnonzero(active)
        m = idx.size
        sysm = np.empty((m + 1, m + 1))
        sysm[:m, :m] = a_mat[np.ix_(idx, idx)]
        sysm[:m, m] = -1.0
        sysm[m, :m] = h
        sysm[m, m] = 0.0
        rhs = np.concatenate([-prof[idx], [case.load]])
        sol = np.linalg.solve(sysm, rhs)
        p = np.zeros(n)
        p[idx] = sol[:m]
        delta = sol[m]
        gap = a_mat @ p - delta + prof
        scale = np.max(np.abs(prof[idx])) + abs(delta)
        drop = active & (p < 0.0)
        add = ~active & (gap < -1e-13 * scale)
        new = active.copy()
        if cautious:  # one cell at a time (the most negative pressure, else the deepest gap)
            if drop.any():
                new[np.flatnonzero(drop)[np.argmin(p[drop])]] = False
            elif add.any():
                new[np.flatnonzero(add)[np.argmin(gap[add])]] = True
        else:
            new[drop] = False
            new[add] = True
        key = new.tobytes()
        if key in seen:  # changing all at once cycles (a stiff, thin boundary layer can)
            cautious = True
        seen.add(key)
        if np.array_equal(new, active):
            if active[0] or active[-1]:
                raise RuntimeError(f"{case.name}: contact reaches the window [{xl}, {xr}]")
            if os.environ.get("VR_DEBUG"):
                print(f"  n={n} iterations {it + 1}", file=sys.stderr)
            return p, xc, h, delta, gap
        active = new
    raise RuntimeError(f"{case.name}: active set did not settle on n = {n}")


def _edge(p, xc, j0, inward):
    """Edge beyond the outermost loaded cell j0: p ~ sqrt(distance) makes p^2 smooth there; a
    quadratic fitted to p^2 on the 6 cells from the third to the eighth inside (the outermost
    two carry the collocation's edge error) is extrapolated to its zero next to j0. The edge
    lies between j0's centre (loaded) and the next centre (unloaded): the estimate is held
    there, which matters where a leading-edge boundary layer thinner than the cells bends p."""
    js = j0 + inward * np.arange(2, 8)
    dx = xc[js] - xc[j0]
    co = np.polyfit(dx, p[js] ** 2, 2)
    roots = np.roots(co)
    roots = roots[np.abs(roots.imag) < 1e-12].real
    lin = np.polyfit(dx, p[js] ** 2, 1)
    r = -lin[1] / lin[0]
    if roots.size:
        r = roots[np.argmin(np.abs(roots - r))]
    h = abs(xc[1] - xc[0])
    return xc[j0] - inward * min(max(-inward * r, 0.0), h)


def grid_quantities(case, p, xc, h):
    """Edges (see _edge), p_max (parabola through the largest cell and its neighbours) and the
    pressure centre of a grid solution."""
    idx = np.flatnonzero(p > 0.0)
    x_lead = _edge(p, xc, idx[-1], -1)
    x_trail = _edge(p, xc, idx[0], 1)
    j = int(np.argmax(p))
    y0, y1, y2 = p[j - 1], p[j], p[j + 1]
    curv = y0 - 2 * y1 + y2
    p_max = y1 - (y2 - y0) ** 2 / (8 * curv) if curv < 0 else y1
    x_p = float(np.sum(p * xc) * h / case.load)
    return {
        "x_lead": float(x_lead),
        "x_trail": float(x_trail),
        "a": float(0.5 * (x_lead - x_trail)),
        "p_max": float(p_max),
        "x_p": x_p,
    }


def grid_window(case):
    """The computational window, a coarse solve's contact +- 12 % of its width, and that
    contact (x_trail, x_lead) as the first guess of the active set."""
    ar = case.hertz_half_width(case.g_rubbery)
    xl, xr = -1.7 * ar, 1.7 * ar
    p, xc, h, _, _ = grid_contact(case, xl, xr, 240)
    idx = np.flatnonzero(p > 0.0)
    lo, hi = xc[idx[0]] - h, xc[idx[-1]] + h
    w = hi - lo
    return (lo - 0.12 * w, hi + 0.12 * w), (lo + h, hi - h)


def grid_solve(case, ns, window=None):
    """Grid solutions on the nested grids ns (same window): list of quantity dicts."""
    if window is None:
        (xl, xr), guess = grid_window(case)
    else:
        (xl, xr), guess = window, None
    out = []
    for n in ns:
        p, xc, h, _, _ = grid_contact(case, xl, xr, n, guess)
        q = grid_quantities(case, p, xc, h)
        q["n"], q["h"], q["_p"], q["_xc"] = n, h, p, xc
        act = np.flatnonzero(p > 0.0)
        guess = (xc[act[0]] - 0.5 * h, xc[act[-1]] + 0.5 * h)
        out.append(q)
    return out


# --------------------------------------------------------------------------------------------
# the exact (Hunter) solution


def scaled_bessel_i(k, nmax):
    """I_n(k) e^-k for n = 0..nmax (k > 0), by Miller's backward recurrence normalised with
    I_0 + 2 sum I_n = e^k."""
    start = nmax + int(math.sqrt(100.0 * k)) + 40
    vals = np.zeros(start + 2)
    vals[start] = 1e-300
    for n in range(start, 0, -1):
        vals[n - 1] = vals[n + 1] + (2.0 * n / k) * vals[n]
        if vals[n - 1] > 1e250:
            vals[n - 1 :] *= 1e-250
    total = vals[0] + 2.0 * np.sum(vals[1:])
    return vals[: nmax + 1] / total


class Hunter:
    """Exact solution for one case (0 < L < inf); resolution: Gauss nodes per panel, Bessel terms."""

    def __init__(self, case, nquad=12, extra_terms=40):
        self.case, self.nquad, self.extra = case, nquad, extra_terms
        self.gx, self.gw = np.polynomial.legendre.leggauss(nquad)

    def _coeffs(self, c, bhat):
        """Chebyshev data for half-width c and leading-edge amplitude bhat of B exp(k t)."""
        cs = self.case
        k = c / (cs.l_creep * cs.eps)
        nmax = int(math.sqrt(90.0 * k)) + self.extra
        return k, scaled_bessel_i(k, nmax)

    def _centre(self, bhat, i0):
        cs = self.case
        return (1.0 - cs.eps) * cs.l_creep + cs.radius * bhat * i0 / cs.g_rubbery

    def load_residual(self, c, bhat):
        """Load condition (airfoil equation, n = 1 term) over P(1 - nu)."""
        cs = self.case
        _, ib = self._coeffs(c, bhat)
        lhs = 0.5 * math.pi * c * (cs.g_rubbery * c / cs.radius - 2.0 * bhat * ib[1])
        return lhs / (cs.load * (1.0 - cs.nu)) - 1.0

    def edge_residual(self, c, bhat):
        """Leading-edge condition (1-eps) int_a^inf e^{-(s-a)/L} W'(s) ds + L eps bhat
        + G_r L (1-eps)(L eps + a)/R = 0, scaled by G_r L c/R."""
        cs = self.case
        lc, eps, gr = cs.l_creep, cs.eps, cs.g_rubbery
        _, ib = self._coeffs(c, bhat)
        m = self._centre(bhat, ib[0])
        # outside the contact (t = cosh(theta) > 1), W'(s) = sum_n f_n z^n with z = exp(-theta);
        # in theta the integrand is analytic. Composite Gauss-Legendre panels resolve both the
        # Bessel series' scale sqrt(L eps/c) and the memory's cut-off at cosh(theta) ~ 45 L/c.
        th_max = math.acosh(1.0 + 45.0 * lc / c)
        width = min(0.25, 0.3 * math.sqrt(lc * eps / c))
        panels = max(4, int(math.ceil(th_max / width)))
        edges = np.linspace(0.0, th_max, panels + 1)
        half = 0.5 * (edges[1] - edges[0])
        th = (edges[:-1, None] + half * (1.0 + self.gx[None, :])).ravel()
        wt = np.tile(half * self.gw, panels)
        z = np.exp(-th)
        coef = 2.0 * bhat * ib
        coef[0] = 0.0
        coef[1] -= gr * c / cs.radius
        s = np.polynomial.polynomial.polyval(z, coef)
        # cosh(theta) - 1 = 2 sinh(theta/2)^2 without cancellation
        decay = np.exp(-2.0 * c * np.sinh(0.5 * th) ** 2 / lc)
        integral = c * np.sum(wt * decay * s * np.sinh(th))
        res = (1.0 - eps) * integral + lc * eps * bhat
        res += gr * lc * (1.0 - eps) * (lc * eps + m + c) / cs.radius
        return res / (gr * lc * c / cs.radius)

    def _c_for(self, bhat):
        """Half-width that carries the load for a given bhat (Brent on the load residual)."""
        ar = self.case.hertz_half_width(self.case.g_rubbery)
        return brent(lambda c: self.load_residual(c, bhat), 1e-6 * ar, 3.0 * ar)

    def solve(self):
        """Solve for (c, bhat); returns the quantities dict."""
        cs = self.case
        # bhat ~ -G_r (1-eps) sqrt(L a)/R for L << a (set by the O(L^1.5) outflow term of the
        # edge condition) and -> -G_r (1-eps) L/R for L >> a (Hertz with G_g): scan around that.
        ar = cs.hertz_half_width(cs.g_rubbery)
        lc = cs.l_creep
        scale = -cs.g_rubbery * (1.0 - cs.eps) * math.sqrt(lc * ar + lc * lc) / cs.radius
        g = lambda beta: self.edge_residual(self._c_for(beta * scale), beta * scale)  # noqa: E731
        betas = np.geomspace(0.05, 20.0, 25)
        vals = [g(b) for b in betas]
        hits = [i for i in range(len(betas) - 1) if vals[i] * vals[i + 1] <= 0.0]
        if len(hits) != 1:
            raise RuntimeError(f"{cs.name}: {len(hits)} roots of the leading-edge condition")
        lo, hi = betas[hits[0]], betas[hits[0] + 1]
        beta = brent(g, lo, hi)
        bhat = beta * scale
        c = self._c_for(bhat)
        self.solution = (c, bhat)
        return self.quantities(c, bhat)

    def pressure(self, x):
        """The solved pressure at the points x [mm] (0 outside the contact); after solve()."""
        c, bhat = self.solution
        cs = self.case
        _, ib = self._coeffs(c, bhat)
        m = self._centre(bhat, ib[0])
        beta = -2.0 * bhat * ib / (1.0 - cs.nu)
        beta[1] += cs.g_rubbery * c / (cs.radius * (1.0 - cs.nu))
        beta[0] = 0.0
        t = (np.asarray(x, float) - m) / c
        inside = np.abs(t) < 1.0
        phi = np.arccos(t[inside])
        out = np.zeros_like(t)
        out[inside] = np.sin(np.outer(phi, np.arange(beta.size))) @ beta
        return out

    def quantities(self, c, bhat):
        """Edges, p_max, pressure centre, and the least pressure (a positivity check)."""
        cs = self.case
        _, ib = self._coeffs(c, bhat)
        m = self._centre(bhat, ib[0])
        beta = -2.0 * bhat * ib / (1.0 - cs.nu)
        beta[1] += cs.g_rubbery * c / (cs.radius * (1.0 - cs.nu))
        beta[0] = 0.0
        nn = np.arange(beta.size)

        def pres(phi):
            return np.sin(np.outer(phi, nn)) @ beta

        phi = np.linspace(0.0, math.pi, 20001)
        pv = pres(phi)
        j = int(np.argmax(pv))
        ph = phi[j]
        for _ in range(30):  # Newton on dp/dphi = 0
            d1 = np.cos(ph * nn) @ (nn * beta)
            d2 = -np.sin(ph * nn) @ (nn * nn * beta)
            step = d1 / d2
            ph -= step
            if abs(step) < 1e-15:
                break
        p_max = float(pres(np.array([ph]))[0])
        if np.min(pv) < -1e-12 * p_max:
            # the series assumes one contact interval with p >= 0 in it; a negative pressure
            # would mean that assumption fails for this case
            raise RuntimeError(f"{cs.name}: the exact pressure turns negative ({np.min(pv):.3e})")
        x_p = m + c * c * math.pi * beta[2] / (4.0 * cs.load)
        return {
            "x_lead": m + c,
            "x_trail": m - c,
            "a": c,
            "p_max": p_max,
            "x_p": x_p,
            "p_min": float(np.min(pv[1:-1])),
            "x_pmax": m + c * math.cos(ph),
        }


def brent(f, a, b, xtol=1e-15):
    """Brent's root finder on a bracket [a, b] (f(a) f(b) <= 0)."""
    fa, fb = f(a), f(b)
    if fa * fb > 0.0:
        raise RuntimeError("brent: no sign change")
    if abs(fa) < abs(fb):
        a, b, fa, fb = b, a, fb, fa
    c, fc, d, mflag = a, fa, a, True
    for _ in range(200):
        if fb == 0.0 or abs(b - a) <= xtol * max(abs(b), 1e-300):
            return b
        if fa != fc and fb != fc:
            s = (
                a * fb * fc / ((fa - fb) * (fa - fc))
                + b * fa * fc / ((fb - fa) * (fb - fc))
                + c * fa * fb / ((fc - fa) * (fc - fb))
            )
        else:
            s = b - fb * (b - a) / (fb - fa)
        cond = (
            not ((3 * a + b) / 4 < s < b or b < s < (3 * a + b) / 4)
            or (mflag and abs(s - b) >= abs(b - c) / 2)
            or (not mflag and abs(s - b) >= abs(c - d) / 2)
        )
        if cond:
            s, mflag = 0.5 * (a + b), True
        else:
            mflag = False
        fs = f(s)
        d, c, fc = c, b, fb
        if fa * fs < 0.0:
            b, fb = s, fs
        else:
            a, fa = s, fs
        if abs(fa) < abs(fb):
            a, b, fa, fb = b, a, fb, fa
    return b


def exact(case, fine=False):
    """The exact quantities; fine=True doubles the quadrature and the Bessel terms' margin."""
    if case.l_creep == 0.0 or math.isinf(case.l_creep):
        g = case.g_rubbery if case.l_creep == 0.0 else case.g_glassy
        a, pm = hertz(case, g)
        out = {"x_lead": a, "x_trail": -a, "a": a, "p_max": pm, "x_p": 0.0, "p_min": 0.0, "x_pmax": 0.0}
        out["_pressure"] = lambda x: pm * np.sqrt(np.clip(1.0 - (np.asarray(x, float) / a) ** 2, 0.0, None))
        return out
    solver = Hunter(case, nquad=24 if fine else 12, extra_terms=80 if fine else 40)
    out = solver.solve()
    out["_pressure"] = solver.pressure
    return out


# --------------------------------------------------------------------------------------------
# the table

A_R = 2.0  # the rubbery Hertz half-width of the rigid-cylinder rows [mm]
RATIOS = [0.01, 0.03, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0, 3.0, 10.0, 30.0, 100.0]  # V tau_c / a_r
GRID_NS = (400, 800, 1600)  # the table's grids (cells over about 1.25 contact widths)
QUANTS = ("a", "p_max", "x_p")


def rigid_case(f, ratio):
    """Rigid cylinder R = 100 mm on an SLS half-plane: E_g = 1000 N/mm^2, nu = 0.3,
    E_r = E_g/(1+f); P such that the rubbery Hertz half-width is A_R."""
    nu, e_g, radius = 0.3, 1000.0, 100.0
    e_r = e_g / (1.0 + f)
    load = math.pi * A_R**2 * e_r / (1.0 - nu * nu) / (4.0 * radius)
    g = lambda e: e / (2.0 * (1.0 + nu))  # noqa: E731
    return Case("rigid_on_sls", f"f{f:g}_r{ratio:g}", g(e_g), g(e_r), nu, radius, load, ratio * A_R)


def visc_cylindr_case(tau_c):
    """CONTACT's visc_cylindr: two SLS cylinders R = 100 mm, G_g = 1143, G_r = 571.5 N/mm^2,
    nu = 0.4, P = 600 N/mm, V = 1000 mm/s: one half-plane with half the moduli, R* = 50 mm."""
    return Case("visc_cylindr", f"tau_c={tau_c:g}", 1143.0 / 2, 571.5 / 2, 0.4, 50.0, 600.0, 1000.0 * tau_c)


def all_cases():
    """The table's rows, in order: (case, bodies, body radius R [mm])."""
    rows = [(rigid_case(f, r), 1, 100.0) for f in (1, 9) for r in RATIOS]
    rows += [(visc_cylindr_case(t), 2, 100.0) for t in (0.0, 0.009, 0.045, 2.0)]
    return rows


COLUMNS = [
    "group",
    "bodies",
    "E_g",
    "G_g",
    "G_r",
    "f",
    "nu",
    "R",
    "R_star",
    "P",
    "V_tau_c",
    "V_tau_c_over_a_r",
    "x_lead",
    "x_trail",
    "a",
    "width_2a",
    "p_max",
    "x_pmax",
    "x_p",
    "Fr_over_P",
    "err_exact",
    "grid_n",
    "grid_a",
    "grid_p_max",
    "grid_x_p",
    "grid_err_a",
    "grid_err_p_max",
    "grid_err_x_p",
]
# The scale a column is compared on (besides its own magnitude): an error estimate on that of
# the quantity it estimates, a position on the contact's half-width (x_p of a symmetric
# contact is rounding noise about 0).
FLOOR_OF = {
    "err_exact": "a",
    "grid_err_a": "a",
    "grid_err_p_max": "p_max",
    "grid_err_x_p": "a",
    "x_lead": "a",
    "x_trail": "a",
    "x_pmax": "a",
    "x_p": "a",
    "grid_x_p": "a",
}


def row(case, bodies, radius, ns=GRID_NS):
    """One table row: exact values, their error (coarse vs fine resolution), grid values on the
    finest of ns and their error estimate (finest vs the one before, or half the one before that
    if larger: the grid values converge unevenly as the edges cross cells)."""
    k = 2.0 if bodies == 2 else 1.0
    ex, ex_fine = exact(case), exact(case, fine=True)
    err_ex = max(abs(ex_fine[q] - ex[q]) for q in ("x_lead", "x_trail", "p_max", "x_p"))
    grids = grid_solve(case, ns)
    gf = grids[-1]
    gerr = {}
    for q in QUANTS:
        e = abs(grids[-1][q] - grids[-2][q])
        if len(grids) > 2:
            e = max(e, 0.5 * abs(grids[-2][q] - grids[-3][q]))
        gerr[q] = e
    a_r = case.hertz_half_width(case.g_rubbery)
    return {
        "group": case.group,
        "bodies": bodies,
        "E_g": 2.0 * k * case.g_glassy * (1.0 + case.nu),
        "G_g": k * case.g_glassy,
        "G_r": k * case.g_rubbery,
        "f": case.g_glassy / case.g_rubbery - 1.0,
        "nu": case.nu,
        "R": radius,
        "R_star": case.radius,
        "P": case.load,
        "V_tau_c": case.l_creep,
        "V_tau_c_over_a_r": round(case.l_creep / a_r, 12),
        "x_lead": ex["x_lead"],
        "x_trail": ex["x_trail"],
        "a": ex["a"],
        "width_2a": 2.0 * ex["a"],
        "p_max": ex["p_max"],
        "x_pmax": ex["x_pmax"],
        "x_p": ex["x_p"],
        "Fr_over_P": ex["x_p"] / case.radius,
        "err_exact": err_ex,
        "grid_n": gf["n"],
        "grid_a": gf["a"],
        "grid_p_max": gf["p_max"],
        "grid_x_p": gf["x_p"],
        "grid_err_a": gerr["a"],
        "grid_err_p_max": gerr["p_max"],
        "grid_err_x_p": gerr["x_p"],
        "_grids": grids,
        "_exact": ex,
    }


HEADER = """\
# Frictionless steady rolling over a standard-linear-solid half-plane: an independent reference
# (not derived from rollbem). Written by:
#   python3 tools/viscoelastic_reference.py --write tests/data/viscoelastic_reference.csv
# checked by the same script with --check (exit 1 on a relative difference beyond 1e-9; error
# columns on the scale of the quantity they estimate, positions on that of a).
# How it is computed and how it compares: docs/viscoelastic-reference.md.
# Units N, mm. group rigid_on_sls: rigid cylinder R on one SLS half-plane (bodies = 1);
# visc_cylindr: two identical SLS cylinders of radius R (bodies = 2), solved as one half-plane
# with twice the compliance against R_star = R/2. E_g, G_g, G_r: one body's moduli (E = 2G(1+nu)),
# f = G_g/G_r - 1, V_tau_c = V tau_c, a_r the rubbery Hertz half-width of the (equivalent) pair.
# Contact moves in +x over the body: x_lead > x_trail, x_p = int p x dx / P > 0 towards x_lead,
# x_pmax where p = p_max; Fr_over_P = x_p/R_star (rolling resistance over load; for two
# cylinders the dissipation per unit distance rolled over P).
# x_lead..Fr_over_P: Hunter's exact solution (Chebyshev/Bessel series); err_exact its change
# at twice the resolution. grid_*: the closed-form grid solver on grid_n cells (uniform, about
# 1.25 contact widths); grid_err_* its change from the grid with half the cells, or half the
# change between the two coarser grids (400 and 800 cells) if that is larger.
"""


def _fmt(v):
    if isinstance(v, str):
        return v
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    return repr(float(v))


def table_rows(ns=GRID_NS):
    """All rows as dicts."""
    return [row(c, b, r, ns) for c, b, r in all_cases()]


def write_table(path, rows):
    """Write the CSV whole (temporary file, then rename)."""
    text = HEADER + ",".join(COLUMNS) + "\n"
    for r in rows:
        text += ",".join(_fmt(r[c]) for c in COLUMNS) + "\n"
    tmp = path + ".tmp"
    with open(tmp, "w") as fh:
        fh.write(text)
    os.replace(tmp, path)


def read_table(path):
    """The CSV's rows as dicts of strings."""
    with open(path) as fh:
        lines = [ln.rstrip("\n") for ln in fh if not ln.startswith("#") and ln.strip()]
    head = lines[0].split(",")
    return head, [dict(zip(head, ln.split(","), strict=True)) for ln in lines[1:]]


def compare(path, rows, rtol=1e-9):
    """Differences between the stored table and fresh rows (a list of messages)."""
    head, stored = read_table(path)
    msgs = []
    if head != COLUMNS:
        return [f"{path}: columns {head} differ from {COLUMNS}"]
    if len(stored) != len(rows):
        return [f"{path}: {len(stored)} rows, the script makes {len(rows)}"]
    for i, (old, new) in enumerate(zip(stored, rows, strict=True)):
        for c in COLUMNS:
            nv = new[c]
            if isinstance(nv, str):
                if old[c] != nv:
                    msgs.append(f"row {i + 1} {c}: stored {old[c]}, now {nv}")
                continue
            ov, nv = float(old[c]), float(nv)
            scale = max(abs(ov), abs(nv))
            if c in FLOOR_OF:
                scale = max(scale, abs(float(new[FLOOR_OF[c]])))
            elif c == "Fr_over_P":
                scale = max(scale, abs(float(new["a"]) / float(new["R_star"])))
            if abs(ov - nv) > rtol * scale:
                msgs.append(f"row {i + 1} {c}: stored {ov!r}, now {nv!r}")
    return msgs


# --------------------------------------------------------------------------------------------
# the tables of docs/viscoelastic-reference.md (between <!-- begin NAME --> and <!-- end NAME -->)

DOC = os.path.join(os.path.dirname(_HERE), "docs", "viscoelastic-reference.md")
CONTACT_VISC = {0.0: (12.8, 60.32), 0.009: (9.9, 78.74), 0.045: (9.1, 84.72), 2.0: (9.0, 85.31)}
CONTACT_H = 0.16  # CONTACT's element size in visc_cylindr [mm]
CONTACT_GRID = (-8.0, 99)  # its grid: left end [mm] (first centre -7.92), number of elements


def coarse_grid_readings(case, h=CONTACT_H, shifts=8):
    """What a uniform grid of element size h reads: the loaded width (elements x h) and the
    largest element pressure (no interpolation), on CONTACT's own grid (CONTACT_GRID) and as
    (min, max) over `shifts` offsets of a grid against the contact."""
    xl, n = CONTACT_GRID
    p, _, _, _, _ = grid_contact(case, xl, xl + n * h, n)
    own = (np.count_nonzero(p > 0.0) * h, float(np.max(p)))
    a_r = case.hertz_half_width(case.g_rubbery)
    n = int(math.ceil(2.6 * a_r / h))
    widths, pmaxs = [], []
    for k in range(shifts):
        xl = -0.5 * n * h + k * h / shifts
        p, _, _, _, _ = grid_contact(case, xl, xl + n * h, n)
        widths.append(np.count_nonzero(p > 0.0) * h)
        pmaxs.append(float(np.max(p)))
    return own, (min(widths), max(widths)), (min(pmaxs), max(pmaxs))


def _g(v, digits=6):
    return f"{v:.{digits}g}"


def doc_blocks(rows):
    """The page's generated tables, by name."""
    blocks = {}
    lines = [
        "| f | V tau_c/a_r | x_lead | x_trail | a | p_max | x_pmax | x_p | F_r/P |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        if r["bodies"] != 1:
            continue
        lines.append(
            f"| {r['f']:g} | {r['V_tau_c_over_a_r']:.3g} | {_g(r['x_lead'])} | {_g(r['x_trail'])} | "
            f"{_g(r['a'])} | {_g(r['p_max'])} | {_g(r['x_pmax'], 4)} | {_g(r['x_p'])} | "
            f"{_g(r['Fr_over_P'], 4)} |"
        )
    blocks["rigid"] = "\n".join(lines)

    lines = [
        "| tau_c [s] | V tau_c [mm] | 2a | p_max | x_lead | x_trail | x_p | F_r/P |",
        "|---|---|---|---|---|---|---|---|",
    ]
    grid_lines = [
        "| tau_c [s] | 2a: exact | CONTACT | grid solver, CONTACT's grid | over 8 shifts "
        "| p_max: exact | CONTACT | grid solver, CONTACT's grid | over 8 shifts | CONTACT inside |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for (cs, bodies, _), r in zip(all_cases(), rows, strict=True):
        if bodies != 2:
            continue
        tau = cs.l_creep / 1000.0
        lines.append(
            f"| {tau:g} | {cs.l_creep:g} | {r['width_2a']:.4f} | {r['p_max']:.4f} | {r['x_lead']:.4f} | "
            f"{r['x_trail']:.4f} | {r['x_p']:.4f} | {_g(r['Fr_over_P'], 4)} |"
        )
        (ow, op), (w0, w1), (p0, p1) = coarse_grid_readings(cs)
        cw, cp = CONTACT_VISC[tau]
        # CONTACT prints 0.1 mm and 0.01 N/mm^2: inside the range up to half a printed unit
        inside = w0 - 0.05 <= cw <= w1 + 0.05 and p0 - 0.005 <= cp <= p1 + 0.005
        grid_lines.append(
            f"| {tau:g} | {r['width_2a']:.3f} | {cw} | {ow:.2f} | {w0:.2f} to {w1:.2f} | "
            f"{r['p_max']:.3f} | {cp} | {op:.3f} | {p0:.2f} to {p1:.2f} | {'yes' if inside else 'NO'} |"
        )
    blocks["visc_cylindr"] = "\n".join(lines)
    blocks["contact_grid"] = "\n".join(grid_lines)

    ns = GRID_NS
    head = " | ".join(f"n = {n}" for n in ns)
    lines = [
        "| case | quantity | " + head + " |",
        "|---|---|" + "---|" * len(ns),
    ]
    labels = QUANTS + ("p, interior",)
    worst = {q: [0.0] * len(ns) for q in labels}
    for (cs, _, _), r in zip(all_cases(), rows, strict=True):
        a_r = cs.hertz_half_width(cs.g_rubbery)
        scale = {"a": a_r, "p_max": r["p_max"], "x_p": a_r}
        errs = {q: [(g[q] - r[q]) / scale[q] for g in r["_grids"]] for q in QUANTS}
        # the pressure itself at the cell centres more than 5 % of a from the exact edges
        errs["p, interior"] = []
        margin = 0.05 * r["a"]
        for g in r["_grids"]:
            inner = (g["_xc"] > r["x_trail"] + margin) & (g["_xc"] < r["x_lead"] - margin)
            dp = g["_p"][inner] - r["_exact"]["_pressure"](g["_xc"][inner])
            errs["p, interior"].append(float(np.max(np.abs(dp))) / r["p_max"])
        for q in labels:
            worst[q] = [max(w, abs(e)) for w, e in zip(worst[q], errs[q], strict=True)]
        if cs.name in ("f1_r0.01", "f9_r0.01", "f9_r0.3", "f9_r1", "f9_r100", "tau_c=0.009"):
            for q in labels:
                cells = " | ".join(f"{e:+.1e}" if q in QUANTS else f"{e:.1e}" for e in errs[q])
                lines.append(f"| {cs.group} {cs.name} | {q} | {cells} |")
    for q in labels:
        cells = " | ".join(f"{w:.1e}" for w in worst[q])
        lines.append(f"| largest of all {len(rows)} rows | {q} | {cells} |")
    blocks["convergence"] = "\n".join(lines)
    return blocks


def render_doc(text, blocks):
    """The page with its generated blocks replaced (ValueError if a marker is missing)."""
    for name, body in blocks.items():
        begin, end = f"<!-- begin {name} -->", f"<!-- end {name} -->"
        i, j = text.find(begin), text.find(end)
        if i < 0 or j < i:
            raise ValueError(f"{DOC}: markers {begin} ... {end} missing")
        text = text[: i + len(begin)] + "\n" + body + "\n" + text[j:]
    return text


# --------------------------------------------------------------------------------------------
# self-checks


def kernel_check():
    """Largest difference between the closed-form delayed kernel and direct quadrature of
    (1/L) int_0^inf exp(-t/L) F(x + t) dt - L (ln L - gamma), relative to max(1, |value|):
    composite Gauss-Legendre in s = t/L on panels of 1/2 graded geometrically towards
    s = -x/L, where F'' = 1/(x + t) is singular (towards s = 0 if that point lies outside)."""
    gx, gw = np.polynomial.legendre.leggauss(20)
    worst = 0.0
    for lc in (0.01, 1.0, 100.0):
        for x in (-3.0, -0.5, -0.011, 0.004, 0.7, 2.9):
            s0 = -x / lc
            sc = max(s0, 0.0)  # the singular point, or the end nearest to it
            pts = set(np.linspace(0.0, 60.0, 121)) | {sc}
            pts |= {sc + sg * 10.0**-j for j in range(0, 15) for sg in (-1, 1)}
            pts = np.array(sorted(q for q in pts if 0.0 <= q <= 60.0))
            lo, hi = pts[:-1], pts[1:]
            s = (0.5 * (lo + hi))[:, None] + (0.5 * (hi - lo))[:, None] * gx[None, :]
            w = (0.5 * (hi - lo))[:, None] * gw[None, :]
            quad = np.sum(w * np.exp(-s) * _f_log(x + lc * s)) - lc * (math.log(lc) - EULER)
            mine = float(_f_log_delayed(np.array([x]), lc)[0])
            worst = max(worst, abs(quad - mine) / max(1.0, abs(mine)))
    return worst


def limits():
    """Limits tau_c -> 0 and tau_c -> inf against Hertz (exact and grid): (all ok, table rows).

    Small L: u = W/G_r + (1 - eps) L W'/G_r + O(L^2): Hertz with G_r shifted by (1 - eps) L to
    the leading edge, so x_p -> (1 - eps) L while a -> a_r. Large L: Hertz with G_g, x_p and
    a/a_g - 1 of order f (a/L) ln(L/a). Tolerances are 1e-3 at L = 1e-3 a_r and at L = 1e6 a_r,
    well above the grids' discretisation errors and the O(L/a) terms.
    """
    ok, out = True, []
    for f in (1, 9):
        for ratio, g_name in ((1e-3, "G_r"), (1e6, "G_g")):
            cs = rigid_case(f, ratio)
            g = cs.g_rubbery if g_name == "G_r" else cs.g_glassy
            a_h, p_h = hertz(cs, g)
            shift = (1.0 - cs.eps) * cs.l_creep if g_name == "G_r" else 0.0
            for src, q in (("exact", exact(cs)), ("grid 800", grid_solve(cs, (400, 800))[-1])):
                da, dp = q["a"] / a_h - 1.0, q["p_max"] / p_h - 1.0
                dx = (q["x_p"] - shift) / a_h
                good = max(abs(da), abs(dp), abs(dx)) < 1e-3
                ok &= good
                out.append((f, ratio, g_name, src, da, dp, dx, good))
    return ok, out


def limits_block(rows):
    """The page's table of the limits."""
    lines = [
        "| f | V tau_c/a_r | Hertz with | solver | a/a_H − 1 | p_max/p_H − 1 "
        "| (x_p − x_p,lim)/a_H | within 1e-3 |",
        "|---|---|---|---|---|---|---|---|",
    ]

    def fmt(v):  # below 1e-9 the digits are rounding noise
        return f"{v:+.1e}" if abs(v) >= 1e-9 else "< 1e-9"

    for f, ratio, g_name, src, da, dp, dx, good in rows:
        verdict = "yes" if good else "NO"
        lines.append(
            f"| {f} | {ratio:g} | {g_name} | {src} | {fmt(da)} | {fmt(dp)} | {fmt(dx)} | {verdict} |"
        )
    return "\n".join(lines)


def self_test():
    """Print the limits; exit status 1 if one is off."""
    ok, rows = limits()
    print(limits_block(rows))
    kerr = kernel_check()
    print(f"delayed kernel against direct quadrature: largest difference {kerr:.1e} (limit 1e-10)")
    return 0 if ok and kerr <= 1e-10 else 1


def convergence(ns=GRID_NS):
    """Grid solver on three grids against the exact solution, printed per row."""
    print("row  V_tau_c/a_r  n: a, p_max, x_p as (grid - exact)/a_r resp. /p_max")
    worst = 0.0
    for cs, _, _ in all_cases():
        ex = exact(cs)
        a_r = cs.hertz_half_width(cs.g_rubbery)
        grids = grid_solve(cs, ns)
        parts = []
        for g in grids:
            parts.append(
                f"{g['n']}: {(g['a'] - ex['a']) / a_r:+.1e} {(g['p_max'] - ex['p_max']) / ex['p_max']:+.1e} "
                f"{(g['x_p'] - ex['x_p']) / a_r:+.1e}"
            )
        worst = max(worst, abs(grids[-1]["x_p"] - ex["x_p"]) / a_r)
        print(f"{cs.group:12s} {cs.name:14s} | " + " | ".join(parts))
    print(f"largest |x_p(grid {ns[-1]}) - x_p(exact)|/a_r = {worst:.1e}")


def print_pressure(name, points):
    """The exact pressure of the row called name (e.g. f9_r1, tau_c=0.009) at `points` evenly
    spaced x over the contact, as CSV on standard output. Exit status."""
    found = [cs for cs, _, _ in all_cases() if cs.name == name]
    if not found:
        names = ", ".join(cs.name for cs, _, _ in all_cases())
        print(f"--pressure: no row called {name!r}; the rows are {names}", file=sys.stderr)
        return 1
    cs = found[0]
    ex = exact(cs)
    x = np.linspace(ex["x_trail"], ex["x_lead"], points)
    p = ex["_pressure"](x)
    print(f"# {cs.group} {cs.name}: exact pressure; x [mm] positive towards the leading edge, p [N/mm^2]")
    print("x,p")
    for xi, pi in zip(x, p, strict=True):
        print(f"{float(xi)!r},{max(float(pi), 0.0)!r}")
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--write", metavar="CSV", help="write the table")
    ap.add_argument("--check", metavar="CSV", help="regenerate and compare; exit 1 on a difference")
    ap.add_argument("--convergence", action="store_true", help="grid solver on 3 grids vs exact")
    ap.add_argument("--self-test", action="store_true", help="the limits against Hertz")
    ap.add_argument("--pressure", metavar="ROW", help="print a row's exact pressure (x,p CSV), e.g. f9_r1")
    ap.add_argument("--points", type=int, default=201, help="points for --pressure (default 201)")
    args = ap.parse_args(argv)
    if not (args.write or args.check or args.convergence or args.self_test or args.pressure):
        ap.error("give --write, --check, --convergence, --self-test or --pressure ROW")
    if args.pressure:
        if args.points < 2:
            ap.error("--points must be at least 2")
        return print_pressure(args.pressure, args.points)
    status = 0
    if args.self_test:
        status |= self_test()
    if args.convergence:
        convergence()
    if args.write or args.check:
        rows = table_rows()
        blocks = doc_blocks(rows)
        lim_ok, lim_rows = limits()
        blocks["limits"] = limits_block(lim_rows)
        if "| NO |" in blocks["contact_grid"]:
            print("CONTACT's visc_cylindr numbers leave the 0.16 mm grids' range", file=sys.stderr)
            status = 1
        kerr = kernel_check()
        if kerr > 1e-10:
            print(f"the delayed kernel differs from quadrature by {kerr:.1e}", file=sys.stderr)
            status = 1
        if not lim_ok:
            print("a limit against Hertz is off:\n" + blocks["limits"], file=sys.stderr)
            status = 1
        if args.write:
            write_table(args.write, rows)
            print(f"wrote {args.write} ({len(rows)} rows)")
            with open(DOC) as fh:
                old = fh.read()
            new = render_doc(old, blocks)
            if new != old:
                with open(DOC + ".tmp", "w") as fh:
                    fh.write(new)
                os.replace(DOC + ".tmp", DOC)
                print(f"updated the tables of {DOC}")
        if args.check:
            try:
                msgs = compare(args.check, rows)
            except (OSError, ValueError, KeyError) as err:
                msgs = [f"{args.check}: cannot be read ({err})"]
            try:
                with open(DOC) as fh:
                    text = fh.read()
                if render_doc(text, blocks) != text:
                    msgs.append(f"{DOC}: its generated tables differ from the script's")
            except (OSError, ValueError) as err:
                msgs.append(str(err))
            for m in msgs:
                print(m, file=sys.stderr)
            if msgs:
                print("differences found: regenerate with --write and review the diff", file=sys.stderr)
                status = 1
            else:
                print(f"{args.check}: {len(rows)} rows agree; {os.path.basename(DOC)}'s tables agree")
    return status


if __name__ == "__main__":
    sys.exit(main())
