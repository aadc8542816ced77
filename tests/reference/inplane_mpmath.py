#!/usr/bin/python3
"""Independent mpmath reference for LONGITUDINAL in-plane oscillation (a_t = 0), from
/work/shared/model.md ("In-plane and combined oscillation") alone.

What it computes
----------------
Phase phi, period 1.  Normal force n(phi) = max(gamma + w(phi), 0) for a catalogue wave w, or
n = 1 ("--wave constant", no gamma).  Drive D(phi) = beta*phi + a*p(phi + P), p a catalogue wave
(default sine), a >= 0, beta >= 0, P any real (in periods).  The tangential force s is the stop
operator of D in the moving interval [-n, n]:
    stick  s' = D'            while |s| < n,
    forward slip  s = n       while D' - n' >= 0,
    backward slip s = -n      while D' + n' <= 0,
    flight s = 0              where n = 0,
and at a jump of D (or of n) s keeps s + (jump of D) and is then projected onto [-n, n].
Output over the periodic steady state: mu = int s / int n and the fractions of the period spent
in stick, slip (forward + backward), backward slip and flight.  mean_lateral is 0 (a_t = 0).

Algorithm
---------
1. The contact point.  With x = D - s (the contact point, in force units) the stop operator is a
   lazy point swept by the interval [L, U] = [D - n, D + n]: x stays put while L < x < U (stick),
   rides on L while L rises (forward slip), on U while U falls (backward slip), equals D in flight,
   and at a jump it is clamped into the new [L, U].  (The catching-up scheme
   s <- clamp(s + dD, -n, n) is exactly x <- clamp(x, L, U) on a grid.)
2. Pieces.  One period [phi0, phi0 + 1] is cut at every breakpoint of w and of p(. + P) (formula
   changes, jumps), and at the contact boundaries gamma + w = 0 (closed forms); phi0 is the middle
   of the widest gap, so nothing happens at phi0.  On a piece n and D are one smooth closed form.
   Breakpoints closer than a few ulps are one point: simultaneous jumps, one projection.
3. Monotone sub-pieces.  Each contact piece is cut again at the sign changes of L' = D' - n' and
   U' = D' + n'.  For sine and piecewise-linear w, p these are closed forms: L' and U' are
   C + A cos(2 pi phi) + B sin(2 pi phi), roots by acos.  With a power:p wave they are isolated by
   interval arithmetic (mpmath.iv): bisect until the range of h excludes 0 or the range of h'
   does (then h is monotone and one sign test decides).  Safety net: the sign of L' and U' is
   sampled inside every sub-piece and a disagreement is an error, never a silent value.
4. Events.  On a monotone sub-piece the mode can change at most once: a stick at x = c ends
   where L rises to c (forward slip) or U falls to c (backward slip), found by a safeguarded
   Newton-bisection on the bracket (closed form when both L and U are linear); a slip ends only at
   a sub-piece end (an extremum of L or U, a kink, a jump).  Ties (L' = 0 exactly while x = L)
   count as slip, as the rules above say.
5. Areas are exact: int s = int (D - c) = ID(v) - ID(u) - c (v - u) in stick (ID an antiderivative
   of D), +-(IN(v) - IN(u)) in slip, 0 in flight.
6. Periodic state.  The one-period map of x is a composition of clamps, hence of the form
   x -> clamp(x, A, B) with A <= B, and periodicity means x(phi0 + 1) = x(phi0) + beta.  We compute
   A and B by running one period from s = n(phi0) and from s = -n(phi0).  For beta > 0 the periodic
   state is unique: x(phi0) = A - beta; it is then iterated (one period from it) until it repeats
   to the working precision.  For beta = 0 every x in [A, B] is periodic: unique only if A = B
   (the map forgets its start, e.g. through flight); otherwise "no unique periodic state" (exit 3).

Numbers are parsed from decimal strings at the working precision (never through float); the
working precision is digits + 20 guard digits, more for large a + beta (D - c cancels), small
beta and gamma near -1 (small int n).  --verify recomputes with 25 more digits from another start
phase, checks the clamp form of the one-period map, and fails if anything disagrees.

Usage:  /usr/bin/python3 inplane_mpmath.py mu --wave W --beta B [--gamma G] --longitudinal A
                [--phase P] [--in-plane-wave W2] [--digits D] [--verify]
        /usr/bin/python3 inplane_mpmath.py trace ...same...   (the periodic state's mode segments)
Waves: sine, triangle, sawtooth-right, sawtooth-left, square, power:p (p >= 1); --wave constant.
Exit status: 0 ok, 2 bad input (or a numerical failure), 3 no unique periodic state.
"""

