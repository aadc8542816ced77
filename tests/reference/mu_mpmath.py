#!/usr/bin/python3
"""Independent mpmath reference for the friction model of /work/shared/model.md.

What it computes
----------------
n(phi) = max(gamma + w(phi), 0) is the normal force (w of unit period), s(phi) the steady-state
tangential force, the lower envelope of n under ramps of slope beta:

    s(phi) = inf over 0 <= tau < 1 of [ n(phi - tau) + beta*tau ],

mu/mu0 = int_0^1 s / int_0^1 n  (paper Eqs. 9, 13, 15) and, for gamma >= 1,
Psi(beta) = int_0^1 (n - s)  evaluated at gamma = 1 (paper Eqs. 11-12).

Algorithm (the running-minimum sweep)
-------------------------------------
Let phi_m be a phase at which n attains its infimum n_min (as a value or as a one-sided limit).
For phi in [phi_m, phi_m + 1) every candidate psi = phi - tau with psi < phi_m gives
n(psi) + beta*(phi - psi) >= n_min + beta*(phi - psi) > n_min + beta*(phi - phi_m), and the right-hand
value is reached (or approached) by psi -> phi_m.  Hence, with h(psi) = n(psi) - beta*psi,

    s(phi) = beta*phi + M(phi),   M(phi) = min( n_min - beta*phi_m,  inf_{[phi_m, phi]} h ).

So s is a running minimum, swept over ONE period that starts at phi_m.  Because the sweep starts
at the global minimum of n (where s = n), no stick phase can straddle the sweep boundary: stick
phases that wrap around phase 0 in the paper's coordinates are simply interior here.  We work in
shifted coordinates x = phi - shift (shift = 3/4 for sine and power:p, 0 otherwise) so that the
sweep is x in [0, 1]; phase shifts do not change any integral over a period.

The sweep interval is cut into pieces on each of which n is given by ONE smooth closed formula and
h is monotone: cuts at contact boundaries (asin/acos/explicit inverse powers), at the formula's own
breakpoints, and at the stick-onset points where n' = beta (asin for the sine, explicit inverse
powers for power:p).  The running minimum is represented by its current ramp R(x) = y0 + beta(x-x0)
("anchor" (x0, y0), a point where s = n).  Per piece (a, b) with one-sided limits na = n(a+),
nb = n(b-):
  * if na <= R(a): the running minimum is reset, anchor := (a, na)  [this is the slip state; a
    downward jump of n lands here];  otherwise the ramp continues through a (stick continues, e.g.
    after an upward jump of n, which therefore starts a stick phase);
  * h nondecreasing on the piece (n' > beta there):  stick on the whole piece (s = R < n); a stick
    phase therefore starts where n' first exceeds beta, at an upward jump, or at first contact if
    n' > beta there;
  * h nonincreasing (n' <= beta):  if the state at a is slip, s = n on the whole piece; otherwise
    the ramp continues until n falls back onto it, i.e. the root c of n(c) = R(c) (paper Eq. 8),
    which exists in the piece iff nb < R(b) and is unique there since n - R is strictly decreasing;
    stick on (a, c), slip on (c, b), anchor := (b, nb).
Eq. 8 roots are closed form on linear pieces; otherwise mpmath.findroot with the bracketing
Anderson-Bjoerck solver on (a, b), then checked (root inside its bracket, residual below a tolerance
derived from the working precision, one guarded Newton polish) and, failing that, retried with
bisection; if that also fails, an error is raised (never a silent value).
Areas use exact antiderivatives of n; the stick contribution is the exact trapezoid of the linear
ramp.  mu = (sum of s-areas)/(sum of n-areas); Psi = sum over stick parts of (n-area - ramp-area).
If no stick occurs at all (beta >= beta_c(gamma)), mu = 1 exactly.

Numbers are parsed from their decimal strings at the working precision (never through float).
The working precision is digits + guard decimal digits, where the guard grows where the formulas
lose digits (gamma -> -1, small beta, Psi near beta_c).  --verify recomputes with 25 more guard
digits and raises if the two answers differ in the requested digits.

Usage:  /usr/bin/python3 mu_mpmath.py mu    --wave W --beta B --gamma G --digits D
        /usr/bin/python3 mu_mpmath.py psi   --wave W --beta B --digits D
        /usr/bin/python3 mu_mpmath.py sweep --wave W --beta FROM:TO:N --gamma G1,G2,.. --digits D
        /usr/bin/python3 mu_mpmath.py events --wave W --beta B --gamma G --digits D
Waves: sine, triangle, sawtooth-right, sawtooth-left, square, power:p (p >= 1).
"""

