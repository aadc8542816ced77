#!/usr/bin/python3
"""Self-test of planar_catchup.py against closed forms and independent semi-analytic solutions.

Nothing here calls the C++ tool.  One line per check, then "N passed, M failed"; the exit status is
non-zero if any check failed.  Tolerances: each check states its own; where the catching-up value is
compared, the tolerance is built from planar_catchup's own error estimate (err) with a safety factor
and a floor, so a check fails when the reference is wrong *or* its error estimate is dishonest.

Checks
 1. Rigid limits (n = 1, sine drive, xi = beta/(2 pi a)):
    a. longitudinal, finite a: the catching-up value against an exact event solution of the stop
       operator (mpmath, 30 digits; closed-form integrals, roots by bracketed solver), a = 100, 1000;
       the event solution tends to (2/pi) arcsin xi like 1/a; xi > 1 gives exactly 1;
       model.md's measured 0.334760 (a = 100) and 0.333475 (a = 1000) to their 6 digits.
    b. transverse: (2/pi) xi/sqrt(1+xi^2) K(k = 1/sqrt(1+xi^2)) (mpmath.ellipk(m = k^2)) against the
       direct integral of xi/sqrt(xi^2 + cos^2 2 pi phi) and model.md's limit 0.642637682; finite
       a: the catching-up value against an RK4 solution of the slip ODE on the circle
       (theta' = D' . e_perp, which holds because D'_x = beta > 0 keeps D' . e > 0, checked), a = 100
       and 1000; a^2 (mu - limit) the same at both (the 1/a^2 law); model.md's 0.642638448
       (a = 1000) to 9 digits.  model.md's a = 100 value 0.642638460 is reported as a NOTE (it
       contradicts both the ODE and model.md's own 1/a^2 law; see the printed line).
    c. 2D stick-slip with n = 1 (not a closed form: an independent event-driven solution, exact in
       stick, RK4 on the circle in slip, bisection for the events): the first two printed cases.
 2. a_l = a_t = 0 (the paper's model): mu against the lower envelope min_tau n(phi - tau) + beta tau,
    computed independently by dense sampling in tau (8192 samples, the exact first-contact kink added
    as a candidate, then two local refinements) on a phi grid of 2^14 midpoints (its error: the
    change from 2^13); s_y = 0 exactly.
 3. The ratchet: n = max(0.5 + sin, 0), a_l = 1, P = 1/4, beta = 0: mu = -0.5364 (model.md, 4 digits).
 4. Symmetry: n = 1, transverse drive with sine / triangle / square (-p is a phase shift of p, and a
    phase shift cannot matter with constant n): mean_lateral = 0 within 1e-12.
 5. Printed reference values (not checks): five transverse/combined cases with their extrapolated
    mu, mean_lateral, fractions, measured order and error estimate.
Options: --quick skips 5 and the a = 1000 runs.
"""

import math
import os
import subprocess
import sys
import time

import mpmath as mp
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import planar_catchup as pc  # noqa: E402

PASSED = 0
FAILED = 0


def check(name, ok, detail):
    global PASSED, FAILED
    if ok:
        PASSED += 1
    else:
        FAILED += 1
    print("%s  %s: %s" % ("PASS" if ok else "FAIL", name, detail))
    sys.stdout.flush()


def note(name, detail):
    print("NOTE  %s: %s" % (name, detail))


# ---------------------------------------------------------------- 1a. longitudinal, exact events
def longitudinal_rigid_exact(a, xi, dps=30):
    """n = 1, D = beta phi + a sin 2 pi phi, beta = 2 pi a xi, 0 < xi < 1: exact periodic mean of s.

    D has a local max at phi1 = acos(-xi)/(2 pi) and a local min at phi2 = 1 - phi1.  Periodic state
    (when D(phi1) - D(phi2) > 2): slip at +1 up to phi1; stick s = 1 - (D(phi1) - D) until D has
    fallen by 2 (phi3); slip at -1 to phi2; stick s = -1 + (D - D(phi2)) until D has risen by 2
    (phi4); slip at +1 to phi1 + 1.
    """
    with mp.workdps(dps):
        a = mp.mpf(a)
        xi = mp.mpf(xi)
        beta = 2 * mp.pi * a * xi
        D = lambda f: beta * f + a * mp.sin(2 * mp.pi * f)
        ID = lambda f: beta * f * f / 2 - a * mp.cos(2 * mp.pi * f) / (2 * mp.pi)   # antiderivative
        f1 = mp.acos(-xi) / (2 * mp.pi)
        f2 = 1 - f1
        assert D(f1) - D(f2) > 2, "the drive must fall by more than 2 for this event structure"
        f3 = mp.findroot(lambda f: D(f1) - D(f) - 2, (f1, f2), solver="anderson")
        f4 = mp.findroot(lambda f: D(f) - D(f2) - 2, (f2, f1 + 1), solver="anderson")
        assert f1 < f3 < f2 < f4 < f1 + 1
        I = ((1 - D(f1)) * (f3 - f1) + ID(f3) - ID(f1)     # stick down
             - (f2 - f3)                                  # slip at -1
             + (-1 - D(f2)) * (f4 - f2) + ID(f4) - ID(f2)  # stick up
             + (f1 + 1 - f4))                             # slip at +1
        return I                                          # n = 1: mu = I


