#!/usr/bin/python3
"""Independent catching-up reference for in-plane and combined oscillation (planar friction).

Model: /work/shared/model.md, sections "In-plane and combined oscillation" and "Waveform catalogue".
Written without looking at the C++ library (lib/); it shares no code with it.

Phase phi (unit period).  Normal force n(phi) = max(gamma + w(phi), 0) for a catalogue wave w, or
n = 1 ("constant").  Drive D(phi) = (beta*phi + a_l p(phi + P), a_t p(phi + P)).  The tangential
force s in R^2 follows Moreau's sweeping process in the disc |s| <= n(phi), discretised by the
catching-up scheme on the uniform grid phi_k = k/N:

    s_{k+1} = proj_{disc n(phi_{k+1})}( s_k + D(phi_{k+1}) - D(phi_k) ),
    proj(x) = x * min(1, n/|x|)         (so s = 0 where n = 0).

Implementation notes
- The increments D(phi_{k+1}) - D(phi_k) are formed as beta/N + a (p(phi_{k+1}+P) - p(phi_k+P)), so the
  large secular part beta*phi never enters a cancellation; they are computed once per N with numpy
  and re-used for every period, so the period map is the same floating-point map every time.
- Waves are evaluated with phi reduced to [0, 1) (right-continuous at their jumps, as in the
  catalogue).  The node phi_N = 1 uses n(0).
- The inner loop is a plain Python loop over complex numbers (s = s_x + i s_y): about 0.15 us a step.

Periodic state: whole periods are iterated from s = 0 until |s_N - s_0| < 1e-13 (at most 2000
periods, else RuntimeError("no periodic state reached ...")).  All outputs come from the last period.

Quadrature (the choice): the trapezoid rule on the nodes phi_0..phi_N.  For periodic node values it
equals the node mean (1/N) sum_{k=1..N} s_k, which is what the scheme produces (s_k is the
state at node k, already projected onto the disc of node k).  The same rule is applied to n, so
mu = sum_k s_x,k / sum_k n_k and mean_lateral = sum_k s_y,k / sum_k n_k.

Fractions: step k -> k+1 is "flight" if n(phi_{k+1}) = 0, else "slip" if the projection was active
(|s_k + dD| > n(phi_{k+1})), else "stick".  Each fraction is (number of steps)/N.

Extrapolation (extrapolate()): the scheme is run at N, 2N, 4N, 8N steps a period (default
N = 2^14), on a grid that starts at the first contact phi_c (contact_onset(); 0 without flight), so
that phi_c is a node at every N.  (On the grid phi_k = k/N a stick phase that starts at first
contact is started at the last flight node instead: an O(1/N) error whose coefficient depends on
frac(N phi_c) and jumps between N and 2N, which defeats any Richardson rule; e.g. the ratchet case
then shows "orders" of 2.4 and errors of 1e-5 instead of a clean order 2 and 1e-10.)  With
m1, m2, m3 the values at the three finest N, the measured order is
    p = log2(|m2 - m1| / |m3 - m2|)
and the Richardson-extrapolated value, with that measured order, is
    x = m3 + (m3 - m2) / (2^p - 1)          (the Aitken delta^2 value).
The error estimate is the largest of
    |x - x_prev|      (x_prev: the same extrapolation from the three coarser values N..4N),
    |x - r1|          (r1 = 2 m3 - m2: Richardson with the theoretical order 1),
i.e. it measures both how stable the extrapolation is under refinement and how much it depends on
the assumed order.  When the differences are at rounding level (|m3 - m2| < 1e-14) the finest value
is returned, p is reported as None and the error is |m3 - m2| + 1e-14.  If the measured order is
outside [0.5, 3] (noisy differences), order 1 is used for x (stated in the output as "order_used");
if the last two differences have opposite signs, p is None and order 1 is used.
The fractions are not extrapolated (they are integer counts / N and jitter at O(1/N)): the
finest-N fractions are reported with the change from the previous N as their error estimate.
Limits of the estimate: other breakpoints off the grid (jumps of n other than at first contact,
e.g. sawtooth-right's drop at 0 when the grid is aligned elsewhere; jumps of a square or sawtooth
drive at a non-dyadic phase P) leave an O(1/N) jitter.  The four levels usually expose it (the
measured order is then missing or far from 1 and the error estimate is ~|m3 - m2|), but a jitter
that happens to repeat with period 2 in log2 N could be underestimated; trust such cases only to
the size of the last differences shown in "runs".

CLI:
  planar_catchup.py --normal sine|triangle|sawtooth-right|sawtooth-left|square|constant --gamma G
                    --in-plane-wave sine --beta B --longitudinal A --transverse A --phase P
                    [--steps N] [--levels L] [--single] [--no-align]
prints JSON (the extrapolate() result; with --single only evaluate() at N steps).
"""

