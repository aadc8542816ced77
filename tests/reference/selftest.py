#!/usr/bin/python3
"""Self-test of mu_mpmath.py.

1. Closed forms at 50 digits (relative agreement better than 1e-52):
   Psi_str = 1 - b/2 (b < 2), Psi_stl = 2/(2+b), Psi_tri = (4-b)/(4+b) (b < 4)      (Eq. 17)
   jumping range -1 < g < 1: mu_str = b/2 (b < 2), mu_stl = b/(2+b), mu_tri = 2b/(4+b) (b < 4)
   (Eq. 19), and mu = 1 exactly above beta_c;
   square: mu = b/(4(1+g)) for b < 2(1+g), else 1 - (1+g)/b                          (Eq. 22)
   non-jumping g >= 1: mu = 1 - Psi(b)/g, with Psi_sqr = 1 - b/8 (b < 4), 2/b (b >= 4)
   (derived here from the envelope; the paper cites it from its Ref. [10]).
2. Properties: power:1 equals the triangle (a phase shift); exact self-similarity of power:p for
   -1 < g <= 0 under b -> b ((1+g0)/(1+g))^((p-1)/p); mu = 1 exactly iff b >= beta_c(g)
   (including the gamma dependence of beta_c for sine and power:p when g < 0); sine
   mu = 1 - Psi/g for g >= 1; agreement across precisions and with --verify.
3. Brute force (brute_envelope.py, no shared code): s(phi) pointwise and mu end-to-end for the
   sine (and power:p), to 1e-20.
4. CLI: output format, the sweep grid, and error messages for bad input.
Exit status is non-zero if any check fails.  --quick skips section 3 (about 40 s).
"""

import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import mpmath                                   # noqa: E402
from mpmath import mp, mpf                      # noqa: E402

import mu_mpmath as R                           # noqa: E402
import brute_envelope as B                      # noqa: E402

PY = "/usr/bin/python3"
SCRIPT = os.path.join(HERE, "mu_mpmath.py")
DIG = 50

passed = 0
failed = 0
BRUTE_LOG = []     # (worst pointwise |s_brute - s_ref|, relative mu difference)
WRAPS = []         # polyline cases with a stick phase across phase 0


def check(name, ok, detail=""):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL %s %s" % (name, detail))


def rel_close(x, y, digits):
    return abs(x - y) <= mpf(10) ** (-digits) * max(abs(y), mpf(10) ** (-digits))


def cmp_closed(name, what, wave, b, g, exact_fn, digits=DIG):
    """Compare evaluate() at `digits` with a closed form evaluated at higher precision."""
    v = R.evaluate(what, wave, b, g, digits)
    with mp.workdps(digits + 30):
        e = exact_fn(mpf(b), mpf(g) if g is not None else None)
        ok = (v == 1) if e == 1 else rel_close(v, e, digits + 2)
        check("%s %s wave=%s beta=%s gamma=%s" % (name, what, wave, b, g), ok,
              "got %s expected %s" % (mpmath.nstr(v, digits + 3), mpmath.nstr(e, digits + 3)))


# --------------------------------------------------------------------------------------------
# closed forms
# --------------------------------------------------------------------------------------------

def psi_str(b): return 1 - b / 2 if b < 2 else mpf(0)
def psi_stl(b): return 2 / (2 + b)
def psi_tri(b): return (4 - b) / (4 + b) if b < 4 else mpf(0)
def psi_sqr(b): return 1 - b / 8 if b < 4 else 2 / b


def mu_jump_str(b, g): return b / 2 if b < 2 else mpf(1)
def mu_jump_stl(b, g): return b / (2 + b)
def mu_jump_tri(b, g): return 2 * b / (4 + b) if b < 4 else mpf(1)


def mu_sqr(b, g):
    if g < 1:
        return b / (4 * (1 + g)) if b < 2 * (1 + g) else 1 - (1 + g) / b
    return 1 - psi_sqr(b) / g


def nonjump(psi):
    def f(b, g):
        v = psi(b)
        return mpf(1) if v == 0 else 1 - v / g
    return f