import argparse
import sys

import mpmath
from mpmath import mp, mpf

BASE_GUARD = 20          # decimal guard digits always added to the requested precision
MAX_DIGITS = 5000


class ModelError(ValueError):
    """Bad input or a numerical failure; the message names the offending value."""


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


def parse_wave(name):
    """Return (kind, p_string) for a catalogue wave name."""
    if name in ("sine", "triangle", "sawtooth-right", "sawtooth-left", "square"):
        return name, None
    if isinstance(name, str) and name.startswith("power:"):
        return "power", name[len("power:"):]
    raise ModelError("wave = %r is not a known wave (sine, triangle, sawtooth-right, "
                     "sawtooth-left, square, power:p with p >= 1)" % (name,))


def wave_param(kind, p_text):
    """Parse the power exponent (at the current precision); None for the other waves."""
    if kind != "power":
        return None
    p = parse_number(p_text, "power exponent p")
    if p < 1:
        raise ModelError("power exponent p = %r must be >= 1" % (p_text,))
    return p


def check_beta_gamma(beta, gamma, beta_text="beta", gamma_text="gamma"):
    if not beta > 0:
        raise ModelError("beta = %s must be > 0" % beta_text)
    if gamma is not None and not gamma > -1:
        raise ModelError("gamma = %s must be > -1 (gamma <= -1 means no contact: mu undefined)"
                         % gamma_text)


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


# --------------------------------------------------------------------------------------------
# Formulas for n on one piece.  Each provides n(x), dn(x), area(a, b) = int_a^b n (exact
# antiderivative) and `slope` (not None iff n is linear on the piece).
# --------------------------------------------------------------------------------------------

class Air(object):
    slope = 0
    def n(self, x): return mpf(0)
    def dn(self, x): return mpf(0)
    def area(self, a, b): return mpf(0)


class Linear(object):
    """n = c0 + k x."""
    def __init__(self, c0, k):
        self.c0, self.slope = c0, k
    def n(self, x): return self.c0 + self.slope * x
    def dn(self, x): return self.slope
    def area(self, a, b): return (b - a) * (self.n(a) + self.n(b)) / 2


class SineContact(object):
    """n = gamma - cos(2 pi x)   (the sine shifted by 3/4: sin(2 pi (x + 3/4)) = -cos(2 pi x))."""
    slope = None
    def __init__(self, gamma):
        self.g = gamma
        self.tp = 2 * mp.pi
    def n(self, x): return self.g - mpmath.cos(self.tp * x)
    def dn(self, x): return self.tp * mpmath.sin(self.tp * x)
    def area(self, a, b):
        # int_a^b -cos(2 pi x) = -(sin 2pi b - sin 2pi a)/(2 pi) = -cos(pi(a+b)) sin(pi(b-a))/pi
        return self.g * (b - a) - mpmath.cos(mp.pi * (a + b)) * mpmath.sin(mp.pi * (b - a)) / mp.pi


