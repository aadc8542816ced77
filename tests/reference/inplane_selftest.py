#!/usr/bin/python3
"""Self-test of inplane_mpmath.py (longitudinal in-plane oscillation).

1. Catching-up: an independent float implementation of s <- clamp(s + dD, -n(phi_k+1), n(phi_k+1))
   at N steps per period (its own wave formulas, no shared code) agrees with the reference to
   O(1/N): N |mu_N - mu| stays bounded and the least-squares order of |mu_N - mu| over N is >= 0.8;
   the mode fractions agree to O(1/N) too.
2. Rigid limit (n = 1, sine, xi = beta/(2 pi a) = 1/2): the distance to (2/pi) arcsin(1/2) = 1/3
   falls like 1/a (a = 10, 100, 1000), and the values at a = 100 and 1000 match model.md's 0.334760
   and 0.333475; xi > 1 gives mu = 1.
3. Ratchet (model.md): n = max(0.5 + sin, 0), a = 1, P = 1/4, beta = 0: mu = -0.5364 to 4 digits.
4. a = 0 is the paper's model: agreement with mu_mpmath.py to 38 of 40 digits.
5. Closed forms and properties: n = 1 with a square drive (mu = beta/8, 1 - 2/beta), p = w with
   P = 0 at beta = 0 (mu = a), mu = 1 where D never falls, mu = 0 by symmetry; P -> P + 1; the
   power:1/triangle shift; P-invariance for n = 1; interval isolation = closed-form critical points;
   15 vs 60 digits; --verify (second start phase, clamp form of the period map); fractions add to 1.
6. Uniqueness: beta = 0 with a small drive and no flight is "no unique periodic state" (exit 3);
   flight makes it unique.
7. CLI: output format and exit status 2 with the value quoted for bad input.
8. (full run only) The cases of inplane_crosscheck.py against the catching-up scheme.
Prints "N passed, M failed" and exits non-zero on failure.  --quick: smaller N and fewer cases
(about 5 s); the full run takes about 10 s.
"""

import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import mpmath                                   # noqa: E402
from mpmath import mp, mpf                      # noqa: E402

import inplane_mpmath as R                      # noqa: E402
import mu_mpmath as M                           # noqa: E402

PY = "/usr/bin/python3"
SCRIPT = os.path.join(HERE, "inplane_mpmath.py")

passed = 0
failed = 0
NOTES = []          # measured numbers, printed at the end


def check(name, ok, detail=""):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL %s %s" % (name, detail))


def note(line):
    NOTES.append(line)
    print(line)


def ev(wave, beta, gamma, a, phase="0", inplane="sine", digits=40, verify=False):
    return R.evaluate(wave, beta, gamma, a, phase, inplane, digits, verify)


def rel_close(x, y, digits):
    return abs(x - y) <= mpf(10) ** (-digits) * max(abs(x), abs(y), mpf(1))


# --------------------------------------------------------------------------------------------
# 1. catching-up scheme, in floats, with its own wave formulas
# --------------------------------------------------------------------------------------------

def float_wave(name):
    if name == "sine":
        return lambda x: math.sin(2 * math.pi * x)
    if name == "triangle":
        return lambda x: 4 * x - 1 if x < 0.5 else 3 - 4 * x
    if name == "sawtooth-right":
        return lambda x: 2 * x - 1
    if name == "sawtooth-left":
        return lambda x: 1 - 2 * x
    if name == "square":
        return lambda x: 1.0 if x < 0.5 else -1.0
    if name.startswith("power:"):
        p = float(name[len("power:"):])
        return lambda x: 1 - abs(4 * x - 1) ** p if x < 0.5 else -(1 - abs(4 * x - 3) ** p)
    raise ValueError(name)