# ---------------------------------------------------------------- 1b. transverse, ODE on the circle
def transverse_rigid_ode(a, xi, M=20000, periods=4):
    """RK4 for theta' = -D'_x sin theta + D'_y cos theta (n = 1, slip on the circle throughout),
    D' = (2 pi a xi, 2 pi a cos 2 pi phi).  Returns (mean cos theta, mean sin theta, min D'.e)."""
    beta = 2.0 * math.pi * a * xi
    w = 2.0 * math.pi * a

    def f(p, th):
        return -beta * math.sin(th) + w * math.cos(2.0 * math.pi * p) * math.cos(th)

    h = 1.0 / M
    th = 0.0
    for _ in range(periods):
        cs = sn = 0.0
        lam = float("inf")
        for k in range(M):
            p = k * h
            c, s = math.cos(th), math.sin(th)
            cs += c
            sn += s
            lam = min(lam, beta * c + w * math.cos(2.0 * math.pi * p) * s)
            k1 = f(p, th)
            k2 = f(p + h / 2, th + h / 2 * k1)
            k3 = f(p + h / 2, th + h / 2 * k2)
            k4 = f(p + h, th + h * k3)
            th += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return cs / M, sn / M, lam


def transverse_limit_K(xi):
    with mp.workdps(30):
        xi = mp.mpf(xi)
        k = 1 / mp.sqrt(1 + xi * xi)
        return 2 / mp.pi * xi * k * mp.ellipk(k * k)      # ellipk takes the parameter m = k^2


def transverse_limit_quad(xi):
    with mp.workdps(30):
        xi = mp.mpf(xi)
        return mp.quad(lambda f: xi / mp.sqrt(xi * xi + mp.cos(2 * mp.pi * f) ** 2),
                       [0, mp.mpf(1) / 4, mp.mpf(1) / 2, mp.mpf(3) / 4, 1])


def agree(x, err, ref, floor, factor=3.0):
    tol = factor * err + floor
    return abs(x - ref) <= tol, tol