class PowerQuarter(object):
    """power:p shifted by 3/4 (x = phi - 3/4), v(x) on the four quarters:
         q=0  [0,1/4]:   -1 + (4x)^p          q=1  [1/4,1/2]:  1 - (2-4x)^p
         q=2  [1/2,3/4]:  1 - (4x-2)^p        q=3  [3/4,1]:   -1 + (4-4x)^p
       n = gamma + v = c + sgn * u(x)^p with u linear in x (u >= 0 on the quarter)."""
    slope = None
    def __init__(self, gamma, p, q):
        self.p, self.q = p, q
        if q == 0:   self.c, self.sg, self.u0, self.du = gamma - 1, 1, mpf(0), mpf(4)
        elif q == 1: self.c, self.sg, self.u0, self.du = gamma + 1, -1, mpf(2), mpf(-4)
        elif q == 2: self.c, self.sg, self.u0, self.du = gamma + 1, -1, mpf(-2), mpf(4)
        else:        self.c, self.sg, self.u0, self.du = gamma - 1, 1, mpf(4), mpf(-4)
        if p == 1:
            # linear: n = c + sg*(u0 + du x)
            self.slope = self.sg * self.du
    def u(self, x):
        r = self.u0 + self.du * x
        return r if r > 0 else mpf(0)     # guard against -0 rounding at quarter ends
    def n(self, x): return self.c + self.sg * self.u(x) ** self.p
    def dn(self, x):
        if self.p == 1:
            return self.sg * self.du
        return self.sg * self.p * self.u(x) ** (self.p - 1) * self.du
    def area(self, a, b):
        p1 = self.p + 1
        return self.c * (b - a) + self.sg * (self.u(b) ** p1 - self.u(a) ** p1) / (p1 * self.du)


class Piece(object):
    __slots__ = ("a", "b", "inc", "f", "na", "nb")
    def __init__(self, a, b, inc, f, na=None, nb=None):
        self.a, self.b, self.inc, self.f = a, b, inc, f
        self.na = f.n(a) if na is None else na
        self.nb = f.n(b) if nb is None else nb


# --------------------------------------------------------------------------------------------
# Piece lists, in sweep coordinates x in [0, 1] (phi = x + shift).  Returns (pieces, n_min, shift).
# --------------------------------------------------------------------------------------------

def _cut(points):
    """Sorted, de-duplicated cut points in [0, 1]."""
    pts = sorted(set([p for p in points if 0 <= p <= 1]))
    return [(pts[i], pts[i + 1]) for i in range(len(pts) - 1) if pts[i] < pts[i + 1]]


def _symmetric_pieces(gamma, beta, xc, Xa, Xb, formula_for, extra_cuts):
    """Generic builder for the waves with v(1-x) = v(x), minimum -1 at x = 0, maximum at 1/2,
    rising on (0, 1/2) and falling on (1/2, 1) in sweep coordinates.
    xc: first contact (0 when gamma >= 1), contact is (xc, 1 - xc).
    (Xa, Xb): the interval where n' > beta (h increasing), or None.
    formula_for(mid): the smooth formula of n valid on the piece containing `mid` (in contact)."""
    zero = mpf(0)
    cuts = [mpf(0), mpf(1)] + list(extra_cuts)
    if xc > 0:
        cuts += [xc, 1 - xc]
    if Xa is not None:
        cuts += [Xa, Xb]
    pieces = []
    for a, b in _cut(cuts):
        in_contact = (xc == 0) or (a >= xc and b <= 1 - xc)
        if not in_contact:
            pieces.append(Piece(a, b, False, Air(), zero, zero))
            continue
        f = formula_for((a + b) / 2)
        inc = Xa is not None and a >= Xa and b <= Xb
        # contact boundaries: n is exactly 0 there (avoid rounding of gamma + v(xc))
        na = zero if (xc > 0 and a == xc) else None
        nb = zero if (xc > 0 and b == 1 - xc) else None
        pieces.append(Piece(a, b, inc, f, na, nb))
    return pieces


