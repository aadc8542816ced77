#!/usr/bin/env python3
"""Every command example of README.md runs and prints what the README shows (issue: documentation
that cannot drift).

An example is a line `$ vibrofric ARGS` in a fenced block (continued by a trailing backslash),
followed by its output up to the next `$ ` line or the end of the block. A block that ends in `…`
shows the beginning of the output only: those lines must be the output's first lines. Output
that starts with `vibrofric: ` is a bad-input message: it is stderr, stdout is empty and the exit
status is 2. Usage:
test_readme.py TOOL [README]."""
import os
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


def main():
    tool = sys.argv[1]
    readme = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "README.md")
    found = examples(open(readme, encoding="utf-8").read())
    failures = 0
    for line, args, expected, complete in found:
        r = subprocess.run([tool] + args, capture_output=True, text=True, timeout=600)
        # An example of bad input shows the message (stderr) and stands for exit status 2.
        error = bool(expected) and expected[0].startswith("vibrofric: ")
        got = (r.stderr if error else r.stdout).splitlines()
        shown = got if complete else got[:len(expected)]
        if r.returncode != (2 if error else 0) or shown != expected or (error and r.stdout):
            failures += 1
            print("FAIL README.md:%d: vibrofric %s (exit %d)" % (line, " ".join(args), r.returncode))
            for k in range(max(len(shown), len(expected))):
                want = expected[k] if k < len(expected) else "<nothing>"
                have = shown[k] if k < len(shown) else "<nothing>"
                if want != have:
                    print("  line %d: README %r\n          tool   %r" % (k + 1, want, have))
            if r.stderr and not error:
                print("  stderr: " + r.stderr.strip())
        else:
            print("ok   README.md:%d: vibrofric %s" % (line, " ".join(args)))
    if not found:
        print("FAIL: no examples found in " + readme)
        return 1
    print("%d examples, %d failed" % (len(found), failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