import argparse
import sys

import mpmath
from mpmath import iv, mp, mpf

BASE_GUARD = 20
MAX_DIGITS = 1000
CATALOGUE = ("sine", "triangle", "sawtooth-right", "sawtooth-left", "square")
FORCE_INTERVAL_ROOTS = False     # self-test switch: isolate critical points by intervals always


class ModelError(ValueError):
    """Bad input or a numerical failure; the message names the offending value.  Exit 2."""


class NoUniqueState(RuntimeError):
    """The periodic state is not unique (beta = 0 and the contact can stick through).  Exit 3."""


# --------------------------------------------------------------------------------------------
# Input parsing
# --------------------------------------------------------------------------------------------

def parse_number(text, what):
    """Parse a decimal string at the current working precision; reject NaN/inf/garbage."""
    if not isinstance(text, str):
        raise ModelError("%s = %r: expected a decimal string" % (what, text))
    t = text.strip()
    try:
        if t == "" or t.lower().lstrip("+-") in ("nan", "inf", "infinity"):
            raise ValueError
        x = mpf(t)
    except (ValueError, TypeError):
        raise ModelError("%s = %r is not a finite decimal number" % (what, text))
    if not mp.isfinite(x):
        raise ModelError("%s = %r is not a finite decimal number" % (what, text))
    return x


def parse_wave(name, what, allow_constant):
    """(kind, exponent text or None) for a wave name."""
    if name in CATALOGUE or (allow_constant and name == "constant"):
        return name, None
    if isinstance(name, str) and name.startswith("power:"):
        return "power", name[len("power:"):]
    raise ModelError("%s = %r is not a known wave (sine, triangle, sawtooth-right, sawtooth-left, "
                     "square, power:p with p >= 1%s)"
                     % (what, name, ", constant" if allow_constant else ""))


def check_digits(digits):
    if isinstance(digits, int):
        d = digits
    elif isinstance(digits, str) and digits.strip().isdigit():
        d = int(digits.strip())
    else:
        raise ModelError("digits = %r is not a positive integer" % (digits,))
    if not 1 <= d <= MAX_DIGITS:
        raise ModelError("digits = %r must be between 1 and %d" % (digits, MAX_DIGITS))
    return d


class Params(object):
    """The model's inputs as decimal strings; .at_precision() parses them at the current mp.prec."""

    def __init__(self, wave, beta, gamma, a, phase="0", inplane="sine"):
        self.wave, self.beta, self.gamma, self.a = wave, beta, gamma, a
        self.phase, self.inplane = phase, inplane
        self.wkind, self.wexp = parse_wave(wave, "wave", True)
        self.pkind, self.pexp = parse_wave(inplane, "in-plane wave", False)
        if self.wkind == "constant" and gamma is not None:
            raise ModelError("gamma = %r given with --wave constant (n = 1 has no gamma)" % (gamma,))
        if self.wkind != "constant" and gamma is None:
            raise ModelError("wave = %r needs --gamma" % (wave,))
        with mp.workdps(30):                 # validate once, at modest precision
            self.at_precision()

    def _exponent(self, text, what):
        if text is None:
            return None
        p = parse_number(text, what)
        if p < 1:
            raise ModelError("%s = %r must be >= 1" % (what, text))
        return p

    def at_precision(self):
        """(wave exponent, in-plane exponent, beta, gamma, a, P) as mpf at the current precision."""
        wp = self._exponent(self.wexp, "power exponent of --wave")
        pp = self._exponent(self.pexp, "power exponent of --in-plane-wave")
        beta = parse_number(self.beta, "beta")
        if beta < 0:
            raise ModelError("beta = %r must be >= 0" % (self.beta,))
        a = parse_number(self.a, "longitudinal amplitude")
        if a < 0:
            raise ModelError("longitudinal amplitude = %r must be >= 0" % (self.a,))
        P = parse_number(self.phase, "phase")
        if self.gamma is None:
            gamma = mpf(1)                   # n = max(1 + 0, 0) = 1
        else:
            gamma = parse_number(self.gamma, "gamma")
            if not gamma > -1:
                raise ModelError("gamma = %r must be > -1 (gamma <= -1: no contact, mu undefined)"
                                 % (self.gamma,))
        return wp, pp, beta, gamma, a, P

    def guard_digits(self):
        """A-priori guard digits; magnitudes estimated at 15 digits (not via float)."""
        with mp.workdps(15):
            g = BASE_GUARD
            b, a = mpf(self.beta), mpf(self.a)
            g += int(mpmath.ceil(mpmath.log10(1 + a + b)))        # s = D - c cancels
            if 0 < b < 1:
                g += int(mpmath.ceil(-mpmath.log10(b)))
            if self.gamma is not None:
                gm = mpf(self.gamma)
                if -1 < gm < 0:
                    g += int(mpmath.ceil(-1.5 * mpmath.log10(1 + gm)))   # int n ~ (1+gamma)^1.5
        return g