def build_pieces(kind, p, gamma, beta):
    one, zero = mpf(1), mpf(0)
    n_min = gamma - 1 if gamma > 1 else zero          # inf n = max(gamma - 1, 0)

    if kind == "sine":
        # x = phi - 3/4, v = -cos(2 pi x); v' = 2 pi sin(2 pi x).
        xc = mpmath.acos(gamma) / (2 * mp.pi) if gamma < 1 else zero   # v(xc) = -gamma
        Xa = Xb = None
        if beta < 2 * mp.pi:
            x1 = mpmath.asin(beta / (2 * mp.pi)) / (2 * mp.pi)           # v'(x1) = beta, rising
            x2 = mpf(1) / 2 - x1
            lo = x1 if x1 > xc else xc   # stick onset: n' = beta, or first contact if n' > beta
            if lo < x2 - _tol(1):   # (an interval of rounding size is no stick)
                Xa, Xb = lo, x2
        f = SineContact(gamma)
        return _symmetric_pieces(gamma, beta, xc, Xa, Xb, lambda m: f, []), n_min, mpf(3) / 4

    if kind == "power":
        # x = phi - 3/4; see PowerQuarter.  Rising branch inverse of v(x) = -gamma:
        if gamma >= 1:
            xc = zero
        elif gamma >= 0:
            xc = (1 - gamma) ** (1 / p) / 4                 # in q=0: (4x)^p = 1 - gamma
        else:
            xc = (2 - (1 + gamma) ** (1 / p)) / 4           # in q=1: (2-4x)^p = 1 + gamma
        Xa = Xb = None
        if p == 1:
            if beta < 4:                                    # v' = 4 on (0, 1/2)
                Xa, Xb = xc, mpf(1) / 2
        elif beta < 4 * p:
            # v' = 4p (4x)^(p-1) on q=0 and 4p (2-4x)^(p-1) on q=1; v' = beta at
            r = (beta / (4 * p)) ** (1 / (p - 1))
            x1, x2 = r / 4, (2 - r) / 4
            lo = x1 if x1 > xc else xc
            if lo < x2 - _tol(1):   # (an interval of rounding size is no stick)
                Xa, Xb = lo, x2
        quarters = [PowerQuarter(gamma, p, q) for q in range(4)]
        def formula_for(mid):
            q = int(mpmath.floor(4 * mid))
            return quarters[min(max(q, 0), 3)]
        cuts = [mpf(1) / 4, mpf(1) / 2, mpf(3) / 4]
        return (_symmetric_pieces(gamma, beta, xc, Xa, Xb, formula_for, cuts), n_min, mpf(3) / 4)

    if kind == "triangle":
        # w = 4x - 1 on [0, 1/2], 3 - 4x on [1/2, 1]; minimum at x = 0, no shift.
        xc = (1 - gamma) / 4 if gamma < 1 else zero
        Xa = Xb = None
        if beta < 4:
            Xa, Xb = xc, mpf(1) / 2
        rise, fall = Linear(gamma - 1, mpf(4)), Linear(gamma + 3, mpf(-4))
        return (_symmetric_pieces(gamma, beta, xc, Xa, Xb,
                                  lambda m: rise if m < mpf(1) / 2 else fall, [mpf(1) / 2]),
                n_min, zero)

    if kind == "sawtooth-right":
        # w = 2x - 1 on [0, 1): minimum -1 at x = 0 (attained); downward jump at x = 1 (sweep end).
        f = Linear(gamma - 1, mpf(2))
        inc = beta < 2
        if gamma >= 1:
            return [Piece(zero, one, inc, f)], n_min, zero
        xc = (1 - gamma) / 2
        return [Piece(zero, xc, False, Air(), zero, zero),
                Piece(xc, one, inc, f, zero, None)], n_min, zero

    if kind == "sawtooth-left":
        # w = 1 - 2x on [0, 1): inf is the left limit at x = 1 (= 0 mod 1); upward jump at x = 0.
        f = Linear(gamma + 1, mpf(-2))
        if gamma >= 1:
            return [Piece(zero, one, False, f)], n_min, zero
        xe = (1 + gamma) / 2                                # loss of contact
        return [Piece(zero, xe, False, f, None, zero),
                Piece(xe, one, False, Air(), zero, zero)], n_min, zero

    if kind == "square":
        # w = 1 on [0, 1/2), -1 on [1/2, 1); upward jump at x = 0, downward jump at x = 1/2.
        half = mpf(1) / 2
        top = Linear(gamma + 1, zero)
        bottom = Linear(gamma - 1, zero) if gamma >= 1 else Air()
        return [Piece(zero, half, False, top), Piece(half, one, False, bottom)], n_min, zero

    raise ModelError("wave kind %r unknown" % (kind,))