def catching_up(wave, beta, gamma, a, phase, inplane, N, lower_start=False, check=True):
    """mu and (stick, slip, backward slip, flight) fractions of the catching-up scheme: grid
    phi_k = k/N, s <- clamp(s + D_k - D_{k-1}, -n_k, n_k), rectangle sums over the last period.
    From s = n(0) one period reaches the discrete periodic state (the period map is a clamp with
    lower end >= L(0)); a third period checks that it repeats.  lower_start: start from s = -n(0)
    instead, and return the state at the end (for the uniqueness check)."""
    beta, a, P = float(beta), float(a), float(phase)
    pf = float_wave(inplane)
    if wave == "constant":
        n = [1.0] * (N + 1)
    else:
        wf, g = float_wave(wave), float(gamma)
        n = [max(g + wf((k / N) % 1.0), 0.0) for k in range(N + 1)]
    D = [beta * k / N + a * pf((k / N + P) % 1.0) for k in range(N + 1)]
    steps = list(zip([D[k] - D[k - 1] for k in range(1, N + 1)], n[1:]))
    s = -n[0] if lower_start else n[0]
    ends = []
    for _ in range(3):
        acc = 0.0
        st = fw = bw = fl = 0
        for d, nk in steps:
            s += d
            if nk == 0.0:
                s = 0.0
                fl += 1
            elif s >= nk:
                s = nk
                fw += 1
            elif s <= -nk:
                s = -nk
                bw += 1
            else:
                st += 1
            acc += s
        ends.append(s)
    if lower_start or not check:
        return s
    if abs(ends[2] - ends[1]) > 1e-9 * (1 + abs(ends[1])):
        raise RuntimeError("catching-up state does not repeat")
    return acc / sum(n[1:]), (st / N, (fw + bw) / N, bw / N, fl / N)


CU_CASES = [
    # (wave, beta, gamma, a, phase, in-plane wave)
    ("sine", "0", "0.5", "1", "0.25", "sine"),                 # the ratchet
    ("triangle", "1.3", "0.3", "0.7", "0.1", "sine"),
    ("sine", "0.2", "0.4", "0.3", "0.7", "triangle"),
    ("square", "0.5", "0.2", "2", "0.35", "square"),
    ("constant", "2", None, "1.3", "0", "sawtooth-right"),
    ("sawtooth-right", "0.9", "1.5", "0.4", "0.6", "sawtooth-left"),
    ("power:2.5", "1", "-0.2", "0.5", "0.2", "sine"),
    ("sine", "4", "2", "3", "0.45", "sine"),                   # no flight, backward slip
    ("square", "1", "0.5", "0.5", "0", "square"),              # simultaneous jumps of n and D
    ("sawtooth-left", "0.7", "-0.3", "1.7", "-0.6", "power:3"),
]


def test_catching_up(quick):
    exps = range(9, 14) if quick else range(9, 18)
    cases = CU_CASES[:6] if quick else CU_CASES
    for c in cases:
        wave, beta, gamma, a, phase, inplane = c
        r = ev(wave, beta, gamma, a, phase, inplane, 20)
        ref = float(r.mu)
        fr = [float(getattr(r, k)) for k in R.FRACTIONS]
        Ns, errs, ferrs = [], [], []
        for e in exps:
            N = 2 ** e
            mu_n, f_n = catching_up(wave, beta, gamma, a, phase, inplane, N)
            Ns.append(N)
            errs.append(abs(mu_n - ref))
            ferrs.append(max(abs(x - y) for x, y in zip(f_n, fr)))
        worst = max(N * e for N, e in zip(Ns, errs))
        fworst = max(N * e for N, e in zip(Ns, ferrs))
        tag = "%s b=%s g=%s a=%s P=%s p=%s" % c
        if max(errs) < 1e-12:
            # every jump and kink on the grid, s piecewise constant: the scheme is exact
            note("catching-up %-62s exact (max |dmu| %.1e)  max N|dfrac| %.2f"
                 % (tag, max(errs), fworst))
            check("catching-up exact " + tag, True)
        else:
            # least-squares slope of log err against log N (errors at exact 0 are left out)
            pts = [(math.log(N), math.log(e)) for N, e in zip(Ns, errs) if e > 0]
            mx = sum(x for x, _ in pts) / len(pts)
            my = sum(y for _, y in pts) / len(pts)
            order = -sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)
            note("catching-up %-62s order %.2f  max N|dmu| %.3f  max N|dfrac| %.2f  "
                 "|dmu| at N=2^%d: %.2e" % (tag, order, worst, fworst, exps[-1], errs[-1]))
            check("catching-up O(1/N) mu " + tag, worst < 4 and order >= 0.8,
                  "order %.2f, N err %.3f" % (order, worst))
        check("catching-up O(1/N) fractions " + tag, fworst < 8, "N err %.2f" % fworst)