# --------------------------------------------------------------------------------------------
# Smooth pieces of the catalogue waves, in the wave's own phase x.  Each formula gives f, f',
# f'', an antiderivative F, interval versions of f' and f'' (for root isolation), the zeros of
# gamma + f inside (lo, hi), and for closed-form critical points its kind.
# --------------------------------------------------------------------------------------------

class Lin(object):
    """f = k x + m."""
    kind = "lin"

    def __init__(self, k, m):
        self.k, self.m = mpf(k), mpf(m)

    def f(self, x): return self.k * x + self.m
    def d1(self, x): return self.k
    def d2(self, x): return mpf(0)
    def F(self, x): return x * (self.k * x / 2 + self.m)
    def d1_iv(self, X): return iv.mpf(self.k)
    def d2_iv(self, X): return iv.mpf(0)

    def zeros(self, g, lo, hi):
        if self.k == 0:
            return []
        z = -(g + self.m) / self.k
        return [z] if lo < z < hi else []


class Sin(object):
    """f = sin(2 pi x)."""
    kind = "sin"

    def f(self, x): return mpmath.sinpi(2 * x)
    def d1(self, x): return 2 * mp.pi * mpmath.cospi(2 * x)
    def d2(self, x): return -4 * mp.pi ** 2 * mpmath.sinpi(2 * x)
    def F(self, x): return -mpmath.cospi(2 * x) / (2 * mp.pi)
    def d1_iv(self, X): return 2 * iv.pi * iv.cos(2 * iv.pi * X)
    def d2_iv(self, X): return -4 * iv.pi ** 2 * iv.sin(2 * iv.pi * X)

    def zeros(self, g, lo, hi):
        if not -1 < g < 1:                    # |gamma| >= 1: no sign change of gamma + sin
            return []
        r = mpmath.asin(-g) / (2 * mp.pi)     # in (-1/4, 1/4)
        cands = [r, r + 1, mpf(1) / 2 - r]
        return [z for z in cands if lo < z < hi]


class Pow(object):
    """f = c0 + sg u^p with u = u0 + du x >= 0 on the segment (power:p, p > 1)."""
    kind = "pow"

    def __init__(self, c0, sg, u0, du, p):
        self.c0, self.sg, self.u0, self.du, self.p = mpf(c0), sg, mpf(u0), mpf(du), p

    def u(self, x):
        r = self.u0 + self.du * x
        return r if r > 0 else mpf(0)          # rounding at the segment ends

    def f(self, x): return self.c0 + self.sg * self.u(x) ** self.p
    def d1(self, x): return self.sg * self.p * self.du * self.u(x) ** (self.p - 1)

    def d2(self, x):
        u = self.u(x)
        if u == 0 and self.p < 2:
            return mpf(0)                      # only reached at a segment end; never used there
        return self.sg * self.p * (self.p - 1) * self.du ** 2 * u ** (self.p - 2)

    def F(self, x):
        p1 = self.p + 1
        return self.c0 * x + self.sg * self.u(x) ** p1 / (p1 * self.du)

    def _u_iv(self, X):
        Ui = iv.mpf(self.u0) + iv.mpf(self.du) * X
        if Ui.a < 0:
            Ui = iv.mpf([0, max(Ui.b, iv.mpf(0)).b])
        return Ui

    def d1_iv(self, X):
        return iv.mpf(self.sg * self.p * self.du) * self._u_iv(X) ** iv.mpf(self.p - 1)

    def d2_iv(self, X):
        return (iv.mpf(self.sg * self.p * (self.p - 1) * self.du ** 2)
                * self._u_iv(X) ** iv.mpf(self.p - 2))

    def zeros(self, g, lo, hi):
        t = -self.sg * (g + self.c0)           # u^p = t
        if t < 0:
            return []
        z = (t ** (1 / self.p) - self.u0) / self.du
        return [z] if lo < z < hi else []


