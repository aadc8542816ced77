#!/usr/bin/python3
"""Whole-process side by side: the `vibrofric` tool of several commits, alternating, in one session.

usage: bench/tool_side_by_side.py [--rounds N] [--mpmath-runs N] LABEL=TOOL [LABEL=TOOL ...]

Each round runs every command with every tool, in an order that rotates from round to round, and
a fixed CPU workload (a pure-Python loop, the same in every round) before and after: its spread
is the noise control. Reports the median wall time of each command and tool, the ratio of each
tool to the last one, and whether the tools' outputs are identical. With --mpmath-runs, also
times tests/reference/mu_mpmath.py on the 50-digit sweep in-process (bench/run's comparison), so
the ratio to mpmath comes from the same session. Process start-up is included throughout, as a
user of the tool pays it.
"""
import argparse
import io
import os
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UNIFORM = ["--wave", "sine", "--beta", "0.01:6:100", "--gamma=-0.99:2:100", "--type", "double", "--threads", "1"]
SPHERE = ["--wave", "sine", "--profile", "sphere", "--beta", "0.5:2:4", "--gamma=-0.3,0.5,1.5", "--threads", "1"]
HARMONIC_50 = ["--wave", "sine", "--beta", "0.1:6.0:60", "--gamma=-0.9,-0.5,0,0.5,1,2", "--digits", "50"]
COMMANDS = [
    ("uniform sine sweep, 10,000 points, raw double", ["sweep"] + UNIFORM + ["--no-escalate"]),
    ("uniform sine sweep, 10,000 points, guaranteed double", ["sweep"] + UNIFORM),
    ("harmonic sweep, 360 points, 50 digits (bench/run's)", ["sweep"] + HARMONIC_50 + ["--threads", "1"]),
    ("sphere + sine, 12 points, guaranteed double", ["sweep"] + SPHERE + ["--type", "double"]),
    ("sphere + sine, 12 points, 50 digits", ["sweep"] + SPHERE + ["--digits", "50"]),
    # The ordered parallel stream (evaluate_stream) on two threads.
    ("uniform sine sweep, 250,000 points, guaranteed double, 2 threads",
     ["sweep", "--wave", "sine", "--beta", "0.01:6:500", "--gamma=-0.99:2:500", "--type", "double", "--threads", "2"]),
    ("harmonic sweep, 360 points, 50 digits, 2 threads", ["sweep"] + HARMONIC_50 + ["--threads", "2"]),
    ("sphere + sine, 12 points, 50 digits, 2 threads",
     ["sweep"] + SPHERE[:-2] + ["--digits", "50", "--threads", "2"]),
]
CONTROL = [sys.executable, "-c", "s = 0\nfor i in range(3 * 10**6): s += i * i"]


def timed(cmd):
    start = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True)
    elapsed = time.perf_counter() - start
    if p.returncode != 0:
        raise SystemExit("tool_side_by_side: %s failed (exit %d): %s" % (" ".join(cmd), p.returncode, p.stderr.strip()))
    return elapsed, p.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--mpmath-runs", type=int, default=0)
    ap.add_argument("tools", nargs="+", metavar="LABEL=TOOL")
    a = ap.parse_args()
    tools = []
    for t in a.tools:
        label, sep, path = t.partition("=")
        if not sep or not label or not os.access(path, os.X_OK):
            raise SystemExit("tool_side_by_side: '%s': expected LABEL=TOOL, TOOL an executable" % t)
        tools.append((label, path))
    times = {(c, l): [] for c, _ in COMMANDS for l, _ in tools}
    outputs = {}
    control = []
    for r in range(a.rounds):
        control.append(timed(CONTROL)[0])
        order = tools[r % len(tools):] + tools[:r % len(tools)]
        for name, args in COMMANDS:
            for label, path in order:
                elapsed, out = timed([path] + args)
                times[(name, label)].append(elapsed)
                outputs[(name, label)] = out
        control.append(timed(CONTROL)[0])
    last = tools[-1][0]
    print("# %d rounds, tools alternating (order rotated each round); wall time per command, median" % a.rounds)
    print("# tools: " + ", ".join("%s = %s" % t for t in tools))
    print("# noise control (fixed Python loop, before and after each round): median %.1f ms, min %.1f, max %.1f, %d runs"
          % (statistics.median(control) * 1e3, min(control) * 1e3, max(control) * 1e3, len(control)))
    for name, _ in COMMANDS:
        cells = []
        for label, _ in tools:
            m = statistics.median(times[(name, label)])
            ratio = m / statistics.median(times[(name, last)])
            cells.append("%s %.2f ms (%.2fx %s)" % (label, m * 1e3, ratio, last))
        same = len({outputs[(name, l)] for l, _ in tools}) == 1
        rows = len(outputs[(name, last)].strip().splitlines()) - 1
        print("%s: %s; %d rows, outputs %s" % (name, "; ".join(cells), rows, "identical" if same else "DIFFER"))
    if a.mpmath_runs > 0:
        sys.path.insert(0, os.path.join(ROOT, "tests", "reference"))
        import mu_mpmath  # noqa: E402  (Debian's mpmath)
        args = dict(wave="sine", beta_spec="0.1:6.0:60", gamma_list="-0.9,-0.5,0,0.5,1,2", digits="50", verify=False)
        runs = []
        for _ in range(a.mpmath_runs + 1):  # the first warms mpmath's caches
            buf = io.StringIO()
            start = time.perf_counter()
            mu_mpmath._sweep_cli(out=buf, **args)
            runs.append(time.perf_counter() - start)
        mp = statistics.median(runs[1:])
        name = COMMANDS[2][0]
        print("mpmath in-process, the same 50-digit sweep: %.1f ms (median of %d); ratio to the tool: %s" % (
            mp * 1e3, len(runs) - 1,
            ", ".join("%s %.1fx" % (l, mp / statistics.median(times[(name, l)])) for l, _ in tools)))


if __name__ == "__main__":
    main()