def build_pwl_pieces(xs, ws, gamma, beta):
    """Continuous periodic piecewise-linear wave through (xs[i], ws[i]), 0 <= xs[0] < ... < 1
    (not a catalogue wave: used by selftest.py to exercise several stick phases per period and
    stick phases wrapping phase 0).  Returns (pieces, n_min, shift) like build_pieces."""
    m = len(xs)
    j = min(range(m), key=lambda i: ws[i])           # sweep starts at the global minimum
    shift = xs[j]
    vx = [(xs[(j + i) % m] - shift) % 1 for i in range(m)] + [mpf(1)]
    vw = [ws[(j + i) % m] for i in range(m)] + [ws[j]]
    zero = mpf(0)
    pieces = []
    for i in range(m):
        a, b, wa, wb = vx[i], vx[i + 1], vw[i], vw[i + 1]
        k = (wb - wa) / (b - a)
        na, nb = gamma + wa, gamma + wb
        f = Linear(na - k * a, k)
        if na >= 0 and nb >= 0:
            pieces.append(Piece(a, b, k > beta, f))
        elif na <= 0 and nb <= 0:
            pieces.append(Piece(a, b, False, Air(), zero, zero))
        else:
            z = a - na / k                                # gamma + w(z) = 0
            if na < 0:                                    # first contact at z
                pieces.append(Piece(a, z, False, Air(), zero, zero))
                pieces.append(Piece(z, b, k > beta, f, zero, None))
            else:                                         # loss of contact at z
                pieces.append(Piece(a, z, False, f, None, zero))
                pieces.append(Piece(z, b, False, Air(), zero, zero))
    n_min = gamma + vw[0] if gamma + vw[0] > 0 else zero
    return pieces, n_min, shift


# --------------------------------------------------------------------------------------------
# Eq. 8: end of a stick phase inside one nonincreasing piece
# --------------------------------------------------------------------------------------------

class Stats(object):
    def __init__(self):
        self.roots = 0
        self.closed_form_roots = 0
        self.bisect_fallbacks = 0


def _tol(scale):
    """Comparison tolerance: 2^24 ulps of the working precision, relative to `scale`."""
    return mp.eps * 2 ** 24 * (1 + abs(scale))


def _stick_end(piece, x0, y0, beta, stats):
    """Root c in (a, b) of g(x) = n(x) - (y0 + beta (x - x0)), g(a+) > 0 > g(b-), g decreasing."""
    f, a, b = piece.f, piece.a, piece.b
    ga = piece.na - (y0 + beta * (a - x0))
    gb = piece.nb - (y0 + beta * (b - x0))
    if not (ga > 0 and gb < 0):
        raise ModelError("internal: Eq. 8 root not bracketed on (%s, %s): g(a)=%s g(b)=%s"
                         % (mpmath.nstr(a, 20), mpmath.nstr(b, 20), mpmath.nstr(ga, 5),
                            mpmath.nstr(gb, 5)))
    if f.slope is not None:
        # linear n: n(a) + k (c - a) = y0 + beta (c - x0)  =>  c = a + g(a)/(beta - k)
        stats.closed_form_roots += 1
        c = a + ga / (beta - f.slope)
        if c < a: c = a
        if c > b: c = b
        return c

    stats.roots += 1
    g = lambda x: f.n(x) - (y0 + beta * (x - x0))
    dg = lambda x: f.dn(x) - beta
    scale = abs(piece.na) + abs(piece.nb) + abs(y0) + beta
    res_tol = mp.eps * 2 ** 20 * (1 + scale)

    def accept(c):
        if c is None or not (a <= c <= b):
            return None
        r = g(c)
        d = dg(c)
        if d != 0:                                   # one guarded Newton polish
            c2 = c - r / d
            if a <= c2 <= b:
                r2 = g(c2)
                if abs(r2) <= abs(r):
                    c, r = c2, r2
        return c if abs(r) <= res_tol else None

    c = None
    try:
        c = accept(mpmath.findroot(g, (a, b), solver="anderson", maxsteps=400, verify=False))
    except (ValueError, ZeroDivisionError):
        c = None
    if c is None:
        stats.bisect_fallbacks += 1
        try:
            c = accept(mpmath.findroot(g, (a, b), solver="bisect", maxsteps=4 * mp.prec + 50,
                                       verify=False))
        except (ValueError, ZeroDivisionError):
            c = None
    if c is None:
        raise ModelError("Eq. 8 stick end not found in (%s, %s) at %d digits"
                         % (mpmath.nstr(a, 20), mpmath.nstr(b, 20), mp.dps))
    return c