def wave_segments(kind, p):
    """[(lo, hi, formula)] covering [0, 1), exactly the catalogue of model.md."""
    h, q = mpf(1) / 2, mpf(1) / 4
    if kind == "sine":
        return [(mpf(0), mpf(1), Sin())]
    if kind == "triangle":
        return [(mpf(0), h, Lin(4, -1)), (h, mpf(1), Lin(-4, 3))]
    if kind == "sawtooth-right":
        return [(mpf(0), mpf(1), Lin(2, -1))]
    if kind == "sawtooth-left":
        return [(mpf(0), mpf(1), Lin(-2, 1))]
    if kind == "square":
        return [(mpf(0), h, Lin(0, 1)), (h, mpf(1), Lin(0, -1))]
    if kind == "constant":
        return [(mpf(0), mpf(1), Lin(0, 0))]   # with gamma = 1: n = 1
    if kind == "power":
        # 1 - |4x-1|^p on [0, 1/2), -(1 - |4x-3|^p) on [1/2, 1), one formula per quarter
        quarters = [(1, -1, 1, -4), (1, -1, -1, 4), (-1, 1, 3, -4), (-1, 1, -3, 4)]
        segs = []
        for i, (c0, sg, u0, du) in enumerate(quarters):
            f = Lin(sg * du, c0 + sg * u0) if p == 1 else Pow(c0, sg, u0, du, p)
            segs.append((i * q, (i + 1) * q, f))
        return segs
    raise ModelError("wave kind %r unknown" % (kind,))


def frac(x):
    return x - mpmath.floor(x)


def find_seg(segs, x):
    """The segment containing x in [0, 1)."""
    for lo, hi, f in segs:
        if lo <= x < hi:
            return f
    return segs[-1][2]


# --------------------------------------------------------------------------------------------
# Root finding
# --------------------------------------------------------------------------------------------

def solve_bracketed(g, dg, lo, hi):
    """Root of g in (lo, hi), g(lo) and g(hi) of opposite signs: Newton steps kept inside the
    shrinking bracket, bisection otherwise (rtsafe).  Converges to the working precision."""
    glo = g(lo)
    if glo == 0:
        return lo
    neg_lo = glo < 0
    x = (lo + hi) / 2
    dx_old = hi - lo
    tol = mp.eps * 8 * (1 + abs(lo) + abs(hi))
    for _ in range(4 * mp.prec + 100):
        gx = g(x)
        if gx == 0:
            return x
        if (gx < 0) == neg_lo:
            lo = x
        else:
            hi = x
        d = dg(x)
        xn = None
        if d != 0:
            xn = x - gx / d
            # reject steps outside the bracket or not halving the step (slow convergence)
            if not (lo < xn < hi) or abs(gx / d) > dx_old / 2:
                xn = None
        if xn is None:
            xn = (lo + hi) / 2
        dx_old = abs(xn - x)
        if dx_old <= tol or hi - lo <= tol:
            return xn
        x = xn
    raise ModelError("root finder did not converge in (%s, %s) at %d digits"
                     % (mpmath.nstr(lo, 20), mpmath.nstr(hi, 20), mp.dps))


def isolate_sign_changes(h, dh, h_iv, dh_iv, a, b, max_depth=60):
    """Sign changes of h in (a, b) by interval arithmetic: drop intervals where the range of h
    excludes 0; where the range of h' excludes 0, h is monotone and the end signs decide (then the
    root is refined by solve_bracketed).  An interval still undecided after max_depth halvings
    (a tangency) counts only if h changes sign across it."""
    out = []
    stack = [(a, b, 0)]
    while stack:
        u, v, depth = stack.pop()
        H = h_iv(u, v)
        if H.a > 0 or H.b < 0:
            continue
        hu, hv = h(u), h(v)
        changes = (hu < 0 < hv) or (hv < 0 < hu)
        if depth >= max_depth:
            if changes:
                out.append((u + v) / 2)
            continue
        dH = dh_iv(u, v)
        if dH.a > 0 or dH.b < 0:                 # monotone on [u, v]
            if changes:
                out.append(solve_bracketed(h, dh, u, v))
            elif hv == 0 and hu != 0:            # a root exactly on a bisection point
                out.append(v)
            continue
        m = (u + v) / 2
        stack.append((u, m, depth + 1))
        stack.append((m, v, depth + 1))
    return sorted(out)


# --------------------------------------------------------------------------------------------
# Pieces: [a, b] on which w and p(. + P) are single smooth formulas.  The contact point x = D - s
# is swept by [L, U] = [D - n, D + n].
# --------------------------------------------------------------------------------------------

def _sign(x, tol):
    return 0 if abs(x) <= tol else (1 if x > 0 else -1)


