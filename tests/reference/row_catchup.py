#!/usr/bin/python3
"""Independent catching-up reference for the MDR spring row (curved contacts) under in-plane and
combined oscillation: a direct simulation of every spring of the row, vectorised with numpy.

Model: /work/shared/model.md, sections "Curved contacts (MDR)", "In-plane and combined oscillation"
and "Waveform catalogue".  Written without looking at the C++ library (lib/); it shares no code with
it.  It imports the wave formulas, the contact-onset phase and (in the self-test only) the single
flat-spring reference from planar_catchup.py, and (self-test only, optional) inplane_mpmath.py.

REFERENCE VALUES (sine normal wave, sine in-plane drive; `python3 row_catchup.py ...` defaults:
grid aligned, steps 2^12..2^17, rules of 32 and 64 panels x 8 Gauss nodes = 256 and 512 springs;
run time = wall clock under `nice -n 10` on the shared 2-core machine while a C++ build ran)
| # | profile | beta | gamma | a_l | a_t | P    | mu                | mean_lateral     | error est. | orders (raw -> after) | time |
|---|---------|------|-------|-----|-----|------|-------------------|------------------|------------|-----------------------|------|
| 1 | power:2 | 0.5  | 0.2   | 1   | 0   | 0    | 1 (exact)         | 0                | 1.2e-14    | none: exact at every N | 9.4 s |
| 2 | power:2 | 0.3  | -0.3  | 0.5 | 0   | 0.25 | -0.69511313483    | 0                | 1.0e-10    | 2.15 -> 2 removed     | 8.7 s |
| 3 | power:1 | 0.5  | 0.2   | 1   | 0   | 0    | 1 (exact)         | 0                | 1.2e-14    | none: exact at every N | 9.7 s |
| 4 | power:2 | 0.5  | 0.2   | 0   | 1   | 0    | 0.17947517378     | 0.96655729112    | 4.7e-11 (mu), 5.9e-11 (lat) | 0.99 -> 1, then 1.98 -> 2 | 9.9 s |
| 5 | power:2 | 0.05 | -0.5  | 1   | 0   | 0.25 | -0.98629280016    | 0                | 8.8e-11    | 2.02 -> 2 removed     | 10.0 s |
Unrounded output: 1: 0.9999999999999996; 2: -0.6951131348259403; 3: 1.0000000000000009;
4: 0.17947517377930367, 0.9665572911183606; 5: -0.986292800157936.  mean_lateral is identically 0
when a_t = 0.  "orders": the measured order (median of the last three successive-difference
ratios, as log2) of the raw values, and what was removed (see "Extrapolation in N").  Raw
successive-difference ratios d_{N/2}/d_N for N = 2^14..2^17: case 2: 4.13, 4.69, 3.57, 4.44;
case 4: 1.917, 1.959, 1.979, 1.990 (mean_lateral: order 1.00 then 1.97); case 5: 3.97, 4.36,
3.51, 4.07.  Cases 1 and 3 are exact: with a_l = 1, a_t = 0, P = 0 and p = w the drive minus the
normal force rises at D_x' - n' = beta > 0 throughout contact, so every spring slips forward from
touch-down, s = n and mu = 1 for any profile; the scheme reproduces this at every N (D_x increment
minus n increment = beta/N > 0), the printed deviation from 1 is rounding.
Independent checks of the table: rows of exact per-spring values (inplane_mpmath.py, longitudinal,
at 17 digits, same tau rule, 512 springs): case 2 -0.695113134812 (1.4e-11 from the table's
unrounded value), case 5 -0.986292800160 (2e-12; -0.98629280015992 at 1024 springs); case 4 rerun
with steps 2^13..2^18 (17 s): mu 0.179475173778 +- 4.7e-12, mean_lateral 0.966557291114 +- 1.1e-11
(1.5e-12 and 3.9e-12 from the table); case 4 on a 64-spring rule against a row of planar_catchup
spring values: 1.1e-9 apart (planar_catchup's own per-spring extrapolation error is of that size).
The a = 0 row (power:2, beta 0.5, gamma 0.2, 9.0 s): 0.186360572038 +- 6.7e-11 against the exact-
spring row 0.186360572045006 (7e-12 apart).

What is simulated
-----------------
MDR: the contact is a row of independent springs at positions x (symmetric, so 0 <= x <= X is
enough), each the flat-punch problem of planar_catchup.py with the same beta, the same drive, and a
shifted mean indentation gamma' = gamma - sigma(x), sigma = g/A the 1-D profile in units of A:
    --profile power:n   sigma(x) = x^n   (power:2 sphere/paraboloid, power:1 cone; the constants
                        kappa_n c / A only rescale x, which cancels in the ratio below)
    --profile flat      sigma = 0        (flat punch: every spring has gamma' = gamma)
The contact edge is X with sigma(X) = gamma + max w = gamma + 1 (all catalogue waves have max 1);
springs beyond never touch.  Spring j: normal force n_j(phi) = max(gamma - sigma(x_j) + w(phi), 0),
tangential force s_j in the plane (complex s = s_x + i s_y), common drive
D(phi) = (beta phi + a_l p(phi + P), a_t p(phi + P)).  Catching-up step for all springs at once:
    s_j <- proj_{|s| <= n_j(phi_{k+1})}( s_j + D(phi_{k+1}) - D(phi_k) ),
    proj(z) = z min(1, n/|z|)   (real clamp to [-n, n] when a_t = 0).
The increments are formed as beta/N + a (p(phi_{k+1}+P) - p(phi_k+P)) (no cancellation of the
secular part).  Whole periods are iterated until every spring's state repeats (|s_end - s_start|
< 1e-13, at most 2000 periods); then, with weights wt_j of the x-rule,
    mu           = sum_j wt_j sum_k s_x,jk / sum_j wt_j sum_k n_jk,
    mean_lateral = sum_j wt_j sum_k s_y,jk / sum_j wt_j sum_k n_jk,
(the sums over k are the trapezoid rule over the period for periodic node values, as in
planar_catchup.py; the same rule for numerator and denominator).

Time grid: per-spring aligned grids (the default, --grid aligned)
-----------------------------------------------------------------
Springs are independent (quasi-static row: the body does not feed back), so each spring may be
stepped on its own grid phi_jk = phi_c,j + k/N, phi_c,j the spring's first-contact phase
(planar_catchup.contact_onset(w, gamma'_j)); the drive is the same function D(phi), sampled on each
spring's grid.  This is planar_catchup's alignment trick done for all springs at once (2-D arrays,
one column a spring): the first contact, where a stick phase may start, is a node of every spring's
grid at every N.  Starting there from s = 0, the first period is already the periodic state for
every spring with flight (s = 0 at its own first contact); the iteration confirms it.
--grid common puts every spring on phi_k = k/N.  Then each spring's first contact is off the grid
by a fraction frac(N phi_c,j) that changes with N: an O(1/N) error with a jittering coefficient.
Averaging over the springs does NOT remove the O(1/N) term, and leaves a jittering coefficient.
Measured with the default rules (256/512 springs), raw ratios d_{N/2}/d_N for N = 2^14..2^17 and
the error of the finest raw value (against the aligned/exact values): case 2: 2.39, 1.98, 2.12,
2.15, error 5.0e-6; case 5: 2.28, 1.92, 2.29, 1.77, error 2.9e-6; a = 0 (power:2, beta 0.5,
gamma 0.2): 2.03, 2.07, 2.30, 1.73, error 2.8e-6.  So the common grid is order 1, and its order-1
Richardson value is only good to 3e-7 (case 5), 5e-7 (case 2), 3e-8 (a = 0), within its printed
estimate (1.5e-6, 1.8e-6, 7.7e-7) but 4 orders of magnitude worse than the aligned grid at the
same cost; that is why aligned is the default.  (The transverse case 4 slips from touch-down, so
both grids agree there to 1e-11.)

Orders measured on the aligned grid (see the table): with a_t = 0 (1-D stop operator) the step
is the stop operator applied to the node values, so with smooth w and p the only errors come from
events between nodes (stick onsets at tangencies, stick and contact ends off the grid): O(1/N^2),
with a coefficient that jitters a little with the grid position, so successive-difference ratios
are 3.5..5 instead of 4 (case 2 against the exact-spring row on 64 springs, N = 2^10..2^20: errors
1.4e-6, 4.0e-7, 9.7e-8, 2.9e-8, 5.5e-9, 1.4e-9, 2.6e-10, 1.0e-10, 2.8e-11, 7.7e-12, 2.2e-12).  With
a_t != 0 the projection onto the disc turns s along a chord instead of an arc: a clean O(1/N) term
(ratios 1.9..1.99 -> 2), and after removing it O(1/N^2).  Jumps of n or of the drive that are not
at first contact (sawtooth-right normal wave; square or sawtooth drives) stay off the grid and leave
an O(1/N) jitter: the error estimate then shows it (and such cases are not in the table).
Not in the table either, and less accurate: gamma >= 1 (springs near the centre never lose
contact; their grid starts at 0 and the periodic state takes many periods).  One trial (power:2,
beta 1, gamma 1.5, a_l 0.7, a_t 0.4, P 0.1, 64/128 springs, 2^12..2^16, 35 s, 19 periods):
mu 0.68988151 +- 5.5e-7, mean_lateral 0.17333472 +- 2.6e-7, measured orders 1.00 then 0.94, i.e.
a second O(1/N)-like term that was not traced; trust such cases only to the printed estimate.

Extrapolation in N (extrapolate_steps())
----------------------------------------
Values m_i at N_i = N0 2^i (default N0 = 2^12, 6 levels to 2^17).  Stage by stage: the measured
order p is the median of log2((m_{i+1} - m_i) / (m_{i+2} - m_{i+1})) over the last three
consecutive pairs of the current sequence (a single pair is too noisy when the O(1/N^2) coefficient
jitters: with 16 springs one pair gave 1.2 where the order is 2); the integer order removed is 1 if
p < 1.5 (and order 1 not yet removed), else 2;
the sequence is replaced by its Richardson values m_{i+1} + (m_{i+1} - m_i)/(2^q - 1).  At most two
stages (orders 1 then 2, or 2 alone); extrapolation stops when the last difference is at rounding
level (1e-14), when most of those ratios are negative or p < 0.5 (jitter-dominated: the current
sequence, e.g. the raw values, is kept).
The N error estimate is max(|F_{-1} - F_{-2}|, |F_{-2} - F_{-3}|/2) over the final sequence F (how
much the extrapolated value still moves between the last level pairs), plus 1e-14.

Quadrature in x (rule())
------------------------
The spring value Phi(gamma') = int s dphi behaves like (1 + gamma')^(3/2) at the contact edge for
the sine (the contact cap is quadratic; the series goes on in half-integer powers), so in x it has
a sqrt-type singularity of its derivative at x = X.  With
    x = X (1 - tau^2),  tau in [0, 1],  dx = 2 X tau dtau,
1 + gamma' = sigma(X) - sigma(x) is tau^2 times a smooth positive function and every half-integer
power becomes an odd power of tau: the integrand is smooth in tau at the edge (and at the centre,
where x^2 or x itself is smooth).  tau in [0, 1] is cut at the breakpoints gamma'_b known in closed
form (gamma' = 1, where flight starts; for a_l = a_t = 0 and the sine gamma' = +-sqrt(1 -
(beta/2pi)^2), where beta crosses beta_c(gamma'); square: gamma' = beta/2 - 1), each piece into
uniform panels (about `panels` per unit tau), and each panel gets an m-point Gauss-Legendre rule
(default m = 8).  Breakpoints that appear only with in-plane drive (e.g. where a pure backward-slip
contact first sticks: gamma' ~ -0.912 in case 2, ~ -0.713 in case 5, a jump of Phi''' in tau) are
not located; they limit the rule to an algebraic rate, which the M comparison measures.
Convergence in the number of springs: the rules with `panels` and 2 `panels` panels are run in
the SAME batch (same N levels), each extrapolated in N; the reported value is the finer rule's, and
    error_estimate = (N error of the finer rule) + |mu(2 panels) - mu(panels)|.
Measured with rows of exact per-spring values (inplane_mpmath.py, a_t = 0, same tau rule; this
isolates the x error): case 2 -0.695113134814048 / -0.695113134812142 at 256 / 512 springs; case
5 -0.986292800451 (128) / -0.986292800159736 (256) / -0.986292800160103 (512) / ...159923 (1024),
i.e. about 3e-10 at 128 springs and a few 1e-13 from 256 on (the unlocated kink); a = 0 with the
breakpoints located: 0.186360572045006 at 128, 256 and 512 springs alike (spectral).  So the M
term of error_estimate (1e-11 in case 5) is mostly the two rules' different O(1/N^2) jitter, not
x error.

CLI
---
  row_catchup.py --profile power:2 --beta B --gamma G --longitudinal A --transverse A --phase P
                 [--wave sine] [--in-plane-wave sine] [--grid aligned|common] [--base-steps N0]
                 [--levels L] [--panels K] [--nodes m]
prints JSON {mu, mean_lateral, error_estimate (for mu), mean_lateral_error_estimate, steps (the
N levels), springs (springs of the finer rule), ...details: measured orders, per-level values,
run time}.
  row_catchup.py --selftest [--quick]      runs the self-checks, prints "N passed, M failed"
                                           (13 checks, 24 s; --quick 9 checks, 8 s; exit 1 on failure).
Bad input (gamma <= -1, beta < 0, non-finite numbers, unknown profile or wave) gives a message on
stderr and exit status 2.

Self-test (selftest())
----------------------
(1) a_l = a_t = 0 (the paper's model, lower envelope): on a small rule (16-20 springs) the row
    machinery equals the row integral of planar_catchup's flat-spring values at the same gamma'
    (combined with the exact N_w), power:2 and power:1; (1b) the same with a transverse and with a
    longitudinal drive.  Measured differences 1e-10 .. 2e-9.
(2) --profile flat (sigma = 0) equals planar_catchup's single flat spring (4 cases, longitudinal,
    transverse, combined, no flight): 1e-10 .. 7e-10.
(3) a_l = 1, P = 0: mu = 1 to rounding.
(4) rows of exact per-spring values from inplane_mpmath.py (longitudinal), if importable: 5e-11,
    2e-10.
(5) the rules of 64 and 128 springs agree (transverse): 1e-10.
(6) bad input is refused.
"""