# --------------------------------------------------------------------------------------------
# The sweep
# --------------------------------------------------------------------------------------------

class Result(object):
    """S = int s, N = int n, D = int (n - s) over one period; segments for s(x); stick phases."""
    pass


def sweep(pieces, beta, n_min, shift=mpf(0)):
    stats = Stats()
    x0, y0 = pieces[0].a, n_min        # anchor of the running-minimum ramp R(x) = y0 + beta(x-x0)
    S = N = D = mpf(0)
    segs = []                          # (a, b, 'stick'|'slip', piece, x0, y0)

    def stick(P, a, b):
        ra, rb = y0 + beta * (a - x0), y0 + beta * (b - x0)
        ramp = (b - a) * (ra + rb) / 2
        segs.append((a, b, "stick", P, x0, y0))
        return ramp, P.f.area(a, b) - ramp

    for P in pieces:
        a, b = P.a, P.b
        N += P.f.area(a, b)
        Ra = y0 + beta * (a - x0)
        slip_state = P.na <= Ra + _tol(Ra)
        if slip_state:
            x0, y0 = a, P.na            # h(a+) <= running min: reset (s = n at a)
        if P.inc:
            ramp, d = stick(P, a, b)    # h increasing: stick on the whole piece
            S += ramp; D += d
            continue
        if slip_state:                  # h decreasing from a state with s = n: slip throughout
            S += P.f.area(a, b)
            segs.append((a, b, "slip", P, None, None))
            x0, y0 = b, P.nb
            continue
        Rb = y0 + beta * (b - x0)
        if P.nb >= Rb - _tol(Rb):       # n stays above the ramp: stick throughout
            ramp, d = stick(P, a, b)
            S += ramp; D += d
            continue
        c = _stick_end(P, x0, y0, beta, stats)   # Eq. 8
        ramp, d = stick(P, a, c)
        S += ramp + P.f.area(c, b); D += d
        segs.append((c, b, "slip", P, None, None))
        x0, y0 = b, P.nb

    r = Result()
    r.S, r.N, r.D, r.segs, r.stats, r.beta, r.shift = S, N, D, segs, stats, beta, shift
    # internal consistency: N - S and D are the same quantity computed along different routes
    if abs((N - S) - D) > mp.eps * 2 ** 30 * (1 + abs(N)):
        raise ModelError("internal: area bookkeeping inconsistent (N-S=%s, D=%s)"
                         % (mpmath.nstr(N - S, 15), mpmath.nstr(D, 15)))
    # stick phases (merged), in sweep coordinates
    phases = []
    for (a, b, kind_, P, _, _) in segs:
        if kind_ != "stick" or not b > a:
            continue
        if phases and phases[-1][1] == a:
            phases[-1][1] = b
        else:
            phases.append([a, b])
    r.stick_phases = phases
    return r


def s_at(result, x):
    """s at sweep coordinate x in [0, 1] from the sweep's segments (for cross-checks)."""
    for (a, b, kind_, P, x0, y0) in result.segs:
        if a <= x <= b:
            if kind_ == "stick":
                return y0 + result.beta * (x - x0)
            return P.f.n(x)
    raise ModelError("x = %s outside the sweep" % x)


# --------------------------------------------------------------------------------------------
# Public computations (arguments are mpf at the current precision)
# --------------------------------------------------------------------------------------------

def compute(kind, p, beta, gamma):
    pieces, n_min, shift = build_pieces(kind, p, gamma, beta)
    return sweep(pieces, beta, n_min, shift), pieces


def mu_value(kind, p, beta, gamma):
    r, _ = compute(kind, p, beta, gamma)
    if not r.stick_phases:
        return mpf(1)                  # beta >= beta_c(gamma): no stick, mu = mu0 exactly (Eq. 6)
    return r.S / r.N