JUMP_G = ["-0.99", "-0.5", "0", "0.3", "0.99", "0.999999"]
NONJUMP_G = ["1", "1.25", "3", "1000"]
BETAS = {
    "sawtooth-right": ["0.001", "0.1", "0.5", "1", "1.5", "1.99", "2", "2.5", "10"],
    "sawtooth-left": ["0.001", "0.1", "0.5", "1", "2", "3.7", "10", "1000"],
    "triangle": ["0.001", "0.1", "1", "2", "3.9", "3.99999999", "4", "4.5", "100"],
    "square": ["0.001", "0.1", "0.5", "1", "1.4", "2", "3", "3.99", "4", "4.01", "7", "100"],
}
PSI = {"sawtooth-right": psi_str, "sawtooth-left": psi_stl, "triangle": psi_tri,
       "square": psi_sqr}
MUJ = {"sawtooth-right": mu_jump_str, "sawtooth-left": mu_jump_stl, "triangle": mu_jump_tri,
       "square": mu_sqr}


def test_closed_forms():
    for wave, betas in BETAS.items():
        for b in betas:
            cmp_closed("Eq17", "psi", wave, b, None, lambda bb, gg, w=wave: PSI[w](bb))
            for g in JUMP_G:
                cmp_closed("Eq19/22", "mu", wave, b, g, MUJ[wave])
            for g in NONJUMP_G:
                cmp_closed("Eq13", "mu", wave, b, g,
                           mu_sqr if wave == "square" else nonjump(PSI[wave]))
    # square at the regime boundary beta = 2(1+gamma), and power:1 == triangle
    for g in ["-0.75", "-0.5", "0", "0.5"]:
        with mp.workdps(40):
            b = mpmath.nstr(2 * (1 + mpf(g)), 30)
        cmp_closed("Eq22-boundary", "mu", "square", b, g, mu_sqr)


# --------------------------------------------------------------------------------------------
# properties
# --------------------------------------------------------------------------------------------

def test_properties():
    # power:1 is the triangle shifted by 1/4
    for b in ["0.3", "1", "3.5", "5"]:
        for g in ["-0.8", "0", "0.6", "2"]:
            v1 = R.evaluate("mu", "power:1", b, g, DIG)
            v2 = R.evaluate("mu", "triangle", b, g, DIG)
            check("power:1==triangle b=%s g=%s" % (b, g), rel_close(v1, v2, DIG + 2))

    # exact self-similarity of power:p inside the top cap (-1 < g <= 0):
    # mu(b, g) = mu(b ((1+g0)/(1+g))^((p-1)/p), g0)
    with mp.workdps(DIG + 30):
        g0 = mpf("-0.3")
        for ptxt in ["2", "3", "2.5", "7"]:
            p = mpf(ptxt)
            e = (p - 1) / p
            for g in ["-0.9", "-0.6", "-0.05", "0"]:
                gg = mpf(g)
                for b in ["0.5", "2", "5"]:
                    bb = mpf(b)
                    v = R.mu_value("power", p, bb, gg)
                    b0 = bb * ((1 + g0) / (1 + gg)) ** e
                    v0 = R.mu_value("power", p, b0, g0)
                    check("power:%s self-similar b=%s g=%s" % (ptxt, b, g),
                          rel_close(v, v0, DIG + 2),
                          "%s vs %s" % (mpmath.nstr(v, 20), mpmath.nstr(v0, 20)))

    # beta_c(gamma): mu == 1 exactly at and above, < 1 just below
    with mp.workdps(DIG + 30):
        cases = []
        for g in ["-0.9", "-0.5", "-0.1", "0", "0.5", "1", "2"]:
            gg = mpf(g)
            bc = 2 * mp.pi * (mpmath.sqrt(1 - gg * gg) if gg < 0 else 1)
            cases.append(("sine", None, gg, bc))
            for ptxt in ["1", "2", "3.5"]:
                p = mpf(ptxt)
                bcp = 4 * p * ((1 + gg) ** ((p - 1) / p) if gg < 0 else 1)
                cases.append(("power", p, gg, bcp))
        for kind, p, gg, bc in cases:
            tag = "%s%s g=%s" % (kind, "" if p is None else ":" + mpmath.nstr(p, 3),
                                 mpmath.nstr(gg, 3))
            check("beta_c above " + tag, R.mu_value(kind, p, bc * (1 + mpf("1e-30")), gg) == 1)
            check("beta_c at " + tag, R.mu_value(kind, p, bc, gg) == 1)
            below = R.mu_value(kind, p, bc * (1 - mpf("1e-6")), gg)
            check("beta_c below " + tag, below < 1 and below > 1 - mpf("1e-3"),
                  mpmath.nstr(below, 10))

    # sine (and power) non-jumping: mu = 1 - Psi/gamma
    for wave in ["sine", "power:2.5"]:
        for b in ["0.2", "1", "3", "6"]:
            psi = R.evaluate("psi", wave, b, None, DIG)
            for g in ["1", "1.7", "5", "123.456"]:
                v = R.evaluate("mu", wave, b, g, DIG)
                with mp.workdps(DIG + 30):
                    check("%s Eq13 b=%s g=%s" % (wave, b, g),
                          rel_close(v, 1 - psi / mpf(g), DIG + 2))

    # precision consistency and the --verify route (including hard corners)
    for wave, b, g in [("sine", "1.3", "0.2"), ("sine", "0.01", "-0.999999"),
                       ("power:3", "2.2", "-0.4"), ("sine", "6.2831", "0.7"),
                       ("power:1.0001", "3.9", "-0.5"), ("square", "0.3", "-0.999")]:
        v15 = R.evaluate("mu", wave, b, g, 15)
        v100 = R.evaluate("mu", wave, b, g, 100, verify=True)
        with mp.workdps(120):
            check("precision 15 vs 100 %s b=%s g=%s" % (wave, b, g), rel_close(v15, v100, 16))
    for wave, b in [("sine", "6.28318"), ("triangle", "3.9999999999"), ("power:3", "11.99999")]:
        v = R.evaluate("psi", wave, b, None, 30, verify=True)
        check("psi near beta_c verify %s b=%s" % (wave, b), v > 0)
    v = R.evaluate("psi", "triangle", "3.9999999999", None, DIG)
    with mp.workdps(DIG + 30):
        check("psi_tri near beta_c 50 digits", rel_close(v, psi_tri(mpf("3.9999999999")), DIG + 2))