import argparse
import json
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import planar_catchup as pc  # noqa: E402

WAVES = pc.WAVES
TOL_PERIODIC = 1e-13
MAX_PERIODS = 2000
ROUND = 1e-14


# ------------------------------------------------------------------------------------------
# Profiles and the x-rule
# ------------------------------------------------------------------------------------------

def parse_profile(profile):
    """'flat' -> None; 'power:n' -> n (float > 0)."""
    if profile == 'flat':
        return None
    if isinstance(profile, str) and profile.startswith('power:'):
        try:
            n = float(profile[6:])
        except ValueError:
            n = float('nan')
        if math.isfinite(n) and n > 0.0:
            return n
    raise ValueError('profile %r: expected power:n with n > 0, or flat' % (profile,))


def normal_mean(wave, g):
    """N_w(gamma') = int_0^1 max(gamma' + w, 0) dphi, closed form (catalogue waves)."""
    if g >= 1.0:
        return g
    if g <= -1.0:
        return 0.0
    if wave == 'sine':
        return (math.sqrt(1.0 - g * g) + g * (0.5 * math.pi + math.asin(g))) / math.pi
    if wave in ('triangle', 'sawtooth-right', 'sawtooth-left'):
        return 0.25 * (1.0 + g) ** 2          # w uniformly distributed on [-1, 1]
    if wave == 'square':
        return 0.5 * (1.0 + g)
    raise ValueError('unknown wave %r' % (wave,))