def psi_value(kind, p, beta):
    r, _ = compute(kind, p, beta, mpf(1))
    return r.D


def beta_c_at_gamma1(kind, p):
    return {"sine": 2 * mp.pi, "triangle": mpf(4), "sawtooth-right": mpf(2)}.get(
        kind, 4 * p if kind == "power" else None)


def guard_digits(kind, p_text, beta_text, gamma_text, digits, what):
    """A-priori guard digits.  Magnitudes are estimated by parsing at 15 digits (not via float)."""
    with mp.workdps(15):
        g = BASE_GUARD
        beta = mpf(beta_text)
        if 0 < beta < 1:
            g += int(mpmath.ceil(-mpmath.log10(beta)))
        if gamma_text is not None:
            gamma = mpf(gamma_text)
            if -1 < gamma < 0:
                g += int(mpmath.ceil(-1.5 * mpmath.log10(1 + gamma)))
        if what == "psi":
            p = mpf(p_text) if p_text is not None else None
            bc = beta_c_at_gamma1(kind, p)
            if bc is not None and beta < bc:
                g += 2 * int(mpmath.ceil(max(0, -mpmath.log10(1 - beta / bc))))
    return g


def _agree(x, y, digits):
    return abs(x - y) <= mpf(10) ** (-digits) * max(abs(x), abs(y), mp.eps)


def evaluate(what, wave, beta_text, gamma_text, digits, verify=False, extra_guard=0):
    """Full pipeline from strings: returns the value as an mpf at the working precision."""
    digits = check_digits(digits)
    kind, p_text = parse_wave(wave)
    # validate first at modest precision so that bad input gives a clear message
    with mp.workdps(30):
        wave_param(kind, p_text)
        b = parse_number(beta_text, "beta")
        gm = parse_number(gamma_text, "gamma") if gamma_text is not None else None
        check_beta_gamma(b, gm, repr(beta_text), repr(gamma_text))
    guard = guard_digits(kind, p_text, beta_text, gamma_text, digits, what) + extra_guard

    def run(dps):
        with mp.workdps(dps):
            p = wave_param(kind, p_text)
            beta = parse_number(beta_text, "beta")
            if what == "mu":
                return mu_value(kind, p, beta, parse_number(gamma_text, "gamma"))
            return psi_value(kind, p, beta)

    v = run(digits + guard)
    if verify:
        v2 = run(digits + guard + 25)
        with mp.workdps(digits + guard + 25):
            if not _agree(v, v2, digits + 2):
                raise ModelError("verification failed for %s wave=%s beta=%s gamma=%s: %s vs %s"
                                 % (what, wave, beta_text, gamma_text,
                                    mpmath.nstr(v, digits + 5), mpmath.nstr(v2, digits + 5)))
    return v


def fmt(x, digits):
    """x with exactly `digits` significant digits."""
    return mpmath.nstr(x, digits, strip_zeros=False)


# --------------------------------------------------------------------------------------------
# CLI
# --------------------------------------------------------------------------------------------

