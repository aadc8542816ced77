#!/usr/bin/python3
"""Cross-check of the tool's transverse (and combined) in-plane oscillation against planar_catchup.py.

Usage:  /usr/bin/python3 planar_crosscheck.py PATH/TO/vibrofric [--verbose]
        /usr/bin/python3 planar_crosscheck.py --list      (the cases and reference values only)

For each case the tool runs as
    TOOL mu --wave W [--gamma G] --beta B --longitudinal A --transverse A --phase P
            --in-plane-wave W2 --digits 12
(no --gamma with --wave constant) and its output is compared with the reference
(planar_catchup.extrapolate: catching-up scheme at N = 2^14 .. 2^17 steps a period, grid started at
the first contact, Richardson with the measured order; called in-process, while the tool runs):
  * first line mu:  |tool - ref| <= 3 * (the reference's mu error estimate) + 2e-10;
  * mean_lateral:   |tool - ref| <= 3 * (the reference's mean_lateral error estimate) + 2e-10.
    Why not tighter: the tool prints 12 digits, but the reference's extrapolation from four
    double-precision catching-up runs supports only about 8-9 digits; its error estimate (with a
    safety factor of 3) plus a floor of 2e-10 is what it can vouch for;
  * stick_fraction, slip_fraction, flight_fraction: present and within 1e-4 (absolute) of the
    reference's finest-N fractions (integer step counts / 2^17; they are not extrapolated and carry
    an O(1/N) error, ~1e-5, there);
  * the three fractions sum to 1 within 1e-10;
  * bad input: exit status 2 and no number printed.
Cases:
  constant n, sine drive, beta = 1, a_t = 1;
  constant n, beta = 0.5, a_l = 0.3, a_t = 0.7, P = 0.1;
  sine gamma = 0.5, beta = 1, a_t = 1;
  sine gamma = 1.5, beta = 2, a_t = 0.5, P = 0.25;
  triangle gamma = 0.5, triangle drive, beta = 1, a_l = 0.5, a_t = 0.5, P = 0.3;
  constant n, square drive, beta = 0.5, a_l = 0.6, a_t = 0.8, P = 3/8 (the drive's jumps at
    phi = 1/8 and 5/8 are nodes of every grid of the reference: grid-aligned jumps);
  transverse-only, rigid-ish: constant n, beta = 2 pi 10 (1/2), a_t = 10 (xi = 1/2, a = 10);
  4 random cases, random.Random(61): normal wave in {sine, triangle, constant}, in-plane wave in
    {sine, triangle} (no jumps anywhere), gamma in [0.3, 2], beta in [0.2, 3], a_l in [0, 1],
    a_t in [0.2, 1.5], P in {0, 1/8, 1/4, 1/2};
  bad input (exit 2 expected): --transverse -1; --transverse 1 with --gamma and --wave constant.
Each disagreement is printed with its command line; the last line is "N passed, M failed"; the
exit status is non-zero if anything failed.  Per-case tool timeout: 120 s.
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

import planar_catchup as R          # noqa: E402

DIGITS = 12
ERR_FACTOR = 3.0
ERR_FLOOR = 2e-10
FRACTION_TOL = 1e-4
SUM_TOL = 1e-10
TIMEOUT = 120.0
FRACTIONS = (("stick_fraction", "stick"), ("slip_fraction", "slip"), ("flight_fraction", "flight"))

BETA_10PI = "31.415926535897932384626433832795"      # 2 pi a xi at a = 10, xi = 1/2


def cases():
    """[(label, normal wave, gamma or None, beta, a_l, a_t, P, in-plane wave)] (strings), or for
    bad input (label, None, [tool args])."""
    out = [
        ("n=1, sine, transverse", "constant", None, "1", "0", "1", "0", "sine"),
        ("n=1, combined, P=0.1", "constant", None, "0.5", "0.3", "0.7", "0.1", "sine"),
        ("sine g=0.5, transverse", "sine", "0.5", "1", "0", "1", "0", "sine"),
        ("sine g=1.5, P=0.25", "sine", "1.5", "2", "0", "0.5", "0.25", "sine"),
        ("triangle g=0.5, tri drive", "triangle", "0.5", "1", "0.5", "0.5", "0.3", "triangle"),
        ("n=1, square drive, P=3/8", "constant", None, "0.5", "0.6", "0.8", "0.375", "square"),
        ("rigid-ish transverse a=10", "constant", None, BETA_10PI, "0", "10", "0", "sine"),
    ]
    rng = random.Random(61)
    for i in range(4):
        w = rng.choice(["sine", "triangle", "constant"])
        p = rng.choice(["sine", "triangle"])
        gamma = "%.4f" % rng.uniform(0.3, 2.0)       # drawn always: the sequence does not depend on w
        beta = "%.4f" % rng.uniform(0.2, 3.0)
        a_l = "%.4f" % rng.uniform(0.0, 1.0)
        a_t = "%.4f" % rng.uniform(0.2, 1.5)
        P = rng.choice(["0", "0.125", "0.25", "0.5"])
        out.append(("random %d" % i, w, None if w == "constant" else gamma, beta, a_l, a_t, P, p))
    out += [
        ("bad: --transverse -1", None,
         ["mu", "--wave", "sine", "--gamma", "0.5", "--beta", "1", "--transverse", "-1",
          "--digits", str(DIGITS)]),
        ("bad: constant with --gamma", None,
         ["mu", "--wave", "constant", "--gamma", "0.5", "--beta", "1", "--transverse", "1",
          "--digits", str(DIGITS)]),
    ]
    return out


def is_bad(c):
    return c[1] is None


def tool_args(c):
    if is_bad(c):
        return list(c[2])
    _, w, gamma, beta, a_l, a_t, P, p = c
    args = ["mu", "--wave", w]
    if gamma is not None:
        args += ["--gamma", gamma]
    args += ["--beta", beta, "--longitudinal", a_l, "--transverse", a_t, "--phase", P,
             "--in-plane-wave", p, "--digits", str(DIGITS)]
    return args


def reference(c):
    """planar_catchup.extrapolate() result (dict) for a good case."""
    _, w, gamma, beta, a_l, a_t, P, p = c
    g = 1.0 if gamma is None else float(gamma)
    return R.extrapolate(w, g, p, float(beta), float(a_l), float(a_t), float(P))


def parse(text):
    """float from the tool's text, or None."""
    try:
        v = float(text.strip())
    except (ValueError, TypeError):
        return None
    return v if math.isfinite(v) else None