def known_breaks(wave, beta, a_l, a_t):
    """Breakpoints in gamma' of the spring value known in closed form (see the docstring)."""
    out = [1.0]
    if a_l == 0.0 and a_t == 0.0:
        if wave == 'sine' and beta < 2.0 * math.pi:
            g = math.sqrt(1.0 - (beta / (2.0 * math.pi)) ** 2)
            out += [-g, g]
        if wave == 'square':
            out.append(beta / 2.0 - 1.0)
    return out


def rule(profile, gamma, panels, m, breaks=()):
    """The springs: positions x_j, weights wt_j (in x), gamma'_j.  See the docstring."""
    n = parse_profile(profile)
    if n is None:                     # flat punch: every spring is the same
        x = np.linspace(0.0, 1.0, m + 2)[1:-1]
        return x, np.full(m, 1.0 / m), np.full(m, float(gamma))
    X = (gamma + 1.0) ** (1.0 / n)
    cuts = {0.0, 1.0}
    for gb in breaks:
        sg = gamma - gb                 # sigma(x_b)
        if 0.0 < sg < gamma + 1.0:
            t = math.sqrt(1.0 - sg ** (1.0 / n) / X)
            if 1e-12 < t < 1.0 - 1e-12:
                cuts.add(t)
    cuts = sorted(cuts)
    tg, wg = np.polynomial.legendre.leggauss(m)
    xs, ws = [], []
    for a, b in zip(cuts[:-1], cuts[1:]):
        k = max(1, int(round(panels * (b - a))))
        edges = np.linspace(a, b, k + 1)
        for c, d in zip(edges[:-1], edges[1:]):
            tau = 0.5 * (c + d) + 0.5 * (d - c) * tg
            xs.append(X * (1.0 - tau * tau))
            ws.append(0.5 * (d - c) * wg * 2.0 * X * tau)
    x = np.concatenate(xs)
    wt = np.concatenate(ws)
    return x, wt, gamma - x ** n