def test_crosscheck_cases():
    """The cases of inplane_crosscheck.py against the catching-up scheme at N = 2^14 and 2^16
    (N |dmu| < 8 at both: O(1/N); the constant oscillates with the grid's alignment); where the
    reference finds no unique state, the scheme's ends from s = n(0) and s = -n(0) stay apart."""
    import inplane_crosscheck as X
    worst = worst_f = 0.0
    n_ok = n_nonunique = 0
    for c in X.cases():
        _, w, b, g, a, P, p = c
        ref = X.reference(c)
        if isinstance(ref, str):
            up = catching_up(w, b, g, a, P, p, 2 ** 12, check=False)
            lo = catching_up(w, b, g, a, P, p, 2 ** 12, lower_start=True)
            check("crosscheck case %s: catching-up also not unique" % c[0], abs(up - lo) > 1e-2,
                  "ends %.6g %.6g" % (up, lo))
            n_nonunique += 1
            continue
        errs = []
        for N in (2 ** 14, 2 ** 16):
            mu_n, f_n = catching_up(w, b, g, a, P, p, N)
            e = N * abs(mu_n - float(ref.mu))
            ef = N * max(abs(x - float(getattr(ref, k))) for x, k in zip(f_n, R.FRACTIONS))
            errs.append((e, ef))
        worst = max(worst, errs[0][0], errs[1][0])
        worst_f = max(worst_f, errs[0][1], errs[1][1])
        check("crosscheck case %s vs catching-up" % c[0],
              max(errs[0][0], errs[1][0]) < 8 and max(errs[0][1], errs[1][1]) < 8,
              "N|dmu| %.3f -> %.3f, N|dfrac| %.2f" % (errs[0][0], errs[1][0], errs[1][1]))
        n_ok += 1
    note("crosscheck cases vs catching-up (N = 2^14, 2^16): %d cases, max N|dmu| %.2f, "
         "max N|dfrac| %.2f; %d without a unique state, confirmed by the scheme"
         % (n_ok, worst, worst_f, n_nonunique))


# --------------------------------------------------------------------------------------------
# 2-3. rigid limit and ratchet
# --------------------------------------------------------------------------------------------