class Piece(object):
    def __init__(self, M, a, b):
        self.a, self.b = a, b
        self.beta, self.amp, self.gamma = M.beta, M.a, M.gamma
        m = (a + b) / 2
        jw = mpmath.floor(m)
        self.wsh = -jw                                 # wave phase of w: phi + wsh
        self.wf = find_seg(M.wsegs, m + self.wsh)
        kp = mpmath.floor(m + M.P)
        self.psh = M.P - kp                            # wave phase of p: phi + psh
        self.pf = find_seg(M.psegs, m + self.psh)
        # contact boundaries are piece ends, so the sign of gamma + w is fixed inside the piece,
        # except at isolated touching points (gamma = 1 for the sine): test several points
        self.contact = any(self.gamma + self.wf.f(a + (b - a) * t + self.wsh) > 0
                           for t in (mpf("0.3"), mpf("0.5"), mpf("0.7")))
        # L and U are linear on the piece iff both formulas are (event roots in closed form)
        self.linear = self.wf.kind == "lin" and (self.pf.kind == "lin" or self.amp == 0)

    # normal force (0 in flight), its derivative and antiderivative (the latter only in contact)
    def n(self, x):
        if not self.contact:
            return mpf(0)
        v = self.gamma + self.wf.f(x + self.wsh)
        return v if v > 0 else mpf(0)                  # rounding at a contact boundary

    def dn(self, x):
        return self.wf.d1(x + self.wsh) if self.contact else mpf(0)

    def IN(self, x):
        return self.gamma * x + self.wf.F(x + self.wsh)

    # drive, its derivative and antiderivative
    def D(self, x):
        return self.beta * x + (self.amp * self.pf.f(x + self.psh) if self.amp else 0)

    def dD(self, x):
        return self.beta + (self.amp * self.pf.d1(x + self.psh) if self.amp else 0)

    def d2D(self, x):
        return self.amp * self.pf.d2(x + self.psh) if self.amp else mpf(0)

    def ID(self, x):
        return self.beta * x * x / 2 + (self.amp * self.pf.F(x + self.psh) if self.amp else 0)

    def L(self, x): return self.D(x) - self.n(x)
    def U(self, x): return self.D(x) + self.n(x)

    def h(self, sigma, x):
        """L' (sigma = -1) or U' (sigma = +1)."""
        return self.dD(x) + sigma * self.dn(x)

    def dh(self, sigma, x):
        return self.d2D(x) + sigma * (self.wf.d2(x + self.wsh) if self.contact else 0)

    def h_iv(self, sigma, u, v):
        X = iv.mpf([u, v])
        r = iv.mpf(self.beta)
        if self.amp:
            r = r + iv.mpf(self.amp) * self.pf.d1_iv(X + self.psh)
        return r + sigma * self.wf.d1_iv(X + self.wsh)

    def dh_iv(self, sigma, u, v):
        X = iv.mpf([u, v])
        r = iv.mpf(0)
        if self.amp:
            r = r + iv.mpf(self.amp) * self.pf.d2_iv(X + self.psh)
        return r + sigma * self.wf.d2_iv(X + self.wsh)

    def critical_points(self):
        """Sign changes of L' and U' inside (a, b), contact pieces only."""
        if not self.contact:
            return []
        pts = []
        closed = self.wf.kind in ("lin", "sin") and (self.pf.kind in ("lin", "sin") or not self.amp) \
            and not FORCE_INTERVAL_ROOTS
        for sigma in (-1, 1):
            if closed:
                pts += self._trig_roots(sigma)
            else:
                pts += isolate_sign_changes(lambda x: self.h(sigma, x),
                                            lambda x: self.dh(sigma, x),
                                            lambda u, v: self.h_iv(sigma, u, v),
                                            lambda u, v: self.dh_iv(sigma, u, v), self.a, self.b)
        edge = mp.eps * 2 ** 8
        return sorted(set(x for x in pts if self.a + edge < x < self.b - edge))

    def _trig_roots(self, sigma):
        """h = C + A cos(2 pi phi) + B sin(2 pi phi) = C + R cos(2 pi phi - theta): acos roots."""
        tp = 2 * mp.pi
        C, A, B = self.beta, mpf(0), mpf(0)
        if self.amp:
            if self.pf.kind == "lin":
                C += self.amp * self.pf.k
            else:       # p'(phi + psh) = 2 pi cos(2 pi phi + 2 pi psh)
                A += self.amp * tp * mpmath.cospi(2 * self.psh)
                B -= self.amp * tp * mpmath.sinpi(2 * self.psh)
        if self.wf.kind == "lin":
            C += sigma * self.wf.k
        else:           # w'(phi + wsh) = 2 pi cos(2 pi phi), wsh an integer
            A += sigma * tp
        R = mpmath.hypot(A, B)
        if R <= mp.eps * 2 ** 10 * tp * (1 + self.amp) or abs(C) >= R:
            return []   # no sign change (R = 0 up to rounding: h is the constant C)
        theta = mpmath.atan2(B, A)
        alpha = mpmath.acos(-C / R)
        out = []
        for k in range(int(mpmath.floor(self.a)) - 2, int(mpmath.ceil(self.b)) + 3):
            for t in (theta + alpha, theta - alpha):
                x = t / tp + k
                if self.a < x < self.b:
                    out.append(x)
        return out

    def subdivide(self):
        """Monotone sub-pieces (u, v, sign of L', sign of U'); checked by sampling (safety net)."""
        bounds = [self.a] + self.critical_points() + [self.b]
        self.subs = []
        for u, v in zip(bounds[:-1], bounds[1:]):
            if not v > u:
                continue
            signs = []
            for sigma in (-1, 1):
                def sg(x):
                    val = self.h(sigma, x)
                    tol = mp.eps * 2 ** 24 * (1 + abs(self.dD(x)) + abs(self.dn(x)))
                    return _sign(val, tol)
                s_mid = sg((u + v) / 2)
                if self.contact:
                    for j in range(1, 8):
                        sj = sg(u + (v - u) * j / 8)
                        if sj * s_mid < 0:
                            raise ModelError("internal: missed a sign change of %s' in (%s, %s)"
                                             % ("LU"[sigma > 0], mpmath.nstr(u, 20),
                                                mpmath.nstr(v, 20)))
                signs.append(s_mid)
            self.subs.append((u, v, signs[0], signs[1]))