# --------------------------------------------------------------------------------------------
# brute force
# --------------------------------------------------------------------------------------------

def test_brute():
    tol = mpf(10) ** -20
    points = [("sine", None, "1", "0.5"), ("sine", None, "3", "-0.5"),
              ("sine", None, "0.3", "-0.9"), ("sine", None, "2", "1"),
              ("sine", None, "5", "2"), ("sine", None, "0.5", "0"),
              ("sine", None, "4.2", "0.8"),
              ("power", "3", "2", "-0.3"), ("power", "2.5", "6", "0.5")]
    for kind, ptxt, b, g in points:
        with mp.workdps(32):
            p = mpf(ptxt) if ptxt else None
            brute = B.Brute(kind, p, mpf(b), mpf(g))
            with mp.workdps(60):
                res, _ = R.compute(kind, p, mpf(b), mpf(g))
                mu_ref = R.mu_value(kind, p, mpf(b), mpf(g))
            worst = mpf(0)
            for i in range(24):
                phi = mpf(i) / 24 + mpf(1) / 997
                sb, _ = brute.s(phi)
                with mp.workdps(60):
                    sr = R.s_at(res, (phi - res.shift) % 1)
                worst = max(worst, abs(sb - sr))
            # stick-phase ends: s = n there (brute), and the envelope is continuous
            for a, c in res.stick_phases:
                for x in (a, c):
                    phi = (x + res.shift) % 1
                    sb, _ = brute.s(phi)
                    with mp.workdps(60):
                        sr = R.s_at(res, x)
                    worst = max(worst, abs(sb - sr))
            check("brute pointwise %s:%s b=%s g=%s" % (kind, ptxt, b, g), worst < tol,
                  "worst |s_brute - s_ref| = %s" % mpmath.nstr(worst, 3))
            S, N, _ = brute.integrals()
            BRUTE_LOG.append((worst, abs(S / N - mu_ref) / mu_ref))
            check("brute mu %s:%s b=%s g=%s" % (kind, ptxt, b, g),
                  abs(S / N - mu_ref) < tol * mu_ref,
                  "brute %s ref %s" % (mpmath.nstr(S / N, 25), mpmath.nstr(mu_ref, 25)))


