#!/usr/bin/python3
"""In-plane oscillation on curved contacts: the tool's `mu --profile P --longitudinal A` against the
direct simulation of the spring row (row_catchup.py, written from model.md alone: every spring of
the row under the common drive by the catching-up scheme, Richardson in the phase step, two spring
rules apart).  Each value must lie within three times the reference's own error estimate (its
estimate was 5 to 40 times its true error wherever an exact row could check it), and never
closer than 1e-12 is asked (the reference runs in double).

Usage: row_crosscheck.py TOOL   (exit status 1 on any disagreement)
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# (profile, normal wave, beta, gamma, a_l, P): the combined drive in each regime the row meets
# (the centre in contact and jumping, a cone's and a sphere's row, a piecewise-linear normal wave).
CASES = [
    ("power:2", "sine", "0.3", "-0.3", "0.5", "0.25"),
    ("power:2", "sine", "0.05", "-0.5", "1", "0.25"),
    ("power:1", "sine", "0.3", "0.2", "0.6", "0.1"),
    ("power:2", "triangle", "0.4", "0", "0.7", "0.4"),
]


def main():
    tool = sys.argv[1]
    failures = 0
    for profile, wave, beta, gamma, a_l, phase in CASES:
        ref = json.loads(subprocess.run(
            [sys.executable, os.path.join(HERE, "row_catchup.py"), "--profile", profile, "--wave", wave,
             "--beta", beta, "--gamma", gamma, "--longitudinal", a_l, "--phase", phase],
            check=True, capture_output=True, text=True).stdout)
        out = json.loads(subprocess.run(
            [tool, "mu", "--wave", wave, "--beta", beta, "--gamma", gamma, "--longitudinal", a_l, "--phase", phase,
             "--profile", profile, "--digits", "15", "--format", "json"],
            check=True, capture_output=True, text=True).stdout)
        value = float(out["mu_over_mu0"])
        bound = max(3 * ref["error_estimate"], 1e-12)
        ok = abs(value - ref["mu"]) <= bound
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {profile} {wave} beta {beta} gamma {gamma} a_l {a_l} P {phase}: "
              f"tool {out['mu_over_mu0']}, row {ref['mu']:.12f} +- {ref['error_estimate']:.1e}, "
              f"apart {abs(value - ref['mu']):.1e}")
    print(f"{len(CASES) - failures} of {len(CASES)} agree")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