# --------------------------------------------------------------------------------------------
# The model over one period and the periodic state
# --------------------------------------------------------------------------------------------

class Result(object):
    pass


class Model(object):
    """All inputs mpf at the current precision.  start = 0: phi0 in the widest gap between
    breakpoints; start = 1: another phi0 (for --verify)."""

    def __init__(self, wkind, wp, pkind, pp, beta, gamma, a, P, start=0):
        self.beta, self.gamma, self.a, self.P = beta, gamma, a, P
        self.wsegs = wave_segments(wkind, wp)
        self.psegs = wave_segments(pkind, pp)
        pts = []
        for lo, hi, f in self.wsegs:
            pts.append(lo)
            pts += f.zeros(gamma, lo, hi)                 # contact boundaries
        for lo, hi, f in self.psegs:
            pts.append(frac(lo - P))
        pts = self._merge(sorted(frac(x) for x in pts))
        gaps = [(pts[(i + 1) % len(pts)] + (1 if i + 1 == len(pts) else 0) - pts[i], i)
                for i in range(len(pts))]
        i, t = max(gaps)[1], mpf(1) / 2
        if start != 0:
            # another start: in the gap holding the phase about half a period later, off-centre
            # (with a single gap this still differs from the first start)
            target = frac(pts[i] + gaps[i][0] / 2 + mpf("0.5123"))
            i = max(j for j in range(len(pts)) if pts[j] <= target) if target >= pts[0] \
                else len(pts) - 1
            t = mpf("0.381966")
        self.phi0 = pts[i] + gaps[i][0] * t
        lifted = sorted(x if x > self.phi0 else x + 1 for x in pts)
        ends = [self.phi0] + lifted + [self.phi0 + 1]
        self.pieces = [Piece(self, u, v) for u, v in zip(ends[:-1], ends[1:]) if v > u]
        for pc in self.pieces:
            pc.subdivide()
        self.N = sum(pc.IN(pc.b) - pc.IN(pc.a) for pc in self.pieces if pc.contact)
        self.scale = 1 + a + 2 * beta + abs(gamma) + 1
        self.tol_c = mp.eps * 2 ** 10 * self.scale        # "x is on L (or U)"
        self.tol_state = mp.eps * 2 ** 40 * self.scale    # "two period ends agree"

    @staticmethod
    def _merge(pts):
        """Breakpoints closer than a few ulps are one (simultaneous jumps: one projection)."""
        tol = mp.eps * 2 ** 12
        out = []
        for x in pts:
            if not out or x - out[-1] > tol:
                out.append(x)
        if len(out) > 1 and out[0] + 1 - out[-1] <= tol:
            out.pop()
        return out

    def _event(self, pc, which, c, u, v):
        """First phi in (u, v) where L rises to c (which = -1) or U falls to c (which = +1)."""
        f = pc.L if which < 0 else pc.U
        if pc.linear:
            fu = f(u)
            t = u + (c - fu) / pc.h(which, (u + v) / 2)
            return min(max(t, u), v)
        return solve_bracketed(lambda x: f(x) - c, lambda x: pc.h(which, x), u, v)

    def run(self, c, trace=None):
        """One period from x(phi0) = c: returns x(phi0 + 1), int s and the time in each mode."""
        S = mpf(0)
        T = {"stick": mpf(0), "fwd": mpf(0), "bwd": mpf(0), "flight": mpf(0)}

        def seg(mode, u, v, pc, c0=None):
            T[mode] += v - u
            if trace is not None and v > u:
                s = {"stick": lambda: pc.D(u) - c0, "fwd": lambda: pc.n(u),
                     "bwd": lambda: -pc.n(u), "flight": lambda: mpf(0)}[mode]()
                trace.append((u, v, mode, s))

        for pc in self.pieces:
            if not pc.contact:                            # flight: s = 0, x = D
                seg("flight", pc.a, pc.b, pc)
                c = pc.D(pc.b)
                continue
            for (u, v, sL, sU) in pc.subs:
                Lu, Uu = pc.L(u), pc.U(u)
                if c < Lu:                                # projection (jumps, touch-down)
                    c = Lu
                if c > Uu:
                    c = Uu
                if sL >= 0 and c <= Lu + self.tol_c:      # on L and L rising: forward slip
                    S += pc.IN(v) - pc.IN(u)
                    seg("fwd", u, v, pc)
                    c = pc.L(v)
                elif sU <= 0 and c >= Uu - self.tol_c:    # on U and U falling: backward slip
                    S -= pc.IN(v) - pc.IN(u)
                    seg("bwd", u, v, pc)
                    c = pc.U(v)
                else:                                     # stick at c until L or U reaches it
                    t, new = v, None
                    if sL > 0 and pc.L(v) > c:
                        t, new = self._event(pc, -1, c, u, v), "fwd"
                    if sU < 0 and pc.U(v) < c:
                        tU = self._event(pc, 1, c, u, v)
                        if tU < t:
                            t, new = tU, "bwd"
                    S += pc.ID(t) - pc.ID(u) - c * (t - u)
                    seg("stick", u, t, pc, c)
                    if new == "fwd":
                        S += pc.IN(v) - pc.IN(t)
                        seg("fwd", t, v, pc)
                        c = pc.L(v)
                    elif new == "bwd":
                        S -= pc.IN(v) - pc.IN(t)
                        seg("bwd", t, v, pc)
                        c = pc.U(v)
        return c, S, T

    def periodic(self, trace=None, check_map=False):
        first = self.pieces[0]
        L0, U0 = first.L(self.phi0), first.U(self.phi0)
        A = self.run(L0)[0]                              # image of s = n(phi0)
        B = self.run(U0)[0]                              # image of s = -n(phi0)
        if A > B + self.tol_state:
            raise ModelError("internal: the one-period map is not a clamp (A - B = %s)"
                             % mpmath.nstr(A - B, 5))
        if self.beta == 0 and B - A > self.tol_state:
            raise NoUniqueState(
                "no unique periodic state: with beta = 0 the starts s = n and s = -n at phase "
                "%s stay %s apart after a period (the contact can stick through the period)"
                % (mpmath.nstr(self.phi0, 10), mpmath.nstr(B - A, 5)))
        if check_map:                                    # F(x) = clamp(x, A, B) at s(phi0) = 0
            xm = first.D(self.phi0)
            Fm = self.run(xm)[0]
            want = min(max(xm, A), B)
            if abs(Fm - want) > self.tol_state:
                raise ModelError("internal: F(x) = %s but clamp(x, A, B) = %s"
                                 % (mpmath.nstr(Fm, 20), mpmath.nstr(want, 20)))
        c = A - self.beta                                # the fixed point x(phi0 + 1) = x + beta
        for _ in range(8):
            tr = [] if trace is not None else None
            c_end, S, T = self.run(c, tr)
            if abs(c_end - self.beta - c) <= self.tol_state:
                break
            c = c_end - self.beta
        else:
            raise ModelError("internal: the periodic state does not repeat (x = %s, next %s)"
                             % (mpmath.nstr(c, 20), mpmath.nstr(c_end - self.beta, 20)))
        if trace is not None:
            trace.extend(tr)
        r = Result()
        r.mu = S / self.N
        r.S, r.N = S, self.N
        r.stick_fraction = T["stick"]
        r.slip_fraction = T["fwd"] + T["bwd"]
        r.backward_slip_fraction = T["bwd"]
        r.flight_fraction = T["flight"]
        r.mean_lateral = mpf(0)
        r.phi0, r.s0, r.A, r.B = self.phi0, first.D(self.phi0) - c, A, B
        return r