def rigid_checks(quick):
    xi = 0.5
    # --- longitudinal
    ex = {}
    for a in (100, 1000, 10 ** 4, 10 ** 6):
        ex[a] = longitudinal_rigid_exact(a, xi)
    lim = 2 / mp.pi * mp.asin(mp.mpf(xi))
    d = {a: float(ex[a] - lim) for a in ex}
    check("longitudinal event solution -> (2/pi) arcsin xi like 1/a",
          d[10 ** 6] > 0 and abs(d[10 ** 6] * 1e6 / (d[10 ** 4] * 1e4) - 1) < 0.02
          and abs(d[1000] * 1000 / (d[100] * 100) - 1) < 0.1 and d[10 ** 6] < 2e-6,
          "limit %.9f; a*(mu-limit) = %.5f (a=100), %.5f (1e3), %.5f (1e4), %.5f (1e6) "
          "[tol: a*dist constant to 10%%/2%%]"
          % (float(lim), d[100] * 100, d[1000] * 1000, d[10 ** 4] * 1e4, d[10 ** 6] * 1e6))
    for a, base in ((100, 1 << 14), (1000, 1 << 14)):
        if quick and a == 1000:
            continue
        t = time.process_time()
        r = pc.extrapolate("constant", 1.0, "sine", 2 * math.pi * a * xi, float(a), 0.0, 0.0,
                           base_steps=base, levels=4)
        ok, tol = agree(r["mu"], r["mu_error"], float(ex[a]), 2e-10)
        check("longitudinal rigid a=%d, catching-up vs exact events" % a, ok,
              "cu %.12f +- %.1e (order %s), exact %.12f, diff %.1e, tol %.1e = 3 err + 2e-10 "
              "[%.1fs]" % (r["mu"], r["mu_error"], _fmt(r["mu_order"]), float(ex[a]),
                           r["mu"] - float(ex[a]), tol, time.process_time() - t))
        quoted = {100: 0.334760, 1000: 0.333475}[a]
        check("longitudinal rigid a=%d vs model.md %.6f" % (a, quoted),
              abs(r["mu"] - quoted) <= 5e-7 + 3 * r["mu_error"],
              "cu %.9f; tol 5e-7 (model.md gives 6 decimals) + 3 err" % r["mu"])
    r = pc.evaluate("constant", 1.0, "sine", 2 * math.pi * 100 * 1.5, 100.0, 0.0, 0.0, 1 << 14)
    check("longitudinal rigid xi=1.5 (beyond critical): mu = 1", abs(r["mu"] - 1) < 1e-12,
          "mu = %.15f, stick %.3g [tol 1e-12: no reversal of D_x, so s = 1 exactly]"
          % (r["mu"], r["stick"]))

    # --- transverse
    K = transverse_limit_K(xi)
    Q = transverse_limit_quad(xi)
    check("transverse limit: K formula (modulus k, ellipk(k^2)) = direct integral",
          abs(K - Q) < mp.mpf("1e-25"), "K form %s, quad %s" % (mp.nstr(K, 20), mp.nstr(Q, 20)))
    check("transverse limit vs model.md 0.642637682", abs(float(K) - 0.642637682) <= 5e-10,
          "%.12f [tol 5e-10: 9 decimals]" % float(K))
    dd = {}
    for a, base in ((100, 1 << 14), (1000, 1 << 15)):
        if quick and a == 1000:
            continue
        t = time.process_time()
        ode, ode_y, lam = transverse_rigid_ode(a, xi)
        ode2, _, _ = transverse_rigid_ode(a, xi, M=40000, periods=3)
        check("transverse slip ODE a=%d stays on the circle and is resolved" % a,
              lam > 0 and abs(ode - ode2) < 1e-9 and abs(ode_y) < 1e-12,
              "min D'.e = %.3g > 0; RK4 M=2e4 %.12f vs M=4e4 %.12f; mean s_y %.1e" % (lam, ode, ode2, ode_y))
        r = pc.extrapolate("constant", 1.0, "sine", 2 * math.pi * a * xi, 0.0, float(a), 0.0,
                           base_steps=base, levels=4)
        ok, tol = agree(r["mu"], r["mu_error"], ode2, 2e-10 + abs(ode - ode2))
        check("transverse rigid a=%d, catching-up vs RK4 slip ODE" % a, ok,
              "cu %.12f +- %.1e (order %s), ODE %.12f, diff %.1e, tol %.1e = 3 err + 2e-10 [%.1fs]"
              % (r["mu"], r["mu_error"], _fmt(r["mu_order"]), ode2, r["mu"] - ode2, tol,
                 time.process_time() - t))
        check("transverse rigid a=%d, mean_lateral = 0" % a, abs(r["mean_lateral"]) < 1e-12,
              "%.2e" % r["mean_lateral"])
        dd[a] = (r["mu"] - float(K)) * a * a
        if a == 100:
            note("model.md transverse a=100 value 0.642638460",
                 "NOT reproduced: catching-up gives %.9f, the slip ODE %.9f (distance to the limit "
                 "%.2e = %.3f/a^2, as model.md's own 1/a^2 law requires). 0.642638460 lies %.1e "
                 "from the limit, i.e. it is a value for a ~ 1000, not 100 (a typo or a mislabelled "
                 "run in model.md). Not counted as a failure of this reference."
                 % (r["mu"], ode2, r["mu"] - float(K), dd[a], 0.642638460 - float(K)))
        if a == 1000:
            check("transverse rigid a=1000 vs model.md 0.642638448",
                  abs(r["mu"] - 0.642638448) <= 5e-10 + 3 * r["mu_error"],
                  "cu %.12f [tol 5e-10 (9 decimals) + 3 err]" % r["mu"])
    if 1000 in dd:
        check("transverse rigid: distance to the limit falls like 1/a^2",
              abs(dd[1000] / dd[100] - 1) < 0.05,
              "a^2 (mu - limit) = %.4f (a=100), %.4f (a=1000) [tol 5%%]" % (dd[100], dd[1000]))