def _sweep_cli(wave, beta_spec, gamma_list, digits, verify, out):
    digits = check_digits(digits)
    kind, p_text = parse_wave(wave)
    parts = beta_spec.split(":")
    if len(parts) != 3:
        raise ModelError("--beta %r: expected FROM:TO:N" % (beta_spec,))
    from_t, to_t, n_t = parts
    try:
        npts = int(n_t)
    except ValueError:
        raise ModelError("N = %r in --beta is not an integer" % (n_t,))
    if npts < 1:
        raise ModelError("N = %r in --beta must be >= 1" % (n_t,))
    gammas = [g.strip() for g in gamma_list.split(",")]
    if not gammas or any(g == "" for g in gammas):
        raise ModelError("--gamma %r: expected a comma-separated list of numbers" % (gamma_list,))
    with mp.workdps(30):
        wave_param(kind, p_text)
        bf, bt = parse_number(from_t, "beta FROM"), parse_number(to_t, "beta TO")
        if npts == 1 and bf != bt:
            raise ModelError("N = 1 in --beta needs FROM == TO")
        for t, v in ((from_t, bf), (to_t, bt)):
            check_beta_gamma(v, None, repr(t))
        for g in gammas:
            check_beta_gamma(mpf(1), parse_number(g, "gamma"), gamma_text=repr(g))
    # one working precision for the whole sweep: guard for the smallest beta and each gamma
    bmin_t = from_t if bf <= bt else to_t
    guard = max(guard_digits(kind, p_text, bmin_t, g, digits, "mu") for g in gammas)
    dps = digits + guard
    out.write("wave,beta,gamma,mu_over_mu0\n")

    def grid_mu(dps, i, g_t):
        """beta_i = FROM + i (TO - FROM)/(N - 1), all parsed and computed at `dps` digits."""
        with mp.workdps(dps):
            p = wave_param(kind, p_text)
            bf, bt = parse_number(from_t, "beta FROM"), parse_number(to_t, "beta TO")
            beta = bf + i * (bt - bf) / (npts - 1) if npts > 1 else bf
            gamma = parse_number(g_t, "gamma")
            return beta, gamma, mu_value(kind, p, beta, gamma)

    for g_t in gammas:
        for i in range(npts):
            beta, gamma, mu = grid_mu(dps, i, g_t)
            if verify:
                _, _, mu2 = grid_mu(dps + 25, i, g_t)
                with mp.workdps(dps + 25):
                    if not _agree(mu, mu2, digits + 2):
                        raise ModelError("verification failed at beta=%s gamma=%s"
                                         % (mpmath.nstr(beta, 20), g_t))
            with mp.workdps(dps):
                out.write("%s,%s,%s,%s\n" % (wave, mpmath.nstr(beta, digits),
                                             mpmath.nstr(gamma, digits), fmt(mu, digits)))


def main(argv=None):
    ap = argparse.ArgumentParser(description="mpmath reference for mu/mu0 and Psi "
                                             "(see the module docstring)")
    sub = ap.add_subparsers(dest="cmd")
    for name in ("mu", "psi", "sweep", "events"):
        sp = sub.add_parser(name)
        sp.add_argument("--wave", required=True)
        sp.add_argument("--beta", required=True)
        if name != "psi":
            sp.add_argument("--gamma", required=True)
        sp.add_argument("--digits", required=True)
        sp.add_argument("--verify", action="store_true",
                        help="recompute with 25 more guard digits and fail on disagreement")
    args = ap.parse_args(argv)
    if args.cmd is None:
        ap.print_help()
        return 2
    try:
        if args.cmd == "mu":
            v = evaluate("mu", args.wave, args.beta, args.gamma, args.digits, args.verify)
            print(fmt(v, check_digits(args.digits)))
        elif args.cmd == "psi":
            v = evaluate("psi", args.wave, args.beta, None, args.digits, args.verify)
            print(fmt(v, check_digits(args.digits)))
        elif args.cmd == "sweep":
            _sweep_cli(args.wave, args.beta, args.gamma, args.digits, args.verify, sys.stdout)
        else:
            d = check_digits(args.digits)
            evaluate("mu", args.wave, args.beta, args.gamma, d)     # validates input
            kind, p_text = parse_wave(args.wave)
            with mp.workdps(d + guard_digits(kind, p_text, args.beta, args.gamma, d, "mu")):
                r, _ = compute(kind, wave_param(kind, p_text), parse_number(args.beta, "beta"),
                               parse_number(args.gamma, "gamma"))
                print("# stick phases in the paper's phase phi (onset, end); shift = %s"
                      % mpmath.nstr(r.shift, 5))
                for a, b in r.stick_phases:
                    print("%s,%s" % (fmt((a + r.shift) % 1, d), fmt((b + r.shift) % 1, d)))
                print("# int s = %s, int n = %s, Eq. 8 roots: %d numeric, %d closed form, "
                      "%d bisection fallbacks" % (fmt(r.S, d), fmt(r.N, d), r.stats.roots,
                                                   r.stats.closed_form_roots,
                                                   r.stats.bisect_fallbacks))
    except ModelError as e:
        sys.stderr.write("error: %s\n" % e)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