# --------------------------------------------------------------------------------------------
# Public entry points
# --------------------------------------------------------------------------------------------

FRACTIONS = ("stick_fraction", "slip_fraction", "backward_slip_fraction", "flight_fraction")


def compute(params, dps, start=0, trace=None, check_map=False):
    """The periodic state's Result at `dps` decimal digits (values are mpf at that precision)."""
    old = iv.prec
    try:
        with mp.workdps(dps):
            iv.prec = mp.prec
            wp, pp, beta, gamma, a, P = params.at_precision()
            M = Model(params.wkind, wp, params.pkind, pp, beta, gamma, a, P, start)
            r = M.periodic(trace, check_map)
            r.dps = dps
            return r
    finally:
        iv.prec = old


def evaluate(wave, beta, gamma, a, phase="0", inplane="sine", digits=30, verify=False):
    """Result at `digits` + guard digits from decimal strings.  verify: recompute with 25 more
    digits from another start phase, check the clamp form of the period map, and compare."""
    digits = check_digits(digits)
    params = Params(wave, beta, gamma, a, phase, inplane)
    dps = digits + params.guard_digits()
    r = compute(params, dps)
    if verify:
        r2 = compute(params, dps + 25, start=1, check_map=True)
        with mp.workdps(dps + 25):
            big = max(abs(r.mu), abs(r2.mu), mpf(1))
            if abs(r.mu - r2.mu) > mpf(10) ** (-digits - 2) * big:
                raise ModelError("verification failed: mu %s vs %s (second start phase, +25 "
                                 "digits)" % (mpmath.nstr(r.mu, digits + 5),
                                              mpmath.nstr(r2.mu, digits + 5)))
            # fractions are event positions: ill-conditioned near tangencies, compared to 1e-15
            for name in FRACTIONS:
                if abs(getattr(r, name) - getattr(r2, name)) > mpf(10) ** (-min(digits, 15)):
                    raise ModelError("verification failed: %s %s vs %s" % (
                        name, mpmath.nstr(getattr(r, name), 20), mpmath.nstr(getattr(r2, name), 20)))
    return r