import argparse
import json
import math
import sys

import numpy as np

WAVES = ("sine", "triangle", "sawtooth-right", "sawtooth-left", "square")
NORMALS = WAVES + ("constant",)
TOL_PERIODIC = 1e-13
MAX_PERIODS = 2000


def wave(name, phi):
    """Catalogue wave on a numpy array of phases (reduced to [0, 1))."""
    x = np.mod(np.asarray(phi, dtype=float), 1.0)
    if name == "sine":
        return np.sin(2.0 * math.pi * x)
    if name == "triangle":
        return np.where(x < 0.5, 4.0 * x - 1.0, 3.0 - 4.0 * x)
    if name == "sawtooth-right":
        return 2.0 * x - 1.0
    if name == "sawtooth-left":
        return 1.0 - 2.0 * x
    if name == "square":
        return np.where(x < 0.5, 1.0, -1.0)
    raise ValueError("unknown wave %r (expected one of %s)" % (name, ", ".join(WAVES)))


def normal_force(normal, gamma, phi):
    phi = np.asarray(phi, dtype=float)
    if normal == "constant":
        return np.ones_like(phi)
    if normal not in WAVES:
        raise ValueError("unknown normal wave %r (expected one of %s)" % (normal, ", ".join(NORMALS)))
    return np.maximum(gamma + wave(normal, phi), 0.0)


def _check(normal, gamma, in_plane, beta, a_l, a_t, phase, steps):
    for name, v in (("gamma", gamma), ("beta", beta), ("a_l", a_l), ("a_t", a_t), ("phase", phase)):
        if not math.isfinite(v):
            raise ValueError("%s = %r is not a finite number" % (name, v))
    if normal not in NORMALS:
        raise ValueError("unknown normal wave %r" % (normal,))
    if in_plane not in WAVES:
        raise ValueError("unknown in-plane wave %r" % (in_plane,))
    if normal != "constant" and gamma <= -1.0:
        raise ValueError("gamma = %r: no contact (need gamma > -1)" % (gamma,))
    if int(steps) != steps or steps < 8:
        raise ValueError("steps = %r: need an integer >= 8" % (steps,))


def _period(s, dz, nn, record=False):
    """One period of the catching-up map.  Returns (s_end, sum of s_k, slip count)."""
    acc = 0j
    nproj = 0
    if not record:
        for d, r in zip(dz, nn):
            z = s + d
            a = abs(z)
            if a > r:
                z *= r / a
            s = z
            acc += z
        return s, acc, 0
    for d, r in zip(dz, nn):
        z = s + d
        a = abs(z)
        if a > r:
            z *= r / a
            if r > 0.0:
                nproj += 1
        s = z
        acc += z
    return s, acc, nproj


def contact_onset(normal, gamma):
    """Phase in [0, 1) where the clipped normal force leaves zero (first contact), or 0.0 when
    there is no flight (constant normal, gamma >= 1) or contact starts at a jump at phi = 0."""
    if normal == "constant" or gamma >= 1.0:
        return 0.0
    if normal == "sine":
        return (-math.asin(gamma) / (2.0 * math.pi)) % 1.0
    if normal == "triangle":
        return (1.0 - gamma) / 4.0
    if normal == "sawtooth-right":
        return (1.0 - gamma) / 2.0
    return 0.0        # sawtooth-left, square: an upward jump at phi = 0