def test_rigid_and_ratchet(quick):
    dist = {}
    with mp.workdps(60):
        third = mpf(1) / 3
    for a in ["10", "100", "1000"]:
        with mp.workdps(70):
            beta = mpmath.nstr(mp.pi * mpf(a), 60)          # xi = beta/(2 pi a) = 1/2
        r = ev("constant", beta, None, a, "0", "sine", 30)
        with mp.workdps(60):
            dist[a] = r.mu - third
            note("rigid limit xi=1/2 a=%-5s mu = %s  distance to 1/3 = %s  a*distance = %s"
                 % (a, R.fmt(r.mu, 20), mpmath.nstr(dist[a], 6),
                    mpmath.nstr(dist[a] * mpf(a), 6)))
    with mp.workdps(30):
        o1 = mpmath.log10(dist["10"] / dist["100"])
        o2 = mpmath.log10(dist["100"] / dist["1000"])
    note("rigid limit: order of the distance in 1/a: %s (10->100), %s (100->1000)"
         % (mpmath.nstr(o1, 4), mpmath.nstr(o2, 4)))
    check("rigid limit distance > 0", all(d > 0 for d in dist.values()))
    check("rigid limit order ~ 1", 0.95 < o1 < 1.1 and 0.97 < o2 < 1.03,
          "%s %s" % (mpmath.nstr(o1, 4), mpmath.nstr(o2, 4)))
    check("rigid limit a=100 vs model.md 0.334760", abs(dist["100"] + third - mpf("0.334760")) < 1e-6)
    check("rigid limit a=1000 vs model.md 0.333475",
          abs(dist["1000"] + third - mpf("0.333475")) < 1e-6)
    # xi = 1/4 at a = 1000: the arcsin law, distance ~ 1/a
    with mp.workdps(70):
        beta = mpmath.nstr(mp.pi * 500, 60)
    r = ev("constant", beta, None, "1000", "0.3", "sine", 30)
    with mp.workdps(40):
        d = r.mu - 2 / mp.pi * mpmath.asin(mpf(1) / 4)
    note("rigid limit xi=1/4 a=1000: distance to (2/pi) asin(1/4) = %s" % mpmath.nstr(d, 6))
    check("rigid limit xi=1/4", 0 < d < 2e-3)
    # xi > 1: D' > 0 throughout, forward slip all period, mu = 1
    with mp.workdps(70):
        beta = mpmath.nstr(3 * mp.pi * 100, 60)          # xi = 3/2
    r = ev("constant", beta, None, "100", "0.7", "sine", 40)
    check("rigid xi=3/2 mu = 1", abs(r.mu - 1) < mpf(10) ** -45 and r.slip_fraction == 1,
          mpmath.nstr(r.mu, 45))

    # the ratchet
    t = time.time()
    r = ev("sine", "0", "0.5", "1", "0.25", "sine", 30)
    note("ratchet (sine, gamma=0.5, a=1, P=1/4, beta=0): mu = %s  (%.2f s)"
         % (R.fmt(r.mu, 30), time.time() - t))
    check("ratchet ~ -0.5364 (model.md)", abs(r.mu + mpf("0.5364")) < 5e-5)
    check("ratchet has backward slip", r.backward_slip_fraction > 0.1)


# --------------------------------------------------------------------------------------------
# 4. a = 0: the paper's model (mu_mpmath.py)
# --------------------------------------------------------------------------------------------

def test_paper_limit(quick):
    waves = ["sine", "triangle", "sawtooth-right", "sawtooth-left", "square", "power:2",
             "power:1.5"]
    gammas = ["-0.5", "0.3", "1.5"]
    betas = ["0.3", "2", "7"]
    if quick:
        waves, betas = waves[:5], ["0.3", "2"]
    worst = mpf(0)
    for w in waves:
        for g in gammas:
            for b in betas:
                ours = ev(w, b, g, "0", "0.37", "sine", 40)
                ref = M.evaluate("mu", w, b, g, 40)
                with mp.workdps(80):
                    d = abs(ours.mu - ref) / abs(ref)
                    worst = max(worst, d)
                check("a=0 vs mu_mpmath %s b=%s g=%s" % (w, b, g), d <= mpf(10) ** -38,
                      "%s vs %s" % (mpmath.nstr(ours.mu, 42), mpmath.nstr(ref, 42)))
                check("a=0 no backward slip %s b=%s g=%s" % (w, b, g),
                      ours.backward_slip_fraction == 0)
    note("a=0 vs mu_mpmath.py: %d waves x %d gammas x %d betas, worst relative difference %s"
         % (len(waves), len(gammas), len(betas), mpmath.nstr(worst, 3)))


# --------------------------------------------------------------------------------------------
# 5. closed forms and properties
# --------------------------------------------------------------------------------------------

