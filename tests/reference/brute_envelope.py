#!/usr/bin/python3
"""Brute-force evaluation of the lower-envelope formula, for validating the event logic of
mu_mpmath.py.  It shares NO code with mu_mpmath.py: the waves are written here again in the
paper's own phase phi (no shift), and no event (stick onset, Eq. 8, contact boundary) is computed
from a formula.

  s(phi) = min over 0 <= tau < 1 of f(tau),  f(tau) = n(phi - tau) + beta tau.

Pointwise: f is sampled in double precision on a uniform grid of K taus; every sampled local
minimum whose value is within the grid's Lipschitz slack of the best sample is refined in mpmath by
golden-section search on its two neighbouring grid cells (f is unimodal there: it is smooth or has a
corner at a contact boundary), and tau = 0 is always a candidate.

Integral: the phase axis is sampled on a grid; the "regime" (n > 0 ?, s < n ?) is evaluated at every
grid point and each change of regime is located by bisection on the brute-force regime itself.
Between regime changes (and the wave's definitional breakpoints) s is smooth (n itself, a straight
ramp, or 0), so a 48-point Gauss-Legendre rule per interval (after an endpoint-clustering substitution, for
the |4 phi - 1|^p breakpoints of power:p) integrates it to working precision.
Regime changes shorter than the phase grid spacing would be missed: use it away from beta_c.
"""

import math

import mpmath
from mpmath import mp, mpf


def wave_functions(kind, p):
    """(w_mp, w_float, max |w'|, breakpoints) in the paper's phase phi in [0, 1)."""
    if kind == "sine":
        return (lambda x: mpmath.sin(2 * mp.pi * x), lambda x: math.sin(2 * math.pi * x),
                2 * math.pi, [])
    if kind == "power":
        pf = float(p)

        def wm(x):
            if x < mpf(1) / 2:
                return 1 - abs(4 * x - 1) ** p
            return -(1 - abs(4 * x - 3) ** p)

        def wf(x):
            if x < 0.5:
                return 1 - abs(4 * x - 1) ** pf
            return -(1 - abs(4 * x - 3) ** pf)
        return wm, wf, 4 * pf, [mpf(1) / 4, mpf(1) / 2, mpf(3) / 4]
    if kind == "pwl":
        xs, ws = p                                     # vertices of a periodic polyline
        xsf, wsf = [float(x) for x in xs], [float(w) for w in ws]

        def interp(x, X, W, one):
            m = len(X)
            for i in range(m):
                a = X[i]
                b = X[i + 1] if i + 1 < m else X[0] + one
                wa, wb = W[i], W[(i + 1) % m]
                xx = x if x >= a else x + one
                if a <= xx <= b:
                    return wa + (wb - wa) * (xx - a) / (b - a)
            raise ValueError("phase %s not covered" % x)
        slopes = [abs((wsf[(i + 1) % len(xs)] - wsf[i]) /
                      (((xsf[(i + 1) % len(xs)] - xsf[i]) % 1.0) or 1.0)) for i in range(len(xs))]
        return (lambda x: interp(x, xs, ws, mpf(1)), lambda x: interp(x, xsf, wsf, 1.0),
                max(slopes), list(xs))
    raise ValueError("brute force implemented for continuous waves only: %r" % kind)