def evaluate(normal, gamma, in_plane, beta, a_l, a_t, phase, steps, start=0.0):
    """Catching-up scheme at `steps` nodes a period, periodic steady state.

    Returns a dict: mu, mean_lateral, stick, slip, flight (fractions of the period), s_periodic
    ([s_x, s_y] at the node phi = 0 = 1, the state the period map maps to itself; this is s(0-)
    unless n jumps down at phi = 0, where it is the state after that jump), periods (number of
    periods iterated, including the last one) and steps.
    start: the grid is phi_k = start + k/N (default 0, the brief's grid; extrapolate() puts the
    first contact on a node, see its docstring).  s_periodic is then the state at phi = start.
    """
    gamma, beta, a_l, a_t, phase = map(float, (gamma, beta, a_l, a_t, phase))
    _check(normal, gamma, in_plane, beta, a_l, a_t, phase, steps)
    N = int(steps)
    start = float(start)
    k = np.arange(N + 1, dtype=float)
    phi = k / N + start
    pw = wave(in_plane, phi + phase)
    dp = np.diff(pw)                      # p(phi_{k+1}+P) - p(phi_k+P), k = 0..N-1
    dx = beta / N + a_l * dp
    dy = a_t * dp
    nn_arr = normal_force(normal, gamma, phi[1:])   # n at node k+1 (phase reduced mod 1 inside)
    if start == 0.0:
        nn_arr[-1] = normal_force(normal, gamma, np.array([0.0]))[0]   # node N is exactly phi = 0
    dz = (dx + 1j * dy).tolist()
    nn = nn_arr.tolist()
    nflight = int(np.count_nonzero(nn_arr == 0.0))

    s = 0j
    periods = 0
    while True:
        periods += 1
        s_new, _, _ = _period(s, dz, nn)
        if abs(s_new - s) < TOL_PERIODIC:
            s = s_new
            break
        s = s_new
        if periods >= MAX_PERIODS:
            raise RuntimeError("no periodic state reached after %d periods (|s_end - s_start| = %.3g; "
                               "normal=%s gamma=%g beta=%g a_l=%g a_t=%g P=%g N=%d)"
                               % (MAX_PERIODS, abs(s_new - s), normal, gamma, beta, a_l, a_t, phase, N))
    # last period (from the converged state), recorded
    periods += 1
    s_end, acc, nslip = _period(s, dz, nn, record=True)
    nsum = float(np.sum(nn_arr))
    if nsum <= 0.0:
        raise ValueError("no contact: the normal force vanishes over the whole period")
    return {
        "mu": acc.real / nsum,
        "mean_lateral": acc.imag / nsum,
        "stick": (N - nslip - nflight) / N,
        "slip": nslip / N,
        "flight": nflight / N,
        "s_periodic": [s_end.real, s_end.imag],
        "periods": periods,
        "steps": N,
        "start": start,
    }


def _richardson(vals):
    """vals: values at N, 2N, 4N, ... (>= 3).  See the module docstring for the rule."""
    def ext(m1, m2, m3):
        d1, d2 = m2 - m1, m3 - m2
        if abs(d2) < 1e-14 or abs(d1) < 1e-14:
            return m3, None, None
        ratio = d1 / d2
        if ratio <= 0.0:
            return m3 + d2, None, 1.0           # non-monotone: order 1, measured order undefined
        p = math.log2(ratio)
        used = p if 0.5 <= p <= 3.0 else 1.0
        return m3 + d2 / (2.0 ** used - 1.0), p, used

    m1, m2, m3 = vals[-3:]
    x, p, used = ext(m1, m2, m3)
    if p is None and used is None:
        return {"value": m3, "order": None, "order_used": None, "error": abs(m3 - m2) + 1e-14,
                "raw": list(vals)}
    r1 = 2.0 * m3 - m2
    err = abs(x - r1)
    if len(vals) >= 4:
        xp, _, _ = ext(*vals[-4:-1])
        err = max(err, abs(x - xp))
    return {"value": x, "order": p, "order_used": used, "error": err, "raw": list(vals)}