PWL_X = ["0", "0.1", "0.25", "0.4", "0.55", "0.7", "0.85"]
PWL_W = ["0.2", "1", "-0.3", "0.6", "-1", "0.4", "-0.6"]


def test_pwl_brute():
    """Several stick phases per period, one wrapping phase 0 (non-catalogue polyline)."""
    tol = mpf(10) ** -20
    for b, g, nphases in [("2", "0.5", 3), ("2", "1.5", 3), ("5.5", "-0.2", 3),
                          ("0.5", "-0.5", 2), ("7", "0.1", 2)]:
        with mp.workdps(32):
            xs, ws = [mpf(x) for x in PWL_X], [mpf(w) for w in PWL_W]
            brute = B.Brute("pwl", (xs, ws), mpf(b), mpf(g))
            with mp.workdps(60):
                xs6, ws6 = [mpf(x) for x in PWL_X], [mpf(w) for w in PWL_W]
                pieces, n_min, shift = R.build_pwl_pieces(xs6, ws6, mpf(g), mpf(b))
                res = R.sweep(pieces, mpf(b), n_min, shift)
                mu_ref = res.S / res.N
                phases = [((a + shift) % 1, (c + shift) % 1) for a, c in res.stick_phases]
            wraps = any(a > c for a, c in phases)
            worst = mpf(0)
            for i in range(40):
                phi = mpf(i) / 40 + mpf(1) / 997
                sb, _ = brute.s(phi)
                with mp.workdps(60):
                    sr = R.s_at(res, (phi - shift) % 1)
                worst = max(worst, abs(sb - sr))
            S, N, _ = brute.integrals(grid=100)
            check("pwl stick phases b=%s g=%s" % (b, g), len(phases) == nphases,
                  "found %d: %s" % (len(phases), [(mpmath.nstr(a, 6), mpmath.nstr(c, 6))
                                                  for a, c in phases]))
            check("pwl brute pointwise b=%s g=%s" % (b, g), worst < tol, mpmath.nstr(worst, 3))
            check("pwl brute mu b=%s g=%s" % (b, g), abs(S / N - mu_ref) < tol * mu_ref,
                  "brute %s ref %s" % (mpmath.nstr(S / N, 25), mpmath.nstr(mu_ref, 25)))
            BRUTE_LOG.append((worst, abs(S / N - mu_ref) / mu_ref))
            if wraps:
                WRAPS.append((b, g))


# --------------------------------------------------------------------------------------------
# CLI
# --------------------------------------------------------------------------------------------

def run(args):
    p = subprocess.run([PY, SCRIPT] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True)
    return p.returncode, p.stdout, p.stderr


