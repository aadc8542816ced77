#!/usr/bin/python3
"""Cross-check of the tool's longitudinal in-plane oscillation against inplane_mpmath.py.

Usage:  /usr/bin/python3 inplane_crosscheck.py PATH/TO/vibrofric [--verbose]
        /usr/bin/python3 inplane_crosscheck.py --list      (the cases and reference values only)

For each case the tool runs as
    TOOL mu --wave W --beta=B [--gamma=G] --longitudinal=A --phase=P --in-plane-wave W2
            --type mpfr --digits 30
and its output is compared with the reference (inplane_mpmath.evaluate at 30 digits, with
--verify's second start phase, called in-process):
  * first line: |tool - ref| <= 1e-27 max(1, |ref|);
  * stick_fraction, slip_fraction, backward_slip_fraction, flight_fraction: present and within
    1e-15 (absolute) of the reference; mean_lateral, if printed, within 1e-15 of 0; with a zero
    amplitude under the normal oscillation (the paper's model) the value line alone;
  * where the reference finds no unique periodic state (beta = 0, the contact can stick through
    the period), the tool must exit with status 1 or 2 and print no number.
Cases (fixed seed, random.Random(61)): the ratchet and a rigid-limit case, the six hand-check
cases of the README, a case where n and D jump at the same phase (one projection onto the new
[-n, n], as the catching-up scheme does on any grid), two cases without a unique state, and 34
random cases covering every pair of
normal wave (sine, triangle, square, sawtooth-right, sawtooth-left, constant) and in-plane wave
(sine, triangle, square, sawtooth-right), gamma in the jumping range (-0.9, 0.95) and above 1,
a log-uniform in [0.01, 50], P in [-1, 2] (including 0, 1/4 and 1/2), beta log-uniform in
[0.03, 10] and beta = 0 in every fifth case.
beta = 0 is not combined with a square drive on a piecewise-constant n (n = 1 or the square wave):
there D' = n' = 0 on whole pieces and "slip at zero rate" and "stick" are the same motion, so the
fractions are a convention, not a result.
Each disagreement is printed with its command line; the last line is "N passed, M failed"; the
exit status is non-zero if anything failed.
"""

import math
import os
import random
import shlex
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import mpmath                       # noqa: E402
from mpmath import mp, mpf          # noqa: E402

import inplane_mpmath as R          # noqa: E402

DIGITS = 30
MU_TOL = mpf(10) ** -27             # times max(1, |ref|)
FRACTION_TOL = mpf(10) ** -15

NORMALS = ["sine", "triangle", "square", "sawtooth-right", "sawtooth-left", "constant"]
INPLANE = ["sine", "triangle", "square", "sawtooth-right"]

with mp.workdps(60):
    BETA_100PI = mpmath.nstr(100 * mp.pi, 45)          # rigid limit at xi = 1/2, a = 100


def cases():
    """[(label, wave, beta, gamma or None, a, phase, in-plane wave)], fixed seed."""
    out = [
        ("ratchet (hand 1)", "sine", "0", "0.5", "1", "0.25", "sine"),
        ("rigid limit (hand 2)", "constant", BETA_100PI, None, "100", "0", "sine"),
        ("hand 3 (a=0, paper)", "sine", "2", "1.5", "0", "0", "sine"),
        ("hand 4", "triangle", "1.3", "0.3", "0.7", "0.1", "sine"),
        ("hand 5", "sine", "0.2", "0.4", "0.3", "0.7", "triangle"),
        ("hand 6", "square", "0.5", "0.2", "2", "0.35", "square"),
        ("simultaneous jumps", "square", "1", "0.5", "0.5", "0", "square"),   # one projection
        ("no unique state (n=1)", "constant", "0", None, "0.5", "0.3", "sine"),
        ("no unique state (gamma>1)", "sine", "0", "1.5", "0.2", "0.6", "triangle"),
    ]
    rng = random.Random(61)
    pairs = [(w, p) for w in NORMALS for p in INPLANE]
    rng.shuffle(pairs)
    pairs += [(rng.choice(NORMALS), rng.choice(INPLANE)) for _ in range(10)]
    special_P = ["0", "0.25", "0.5"]
    jumping_next = {w: True for w in NORMALS}          # alternate gamma ranges per normal wave
    for i, (w, p) in enumerate(pairs):
        gamma = None
        if w != "constant":
            if jumping_next[w]:
                gamma = "%.4f" % rng.uniform(-0.9, 0.95)
            else:
                gamma = "%.4f" % rng.uniform(1.0, 3.0)
            jumping_next[w] = not jumping_next[w]
        a = "%.3g" % (10 ** rng.uniform(-2, math.log10(50)))
        if i < len(special_P):
            P = special_P[i]
        elif rng.random() < 0.25:
            P = rng.choice(special_P)
        else:
            P = "%.4f" % rng.uniform(-1, 2)
        # log-uniform beta: uniform in [0, 10] would mostly exceed the critical velocity (mu = 1)
        beta = "0" if (i % 5 == 3) else "%.3g" % (10 ** rng.uniform(-1.5, 1))
        if beta == "0" and p == "square" and w in ("constant", "square"):
            beta = "%.3g" % (10 ** rng.uniform(-1.5, 1))   # see the docstring: fractions ambiguous
        out.append(("random %d" % i, w, beta, gamma, a, P, p))
    return out