def extrapolate(normal, gamma, in_plane, beta, a_l, a_t, phase, base_steps=1 << 14, levels=4,
                align=True):
    """Run evaluate() at base_steps * 2^j, j = 0..levels-1 (levels >= 3) and extrapolate.

    align: start the grid at the first contact (contact_onset()), so that it is a node at every N.
    Where a stick phase starts at first contact, the scheme starts it at the last flight node
    instead, an O(1/N) error whose coefficient depends on frac(N phi_c) and so jumps between N and
    2N; no Richardson rule survives that.  Putting phi_c on the grid removes it.  (Other jumps of n
    off the grid, e.g. sawtooth-right's drop at 0 with the grid aligned elsewhere, still jitter; the
    error estimate then shows it.)  Phase shifts of the grid do not change the continuous values.

    Returns a dict with mu, mu_error, mu_order (measured), mean_lateral (and its error and order),
    the finest-N fractions with their change from the previous N, the finest periodic state, the
    runs themselves (N, mu, mean_lateral, periods) and the rule used.
    """
    if levels < 3:
        raise ValueError("levels must be >= 3")
    start = contact_onset(normal, float(gamma)) if align else 0.0
    runs = [evaluate(normal, gamma, in_plane, beta, a_l, a_t, phase, base_steps << j, start=start)
            for j in range(levels)]
    rmu = _richardson([r["mu"] for r in runs])
    rlat = _richardson([r["mean_lateral"] for r in runs])
    fin, prev = runs[-1], runs[-2]
    out = {
        "input": {"normal": normal, "gamma": gamma, "in_plane_wave": in_plane, "beta": beta,
                  "a_l": a_l, "a_t": a_t, "phase": phase},
        "mu": rmu["value"], "mu_error": rmu["error"], "mu_order": rmu["order"],
        "mu_order_used": rmu["order_used"],
        "mean_lateral": rlat["value"], "mean_lateral_error": rlat["error"],
        "mean_lateral_order": rlat["order"], "mean_lateral_order_used": rlat["order_used"],
        "stick": fin["stick"], "slip": fin["slip"], "flight": fin["flight"],
        "fraction_error": max(abs(fin[f] - prev[f]) for f in ("stick", "slip", "flight")),
        "s_periodic": fin["s_periodic"], "s_periodic_phase": start,
        "runs": [{"steps": r["steps"], "mu": r["mu"], "mean_lateral": r["mean_lateral"],
                  "periods": r["periods"]} for r in runs],
        "rule": "Richardson with the order measured from the three finest N (Aitken); error = "
                "max(|x - x from the 3 coarser N|, |x - (2 m_finest - m_previous)|)",
    }
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description="Catching-up reference for planar (in-plane + normal) "
                                             "oscillation; prints JSON.")
    ap.add_argument("--normal", default="sine", choices=NORMALS)
    ap.add_argument("--gamma", type=float, default=1.0)
    ap.add_argument("--in-plane-wave", default="sine", choices=WAVES)
    ap.add_argument("--beta", type=float, required=True)
    ap.add_argument("--longitudinal", type=float, default=0.0)
    ap.add_argument("--transverse", type=float, default=0.0)
    ap.add_argument("--phase", type=float, default=0.0)
    ap.add_argument("--steps", type=int, default=1 << 14,
                    help="base steps a period (extrapolation uses N, 2N, 4N, 8N)")
    ap.add_argument("--levels", type=int, default=4)
    ap.add_argument("--single", action="store_true", help="only evaluate() at --steps (grid from 0)")
    ap.add_argument("--no-align", action="store_true", help="grid from phi = 0 in the extrapolation")
    a = ap.parse_args(argv)
    try:
        args = (a.normal, a.gamma, a.in_plane_wave, a.beta, a.longitudinal, a.transverse, a.phase)
        if a.single:
            res = evaluate(*args, a.steps)
        else:
            res = extrapolate(*args, base_steps=a.steps, levels=a.levels, align=not a.no_align)
    except (ValueError, RuntimeError) as e:
        print("error: %s" % e, file=sys.stderr)
        return 2
    print(json.dumps(res, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