def test_closed_forms():
    D = 40
    # n = 1, square drive with a >= 1: after the up-jump s = 1 (forward slip, D' = beta > 0), after
    # the down-jump s = -1 then stick s' = beta until s = 1: mu = beta/8 (beta < 4), 1 - 2/beta.
    for b in ["0.1", "1", "3.5", "4", "6", "25"]:
        for a in ["1", "1.5", "7"]:
            r = ev("constant", b, None, a, "0.3", "square", D)
            with mp.workdps(D + 20):
                bb = mpf(b)
                mu = bb / 8 if bb < 4 else 1 - 2 / bb
                st = mpf(1) / 2 if bb < 4 else 2 / bb
                check("n=1 square drive b=%s a=%s mu" % (b, a), rel_close(r.mu, mu, D),
                      "%s vs %s" % (mpmath.nstr(r.mu, 30), mpmath.nstr(mu, 30)))
                check("n=1 square drive b=%s a=%s stick" % (b, a),
                      abs(r.stick_fraction - st) < mpf(10) ** -D and r.backward_slip_fraction == 0)
    # p = w, P = 0, beta = 0, jumping, a < 1: s = a n (stick after touch-down), mu = a
    for w in ["sine", "triangle", "power:2", "sawtooth-right"]:
        for g, a in [("0.5", "0.01"), ("-0.3", "0.6"), ("0.9", "0.999")]:
            r = ev(w, "0", g, a, "0", w, D)
            with mp.workdps(D + 20):
                check("p=w P=0 beta=0 mu=a %s g=%s a=%s" % (w, g, a), rel_close(r.mu, mpf(a), D),
                      mpmath.nstr(r.mu, 30))
    # L = D - n never falls (D' - n' >= beta - 2 pi a - max n' > 0): forward slip throughout
    for w, g in [("sine", "0.5"), ("triangle", "2"), ("constant", None)]:
        r = ev(w, "15", g, "1", "0.3", "sine", D)
        check("D rising mu=1 %s" % w, abs(r.mu - 1) < mpf(10) ** -(D + 5), mpmath.nstr(r.mu, 30))
        r = ev(w, "11", g, "1.1", "0.8", "triangle", D)
        check("D rising (triangle) mu=1 %s" % w, abs(r.mu - 1) < mpf(10) ** -(D + 5))
    # n = 1, beta = 0, sine drive with a > 1: odd symmetry gives mu = 0
    for a in ["1.01", "2", "50"]:
        r = ev("constant", "0", None, a, "0.123", "sine", D)
        check("n=1 beta=0 a=%s mu=0" % a, abs(r.mu) < mpf(10) ** -(D + 5), mpmath.nstr(r.mu, 5))