# ---------------------------------------------------------------- 1c. 2D stick-slip, event solution
def stick_slip_events_2d(beta, al, at, P, M=4000, periods=24):
    """n = 1, sine drive D = (beta phi + al p, at p), p = sin 2 pi (phi + P): event-driven solution.
    Stick: s = s0 + D - D0 exactly, until |s| = 1 (bisection).  Slip: s = e(theta),
    theta' = D' . e_perp by RK4 (step 1/M), until lambda = D' . e < 0 (bisection on the step length).
    Integrals by Simpson's rule on each step (the midpoint state from an RK4 half step).
    Returns (mean s_x, mean s_y) of the last period and the change from the period before."""
    w = 2.0 * math.pi
    D = lambda f: (beta * f + al * math.sin(w * (f + P)), at * math.sin(w * (f + P)))
    Dp = lambda f: (beta + al * w * math.cos(w * (f + P)), at * w * math.cos(w * (f + P)))
    F = lambda f, t: -Dp(f)[0] * math.sin(t) + Dp(f)[1] * math.cos(t)
    lam = lambda f, t: Dp(f)[0] * math.cos(t) + Dp(f)[1] * math.sin(t)

    def rk4(f0, t0, f1):
        hh = f1 - f0
        k1 = F(f0, t0)
        k2 = F(f0 + hh / 2, t0 + hh / 2 * k1)
        k3 = F(f0 + hh / 2, t0 + hh / 2 * k2)
        k4 = F(f1, t0 + hh * k3)
        return t0 + hh / 6 * (k1 + 2 * k2 + 2 * k3 + k4)

    def bis(g, a, b):
        ga = g(a) > 0
        for _ in range(60):
            m = 0.5 * (a + b)
            if (g(m) > 0) == ga:
                a = m
            else:
                b = m
        return 0.5 * (a + b)

    h = 1.0 / M
    stick, s0, D0, th = True, (0.0, 0.0), D(0.0), 0.0
    out = []
    for per in range(periods):
        Ix = Iy = 0.0
        for k in range(M):
            f, fe = per + k * h, per + (k + 1) * h
            while f < fe:
                if stick:
                    sf = lambda x: (s0[0] + D(x)[0] - D0[0], s0[1] + D(x)[1] - D0[1])
                    g = lambda x: math.hypot(*sf(x)) - 1.0
                    e = bis(g, f, fe) if g(fe) > 0 else fe
                    a, m, b = sf(f), sf(0.5 * (f + e)), sf(e)
                    Ix += (e - f) / 6 * (a[0] + 4 * m[0] + b[0])
                    Iy += (e - f) / 6 * (a[1] + 4 * m[1] + b[1])
                    if e < fe:
                        stick, th = False, math.atan2(b[1], b[0])
                else:
                    e = fe
                    if lam(fe, rk4(f, th, fe)) < 0:
                        e = bis(lambda x: lam(x, rk4(f, th, x)), f, fe)
                    tm, t1 = rk4(f, th, 0.5 * (f + e)), rk4(f, th, e)
                    Ix += (e - f) / 6 * (math.cos(th) + 4 * math.cos(tm) + math.cos(t1))
                    Iy += (e - f) / 6 * (math.sin(th) + 4 * math.sin(tm) + math.sin(t1))
                    th = t1
                    if e < fe:
                        stick, s0, D0 = True, (math.cos(t1), math.sin(t1)), D(e)
                f = e
        out.append((Ix, Iy))
    return out[-1], max(abs(out[-1][0] - out[-2][0]), abs(out[-1][1] - out[-2][1]))