def fmt(x, digits):
    """x with exactly `digits` significant digits."""
    return mpmath.nstr(x, digits, strip_zeros=False)


def fmt_fraction(x, dps):
    """17 significant digits; rounding noise (below the working precision) prints as 0."""
    with mp.workdps(dps):
        if abs(x) <= mpf(10) ** (-(dps - 10)):
            return "0"
        return mpmath.nstr(x, 17, strip_zeros=False)


def report_lines(r, digits):
    lines = [fmt(r.mu, digits), "mean_lateral: 0"]
    for name in FRACTIONS:
        lines.append("%s: %s" % (name, fmt_fraction(getattr(r, name), r.dps)))
    return lines


# --------------------------------------------------------------------------------------------
# CLI
# --------------------------------------------------------------------------------------------

def main(argv=None):
    ap = argparse.ArgumentParser(description="mpmath reference for longitudinal in-plane "
                                             "oscillation (see the module docstring)")
    sub = ap.add_subparsers(dest="cmd")
    for name in ("mu", "trace"):
        sp = sub.add_parser(name)
        sp.add_argument("--wave", required=True)
        sp.add_argument("--beta", required=True)
        sp.add_argument("--gamma")
        sp.add_argument("--longitudinal", required=True)
        sp.add_argument("--phase", default="0")
        sp.add_argument("--in-plane-wave", default="sine")
        sp.add_argument("--digits", default="17")
        sp.add_argument("--verify", action="store_true")
    args = ap.parse_args(argv)
    if args.cmd is None:
        ap.print_help()
        return 2
    try:
        d = check_digits(args.digits)
        if args.cmd == "mu":
            r = evaluate(args.wave, args.beta, args.gamma, args.longitudinal, args.phase,
                         args.in_plane_wave, d, args.verify)
            with mp.workdps(r.dps):
                print("\n".join(report_lines(r, d)))
        else:
            params = Params(args.wave, args.beta, args.gamma, args.longitudinal, args.phase,
                            args.in_plane_wave)
            tr = []
            r = compute(params, d + params.guard_digits(), trace=tr)
            with mp.workdps(r.dps):
                print("# phi0 = %s, s(phi0) = %s, mu = %s" % (fmt(r.phi0, d), fmt(r.s0, d),
                                                              fmt(r.mu, d)))
                print("from,to,mode,s_at_from")
                for u, v, mode, s in tr:
                    print("%s,%s,%s,%s" % (fmt(u, d), fmt(v, d), mode, fmt(s, d)))
    except ModelError as e:
        sys.stderr.write("error: %s\n" % e)
        return 2
    except NoUniqueState as e:
        sys.stderr.write("error: %s\n" % e)
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main())