def test_properties(quick):
    D = 40
    base = [("sine", "1.7", "0.2", "0.8", "sine"), ("triangle", "0.4", "1.3", "2.5", "square"),
            ("square", "2.2", "-0.4", "0.35", "sawtooth-right"),
            ("power:3", "0.9", "0.1", "1.2", "triangle")]
    for w, b, g, a, p in base:
        v = [ev(w, b, g, a, P, p, D).mu for P in ("0.3", "1.3", "-0.7")]
        check("P -> P+1 %s/%s" % (w, p), rel_close(v[0], v[1], D) and rel_close(v[0], v[2], D))
    # power:1 = triangle shifted by 1/4: mu(power:1, P) = mu(triangle, P - 1/4)
    for b, g, a, P, p in [("1.1", "0.3", "0.9", "0.6", "sine"), ("0", "-0.5", "1.4", "0.1", "square"),
                          ("3", "1.2", "0.5", "0.2", "triangle")]:
        with mp.workdps(60):
            P2 = mpmath.nstr(mpf(P) - mpf(1) / 4, 50)
        v1 = ev("power:1", b, g, a, P, p, D)
        v2 = ev("triangle", b, g, a, P2, p, D)
        check("power:1 == triangle shifted, b=%s g=%s" % (b, g), rel_close(v1.mu, v2.mu, D))
    # in-plane power:1 = triangle shifted by 1/4 in the drive
    v1 = ev("sine", "0.8", "0.4", "1.3", "0.5", "power:1", D)
    v2 = ev("sine", "0.8", "0.4", "1.3", "0.75", "triangle", D)
    check("in-plane power:1 == triangle shifted", rel_close(v1.mu, v2.mu, D))
    # n = 1: the drive's phase is a time shift
    for p in ["sine", "square", "sawtooth-right"]:
        v = [ev("constant", "1.2", None, "0.9", P, p, D).mu for P in ("0", "0.37", "-1.91")]
        check("n=1 P-invariance %s" % p, rel_close(v[0], v[1], D) and rel_close(v[0], v[2], D))
    # interval isolation of critical points = closed forms
    for c in [("sine", "0", "0.5", "1", "0.25", "sine"), ("triangle", "1.3", "0.3", "0.7", "0.1", "sine"),
              ("sine", "4", "2", "3", "0.45", "sine"), ("sine", "0.2", "0.4", "0.3", "0.7", "triangle")]:
        v1 = ev(*c, digits=D)
        R.FORCE_INTERVAL_ROOTS = True
        try:
            v2 = ev(*c, digits=D)
        finally:
            R.FORCE_INTERVAL_ROOTS = False
        check("interval roots == closed form %s" % (c,), rel_close(v1.mu, v2.mu, D + 5))
    # 15 vs 60 digits, --verify, fractions add to 1
    cases = [("sine", "0", "0.5", "1", "0.25", "sine"), ("triangle", "1.3", "0.3", "0.7", "0.1", "sine"),
             ("sine", "0.2", "0.4", "0.3", "0.7", "triangle"), ("square", "0.5", "0.2", "2", "0.35", "square"),
             ("power:2.5", "0.5", "0.2", "2", "0.35", "power:3"),
             ("power:1.5", "0.5", "-0.3", "0.3", "0.35", "sine"),
             ("sawtooth-left", "9.5", "-0.95", "48", "1.99", "sawtooth-right"),
             ("sine", "0.001", "-0.99", "0.02", "-0.9", "sine")]
    if quick:
        cases = cases[:5]
    for c in cases:
        v15 = ev(*c, digits=15)
        v60 = ev(*c, digits=60, verify=True)
        with mp.workdps(80):
            check("15 vs 60 digits %s" % (c,), rel_close(v15.mu, v60.mu, 15))
            tot = v60.stick_fraction + v60.slip_fraction + v60.flight_fraction
            check("fractions add to 1 %s" % (c,), abs(tot - 1) < mpf(10) ** -55)


# --------------------------------------------------------------------------------------------
# 6. uniqueness
# --------------------------------------------------------------------------------------------

def test_uniqueness():
    for c in [("constant", "0", None, "0.5", "0", "sine"), ("sine", "0", "1.5", "0.2", "0.3", "sine"),
              ("triangle", "0", "1.2", "0.1", "0.5", "triangle"),
              ("constant", "0", None, "0.9", "0.2", "square")]:
        try:
            ev(*c, digits=30)
            ok = False
        except R.NoUniqueState:
            ok = True
        check("no unique state %s" % (c,), ok)
    # flight forgets the start: unique at beta = 0; so does n = 0 at a single point (gamma = 1)
    r = ev("sine", "0", "0.5", "0.01", "0.3", "sine", 30)
    check("beta=0 with flight is unique", r.flight_fraction > 0)
    r = ev("triangle", "0", "1", "0.1", "0.5", "triangle", 30)
    check("beta=0 with n = 0 at a point is unique", r.flight_fraction == 0)
    # a tiny beta > 0 is unique, and close to beta = 0 when that is unique
    r0 = ev("sine", "0", "0.5", "1", "0.25", "sine", 30)
    r1 = ev("sine", "1e-20", "0.5", "1", "0.25", "sine", 30)
    check("beta=1e-20 near beta=0", abs(r1.mu - r0.mu) < 1e-18)
    r2 = ev("constant", "1e-20", None, "0.5", "0", "sine", 30)
    check("beta=1e-20 without flight: a value", abs(r2.mu) <= 1)


# --------------------------------------------------------------------------------------------
# 7. CLI
# --------------------------------------------------------------------------------------------

def run_cli(args):
    p = subprocess.run([PY, SCRIPT] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       timeout=300)
    return p.returncode, p.stdout.decode(), p.stderr.decode()