def tool_args(c):
    _, w, beta, gamma, a, P, p = c
    args = ["mu", "--wave", w, "--beta=" + beta]
    if gamma is not None:
        args.append("--gamma=" + gamma)
    args += ["--longitudinal=" + a, "--phase=" + P, "--in-plane-wave", p, "--type", "mpfr",
             "--digits", str(DIGITS)]
    return args


def reference(c):
    """Result, or the string "no unique state"."""
    _, w, beta, gamma, a, P, p = c
    try:
        return R.evaluate(w, beta, gamma, a, P, p, DIGITS, verify=True)
    except R.NoUniqueState:
        return "no unique state"


def parse(text):
    """mpf from the tool's text at 60 digits, or None."""
    with mp.workdps(60):
        try:
            v = mpf(text.strip())
        except (ValueError, TypeError):
            return None
        return v if mp.isfinite(v) else None


def compare(ref, rc, out, err, paper=False):
    """List of problems (empty: agreement). paper: a zero amplitude under the normal oscillation,
    which the tool prints as the paper's model (the value line alone)."""
    lines = [l for l in out.strip().split("\n") if l.strip()]
    if ref == "no unique state":
        probs = []
        if rc not in (1, 2):
            probs.append("reference: no unique periodic state; tool exit %d, expected 1 or 2" % rc)
        if lines and parse(lines[0]) is not None:
            probs.append("reference: no unique periodic state; tool printed a number %r" % lines[0])
        return probs
    if rc != 0:
        return ["tool exit %d: %s" % (rc, err.strip())]
    if not lines:
        return ["tool printed nothing"]
    probs = []
    with mp.workdps(60):
        t = parse(lines[0])
        if t is None:
            probs.append("first line %r is not a number" % lines[0])
        else:
            d = abs(t - ref.mu)
            if d > MU_TOL * max(1, abs(ref.mu)):
                probs.append("mu: tool %s, reference %s, difference %s"
                             % (lines[0], R.fmt(ref.mu, DIGITS + 3), mpmath.nstr(d, 3)))
        if paper:
            if len(lines) != 1:
                probs.append("zero amplitude: %d lines, the paper's model prints its value alone" % len(lines))
            return probs
        fields = {}
        for l in lines[1:]:
            if ":" in l:
                k, v = l.split(":", 1)
                fields[k.strip()] = v.strip()
        for name in R.FRACTIONS:
            if name not in fields:
                probs.append("no %s line" % name)
                continue
            v = parse(fields[name])
            want = getattr(ref, name)
            if v is None or abs(v - want) > FRACTION_TOL:
                probs.append("%s: tool %s, reference %s" % (name, fields[name],
                                                           mpmath.nstr(want, 20)))
        if "mean_lateral" in fields:
            v = parse(fields["mean_lateral"])
            if v is None or abs(v) > FRACTION_TOL:
                probs.append("mean_lateral: tool %s, expected 0" % fields["mean_lateral"])
    return probs


def main():
    argv = sys.argv[1:]
    verbose = "--verbose" in argv
    argv = [a for a in argv if a != "--verbose"]
    if argv == ["--list"]:
        for c in cases():
            ref = reference(c)
            first = ref if isinstance(ref, str) else R.fmt(ref.mu, DIGITS)
            print("%-26s %-40s vibrofric %s" % (c[0], first, " ".join(map(shlex.quote, tool_args(c)))))
        return 0
    if len(argv) != 1:
        sys.stderr.write("usage: inplane_crosscheck.py PATH/TO/vibrofric [--verbose] | --list\n")
        return 2
    tool = os.path.abspath(argv[0])
    if not os.access(tool, os.X_OK):
        sys.stderr.write("error: tool %r is not an executable file\n" % argv[0])
        return 2
    t0 = time.time()
    passed = failed = 0
    for c in cases():
        args = tool_args(c)
        cmd = " ".join(shlex.quote(x) for x in [tool] + args)
        try:
            ref = reference(c)
        except R.ModelError as e:                     # never skip: a reference failure fails
            failed += 1
            print("FAIL %s: reference error: %s\n     command   %s" % (c[0], e, cmd))
            continue
        try:
            p = subprocess.run([tool] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               timeout=600)
            rc, out, err = p.returncode, p.stdout.decode(), p.stderr.decode()
        except subprocess.TimeoutExpired:
            rc, out, err = -1, "", "timed out after 600 s"
        probs = compare(ref, rc, out, err, paper=(c[1] != "constant" and mpmath.mpf(c[4]) == 0))
        if probs:
            failed += 1
            print("FAIL %s:\n     %s\n     command   %s" % (c[0], "\n     ".join(probs), cmd))
        else:
            passed += 1
            if verbose:
                print("ok   %s: %s" % (c[0], out.strip().split("\n")[0] if out.strip() else
                                       "(exit %d, as the reference: no unique state)" % rc))
    print("# %d cases, %.1f s" % (passed + failed, time.time() - t0))
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