class Brute(object):
    def __init__(self, kind, p, beta, gamma, K=2000):
        self.beta, self.gamma, self.K = beta, gamma, K
        self.wm, self.wf, wmax, self.breaks = wave_functions(kind, p)
        self.bf, self.gf = float(beta), float(gamma)
        self.L = wmax + self.bf           # Lipschitz bound of f(tau)
        self.golden_iters = int(mp.prec * 0.7) + 40   # width (1e-3) * 0.618^iters << eps

    def n(self, x):
        x = x - mpmath.floor(x)
        v = self.gamma + self.wm(x)
        return v if v > 0 else mpf(0)

    def nf(self, x):
        x = x - math.floor(x)
        v = self.gf + self.wf(x)
        return v if v > 0 else 0.0

    def f(self, phi, tau):
        return self.n(phi - tau) + self.beta * tau

    def _golden(self, phi, lo, hi):
        gr = (mpmath.sqrt(5) - 1) / 2
        a, b = lo, hi
        c, d = b - gr * (b - a), a + gr * (b - a)
        fc, fd = self.f(phi, c), self.f(phi, d)
        for _ in range(self.golden_iters):
            if fc <= fd:
                b, d, fd = d, c, fc
                c = b - gr * (b - a)
                fc = self.f(phi, c)
            else:
                a, c, fc = c, d, fd
                d = a + gr * (b - a)
                fd = self.f(phi, d)
        # the endpoints are candidates too (the minimum may sit at the cell's edge)
        best = min([(fc, c), (fd, d), (self.f(phi, lo), lo), (self.f(phi, hi), hi)],
                   key=lambda t: t[0])
        return best

    def s(self, phi):
        """(s(phi), tau*)."""
        K, phif = self.K, float(phi)
        samples = [self.nf(phif - k / K) + self.bf * k / K for k in range(K)]
        best = min(samples)
        slack = 2.0 * self.L / K + 1e-9
        cands = []
        for k in range(K):
            v = samples[k]
            if v > best + slack:
                continue
            left = samples[k - 1] if k > 0 else float("inf")
            right = samples[k + 1] if k + 1 < K else float("inf")
            if v <= left and v <= right:
                cands.append(k)
        result = (self.f(phi, mpf(0)), mpf(0))
        for k in cands:
            lo = mpf(max(k - 1, 0)) / K
            hi = mpf(min(k + 1, K)) / K
            v, t = self._golden(phi, lo, hi)
            if v < result[0]:
                result = (v, t)
        return result

    # ---- integral --------------------------------------------------------------------------
    def regime(self, phi):
        nv = self.n(phi)
        sv, _ = self.s(phi)
        thr = mpf(10) ** (-mp.dps + 6)
        return (nv > 0, sv < nv - thr)

    def _boundary(self, lo, hi, rlo, bisect_width):
        while hi - lo > bisect_width:
            mid = (lo + hi) / 2
            if self.regime(mid) == rlo:
                lo = mid
            else:
                hi = mid
        return (lo + hi) / 2

    def integrals(self, grid=200, bisect_width=None, gl_degree=5):
        """(int_0^1 s, int_0^1 n, regime-change points)."""
        if bisect_width is None:
            bisect_width = mpf(10) ** (-(mp.dps * 2) // 3)
        xs = [mpf(i) / grid for i in range(grid + 1)]
        regs = [self.regime(x) for x in xs]
        cuts = set([mpf(0), mpf(1)] + list(self.breaks))
        changes = []
        for i in range(grid):
            lo, hi, rlo, rhi = xs[i], xs[i + 1], regs[i], regs[i + 1]
            # several changes inside one cell: peel them off from the left
            guard = 0
            while rlo != rhi and guard < 4:
                c = self._boundary(lo, hi, rlo, bisect_width)
                changes.append(c)
                cuts.add(c)
                lo = c + bisect_width
                rlo = self.regime(lo)
                guard += 1
        cuts = sorted(cuts)
        gl = mpmath.calculus.quadrature.GaussLegendre(mp)
        nodes = gl.calc_nodes(gl_degree, mp.prec)
        S = N = mpf(0)
        for a, b in zip(cuts[:-1], cuts[1:]):
            h = (b - a) / 2
            m = (a + b) / 2
            for (t, w) in nodes:
                # x = m + h (3t - t^3)/2 clusters nodes at both ends, dx = h 3(1 - t^2)/2 dt:
                # an endpoint singularity |x - a|^p (power:p at its breakpoints) becomes
                # (1 - |t|)^(2p+1), analytic for half-integer p and much milder otherwise.
                ph = m + h * (3 * t - t ** 3) / 2
                jw = h * w * 3 * (1 - t * t) / 2
                S += jw * self.s(ph)[0]
                N += jw * self.n(ph)
        return S, N, changes