def test_cli():
    rc, out, err = run_cli(["mu", "--wave", "sine", "--beta", "0", "--gamma", "0.5",
                            "--longitudinal", "1", "--phase", "0.25", "--digits", "30"])
    lines = out.strip().split("\n")
    check("cli ok", rc == 0 and len(lines) == 6, out + err)
    if rc == 0 and len(lines) == 6:
        mant = lines[0].lstrip("-").replace(".", "").lstrip("0")
        check("cli 30 digits", len(mant) == 30, lines[0])
        names = [l.split(":")[0] for l in lines[1:]]
        check("cli line names", names == ["mean_lateral"] + list(R.FRACTIONS), str(names))
        check("cli mean_lateral 0", lines[1] == "mean_lateral: 0", lines[1])
        for l in lines[2:]:
            v = l.split(": ")[1]
            check("cli fraction 17 digits " + l,
                  v == "0" or len(v.replace(".", "").lstrip("0")) == 17)
    bad = [(["--wave", "sine", "--beta", "nan", "--gamma", "0.5", "--longitudinal", "1"], "'nan'"),
           (["--wave", "sine", "--beta", "1", "--gamma", "0.5", "--longitudinal=-0.5"], "'-0.5'"),
           (["--wave", "sine", "--beta=-2", "--gamma", "0.5", "--longitudinal", "1"], "'-2'"),
           (["--wave", "cosine", "--beta", "1", "--gamma", "0.5", "--longitudinal", "1"], "'cosine'"),
           (["--wave", "sine", "--beta", "1", "--gamma", "0.5", "--longitudinal", "1",
             "--in-plane-wave", "blob"], "'blob'"),
           (["--wave", "constant", "--beta", "1", "--gamma", "0.5", "--longitudinal", "1"], "'0.5'"),
           (["--wave", "sine", "--beta", "1", "--longitudinal", "1"], "'sine'"),
           (["--wave", "sine", "--beta", "1", "--gamma=-1", "--longitudinal", "1"], "'-1'"),
           (["--wave", "sine", "--beta", "1", "--gamma=-3", "--longitudinal", "1"], "'-3'"),
           (["--wave", "sine", "--beta", "1", "--gamma", "0.5", "--longitudinal", "inf"], "'inf'"),
           (["--wave", "sine", "--beta", "1", "--gamma", "0.5", "--longitudinal", "1",
             "--phase", "x1"], "'x1'"),
           (["--wave", "power:0.5", "--beta", "1", "--gamma", "0.5", "--longitudinal", "1"], "'0.5'"),
           (["--wave", "sine", "--beta", "1", "--gamma", "0.5", "--longitudinal", "1",
             "--digits", "0"], "'0'")]
    for args, quoted in bad:
        rc, out, err = run_cli(["mu"] + args)
        check("cli bad input exit 2 %s" % " ".join(args),
              rc == 2 and out == "" and quoted in err and len(err.strip().split("\n")) == 1,
              "rc=%d out=%r err=%r" % (rc, out, err))
    rc, out, err = run_cli(["mu", "--wave", "constant", "--beta", "0", "--longitudinal", "0.5"])
    check("cli no unique state exit 3", rc == 3 and out == "" and "unique" in err,
          "rc=%d out=%r err=%r" % (rc, out, err))


def main():
    quick = "--quick" in sys.argv[1:]
    t0 = time.time()
    sections = [("catching-up", lambda: test_catching_up(quick))]
    if not quick:
        sections.append(("crosscheck cases", test_crosscheck_cases))
    sections += [("rigid limit and ratchet", lambda: test_rigid_and_ratchet(quick)),
                 ("paper limit a=0", lambda: test_paper_limit(quick)),
                 ("closed forms", test_closed_forms),
                 ("properties", lambda: test_properties(quick)),
                 ("uniqueness", test_uniqueness),
                 ("cli", test_cli)]
    for name, fn in sections:
        t = time.time()
        fn()
        note("# section %-24s %.1f s" % (name, time.time() - t))
    note("# total %.1f s%s" % (time.time() - t0, " (--quick)" if quick else ""))
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
