#!/usr/bin/python3
"""Independent cross-check: the vibrofric tool against the mpmath reference (mu_mpmath.py).

Usage:  /usr/bin/python3 crosscheck.py PATH/TO/vibrofric [--verbose]

For every point, `vibrofric mu --wave W --beta B --gamma G --digits 40` (or `psi`) is compared with
mu_mpmath.evaluate(...) at 40 digits (the reference works with 20+ guard digits and returns the
unrounded value), called in-process. A point passes if the tool prints exactly 40 significant
digits and
  * the reference value is exactly 1 (no stick, Eq. 6) and the tool prints exactly 1, or
  * the reference value is exactly 0 (Psi above beta_c) and the tool prints exactly 0, or
  * otherwise |tool - ref| <= 1e-38 |ref|.
Grid: the waves sine, triangle, sawtooth-right, sawtooth-left, square, power:1.5, power:2, power:3;
gamma non-jumping (1, 1.5, 10) and jumping (-0.999, -0.9, -0.5, -0.3, 0, 0.6, 0.99); beta from
1e-4 to above beta_c, including beta_c itself and its neighbours (for gamma < 0 the sine and power:p
have a gamma-dependent beta_c, the slope at first contact: 2 pi sqrt(1 - g^2) and
4p (1 + g)^((p-1)/p)), then Psi at a few betas, then a small-beta section (1e-8 to 1e-60, at 40
digits and at 20 digits, where agreement to 18 digits is required).
Each failure is printed with its inputs and both values; the last line is "N passed, M failed";
the exit status is non-zero if anything failed.
"""

import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import mpmath                      # noqa: E402
from mpmath import mp, mpf         # noqa: E402

import mu_mpmath as R              # noqa: E402

DIGITS = 40
REL_TOL_EXP = 38                   # agreement to 38 significant digits

WAVES = ["sine", "triangle", "sawtooth-right", "sawtooth-left", "square", "power:1.5", "power:2",
         "power:3"]
GAMMAS = ["-0.999", "-0.9", "-0.5", "-0.3", "0", "0.6", "0.99", "1", "1.5", "10"]
BETAS = ["1e-4", "1e-3", "0.01", "0.05", "0.1", "0.25", "0.5", "0.75", "1", "1.5", "2", "2.5", "3",
         "3.5", "4", "5", "6", "7", "8", "10", "12", "13", "20"]
# beta_c at gamma >= 0 (the largest slope of w), written exactly where it is a short decimal, and
# its neighbours
BETA_C = {
    "sine": ["6.2831853", "6.2831854", "6.28", "6.29"],
    "triangle": ["3.9999999", "4", "4.0000001"],
    "sawtooth-right": ["1.9999999", "2", "2.0000001"],
    "sawtooth-left": ["100", "1000"],
    "square": ["100", "1000"],
    "power:1.5": ["5.9999999", "6", "6.0000001"],
    "power:2": ["7.9999999", "8", "8.0000001"],
    "power:3": ["11.9999999", "12", "12.0000001"],
}
PSI_BETAS = ["1e-4", "0.01", "0.5", "1", "1.9", "2", "3", "3.99", "4", "5", "6.2", "7", "11.9", "20"]
TINY_BETAS = ["1e-8", "1e-15", "1e-25", "1e-35", "1e-45", "1e-60"]
TINY_GAMMAS = ["-0.9", "0", "0.05", "0.3", "0.5", "0.6", "0.99", "1.5"]
TINY_DIGITS = [40, 20]             # at 20 digits: agreement to 18 digits

passed = 0
failed = 0
failures_by_section = {}
verbose = False


def sig_digits(s):
    mant = s.lstrip("+-").split("e")[0].split("E")[0]
    return len(mant.replace(".", "").lstrip("0"))


def beta_c_gamma(wave, gamma_text):
    """beta_c(gamma) for gamma < 0 where it depends on gamma (sine, power:p), as 30-digit strings
    of beta_c and of beta_c (1 -+ 1e-9); [] otherwise."""
    with mp.workdps(60):
        g = mpf(gamma_text)
        if g >= 0:
            return []
        if wave == "sine":
            bc = 2 * mp.pi * mp.sqrt(1 - g * g)
        elif wave.startswith("power:"):
            p = mpf(wave[len("power:"):])
            bc = 4 * p * (1 + g) ** ((p - 1) / p)
        else:
            return []
        return [mpmath.nstr(x, 30, strip_zeros=True)
                for x in (bc * (1 - mpf("1e-9")), bc, bc * (1 + mpf("1e-9")))]