def compare(c, ref, rc, out, err):
    """List of problems (empty: agreement)."""
    lines = [l for l in out.strip().split("\n") if l.strip()]
    if is_bad(c):
        probs = []
        if rc != 2:
            probs.append("bad input: tool exit %d, expected 2" % rc)
        if lines and parse(lines[0]) is not None:
            probs.append("bad input: tool printed a number %r" % lines[0])
        return probs
    if rc != 0:
        return ["tool exit %d: %s" % (rc, err.strip())]
    if not lines:
        return ["tool printed nothing"]
    probs = []
    t = parse(lines[0])
    if t is None:
        probs.append("first line %r is not a number" % lines[0])
    else:
        d = abs(t - ref["mu"])
        tol = ERR_FACTOR * ref["mu_error"] + ERR_FLOOR
        if not d <= tol:
            probs.append("mu: tool %s, reference %.12g (error estimate %.2g), difference %.3g > %.3g"
                         % (lines[0], ref["mu"], ref["mu_error"], d, tol))
    fields = {}
    for l in lines[1:]:
        if ":" in l:
            k, v = l.split(":", 1)
            fields[k.strip()] = v.strip()
    if "mean_lateral" not in fields:
        probs.append("no mean_lateral line")
    else:
        v = parse(fields["mean_lateral"])
        tol = ERR_FACTOR * ref["mean_lateral_error"] + ERR_FLOOR
        if v is None or not abs(v - ref["mean_lateral"]) <= tol:
            probs.append("mean_lateral: tool %s, reference %.12g (error estimate %.2g), "
                         "tolerance %.3g" % (fields["mean_lateral"], ref["mean_lateral"],
                                             ref["mean_lateral_error"], tol))
    total = 0.0
    complete = True
    for name, key in FRACTIONS:
        if name not in fields:
            probs.append("no %s line" % name)
            complete = False
            continue
        v = parse(fields[name])
        if v is None:
            probs.append("%s: %r is not a number" % (name, fields[name]))
            complete = False
            continue
        total += v
        if not abs(v - ref[key]) <= FRACTION_TOL:
            probs.append("%s: tool %s, reference %.6f (finest N; change from the previous N %.2g)"
                         % (name, fields[name], ref[key], ref["fraction_error"]))
    if complete and not abs(total - 1.0) <= SUM_TOL:
        probs.append("fractions sum to %.15g, not 1 within %g" % (total, SUM_TOL))
    return probs