def test_cli():
    rc, out, err = run(["mu", "--wave", "sawtooth-left", "--beta", "1", "--gamma", "0.5",
                        "--digits", "50"])
    with mp.workdps(60):
        check("cli mu", rc == 0 and out.strip() == R.fmt(mpf(1) / 3, 50), out + err)
    rc, out, err = run(["mu", "--wave", "triangle", "--beta", "5", "--gamma", "0.5",
                        "--digits", "20"])
    check("cli mu==1", rc == 0 and out.strip() == "1.0000000000000000000", out + err)
    rc, out, err = run(["psi", "--wave", "triangle", "--beta", "1", "--digits", "40"])
    with mp.workdps(60):
        check("cli psi", rc == 0 and out.strip() == R.fmt(mpf(3) / 5, 40), out + err)
    rc, out, err = run(["sweep", "--wave", "sine", "--beta", "0.1:6.0:60",
                        "--gamma=-0.9,-0.5,0,0.5,1,2", "--digits", "50"])
    lines = out.strip().split("\n")
    ok = rc == 0 and lines[0] == "wave,beta,gamma,mu_over_mu0" and len(lines) == 361
    if ok:
        rows = [l.split(",") for l in lines[1:]]
        ok = (rows[0][:3] == ["sine", "0.1", "-0.9"] and rows[59][:3] == ["sine", "6.0", "-0.9"]
              and rows[60][:3] == ["sine", "0.1", "-0.5"] and rows[-1][:3] == ["sine", "6.0", "2.0"]
              and all(len(r) == 4 for r in rows))
        # each row equals the single-point computation
        for r in (rows[5], rows[123], rows[250], rows[359]):
            v = R.evaluate("mu", "sine", r[1], r[2], 50)
            ok = ok and r[3] == R.fmt(v, 50)
    check("cli sweep", ok, (out[:300] + err))
    rc, out, err = run(["sweep", "--wave", "square", "--beta", "1:3:3", "--gamma", "0",
                        "--digits", "10"])
    check("cli sweep square", rc == 0 and out.split() == [
        "wave,beta,gamma,mu_over_mu0", "square,1.0,0.0,0.2500000000",
        "square,2.0,0.0,0.5000000000", "square,3.0,0.0,0.6666666667"], out + err)
    for args, needle in [
            (["mu", "--wave", "sine", "--beta", "1", "--gamma=-1", "--digits", "10"], "-1"),
            (["mu", "--wave", "sine", "--beta", "0", "--gamma", "0", "--digits", "10"], "beta"),
            (["mu", "--wave", "sine", "--beta", "nan", "--gamma", "0", "--digits", "10"], "nan"),
            (["mu", "--wave", "sine", "--beta", "1", "--gamma", "inf", "--digits", "10"], "inf"),
            (["mu", "--wave", "sine", "--beta", "1x", "--gamma", "0", "--digits", "10"], "1x"),
            (["mu", "--wave", "cosine", "--beta", "1", "--gamma", "0", "--digits", "10"], "cosine"),
            (["mu", "--wave", "power:0.5", "--beta", "1", "--gamma", "0", "--digits", "10"],
             "0.5"),
            (["mu", "--wave", "sine", "--beta", "1", "--gamma", "0", "--digits", "0"], "digits"),
            (["psi", "--wave", "sine", "--beta", "-2", "--digits", "10"], "-2"),
            (["sweep", "--wave", "sine", "--beta", "1:2", "--gamma", "0", "--digits", "10"],
             "FROM:TO:N")]:
        rc, out, err = run(args)
        check("cli error %s" % " ".join(args), rc == 2 and out == "" and needle in err,
              "rc=%s out=%r err=%r" % (rc, out, err))


def main():
    t0 = time.time()
    quick = "--quick" in sys.argv[1:]          # skip the (slow, ~40 s) brute-force sections
    tests = [("closed forms", test_closed_forms), ("properties", test_properties)]
    if not quick:
        tests += [("brute force", test_brute), ("polyline brute", test_pwl_brute)]
    tests += [("cli", test_cli)]
    for name, fn in tests:
        t = time.time()
        before = (passed, failed)
        fn()
        print("%-13s %4d passed, %d failed  (%.1f s)" % (name, passed - before[0],
                                                         failed - before[1], time.time() - t))
    if BRUTE_LOG:
        print("info: brute force vs reference: worst |s| difference %s, worst relative mu "
              "difference %s over %d cases; polyline cases with a stick phase across phase 0: %s"
              % (mpmath.nstr(max(w for w, _ in BRUTE_LOG), 3),
                 mpmath.nstr(max(m for _, m in BRUTE_LOG), 3), len(BRUTE_LOG), WRAPS))
    # informational: Eq. 24 as printed (exponent 1/p) is not an exact invariance for p != 2
    with mp.workdps(40):
        p, g0, g, b = mpf(3), mpf("-0.3"), mpf("-0.8"), mpf(2)
        v = R.mu_value("power", p, b, g)
        v_print = R.mu_value("power", p, b * ((1 + g0) / (1 + g)) ** (1 / p), g0)
        v_right = R.mu_value("power", p, b * ((1 + g0) / (1 + g)) ** ((p - 1) / p), g0)
        print("info: power:3, b=2, g=-0.8, g0=-0.3: mu=%s; Eq.24 as printed (1/p) gives %s; "
              "exponent (p-1)/p gives %s" % (mpmath.nstr(v, 15), mpmath.nstr(v_print, 15),
                                             mpmath.nstr(v_right, 15)))
    print("%d passed, %d failed  (%.1f s)" % (passed, failed, time.time() - t0))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