# ------------------------------------------------------------------------------------------
# The vectorised catching-up scheme
# ------------------------------------------------------------------------------------------

def simulate(gp, wave, beta, a_l, a_t, phase, N, grid='aligned', in_plane='sine', chunk=2048):
    """All springs gamma'_j at once, N steps a period.  Returns per-spring node means over the
    periodic period: (mean s_x, mean s_y, mean n) as arrays, and the number of periods run."""
    gp = np.asarray(gp, dtype=float)
    M = gp.size
    if grid == 'aligned':
        start = np.array([pc.contact_onset(wave, float(g)) for g in gp])
    elif grid == 'common':
        start = np.zeros(M)
    else:
        raise ValueError('grid %r: aligned or common' % (grid,))
    planar = a_t != 0.0
    s = np.zeros(M, dtype=complex if planar else float)
    z = np.empty(M, dtype=complex)
    a = np.empty(M)
    f = np.empty(M)
    periods = 0
    while True:
        periods += 1
        s_start = s.copy()
        acc = np.zeros_like(s)
        nsum = np.zeros(M)
        for c0 in range(0, N, chunk):
            L = min(chunk, N - c0)
            k = np.arange(c0, c0 + L + 1, dtype=float)[:, None]
            phi = start[None, :] + k / N
            dp = np.diff(pc.wave(in_plane, phi + phase), axis=0)
            nn = np.maximum(gp[None, :] + pc.wave(wave, phi[1:]), 0.0)
            nsum += nn.sum(axis=0)
            if planar:
                dz = (beta / N + a_l * dp) + 1j * (a_t * dp)
                for d, r in zip(dz, nn):
                    np.add(s, d, out=z)
                    np.abs(z, out=a)
                    a += 1e-300                      # z = 0 (with n = 0) stays 0, no 0/0
                    np.divide(r, a, out=f)
                    np.minimum(f, 1.0, out=f)
                    np.multiply(z, f, out=s)
                    acc += s
            else:
                dz = beta / N + a_l * dp
                for d, r in zip(dz, nn):
                    s += d
                    np.minimum(s, r, out=s)
                    np.maximum(s, -r, out=s)
                    acc += s
        if np.max(np.abs(s - s_start)) < TOL_PERIODIC:
            break
        if periods >= MAX_PERIODS:
            raise RuntimeError('no periodic state reached after %d periods (largest |s_end - '
                               's_start| = %.3g)' % (MAX_PERIODS, np.max(np.abs(s - s_start))))
    sx = acc.real / N
    sy = acc.imag / N if planar else np.zeros(M)
    return sx, sy, nsum / N, periods