def events_2d_checks():
    for c in ((1.0, 0.0, 1.0, 0.0), (0.5, 0.3, 0.7, 0.1)):
        t = time.process_time()
        (ex, ey), dper = stick_slip_events_2d(*c, M=2000)
        (ex2, ey2), _ = stick_slip_events_2d(*c, M=4000)
        eerr = max(abs(ex2 - ex), abs(ey2 - ey)) + dper
        r = pc.extrapolate("constant", 1.0, "sine", c[0], c[1], c[2], c[3], base_steps=1 << 14,
                           levels=4)
        okx, tolx = agree(r["mu"], r["mu_error"], ex2, 2 * eerr + 2e-10)
        oky, toly = agree(r["mean_lateral"], r["mean_lateral_error"], ey2, 2 * eerr + 2e-10)
        check("2D stick-slip n=1, beta=%g a_l=%g a_t=%g P=%g: catching-up vs event solution" % c,
              okx and oky,
              "mu cu %.11f +- %.1e vs events %.11f (diff %.1e, tol %.1e); lateral cu %.11f +- %.1e vs "
              "events %.11f (diff %.1e, tol %.1e); events' own error %.1e (M=2000 vs 4000, last "
              "period change) [%.1fs]"
              % (r["mu"], r["mu_error"], ex2, r["mu"] - ex2, tolx, r["mean_lateral"],
                 r["mean_lateral_error"], ey2, r["mean_lateral"] - ey2, toly, eerr,
                 time.process_time() - t))


def _fmt(p):
    return "n/a" if p is None else "%.3f" % p


# ---------------------------------------------------------------- 2. envelope by dense sampling
def envelope_mu(normal, gamma, beta, K=1 << 13, M=8192, chunk=256):
    """mu of the lower envelope s(phi) = min_{0<=tau<1} n(phi - tau) + beta tau, by dense sampling:
    M uniform tau samples plus the exact first-contact kink, then two refinements of 65 samples
    around the best sample; phi on K midpoints; trapezoid/midpoint rule for both integrals."""
    nf = lambda x: pc.normal_force(normal, gamma, x)
    phic = pc.contact_onset(normal, gamma)
    phi = (np.arange(K) + 0.5) / K
    tau = np.arange(M) / M
    s = np.empty(K)
    for i0 in range(0, K, chunk):
        ph = phi[i0:i0 + chunk, None]
        v = nf(ph - tau[None, :]) + beta * tau[None, :]
        j = np.argmin(v, axis=1)
        best = v[np.arange(len(j)), j]
        t0 = tau[j]
        width = 1.0 / M
        for _ in range(2):
            tt = np.clip(t0[:, None] + np.linspace(-width, width, 65)[None, :], 0.0, 1.0 - 1e-15)
            vv = nf(ph - tt) + beta * tt
            jj = np.argmin(vv, axis=1)
            t0 = tt[np.arange(len(jj)), jj]
            best = np.minimum(best, vv[np.arange(len(jj)), jj])
            width /= 32.0
        tk = np.mod(ph[:, 0] - phic, 1.0)                       # the kink candidate
        best = np.minimum(best, nf(np.array(phic)) + beta * tk)
        s[i0:i0 + chunk] = best
    return float(np.sum(s) / np.sum(nf(phi)))


def envelope_checks():
    for beta in (1.0, 3.0):
        t = time.process_time()
        e1 = envelope_mu("sine", 0.5, beta, K=1 << 13)
        e2 = envelope_mu("sine", 0.5, beta, K=1 << 14)
        eerr = abs(e2 - e1)
        r = pc.extrapolate("sine", 0.5, "sine", beta, 0.0, 0.0, 0.0, base_steps=1 << 14, levels=4)
        ok, tol = agree(r["mu"], r["mu_error"], e2, 2 * eerr + 1e-9)
        check("paper model n=max(0.5+sin,0), beta=%g: catching-up vs dense envelope" % beta, ok,
              "cu %.11f +- %.1e, envelope %.11f (K=2^13: %.11f), diff %.1e, tol %.1e = "
              "3 err + 2|env(2^14)-env(2^13)| + 1e-9 [%.1fs]"
              % (r["mu"], r["mu_error"], e2, e1, r["mu"] - e2, tol, time.process_time() - t))
        check("paper model beta=%g: mean_lateral = 0 exactly" % beta,
              r["mean_lateral"] == 0.0 and all(x["mean_lateral"] == 0.0 for x in r["runs"]),
              "%r" % r["mean_lateral"])