def describe(ref):
    return ("mu %.10f +- %.1e  mean_lateral %.10f +- %.1e  stick %.5f slip %.5f flight %.5f"
            % (ref["mu"], ref["mu_error"], ref["mean_lateral"], ref["mean_lateral_error"],
               ref["stick"], ref["slip"], ref["flight"]))


def main():
    argv = sys.argv[1:]
    verbose = "--verbose" in argv
    argv = [a for a in argv if a != "--verbose"]
    if argv == ["--list"]:
        for c in cases():
            cmd = "vibrofric " + " ".join(map(shlex.quote, tool_args(c)))
            if is_bad(c):
                print("%-28s %-100s %s" % (c[0], "expect exit 2, no number", cmd))
                continue
            try:
                first = describe(reference(c))
            except (ValueError, RuntimeError) as e:
                first = "reference error: %s" % e
            print("%-28s %-100s %s" % (c[0], first, cmd))
        return 0
    if len(argv) != 1:
        sys.stderr.write("usage: planar_crosscheck.py PATH/TO/vibrofric [--verbose] | --list\n")
        return 2
    tool = os.path.abspath(argv[0])
    if not os.access(tool, os.X_OK) or not os.path.isfile(tool):
        sys.stderr.write("error: tool %r is not an executable file\n" % argv[0])
        return 2
    t0 = time.time()
    passed = failed = 0
    for c in cases():
        args = tool_args(c)
        cmd = " ".join(shlex.quote(x) for x in [tool] + args)
        t_start = time.time()
        # start the tool, compute the reference while it runs, then collect the tool's output
        proc = subprocess.Popen([tool] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        ref = None
        ref_error = None
        if not is_bad(c):
            try:
                ref = reference(c)
            except (ValueError, RuntimeError) as e:      # never skip: a reference failure fails
                ref_error = e
        try:
            o, e = proc.communicate(timeout=max(1.0, TIMEOUT - (time.time() - t_start)))
            rc, out, err = proc.returncode, o.decode(errors="replace"), e.decode(errors="replace")
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            rc, out, err = -1, "", "timed out after %g s" % TIMEOUT
        if ref_error is not None:
            failed += 1
            print("FAIL %s: reference error: %s\n     command   %s" % (c[0], ref_error, cmd))
            continue
        probs = compare(c, ref, rc, out, err)
        if probs:
            failed += 1
            print("FAIL %s:\n     %s\n     command   %s" % (c[0], "\n     ".join(probs), cmd))
        else:
            passed += 1
            if verbose:
                if is_bad(c):
                    print("ok   %s: exit %d (%.1f s)" % (c[0], rc, time.time() - t_start))
                else:
                    print("ok   %s: %s (reference %.10f +- %.1e; %.1f s)"
                          % (c[0], out.strip().split("\n")[0], ref["mu"], ref["mu_error"],
                             time.time() - t_start))
        sys.stdout.flush()
    print("# %d cases, %.1f s" % (passed + failed, time.time() - t0))
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