def run_tool(tool, args):
    p = subprocess.run([tool] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=300)
    return p.returncode, p.stdout.decode().strip(), p.stderr.decode().strip()


def check_point(tool, section, what, wave, beta, gamma, digits=DIGITS):
    global passed, failed
    tol_exp = digits - (DIGITS - REL_TOL_EXP)
    args = [what, "--wave", wave, "--beta", beta] + (["--gamma", gamma] if what == "mu" else []) \
        + ["--digits", str(digits)]
    where = "%s wave=%s beta=%s%s" % (what, wave, beta, "" if gamma is None else " gamma=" + gamma)
    problem = None
    rc, out, err = run_tool(tool, args)
    try:
        ref = R.evaluate(what, wave, beta, gamma, digits)
        ref_s = mpmath.nstr(ref, digits + 5, strip_zeros=False)
    except Exception as e:           # the reference could not evaluate: report, never skip
        ref, ref_s = None, "reference error: %s" % e
    if rc != 0:
        problem = "tool exit %d: %s" % (rc, err)
    elif ref is None:
        problem = "no reference value"
    else:
        with mp.workdps(digits + 60):
            try:
                t = mpf(out)
            except (ValueError, TypeError):
                t = None
            if t is None or not mp.isfinite(t):
                problem = "tool printed %r, not a number" % out
            elif sig_digits(out) != digits and not (ref == 0 and t == 0):
                problem = "tool printed %d significant digits, expected %d" % (sig_digits(out), digits)
            elif ref == 1:
                if t != 1:
                    problem = "reference is exactly 1 (no stick), tool is not"
            elif ref == 0:
                if t != 0:
                    problem = "reference is exactly 0, tool is not"
            else:
                rel = abs(t - ref) / abs(ref)
                if not rel <= mpf(10) ** (-tol_exp):
                    problem = "relative difference %s > 1e-%d" % (mpmath.nstr(rel, 3), tol_exp)
    if problem:
        failed += 1
        failures_by_section[section] = failures_by_section.get(section, 0) + 1
        print("FAIL %s [%s]: %s\n     tool      %s\n     reference %s\n     command   vibrofric %s"
              % (where, section, problem, out if rc == 0 else "(exit %d)" % rc, ref_s, " ".join(args)))
    else:
        passed += 1
        if verbose:
            print("ok   %s: %s" % (where, out))


def main():
    global verbose
    args = [a for a in sys.argv[1:] if a != "--verbose"]
    verbose = len(args) != len(sys.argv) - 1
    if len(args) != 1:
        sys.stderr.write("usage: crosscheck.py PATH/TO/vibrofric [--verbose]\n")
        return 2
    tool = os.path.abspath(args[0])
    t0 = time.time()
    counts = []
    for wave in WAVES:
        n0 = passed + failed
        for g in GAMMAS:
            betas = BETAS + BETA_C[wave] + beta_c_gamma(wave, g)
            for b in sorted(set(betas), key=lambda s: mpf(s)):
                check_point(tool, "mu", "mu", wave, b, g)
        counts.append("%s %d" % (wave, passed + failed - n0))
    for wave in WAVES:
        for b in sorted(set(PSI_BETAS + BETA_C[wave]), key=lambda s: mpf(s)):
            check_point(tool, "psi", "psi", wave, b, None)
    n_psi = passed + failed - sum(int(c.split()[-1]) for c in counts)
    for wave in WAVES:
        for g in TINY_GAMMAS:
            for b in TINY_BETAS:
                for d in TINY_DIGITS:
                    check_point(tool, "small beta", "mu", wave, b, g, d)
    print("# points: mu %s; psi %d; small beta %d; %.1f s"
          % (", ".join(counts), n_psi, len(WAVES) * len(TINY_GAMMAS) * len(TINY_BETAS) * len(TINY_DIGITS),
             time.time() - t0))
    if failures_by_section:
        print("# failures by section: %s" % ", ".join("%s %d" % kv for kv in failures_by_section.items()))
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