# ------------------------------------------------------------------------------------------
# Extrapolation in N
# ------------------------------------------------------------------------------------------

def extrapolate_steps(vals):
    """Values at N0 2^i, i = 0..L-1 (L >= 3).  See the docstring.  Returns a dict."""
    seq = [float(v) for v in vals]
    measured, removed = [], []
    for _stage in range(2):
        if len(seq) < 3:
            break
        scale = max(1.0, abs(seq[-1]))
        d = [seq[i + 1] - seq[i] for i in range(len(seq) - 1)]
        if abs(d[-1]) <= ROUND * scale:
            measured.append(None)                 # converged to rounding
            break
        ratios = [d[i] / d[i + 1] for i in range(len(d) - 1) if d[i + 1] != 0.0][-3:]
        ps = sorted(math.log2(r) for r in ratios if r > 0.0)
        if 2 * len(ps) <= len(ratios):            # mostly sign changes: jitter-dominated
            measured.append(None)
            break
        p = ps[len(ps) // 2] if len(ps) % 2 else 0.5 * (ps[len(ps) // 2 - 1] + ps[len(ps) // 2])
        measured.append(p)
        if p < 0.5:                               # not converging at a usable rate: stop here
            break
        q = 1 if (p < 1.5 and 1 not in removed) else 2
        if q in removed:
            break
        removed.append(q)
        c = 2.0 ** q - 1.0
        seq = [seq[i + 1] + (seq[i + 1] - seq[i]) / c for i in range(len(seq) - 1)]
        if q == 2:
            break
    F = seq
    err = ROUND * max(1.0, abs(F[-1]))
    if len(F) >= 2:
        err += abs(F[-1] - F[-2])
    if len(F) >= 3:
        err = max(err, abs(F[-2] - F[-3]) / 2.0 + ROUND)
    raw = [float(v) for v in vals]
    ratios = [None if raw[i + 2] == raw[i + 1] else (raw[i + 1] - raw[i]) / (raw[i + 2] - raw[i + 1])
              for i in range(len(raw) - 2)]
    return {'value': F[-1], 'error': err, 'measured_orders': measured, 'orders_removed': removed,
            'raw_ratios': ratios, 'raw': raw}


# ------------------------------------------------------------------------------------------
# The row
# ------------------------------------------------------------------------------------------

def _check(profile, wave, in_plane, gamma, beta, a_l, a_t, phase, grid):
    for name, v in (('gamma', gamma), ('beta', beta), ('longitudinal', a_l), ('transverse', a_t),
                    ('phase', phase)):
        if not math.isfinite(v):
            raise ValueError('%s = %r is not a finite number' % (name, v))
    parse_profile(profile)
    if wave not in WAVES:
        raise ValueError('unknown wave %r (expected one of %s)' % (wave, ', '.join(WAVES)))
    if in_plane not in WAVES:
        raise ValueError('unknown in-plane wave %r' % (in_plane,))
    if gamma <= -1.0:
        raise ValueError('gamma = %r: no contact (need gamma > -1)' % (gamma,))
    if beta < 0.0:
        raise ValueError('beta = %r: need beta >= 0' % (beta,))
    if beta == 0.0 and gamma >= 1.0:
        raise ValueError('beta = 0 with gamma >= 1: springs without flight may have no unique '
                         'periodic state')
    if grid not in ('aligned', 'common'):
        raise ValueError('grid %r: aligned or common' % (grid,))


def row(profile, beta, gamma, a_l=0.0, a_t=0.0, phase=0.0, wave='sine', in_plane='sine',
        grid='aligned', base_steps=1 << 12, levels=6, panels=32, nodes=8, breaks=None):
    """The row value with its error estimate (see the docstring).  Returns a dict."""
    beta, gamma, a_l, a_t, phase = map(float, (beta, gamma, a_l, a_t, phase))
    _check(profile, wave, in_plane, gamma, beta, a_l, a_t, phase, grid)
    if levels < 3:
        raise ValueError('levels = %r: need >= 3' % (levels,))
    t0 = time.time()
    if breaks is None:
        breaks = known_breaks(wave, beta, a_l, a_t)
    rules = []
    for K in (panels, 2 * panels):
        x, wt, gp = rule(profile, gamma, K, nodes, breaks)
        keep = gp > -1.0                       # springs that touch (all, by construction)
        rules.append((K, x[keep], wt[keep], gp[keep]))
    allgp = np.concatenate([r[3] for r in rules])
    per_rule = [{'mu': [], 'lat': []} for _ in rules]
    steps, periods = [], []
    for i in range(levels):
        N = base_steps << i
        sx, sy, ns, per = simulate(allgp, wave, beta, a_l, a_t, phase, N, grid, in_plane)
        steps.append(N)
        periods.append(per)
        j = 0
        for r, out in zip(rules, per_rule):
            wt = r[2]
            sl = slice(j, j + wt.size)
            j += wt.size
            den = float(wt @ ns[sl])
            out['mu'].append(float(wt @ sx[sl]) / den)
            out['lat'].append(float(wt @ sy[sl]) / den)
    ex = [{'mu': extrapolate_steps(o['mu']), 'lat': extrapolate_steps(o['lat'])} for o in per_rule]
    coarse, fine = ex
    mu = fine['mu']['value']
    lat = fine['lat']['value']
    err_mu = fine['mu']['error'] + abs(fine['mu']['value'] - coarse['mu']['value'])
    err_lat = fine['lat']['error'] + abs(fine['lat']['value'] - coarse['lat']['value'])
    return {
        'input': {'profile': profile, 'wave': wave, 'in_plane_wave': in_plane, 'beta': beta,
                  'gamma': gamma, 'longitudinal': a_l, 'transverse': a_t, 'phase': phase},
        'mu': mu, 'mean_lateral': lat,
        'error_estimate': err_mu, 'mean_lateral_error_estimate': err_lat,
        'steps': steps, 'springs': int(rules[1][2].size),
        'springs_coarse_rule': int(rules[0][2].size),
        'grid': grid,
        'mu_N_error': fine['mu']['error'],
        'mu_M_change': abs(fine['mu']['value'] - coarse['mu']['value']),
        'mu_measured_orders': fine['mu']['measured_orders'],
        'mu_orders_removed': fine['mu']['orders_removed'],
        'mu_raw_ratios': fine['mu']['raw_ratios'],
        'mean_lateral_measured_orders': fine['lat']['measured_orders'],
        'mean_lateral_orders_removed': fine['lat']['orders_removed'],
        'mu_per_level': fine['mu']['raw'],
        'mean_lateral_per_level': fine['lat']['raw'],
        'mu_coarse_rule': coarse['mu']['value'],
        'periods': periods,
        'breaks_gamma_prime': sorted(breaks),
        'seconds': round(time.time() - t0, 2),
    }


# ------------------------------------------------------------------------------------------
# Self-test
# ------------------------------------------------------------------------------------------

def selftest(quick=False):
    results = []

    def check(name, ok, detail):
        results.append(ok)
        print('%s  %s: %s' % ('PASS' if ok else 'FAIL', name, detail), flush=True)

    # (1) a_l = a_t = 0: the row is the x-integral of the paper's flat-spring values.  The same
    # springs (a small rule) are evaluated one by one with planar_catchup.extrapolate (a = 0: the
    # lower envelope, the paper's model), combined with the exact N_w, and compared with the row
    # machinery on that rule.  (1b) the same with an in-plane drive (transverse; longitudinal).
    spring_cases = [('power:2', 0.5, 0.2, 0.0, 0.0, 0.0), ('power:2', 0.5, 0.2, 0.0, 1.0, 0.0)]
    if not quick:
        spring_cases += [('power:1', 1.3, -0.4, 0.0, 0.0, 0.0), ('power:1', 0.3, -0.3, 0.5, 0.0, 0.25)]
    for prof, beta, gamma, al, at, P in spring_cases:
        x, wt, gp = rule(prof, gamma, 4, 4, known_breaks('sine', beta, al, at))
        px, py, nws = [], [], []
        for g in gp:
            r = pc.extrapolate('sine', float(g), 'sine', beta, al, at, P)
            nw = normal_mean('sine', float(g))
            px.append(r['mu'] * nw)
            py.append(r['mean_lateral'] * nw)
            nws.append(nw)
        den = float(wt @ np.array(nws))
        ref = (float(wt @ np.array(px)) / den, float(wt @ np.array(py)) / den)
        vx, vy = [], []
        for i in range(5):
            sx, sy, ns, _ = simulate(gp, 'sine', beta, al, at, P, (1 << 12) << i)
            vx.append(float(wt @ sx) / float(wt @ ns))
            vy.append(float(wt @ sy) / float(wt @ ns))
        ex, ey = extrapolate_steps(vx), extrapolate_steps(vy)
        dev = max(abs(ex['value'] - ref[0]), abs(ey['value'] - ref[1]))
        check('row = row of planar_catchup spring values (%s, beta=%g, gamma=%g, a_l=%g, a_t=%g, '
              'P=%g, %d springs)' % (prof, beta, gamma, al, at, P, gp.size),
              dev < 1e-8 + ex['error'] + ey['error'],
              'row (%.12f, %.12f), planar_catchup row (%.12f, %.12f), |diff| %.2e '
              '(row N error %.1e)' % (ex['value'], ey['value'], ref[0], ref[1], dev,
                                      ex['error'] + ey['error']))

    # (2) flat profile (sigma = 0): the row equals planar_catchup's single flat spring.
    flat_cases = [(0.3, 0.5, 1.0, 0.0, 0.25), (0.5, 0.2, 0.0, 1.0, 0.0), (0.05, -0.5, 1.0, 0.0, 0.25)]
    if not quick:
        flat_cases.append((1.0, 1.5, 0.7, 0.4, 0.1))
    for beta, gamma, al, at, P in flat_cases:
        r = row('flat', beta, gamma, al, at, P, panels=1, nodes=4, levels=5)
        p = pc.extrapolate('sine', gamma, 'sine', beta, al, at, P)
        dev = max(abs(r['mu'] - p['mu']), abs(r['mean_lateral'] - p['mean_lateral']))
        tol = 1e-9 + r['error_estimate'] + r['mean_lateral_error_estimate'] + p['mu_error'] + \
            p['mean_lateral_error']
        check('flat row = planar_catchup (beta=%g gamma=%g a_l=%g a_t=%g P=%g)'
              % (beta, gamma, al, at, P), dev < tol,
              'row (%.12f, %.12f), planar_catchup (%.12f, %.12f), |diff| %.2e (tol %.1e)'
              % (r['mu'], r['mean_lateral'], p['mu'], p['mean_lateral'], dev, tol))

    # (3) exactness: a_l = 1, a_t = 0, P = 0, p = w: D_x' - n' = beta > 0 in contact, so every
    # spring slips forward from touch-down (s = n) and mu = 1 exactly, also in the discrete scheme.
    r = row('power:2', 0.5, 0.2, 1.0, 0.0, 0.0, levels=3, base_steps=1 << 10, panels=4, nodes=4)
    check('a_l = 1, P = 0: mu = 1 exactly', abs(r['mu'] - 1.0) < 1e-13, 'mu - 1 = %.2e' % (r['mu'] - 1.0))

    # (4) springs: the per-spring catching-up values against exact ones (inplane_mpmath.py,
    # longitudinal only), on the same x-rule: separates the x-quadrature from the time stepping.
    try:
        import inplane_mpmath as im
    except ImportError:
        im = None
    if im is None:
        print('skip  inplane_mpmath.py not importable', flush=True)
    else:
        for prof, beta, gamma, al, P in ((('power:2', 0.3, -0.3, 0.5, 0.25),) if quick else
                                         (('power:2', 0.3, -0.3, 0.5, 0.25),
                                          ('power:1', 0.05, -0.5, 1.0, 0.25))):
            x, wt, gp = rule(prof, gamma, 4, 4, known_breaks('sine', beta, al, 0.0))
            phis = np.array([float(im.evaluate('sine', repr(beta), repr(float(g)), repr(al),
                                               repr(P), digits=17).mu) for g in gp])
            nw = np.array([normal_mean('sine', float(g)) for g in gp])
            ref = float(wt @ (phis * nw)) / float(wt @ nw)
            vals = []
            for i in range(6):
                sx, sy, ns, _ = simulate(gp, 'sine', beta, al, 0.0, P, (1 << 12) << i)
                vals.append(float(wt @ sx) / float(wt @ ns))
            e = extrapolate_steps(vals)
            dev = abs(e['value'] - ref)
            check('row of exact longitudinal spring values (%s beta=%g gamma=%g a_l=%g P=%g)'
                  % (prof, beta, gamma, al, P), dev < 1e-9 + e['error'],
                  'catching-up %.12f, exact-spring row %.12f, |diff| %.2e (N error est. %.1e)'
                  % (e['value'], ref, dev, e['error']))

    # (5) convergence in the springs: two rules in one batch must agree within the estimate.
    r = row('power:2', 0.5, 0.2, 0.0, 1.0, 0.0, levels=4, base_steps=1 << 12, panels=8, nodes=8)
    check('transverse row: rules of %d and %d springs agree' % (r['springs_coarse_rule'],
                                                               r['springs']),
          r['mu_M_change'] < 1e-7, 'change %.2e, N error %.1e, orders %s'
          % (r['mu_M_change'], r['mu_N_error'], r['mu_measured_orders']))

    # (6) bad input is refused.
    bad = 0
    for args in ((('power:2', 0.5, -1.0),), (('power:0', 0.5, 0.2),), (('power:2', float('nan'), 0.2),),
                 (('cylinder', 0.5, 0.2),)):
        try:
            row(*args[0], levels=3, base_steps=64, panels=1, nodes=2)
        except ValueError:
            bad += 1
    check('bad input refused', bad == 4, '%d of 4 refused' % bad)

    npass = sum(results)
    nfail = len(results) - npass
    print('%d passed, %d failed' % (npass, nfail))
    return nfail == 0


def main(argv=None):
    ap = argparse.ArgumentParser(description='Catching-up reference for the MDR spring row under '
                                             'in-plane + normal oscillation; prints JSON.')
    ap.add_argument('--selftest', action='store_true')
    ap.add_argument('--quick', action='store_true', help='with --selftest: fewer cases')
    ap.add_argument('--profile', default='power:2')
    ap.add_argument('--wave', default='sine', help='normal wave (%s)' % ', '.join(WAVES))
    ap.add_argument('--in-plane-wave', default='sine')
    ap.add_argument('--beta', type=float)
    ap.add_argument('--gamma', type=float)
    ap.add_argument('--longitudinal', type=float, default=0.0)
    ap.add_argument('--transverse', type=float, default=0.0)
    ap.add_argument('--phase', type=float, default=0.0)
    ap.add_argument('--grid', default='aligned', choices=('aligned', 'common'))
    ap.add_argument('--base-steps', type=int, default=1 << 12)
    ap.add_argument('--levels', type=int, default=6)
    ap.add_argument('--panels', type=int, default=32)
    ap.add_argument('--nodes', type=int, default=8)
    a = ap.parse_args(argv)
    if a.selftest:
        return 0 if selftest(a.quick) else 1
    if a.beta is None or a.gamma is None:
        print('error: --beta and --gamma are required', file=sys.stderr)
        return 2
    try:
        res = row(a.profile, a.beta, a.gamma, a.longitudinal, a.transverse, a.phase, a.wave,
                  a.in_plane_wave, a.grid, a.base_steps, a.levels, a.panels, a.nodes)
    except (ValueError, RuntimeError) as e:
        print('error: %s' % e, file=sys.stderr)
        return 2
    print(json.dumps(res, indent=2))
    return 0


if __name__ == '__main__':
    sys.exit(main())
