#!/usr/bin/env python3
"""Every command example of README.md runs and prints what the README shows (issue: documentation
that cannot drift).

An example is a line `$ vibrofric ARGS` in a fenced block (continued by a trailing backslash),
followed by its output up to the next `$ ` line or the end of the block. A block that ends in `…`
shows the beginning of the output only: those lines must be the output's first lines. Output
that starts with `vibrofric: ` is a bad-input message: it is stderr, stdout is empty and the exit
status is 2. A command ending in `2>&1` shows stderr and stdout together. Examples run in the
repository's root (README paths such as tests/tool/data/rig.csv). Usage:
test_readme.py TOOL [README]."""
import os
import re
import shlex
import subprocess
import sys


def examples(text):
    """(line number, argument list, expected output lines, complete?) of every example."""
    out, in_block, lines = [], False, text.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("```"):
            in_block = not in_block
            i += 1
            continue
        if in_block and line.startswith("$ vibrofric "):
            start = i + 1
            command = line[2:]
            while command.endswith("\\"):
                i += 1
                command = command[:-1] + " " + lines[i].strip()
            expected, complete = [], True
            i += 1
            while i < len(lines) and not lines[i].startswith("```") and not lines[i].startswith("$ "):
                if lines[i] == "…":
                    complete = False
                else:
                    expected.append(lines[i])
                i += 1
            out.append((start, shlex.split(command)[1:], expected, complete))
            continue
        i += 1
    return out


TIME = re.compile(r"(\d[\d.]*)\s?(ns|µs|ms)\b")


def timings_from_bench(docs, results):
    """Every time a README quotes (a number with ns, µs or ms) occurs in bench/results/latest.md,
    the one run that bench/run wrote; a configured time ("minimum time of 10 ms") is no measurement."""
    measured = {(float(v), u) for v, u in TIME.findall(open(results, encoding="utf-8").read())}
    bad = []
    for doc in docs:
        for n, line in enumerate(open(doc, encoding="utf-8"), 1):
            for m in TIME.finditer(line):
                if "minimum time of" in line[:m.start()]:
                    continue
                if (float(m.group(1)), m.group(2)) not in measured:
                    bad.append("%s:%d: %s %s is not in %s" % (doc, n, m.group(1), m.group(2), results))
    return bad


def main():
    tool = sys.argv[1]
    readme = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "README.md")
    found = examples(open(readme, encoding="utf-8").read())
    failures = 0
    for line, args, expected, complete in found:
        # `2>&1` at the end shows stderr with stdout (e.g. --diagnostics): one pipe for both.
        merged = args[-1:] == ["2>&1"]
        if merged:
            args = args[:-1]
        r = subprocess.run([tool] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT if merged else subprocess.PIPE,
                           text=True, timeout=600)
        # An example of bad input shows the message (stderr) and stands for exit status 2.
        error = bool(expected) and expected[0].startswith("vibrofric: ")
        got = (r.stderr if error and not merged else r.stdout).splitlines()
        shown = got if complete else got[:len(expected)]
        if r.returncode != (2 if error else 0) or shown != expected or (error and r.stdout):
            failures += 1
            print("FAIL README.md:%d: vibrofric %s (exit %d)" % (line, " ".join(args), r.returncode))
            for k in range(max(len(shown), len(expected))):
                want = expected[k] if k < len(expected) else "<nothing>"
                have = shown[k] if k < len(shown) else "<nothing>"
                if want != have:
                    print("  line %d: README %r\n          tool   %r" % (k + 1, want, have))
            if r.stderr and not error and not merged:
                print("  stderr: " + r.stderr.strip())
        else:
            print("ok   README.md:%d: vibrofric %s" % (line, " ".join(args)))
    if not found:
        print("FAIL: no examples found in " + readme)
        return 1
    root = os.path.dirname(os.path.abspath(readme))
    for problem in timings_from_bench([readme, os.path.join(root, "bench", "README.md")],
                                      os.path.join(root, "bench", "results", "latest.md")):
        failures += 1
        print("FAIL " + problem)
    print("%d examples, %d failed" % (len(found), failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