# ---------------------------------------------------------------- 3. ratchet
def ratchet_check():
    r = pc.extrapolate("sine", 0.5, "sine", 0.0, 1.0, 0.0, 0.25, base_steps=1 << 14, levels=4)
    check("ratchet n=max(0.5+sin,0), a_l=1, P=1/4, beta=0: mu = -0.5364 (model.md)",
          abs(r["mu"] - (-0.5364)) <= 5e-5 + 3 * r["mu_error"],
          "cu %.11f +- %.1e (order %s) [tol 5e-5: model.md gives 4 decimals]"
          % (r["mu"], r["mu_error"], _fmt(r["mu_order"])))
    r0 = pc.evaluate("sine", 0.5, "sine", 0.0, 1.0, 0.0, 0.25, 1 << 14)
    check("ratchet, unaligned grid (phi_k = k/N) at N=2^14 agrees to O(1/N)",
          abs(r0["mu"] - r["mu"]) < 2.0 / (1 << 14),
          "%.8f, diff %.1e [tol 2/N]" % (r0["mu"], r0["mu"] - r["mu"]))


# ---------------------------------------------------------------- 4. symmetry
def symmetry_checks():
    for w in ("sine", "triangle", "square"):
        r = pc.extrapolate("constant", 1.0, w, 1.0, 0.0, 1.0, 0.0, base_steps=1 << 12, levels=3)
        worst = max(abs(x["mean_lateral"]) for x in r["runs"])
        check("symmetry n=1, beta=1, a_t=1, %s drive: mean_lateral = 0" % w, worst < 1e-12,
              "max over N of |mean_lateral| = %.1e [tol 1e-12: rounding only]" % worst)


# ---------------------------------------------------------------- CLI / error paths
def cli_checks():
    exe = [sys.executable, os.path.join(HERE, "planar_catchup.py")]
    p = subprocess.run(exe + ["--normal", "constant", "--beta", "1", "--transverse", "1",
                              "--steps", "1024", "--levels", "3"], capture_output=True, text=True)
    import json
    try:
        js = json.loads(p.stdout)
        ok = p.returncode == 0 and abs(js["mu"] - 0.74147) < 1e-3
    except Exception:  # noqa: BLE001
        ok, js = False, None
    check("CLI prints JSON", ok, "exit %d, mu %s" % (p.returncode, js and js["mu"]))
    p = subprocess.run(exe + ["--normal", "sine", "--gamma", "-1", "--beta", "1"],
                       capture_output=True, text=True)
    check("CLI rejects gamma=-1 (no contact)", p.returncode == 2 and "gamma" in p.stderr,
          "exit %d, %s" % (p.returncode, p.stderr.strip()))


# ---------------------------------------------------------------- 5. printed reference values
CASES = [
    ("constant", 1.0, "sine", 1.0, 0.0, 1.0, 0.0),
    ("constant", 1.0, "sine", 0.5, 0.3, 0.7, 0.1),
    ("sine", 0.5, "sine", 1.0, 0.0, 1.0, 0.0),
    ("sine", 1.5, "sine", 2.0, 0.0, 0.5, 0.25),
    ("triangle", 0.5, "triangle", 1.0, 0.5, 0.5, 0.3),
]


def reference_values():
    print("\nReference values (catching-up, N = 2^14..2^17, Richardson with the measured order; "
          "fractions at N = 2^17, f_err = their change from 2^16):")
    hdr = ("normal", "gamma", "p", "beta", "a_l", "a_t", "P", "mu", "mu_err", "ord", "mean_lat",
           "lat_err", "ord", "stick", "slip", "flight", "f_err")
    print("  %-8s %5s %-8s %4s %4s %4s %4s | %15s %8s %5s | %15s %8s %5s | %7s %7s %7s %7s" % hdr)
    for c in CASES:
        t = time.process_time()
        r = pc.extrapolate(*c, base_steps=1 << 14, levels=4)
        print("  %-8s %5g %-8s %4g %4g %4g %4g | %15.11f %8.1e %5s | %15.11f %8.1e %5s | %7.5f %7.5f "
              "%7.5f %7.1e  [%.1fs]"
              % (c + (r["mu"], r["mu_error"], _fmt(r["mu_order"]), r["mean_lateral"],
                      r["mean_lateral_error"], _fmt(r["mean_lateral_order"]), r["stick"], r["slip"],
                      r["flight"], r["fraction_error"], time.process_time() - t)))


def main():
    quick = "--quick" in sys.argv[1:]
    t0 = time.time()
    rigid_checks(quick)
    events_2d_checks()
    envelope_checks()
    ratchet_check()
    symmetry_checks()
    cli_checks()
    if not quick:
        reference_values()
    print("\n%d passed, %d failed  (%.1fs)" % (PASSED, FAILED, time.time() - t0))
    return 1 if FAILED else 0


if __name__ == "__main__":
    sys.exit(main())
