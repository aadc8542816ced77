#!/usr/bin/env python3
"""A corpus of vibrofric invocations and their exact outputs, to prove a refactor byte-identical.

    record.py --tool PATH --out FILE.jsonl [--jobs N]   run every command, one JSON line each
    record.py --compare A.jsonl B.jsonl                  the commands whose rc/stdout/stderr differ
    record.py --list                                     the commands, one per line, and their count

Every command runs with the repository root as working directory (relative data paths such as
tests/tool/data/rig.csv), stdin from /dev/null, a fixed environment (LC_ALL=C) and a timeout of
60 s. Each JSON line is {"args": [...], "rc": int, "stdout": str, "stderr": str}, in corpus order
whatever --jobs. Output bytes that are not UTF-8 are kept as lone surrogates (surrogateescape),
so the record is lossless. A command that times out is recorded with rc = -999 and the stderr
"record.py: timeout after 60 s"; one killed by a signal has rc = -SIGNAL (subprocess's convention).

The corpus is built in code below, deterministically (no randomness), in categories; see
tests/corpus/README.md. Standard library only.
"""

import argparse
import concurrent.futures
import difflib
import gzip
import json
import os
import shlex
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
TIMEOUT = 60
TIMEOUT_RC = -999

# Input files, relative to the repository root (they appear in outputs and messages as typed).
DATA = "tests/corpus/data"
RIG = "tests/tool/data/rig.csv"
FUZZ = "tests/fuzz/corpus"


def data(name):
    return DATA + "/" + name


# --------------------------------------------------------------------------------------------
# Building blocks
# --------------------------------------------------------------------------------------------

CATALOGUE = ["sine", "triangle", "sawtooth-right", "sawtooth-left", "square"]
ALIASES = ["harmonic", "tri", "str", "stl", "sqr"]
POWERS = ["power:1", "power:1.5", "power:2", "power:2.5", "power:3", "power:8", "power:100"]

# Precisions: the five --type values, the default (mpfr at 50 digits) and mpfr at other digits.
P_DOUBLE = ["--type", "double"]
P_LDOUBLE = ["--type", "long-double"]
P_BIN50 = ["--type", "cpp_bin_float_50"]
P_BIN100 = ["--type", "cpp_bin_float_100"]
P_DEFAULT = []
PRECISIONS = [P_DOUBLE, P_LDOUBLE, P_BIN50, P_BIN100, P_DEFAULT,
              ["--digits", "6"], ["--digits", "20"], ["--digits", "120"]]
PRECISIONS_SHORT = [P_DOUBLE, P_LDOUBLE, P_BIN50, ["--digits", "20"]]

# Fourier and samples files of the repository that read (the fuzz seeds are read only: libFuzzer
# writes to a scratch directory). fuzz_fourier/k-max (a lone k = 100000) is left out: minutes.
FOURIER_OK = ["commas", "crlf-tabs-comments", "decaying-10", "fitted-file", "grammar-header-semicolons",
              "high-16", "huge-coefficient", "mean-and-sine", "square-like", "tangency", "three-harmonics",
              "tiny-coefficient"]
FOURIER_BAD = ["binary", "empty", "inf", "k-over", "k-twice", "mean-only", "nan", "overflow", "two-fields", "zero"]
SAMPLES_OK = ["comma-inside", "contact-beyond-31-digits", "grammar-bom-crlf-column", "grammar-one-line-commas",
              "grammar-time-value-header", "grammar-value-time-semicolons", "mixed", "near-overflow", "sawtooth",
              "sine-64", "square-like", "subnormal", "two", "walk-500", "zero-and-spike"]
SAMPLES_BAD = ["binary", "comments-commas", "constant", "empty", "grammar-empty-field", "grammar-end-point",
               "grammar-multi-column-duplicate-names", "grammar-multi-column-header",
               "grammar-multi-column-header-no-time", "grammar-multi-column-two-time-names", "grammar-ragged",
               "grammar-three-periods", "grammar-time-not-increasing", "grammar-two-columns-no-header", "inf",
               "nan", "single", "tiny-differences"]

USER_WAVES = (["fourier:%s/fuzz_fourier/%s" % (FUZZ, f) for f in FOURIER_OK] +
              ["fourier:" + data(f) for f in ("fourier-rig-k3.txt", "fourier-cosine.txt", "fourier-two-tone.tsv")] +
              ["samples:%s/fuzz_samples/%s" % (FUZZ, f) for f in SAMPLES_OK] +
              ["samples:" + data(f) for f in ("samples-triangle-8.txt", "samples-one-line.txt",
                                              "samples-time-value.csv", "samples-quoted-header.csv",
                                              "samples-offset.txt")])
# User waves that need --column, with the column.
COLUMN_WAVES = [("samples:" + RIG, "3"), ("samples:" + RIG, "displacement [um]"), ("samples:" + RIG, "2"),
                ("samples:" + RIG, "force [N]"), ("samples:" + data("samples-tabs.tsv"), "2"),
                ("samples:" + data("samples-tabs.tsv"), "force [N]")]

PROFILE_FILES = ["profile-parabola.txt", "profile-cone.txt", "profile-measured.csv", "profile-semicolons.txt"]
PROFILES = (["flat", "sphere", "cone", "power:1", "power:1.5", "power:2", "power:3", "power:8",
             "wearflat:0.1", "wearflat:1", "wearflat:10"] + ["profile:" + data(f) for f in PROFILE_FILES])

# physical: steel on steel, a flat punch of radius 1 mm (the README's example).
STEEL = ["--E1", "210e9", "--nu1", "0.3", "--E2", "210e9", "--nu2", "0.3"]
KINEMATICS = ["--v0", "1e-3", "--f", "100", "--A", "1e-5"]
FLAT = ["--radius", "1e-3"]
SHAPES = [
    ("flat", FLAT),
    ("sphere", ["--shape", "sphere", "--R", "0.01"]),
    ("cone", ["--shape", "cone", "--half-angle", "80"]),
    ("wearflat", ["--shape", "wearflat", "--R", "0.01", "--flat-radius", "2e-4"]),
    ("profile", ["--shape", "profile:" + data("profile-sphere-metres.txt")]),
]


def mu(wave, beta, gamma, *extra):
    return ["mu", "--wave", wave, "--beta", beta, "--gamma", gamma] + list(extra)


def psi(wave, beta, *extra):
    return ["psi", "--wave", wave, "--beta", beta] + list(extra)


def sweep(wave, beta, gamma, *extra):
    args = ["sweep", "--wave", wave, "--beta", beta]
    if gamma is not None:
        args += ["--gamma", gamma]
    return args + list(extra) + ["--threads", "1"]


def physical(*extra, wave="sine", materials=STEEL, kinematics=KINEMATICS, mean=("--u-mean", "-2e-6"),
             shape=FLAT, mu0="0.5"):
    return (["physical", "--wave", wave] + list(materials) + list(kinematics) + list(mean) +
            ["--mu0", mu0] + list(shape) + list(extra))


def trace(wave, beta, gamma, *extra):
    return ["trace", "--wave", wave, "--beta", beta, "--gamma", gamma] + list(extra)


def readme_examples(path):
    """The `$ vibrofric ...` lines of README.md in fenced blocks (backslash continuations joined),
    as argument lists without `vibrofric`; and the plain `vibrofric ...` lines of fenced blocks
    that are commands (the figures'), not the usage synopsis."""
    dollar, plain, in_block = [], [], False
    lines = open(path, encoding="utf-8").read().splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("```"):
            in_block = not in_block
        elif in_block and (line.startswith("$ vibrofric ") or line.startswith("vibrofric ")):
            command = line
            while command.endswith("\\") and i + 1 < len(lines):
                i += 1
                command = command[:-1] + " " + lines[i].strip()
            words = shlex.split(command)
            if words[0] == "$":
                dollar.append(words[2:])
            elif not any(c in command for c in "[|…"):   # not the usage synopsis (placeholders)
                plain.append(words[1:])
        i += 1
    return dollar, plain


def fuzz_tool_seeds():
    """tests/fuzz/corpus/fuzz_tool: argument lists, one per line; "@S" and "@F" stand for a
    samples and a fourier file (fuzz_tool.cpp makes its own; here two files of this corpus with
    the same contents)."""
    out = []
    folder = os.path.join(ROOT, FUZZ, "fuzz_tool")
    for name in sorted(os.listdir(folder)):
        raw = open(os.path.join(folder, name), "rb").read()
        text = raw.decode("utf-8", "surrogateescape")
        if text.endswith("\n"):
            text = text[:-1]
        args = text.split("\n")
        args = [a.replace("@S", "samples:" + data("samples-one-line.txt"))
                 .replace("@F", "fourier:%s/fuzz_fourier/three-harmonics" % FUZZ) for a in args]
        out.append(args)
    return out


# --------------------------------------------------------------------------------------------
# The corpus, by category
# --------------------------------------------------------------------------------------------

COMMANDS = ["mu", "psi", "sweep", "physical", "trace", "fit", "verify", "version"]
CLAIMS = ["eq6", "eq13", "eq17", "eq18", "eq19", "eq20-21", "eq22", "eq23", "eq24", "sec3", "fig3",
          "fig4-bunching", "fig4-minimum", "fig4-scaling", "eqs7-13", "eq6-jumping", "entanglement",
          "continuity", "uniqueness", "convexity", "eq23-range", "fig2", "beta-c", "scope-wearflat",
          "curved-eq6-sec3", "curved-power-flat"]
# Not in the corpus: `verify --claim scope-numerics` and the whole `verify` (which includes it)
# print CPU times measured at run time, so their output differs from run to run.


def cat_help(add):
    add([])
    for h in ("--help", "-h", "help"):
        add([h])
    for c in COMMANDS:
        add([c, "--help"])
        add([c, "-h"])
    add(["mu", "--wave", "sine", "--help"])
    add(["mu", "--wave", "sine", "--beta", "1", "--gamma", "0.5", "-h"])
    add(["sweep", "--bogus", "--help"])
    add(["mu", "--help", "--beta"])
    add(["help", "mu"])
    add(["--help", "mu"])
    add(["--version"])
    add(["-v"])


def cat_version(add):
    add(["version"])
    add(["version", "--bogus"])
    add(["version", "extra"])
    add(["version", "--digits", "5"])


def cat_mu_grid(add):
    """The catalogue waves over a β × γ grid in every number type and several mpfr precisions."""
    for wave in CATALOGUE:
        for beta in ("0.05", "0.5", "1", "2", "4", "7"):
            for gamma in ("-0.9", "-0.5", "0", "0.5", "1", "3"):
                for p in PRECISIONS:
                    add(mu(wave, beta, gamma, *p))


def cat_mu_power(add):
    for wave in POWERS:
        for beta in ("0.1", "1", "3", "12"):
            for gamma in ("-0.7", "0", "0.8", "2"):
                for p in PRECISIONS_SHORT:
                    add(mu(wave, beta, gamma, *p))
    # power:P spellings and extremes
    for wave in ("power:1.0", "power:1e0", "power:+2", "power:2.000", "power:1.000001", "power:1.25",
                 "power:4", "power:16", "power:1000", "power:1e6", "power:123456.789"):
        for p in (P_DOUBLE, ["--digits", "20"], P_BIN100):
            add(mu(wave, "1", "0.5", *p))
            add(mu(wave, "2", "-0.5", *p))
        add(psi(wave, "1", *P_DOUBLE))


def cat_mu_aliases(add):
    for alias, name in zip(ALIASES, CATALOGUE):
        for w in (alias, name):
            for fmt in ("text", "csv", "json"):
                add(mu(w, "1", "-0.3", "--format", fmt))
                add(mu(w, "1.5", "0.25", "--type", "double", "--format", fmt))
            add(psi(w, "1", "--digits", "30", "--format", "json"))


def cat_mu_corners(add):
    """Where the ladder escalates: β → 0, γ → −1, β at β_c, huge β and γ, long decimals."""
    points = [("1e-9", "-0.999999"), ("1e-6", "0.5"), ("1e-3", "-0.99"), ("1e-4", "2"), ("1e6", "0.5"),
              ("1e300", "0"), ("1", "-0.999999999999"), ("1", "1e6"), ("1", "1e-300"), ("0.3", "-1e-30"),
              ("1.0000000000000000000000000000001", "0.50000000000000000000000000001"),
              ("2", "0.5"), ("4", "0.5"), ("3.9999999999999999", "0.5"), ("4.0000000000000001", "-0.2"),
              ("6.283185307179586", "0.3"), ("6.2831853071795865", "0"), ("12", "0"),
              ("5.4", "-0.5"), ("0.5", "-0.5"), ("2", "1")]
    for wave in CATALOGUE + ["power:3"]:
        for beta, gamma in points:
            for p in (P_DOUBLE, P_LDOUBLE, P_BIN50, P_BIN100, ["--digits", "17"], P_DEFAULT):
                add(mu(wave, beta, gamma, *p))


def cat_mu_digits(add):
    for d in ("1", "2", "3", "5", "10", "15", "16", "17", "18", "21", "30", "49", "50", "51", "99", "100",
              "101", "200", "333", "500", "1000"):
        add(mu("sine", "1", "0.5", "--digits", d))
        add(mu("sawtooth-left", "1", "0.5", "--digits", d))
        add(mu("triangle", "4", "0.5", "--digits", d))
        add(mu("square", "1.5", "-0.5", "--digits", d))
        add(psi("sine", "2", "--digits", d))
    add(mu("sawtooth-left", "1", "0.5", "--digits", "10000"))
    add(mu("sine", "1", "-0.3", "--digits", "3000"))
    for p in (["--type", "mpfr"], ["--type", "mpfr", "--digits", "30"], ["--digits", "30", "--type", "mpfr"],
              ["--type=mpfr", "--digits=7"]):
        add(mu("sine", "1", "-0.3", *p))
        add(mu("sawtooth-left", "1", "0.5", *p))


def cat_mu_escalate(add):
    """--no-escalate and its switch values on the fixed types."""
    for wave in CATALOGUE + ["power:2.5", "power:1e6"]:
        for beta, gamma in (("1", "0.5"), ("1e-6", "-0.999"), ("0.7", "-0.3")):
            for p in (P_DOUBLE, P_LDOUBLE, P_BIN50, P_BIN100):
                add(mu(wave, beta, gamma, *p, "--no-escalate"))
    for v in ("true", "false", "yes", "no", "1", "0"):
        add(mu("sine", "1e-6", "-0.999", "--type", "double", "--no-escalate=" + v))
        add(mu("sine", "1", "0.5", "--no-escalate=" + v))
    add(mu("sine", "1", "0.5", "--no-escalate"))
    add(psi("sine", "0.001", "--type", "double", "--no-escalate"))
    add(psi("sine", "0.001", "--type", "long-double", "--no-escalate"))


def cat_mu_solver(add):
    """Solver controls: area method, root-finder budget, tanh-sinh levels and tolerance."""
    for wave in CATALOGUE + ["power:3", "fourier:%s/fuzz_fourier/three-harmonics" % FUZZ,
                             "samples:%s/fuzz_samples/sine-64" % FUZZ]:
        for area in ("auto", "exact", "quadrature"):
            for p in (P_DOUBLE, ["--digits", "10"], ["--digits", "30"]):
                add(mu(wave, "1", "-0.3", "--area", area, *p))
            add(psi(wave, "1.5", "--area", area, "--digits", "20"))
    for it in ("1", "2", "5", "20", "100", "100000"):
        add(mu("sine", "1", "0.5", "--max-iterations", it))
        add(mu("sine", "1", "0.5", "--max-iterations", it, "--type", "double"))
        add(psi("triangle", "1", "--max-iterations", it))
    for lv in ("4", "6", "10", "30"):
        add(mu("sine", "1", "0.5", "--area", "quadrature", "--max-levels", lv, "--digits", "20"))
        add(mu("sine", "1", "0.5", "--max-levels", lv))
    for tol in ("0.5", "1e-3", "1e-10", "1e-30", "1e-300"):
        add(mu("sine", "1", "0.5", "--area", "quadrature", "--quadrature-tolerance", tol, "--digits", "20"))
        add(mu("sine", "1", "0.5", "--area", "quadrature", "--quadrature-tolerance", tol, "--max-levels", "4"))
    add(mu("sine", "1", "0.5", "--area", "quadrature", "--quadrature-tolerance", "1e-300", "--max-levels", "4"))
    add(mu("sine", "1", "0.5", "--area", "quadrature", "--digits", "100"))
    add(psi("sine", "1", "--area", "quadrature", "--type", "cpp_bin_float_50"))
    add(psi("fourier:%s/fuzz_fourier/three-harmonics" % FUZZ, "2", "--area", "quadrature", "--digits", "25"))


def cat_mu_syntax(add):
    """Flags as `--flag=value`, in any order, and number spellings."""
    add(["mu", "--wave=sine", "--beta=1", "--gamma=-0.3", "--type=double"])
    add(["mu", "--gamma", "-0.3", "--beta", "1", "--wave", "sine"])
    add(["mu", "--digits", "12", "--gamma=-0.3", "--wave", "sine", "--beta=1"])
    add(["mu", "--format=json", "--wave=tri", "--beta=1", "--gamma=-0.5", "--digits=5"])
    for beta in ("1", "1.", ".5", "+1", "1e0", "1E0", "0001", "10e-1", "0.1e+1", "1.000000000000000000000000000001",
                 "3.14159265358979323846264338327950288419716939937510582097494459",
                 "100000000000000000000", "1e-300", "4.9e-324", "2.2250738585072014e-308", "1.7976931348623157e308"):
        add(mu("sine", beta, "0.5", "--type", "double"))
        add(mu("sine", beta, "0.5", "--digits", "25"))
    for gamma in ("-0", "+0", "0.0", "-0.0", "0e10", "-.5", "-5e-1", "1e-320", "-0.99999999999999999999",
                  "0.30000000000000004", "1e308", "-1e-308"):
        add(mu("sine", "1", gamma, "--type", "double"))
        add(mu("triangle", "2", gamma, "--digits", "25"))
    add(mu("sine", "1", "0.5", "--diagnostics"))
    add(mu("sine", "1", "0.5", "--diagnostics=false"))
    add(mu("power:2", "1", "0.5", "--diagnostics", "--type", "double"))


def cat_formats(add):
    for fmt in ("text", "csv", "json"):
        for wave in CATALOGUE + ["power:2", "fourier:" + data("fourier-cosine.txt"),
                                 "samples:" + data("samples-quoted-header.csv")]:
            for p in (P_DOUBLE, ["--digits", "12"], P_BIN100):
                add(mu(wave, "1.25", "-0.4", "--format", fmt, *p))
                add(psi(wave, "0.75", "--format", fmt, *p))
        for prof in ("sphere", "cone", "wearflat:1", "power:3", "profile:" + data("profile-parabola.txt")):
            add(mu("sine", "1", "0.5", "--profile", prof, "--format", fmt, "--type", "double"))
        add(mu("samples:" + RIG, "2", "-0.2", "--column", "displacement [um]", "--format", fmt, "--type", "double"))
        add(mu("sine", "1", "0.5", "--profile", "flat", "--format", fmt))
        add(psi("sine", "1", "--profile", "flat", "--format", fmt))
    # A wave name with a comma or a quote is quoted in CSV (RFC 4180).
    add(mu("samples:%s/fuzz_samples/comma-inside" % FUZZ, "1", "0.5", "--format", "csv"))


def cat_psi(add):
    for wave in CATALOGUE:
        for beta in ("0.01", "0.1", "0.5", "1", "2", "3.99", "4", "6.5", "8", "100"):
            for p in PRECISIONS:
                add(psi(wave, beta, *p))
    for wave in POWERS:
        for beta in ("0.2", "1", "5", "40"):
            for p in (P_DOUBLE, ["--digits", "20"], P_BIN50):
                add(psi(wave, beta, *p))
    for wave in USER_WAVES:
        for beta in ("0.5", "2"):
            add(psi(wave, beta, "--type", "double"))
            add(psi(wave, beta, "--digits", "20"))
    for wave, column in COLUMN_WAVES:
        add(psi(wave, "1", "--column", column, "--type", "double"))
    for prof in ("sphere", "cone", "power:3", "wearflat:1", "profile:" + data("profile-cone.txt"), "ball"):
        add(psi("sine", "1", "--profile", prof))


def cat_user_waves(add):
    points = (("0.5", "0.2"), ("2", "-0.3"), ("1", "1.5"))
    for wave in USER_WAVES:
        for beta, gamma in points:
            for p in (P_DOUBLE, P_LDOUBLE, ["--digits", "20"], P_BIN50):
                add(mu(wave, beta, gamma, *p))
        add(mu(wave, "1", "0.5", "--diagnostics", "--type", "double"))
        add(mu(wave, "1", "-5", "--diagnostics"))
        add(mu(wave, "1", "0.5", "--column", "1"))
    for wave, column in COLUMN_WAVES:
        for beta, gamma in points + (("2", "-0.2"),):
            for p in (P_DOUBLE, ["--digits", "20"]):
                add(mu(wave, beta, gamma, "--column", column, *p))
        add(mu(wave, "2", "-0.2", "--column", column, "--type", "double", "--diagnostics"))
        add(mu(wave, "2", "-0.2", "--column", column, "--diagnostics=yes", "--format", "json"))
    # --column: out of range, not in the header, on waves that have none
    for column in ("0", "4", "-1", "1.5", "", "displacement", "DISPLACEMENT [UM]", " 3", "time [s]", "1"):
        add(mu("samples:" + RIG, "1", "0.5", "--column", column))
    for column in ("1", "2"):
        add(mu("samples:" + data("samples-one-line.txt"), "1", "0.5", "--column", column))
        add(mu("fourier:" + data("fourier-cosine.txt"), "1", "0.5", "--column", column))
        add(mu("sine", "1", "0.5", "--column", column))
        add(mu("power:2", "1", "0.5", "--column", column))
    add(mu("samples:" + RIG, "1", "0.5"))
    add(mu("samples:" + RIG, "2", "-0.2", "--column", "3", "--diagnostics", "--type", "long-double"))
    # Files that do not read: every one is exit 2 with a message naming the file and the line.
    for f in FOURIER_BAD:
        add(mu("fourier:%s/fuzz_fourier/%s" % (FUZZ, f), "1", "0.5"))
        add(mu("samples:%s/fuzz_fourier/%s" % (FUZZ, f), "1", "0.5", "--type", "double"))
    for f in SAMPLES_BAD:
        add(mu("samples:%s/fuzz_samples/%s" % (FUZZ, f), "1", "0.5"))
        add(mu("fourier:%s/fuzz_samples/%s" % (FUZZ, f), "1", "0.5", "--type", "double"))
    for f in ("fourier-bad-k-float.txt", "fourier-bad-k-negative.txt", "fourier-bad-header.txt",
              "fourier-bad-quoted.txt"):
        add(mu("fourier:" + data(f), "1", "0.5"))
    for f in ("samples-bad-nbsp.txt", "samples-bad-two-columns.txt", "samples-bad-no-end-point.csv",
              "samples-bad-quote-separator.csv", "samples-bad-decimal-comma.txt", "samples-tabs.tsv"):
        add(mu("samples:" + data(f), "1", "0.5"))
    for w in ("fourier:" + DATA, "samples:" + DATA, "fourier:" + data("no-such-file.txt"),
              "samples:" + data("no-such-file.txt"), "fourier:/dev/null", "samples:/dev/null",
              "samples:" + data("fourier-cosine.txt"), "fourier:" + data("samples-triangle-8.txt"),
              "fourier:" + RIG, "samples:" + data("profile-cone.txt")):
        add(mu(w, "1", "0.5"))
    for f in SAMPLES_OK[:6]:
        add(["sweep", "--wave", "samples:%s/fuzz_samples/%s" % (FUZZ, f), "--beta", "0.5:2:4", "--gamma", "0,0.5",
             "--type", "double", "--threads", "1"])


def cat_profiles(add):
    """Curved contacts: cheap precisions mostly (double, long double, digits up to 20), a few at
    30 to 50 digits."""
    points = (("1", "0.5"), ("0.3", "-0.5"), ("2.5", "1.5"), ("8", "0"))
    for prof in PROFILES[1:]:
        for wave in CATALOGUE:
            for beta, gamma in points:
                add(mu(wave, beta, gamma, "--profile", prof, "--type", "double"))
            add(mu(wave, "1", "0.5", "--profile", prof, "--digits", "6"))
        add(mu("sine", "1", "0.5", "--profile", prof, "--type", "long-double"))
        add(mu("sine", "1", "-0.3", "--profile", prof, "--digits", "10"))
        add(mu("triangle", "1", "-0.5", "--profile", prof, "--digits", "20"))
        add(mu("power:3", "1", "0.5", "--profile", prof, "--type", "double"))
        add(mu("fourier:%s/fuzz_fourier/three-harmonics" % FUZZ, "1", "0.5", "--profile", prof, "--type", "double"))
    for prof in PROFILES[1:] + ["power:1.0", "power:2.5", "power:100", "power:1e6", "wearflat:1e-3", "wearflat:1000"]:
        for wave in CATALOGUE + ["power:1.5", "power:4"]:
            for beta, gamma in (("0.7", "0.3"), ("1.5", "-0.6"), ("3", "1.2")):
                add(mu(wave, beta, gamma, "--profile", prof, "--digits", "12"))
            add(mu(wave, "0.7", "0.3", "--profile", prof, "--type", "long-double"))
            add(mu(wave, "1.5", "-0.6", "--profile", prof, "--type", "double"))
    for prof in ("sphere", "cone", "wearflat:1", "profile:" + data("profile-measured.csv")):
        add(mu("sine", "1", "0.5", "--profile", prof, "--digits", "20"))
        add(mu("square", "2", "0.2", "--profile", prof, "--digits", "12"))
        add(mu("sine", "1", "0.5", "--profile", prof, "--type", "cpp_bin_float_50"))
    add(mu("sine", "1", "0.5", "--profile", "sphere", "--digits", "30"))
    add(mu("sine", "1", "0.5", "--profile", "sphere", "--digits", "40"))
    add(mu("sine", "1", "0.5", "--profile", "sphere", "--digits", "50"))
    add(mu("triangle", "1", "-0.5", "--profile", "cone", "--digits", "30"))
    add(mu("sine", "1", "-0.3", "--profile", "wearflat:2", "--digits", "30"))
    add(mu("sine", "2", "1", "--profile", "profile:" + data("profile-parabola.txt"), "--digits", "30"))
    add(mu("sine", "1", "0.5", "--profile", "sphere", "--area", "quadrature", "--type", "double"))
    add(mu("sine", "1", "0.5", "--profile", "sphere", "--type", "double", "--no-escalate"))
    add(mu("sine", "1", "0.5", "--profile", "sphere", "--type", "long-double", "--no-escalate"))
    # User samples on a curved contact are slow in general (a known issue): two cheap ones, timed.
    add(mu("samples:%s/fuzz_samples/square-like" % FUZZ, "1", "0.5", "--profile", "sphere", "--type", "double"))
    add(mu("samples:%s/fuzz_samples/sawtooth" % FUZZ, "1", "0.5", "--profile", "cone", "--type", "double"))
    # A time-stamped samples file on a curved contact (rig.csv): exit 2 at every γ in this build.
    add(mu("samples:" + RIG, "1", "0.5", "--column", "3", "--profile", "sphere", "--type", "double"))
    add(mu("samples:" + RIG, "2", "-0.2", "--column", "3", "--profile", "cone", "--digits", "10"))
    # Bad profiles.
    for prof in ("power:0.5", "power:0", "power:nan", "power:", "power:x", "wearflat:0", "wearflat:-1",
                 "wearflat:", "wearflat:nan", "wearflat:inf", "ball", "Sphere", "", "profile:", "flat:1",
                 "profile:" + DATA, "profile:" + data("no-such-file.txt"), "profile:" + data("profile-bad-nan.txt"),
                 "profile:" + data("profile-bad-decreasing.txt"), "profile:" + data("profile-bad-f0.txt"),
                 "profile:" + data("profile-bad-one.txt"), "profile:" + data("profile-bad-concave.txt"),
                 "profile:" + data("profile-bad-text.txt"), "profile:" + data("profile-bad-header.csv")):
        add(mu("sine", "1", "0.5", "--profile", prof))
    add(mu("sine", "1", "5", "--profile", "profile:" + data("profile-bad-short.txt")))
    add(mu("sine", "1", "0.5", "--profile", "profile:" + data("profile-bad-short.txt"), "--type", "double"))
    add(mu("sine", "1", "-1", "--profile", "sphere"))
    add(mu("sine", "1", "-1.5", "--profile", "cone", "--type", "double"))
    add(mu("sine", "0", "0.5", "--profile", "sphere"))


def cat_sweep(add):
    for wave in CATALOGUE + ["power:2", "power:5"]:
        for fmt in ("csv", "json"):
            for p in (P_DOUBLE, ["--digits", "12"], P_BIN50):
                add(sweep(wave, "0.5:4:8", "-0.5,0,0.5,1", "--format", fmt, *p))
        add(sweep(wave, "log:0.01:100:9", "1:-0.8:10", "--type", "double"))
        add(sweep(wave, "0.1:3:5", None, "--quantity", "psi", "--digits", "15"))
        add(sweep(wave, "0.1:3:5", None, "--quantity", "psi", "--format", "json", "--type", "long-double"))
    for alias in ALIASES:
        add(sweep(alias, "1:2:2", "0", "--digits", "8"))
    # ranges: one point, descending γ, log β, many points
    add(sweep("sine", "1:1:1", "0.5", "--digits", "10"))
    add(sweep("sine", "log:2:2:1", "0.5:0.5:1", "--digits", "10"))
    add(sweep("sine", "0.1:6:60", "-0.9,-0.5,0,0.5,1,2", "--digits", "50"))
    add(sweep("sine", "log:1e-3:1e3:200", "-0.3,0.5,2", "--type", "double"))
    add(sweep("triangle", "0.02:8:400", "1,0.5,0,-0.5,-0.999", "--digits", "12"))
    add(sweep("sine", "0.1:1:10", "1:-1:5"))
    add(sweep("sine", "0.1:1:10", "-0.99:0.99:7", "--type", "long-double", "--format", "json"))
    add(sweep("sine", "log:1e-6:1e6:13", "0.5", "--type", "cpp_bin_float_100"))
    add(sweep("sine", "0.5:1:3", "-0.5", "--no-escalate", "--type", "double"))
    add(sweep("sine", "0.5:1:3", "-0.5", "--area", "quadrature", "--digits", "20"))
    add(sweep("sine", "0.5:1:3", "-0.5", "--max-iterations", "3"))
    add(sweep("square", "0.5:2:4", "1,0,-0.5", "--digits", "12", "--diagnostics"))
    add(sweep("sine", "1:2:3", "1.5,0.5,-0.5", "--format", "json", "--digits", "3"))
    add(sweep("sine", "1.00000000000000000001:1.00000000000000000003:3", "0.5", "--digits", "25"))
    add(sweep("sine", "0.3:0.7:3", "0.1:0.3:3"))
    add(sweep("sine", "1e-9:1e-8:2", "-0.999999", "--type", "double"))
    # threads: the output does not depend on them
    for th in ("1", "0", "2", "3"):
        args = sweep("sine", "0.5:4:8", "-0.5,0.5", "--digits", "20")
        add(args[:-2] + ["--threads", th])
    add(["sweep", "--wave", "sine", "--beta", "0.5:4:8", "--gamma", "-0.5,0.5", "--digits", "20"])
    # user waves
    for wave in USER_WAVES[::3]:
        add(sweep(wave, "0.5:3:6", "-0.2,0.4", "--type", "double"))
    for wave, column in COLUMN_WAVES[:2]:
        add(sweep(wave, "0.5:3:6", "-0.2,0.4", "--column", column, "--digits", "12"))
    add(sweep("fourier:" + data("fourier-rig-k3.txt"), "1:3:3", None, "--quantity", "psi", "--digits", "20"))
    # curved contacts
    for prof in PROFILES[1:]:
        add(sweep("sine", "1:4:4", "0.5,-0.3", "--profile", prof, "--type", "double"))
        add(sweep("triangle", "0.5:2:4", "-0.5,0.5,1.5", "--profile", prof, "--type", "double", "--format", "json"))
    add(sweep("sine", "1:4:4", "0.5,-0.3", "--profile", "sphere", "--digits", "12"))
    add(sweep("square", "1:4:4", "0.5,-0.3", "--profile", "cone", "--digits", "10"))
    add(sweep("sine", "1:2:2", "0.5", "--profile", "wearflat:3", "--digits", "20"))
    add(sweep("sine", "1:2:2", "0.5", "--profile", "sphere", "--quantity", "psi"))
    add(sweep("sine", "1:2:2", "0.5,5", "--profile", "profile:" + data("profile-bad-short.txt")))


def cat_physical(add):
    means = (("--u-mean", "-2e-6"), ("--u-mean", "0"), ("--u-mean", "5e-6"), ("--u-mean", "2e-5"),
             ("--u-mean", "-9.99e-6"), ("--F-N", "1"), ("--F-N", "100"), ("--F-N", "1e4"))
    for mean in means:
        for fmt in ("text", "csv", "json"):
            add(physical("--format", fmt, "--digits", "12", mean=mean))
        for p in (P_DOUBLE, P_LDOUBLE, P_BIN50, P_DEFAULT, ["--digits", "6"]):
            add(physical(*p, mean=mean))
    for wave in CATALOGUE + ALIASES + ["power:1.5", "power:4", "fourier:" + data("fourier-two-tone.tsv"),
                                       "samples:" + data("samples-time-value.csv")]:
        add(physical("--digits", "12", wave=wave))
        add(physical("--type", "double", wave=wave, mean=("--F-N", "50")))
    add(physical("--digits", "12", "--column", "3", wave="samples:" + RIG))
    add(physical("--type", "double", "--column", "displacement [um]", "--diagnostics", wave="samples:" + RIG))
    # materials: rubber (nu = 0.5), auxetic, explicit shear moduli, dissimilar bodies
    for materials in (["--E1", "210e9", "--nu1", "0.3", "--E2", "10e6", "--nu2", "0.5"],
                      ["--E1", "70e9", "--nu1", "0.33", "--E2", "1e9", "--nu2", "-0.5"],
                      ["--E1", "210e9", "--nu1", "0", "--E2", "210e9", "--nu2", "0"],
                      STEEL + ["--G1", "80e9", "--G2", "81e9"],
                      STEEL + ["--G1", "80e9"],
                      ["--E1", "1", "--nu1", "0.499999", "--E2", "1e12", "--nu2", "-0.999"]):
        add(physical("--digits", "12", materials=materials))
        add(physical("--type", "double", "--format", "json", materials=materials, mean=("--F-N", "10")))
    # kinematics: stick-free (β ≥ β_c), slow sliding, big amplitude
    for kin in (["--v0", "1", "--f", "100", "--A", "1e-5"], ["--v0", "1e-9", "--f", "100", "--A", "1e-5"],
                ["--v0", "1e-3", "--f", "1e4", "--A", "1e-3"], ["--v0", "0.1", "--f", "1", "--A", "1e-6"]):
        add(physical("--digits", "12", kinematics=kin))
        add(physical("--type", "double", kinematics=kin, mean=("--F-N", "100")))
    # shapes
    for name, shape in SHAPES:
        for mean in (("--u-mean", "-2e-6"), ("--u-mean", "3e-6"), ("--F-N", "10"), ("--F-N", "100")):
            for p in (P_DOUBLE, ["--digits", "6"], ["--digits", "12"]):
                add(physical(*p, shape=shape, mean=mean))
        for fmt in ("csv", "json"):
            add(physical("--type", "double", "--format", fmt, shape=shape))
        add(physical("--type", "long-double", shape=shape))
        add(physical("--digits", "20", shape=shape))
        add(physical("--type", "double", shape=shape, wave="triangle"))
        add(physical("--type", "double", shape=shape, wave="square", mean=("--F-N", "20")))
    add(physical("--digits", "12", shape=["--shape", "cone", "--half-angle", "45"]))
    add(physical("--digits", "12", shape=["--shape", "cone", "--half-angle", "89.9"]))
    add(physical("--digits", "12", shape=["--shape", "wearflat", "--R", "0.01", "--flat-radius", "1e-6"]))
    add(physical("--digits", "12", shape=["--shape", "flat", "--radius", "2e-3"]))
    # sweeps of one input: linear and log, csv and json
    ranges = {"--v0": ("1e-4:1e-2:3", "log:1e-4:1e-2:5"), "--A": ("1e-6:1e-5:4", "log:1e-6:1e-4:3"),
              "--f": ("10:1000:3", "log:10:1e4:4"), "--F-N": ("10:100:4", "log:1:1000:4"),
              "--u-mean": ("-5e-6:5e-6:5", "1e-5:-1e-5:5")}
    def swept(flag, spec, *extra, shape=FLAT):
        """physical with `flag` given as the range `spec` (the mean load is --F-N 100 unless swept)."""
        if flag in ("--u-mean", "--F-N"):
            return physical(*extra, shape=shape, mean=(flag, spec))
        args = physical(*extra, shape=shape, mean=("--F-N", "100"))
        args[args.index(flag) + 1] = spec
        return args

    for flag, specs in ranges.items():
        for spec in specs:
            for fmt in ("csv", "json"):
                add(swept(flag, spec, "--digits", "6", "--format", fmt))
        add(swept(flag, specs[0], "--type", "double", shape=SHAPES[1][1]))
    # README example sweep, and sweeps with rows out of the domain or two ranges
    add(physical("--digits", "6", kinematics=["--v0", "log:1e-4:1e-2:3", "--f", "100", "--A", "1e-5"],
                 mean=("--F-N", "100")))
    add(physical("--digits", "6", mean=("--u-mean", "-2e-5:0:5")))
    add(physical("--digits", "6", mean=("--u-mean", "0:-2e-5:5")))
    add(physical("--digits", "6", kinematics=["--v0", "1e-4:1e-2:3", "--f", "10:100:3", "--A", "1e-5"]))
    add(physical("--digits", "6", "--format", "text", mean=("--F-N", "1:10:3")))
    add(physical("--digits", "6", mean=("--F-N", "1:10:0")))
    add(physical("--digits", "6", mean=("--F-N", "log:0:10:3")))
    add(physical("--digits", "6", kinematics=["--v0", "1e-3", "--f", "100", "--A", "-1e-5:1e-5:3"]))
    add(physical("--digits", "6", "--format", "json", shape=["--shape", "sphere", "--R", "0.01"],
                 mean=("--u-mean", "-2e-5:1e-5:4")))


def cat_trace(add):
    for wave in CATALOGUE + ["power:2", "power:6"]:
        for beta, gamma in (("1", "0.5"), ("2", "0"), ("0.5", "-0.5"), ("3", "2"), ("10", "0")):
            add(trace(wave, beta, gamma, "--points", "10"))
            add(trace(wave, beta, gamma, "--points", "37", "--digits", "30"))
        add(trace(wave, "1", "-0.3"))
        add(trace(wave, "1", "-0.3", "--points", "2"))
        add(trace(wave, "1", "-0.3", "--points", "100", "--digits", "5"))
    for d in ("1", "3", "17", "50", "120"):
        add(trace("sine", "2", "0", "--points", "8", "--digits", d))
    add(trace("sine", "2", "0"))
    add(trace("sine", "2", "0", "--points", "5000", "--digits", "8"))
    add(trace("sine", "1e-6", "-0.999", "--points", "10"))
    add(trace("sine", "1", "0.5", "--points=20", "--digits=6"))
    for wave in USER_WAVES[::2]:
        add(trace(wave, "1", "0.2", "--points", "16"))
    for wave, column in COLUMN_WAVES[:3]:
        add(trace(wave, "2", "-0.2", "--points", "20", "--column", column, "--diagnostics"))
    add(trace("fourier:" + data("fourier-rig-k3.txt"), "2", "-0.2", "--points", "50", "--digits", "25"))


def cat_fit(add):
    for column in ("3", "displacement [um]", "2", "force [N]"):
        for k in ("1", "2", "3", "5", "10", "50", "99"):
            add(["fit", "--wave", "samples:" + RIG, "--column", column, "--harmonics", k])
    add(["fit", "--wave", "samples:" + RIG, "--column", "3", "--harmonics", "100"])
    add(["fit", "--wave", "samples:" + RIG, "--column", "3", "--harmonics", "3", "--diagnostics"])
    for f in SAMPLES_OK:
        for k in ("1", "2", "3", "31", "250"):
            add(["fit", "--wave", "samples:%s/fuzz_samples/%s" % (FUZZ, f), "--harmonics", k])
    for f in ("samples-triangle-8.txt", "samples-one-line.txt", "samples-time-value.csv", "samples-offset.txt",
              "samples-quoted-header.csv"):
        for k in ("1", "3", "4"):
            add(["fit", "--wave", "samples:" + data(f), "--harmonics", k])
    for column in ("2", "3"):
        add(["fit", "--wave", "samples:" + data("samples-tabs.tsv"), "--column", column, "--harmonics", "1"])
    # --output: to a device (no file is left behind), and the bad cases
    for out in ("/dev/stdout", "/dev/null", DATA, "/nonexistent-dir/x.fourier", ""):
        add(["fit", "--wave", "samples:" + RIG, "--column", "3", "--harmonics", "3", "--output", out])
    add(["fit", "--wave", "samples:" + RIG, "--column", "3", "--harmonics", "3", "--output=/dev/stdout"])
    # bad input
    for k in ("0", "-1", "10001", "x", "", "1.5", "1e2", "10000"):
        add(["fit", "--wave", "samples:%s/fuzz_samples/sine-64" % FUZZ, "--harmonics", k])
    for wave in ("sine", "power:2", "fourier:" + data("fourier-cosine.txt"), "samples:" + data("no-such-file.txt"),
                 "samples:" + RIG, "samples:%s/fuzz_samples/nan" % FUZZ):
        add(["fit", "--wave", wave, "--harmonics", "2"])
    add(["fit", "--wave", "samples:" + RIG, "--column", "3"])
    add(["fit", "--harmonics", "3"])
    add(["fit", "--wave", "samples:" + RIG, "--column", "3", "--harmonics", "3", "--digits", "20"])
    add(["fit", "--wave", "samples:" + RIG, "--column", "3", "--harmonics", "3", "--output"])


def cat_verify(add):
    for claim in CLAIMS:
        add(["verify", "--claim", claim, "--digits", "10"])
    for claim in ("eq6", "eq17", "eq19", "eq22", "sec3", "beta-c", "eq6-jumping", "entanglement"):
        add(["verify", "--claim", claim, "--digits", "13"])
        add(["verify", "--claim", claim, "--digits", "10", "--format", "json"])
    for claim in ("eq13", "eq24", "fig3", "convexity"):
        add(["verify", "--claim", claim, "--digits", "12", "--format", "json"])
        add(["verify", "--claim", claim, "--digits", "11", "--format", "text"])
    add(["verify", "--claim", "eq17"])
    add(["verify", "--claim=eq22", "--digits=20"])
    add(["verify", "--claim", "eq6", "--digits", "30"])
    # bad input
    for claim in ("eq99", "", "EQ6", "all", "eq6 ", "scope"):
        add(["verify", "--claim", claim, "--digits", "10"])
    for d in ("5", "9", "301", "abc", "", "1e2", "-10"):
        add(["verify", "--claim", "eq6", "--digits", d])
    for fmt in ("xml", "csv", ""):
        add(["verify", "--claim", "eq6", "--digits", "10", "--format", fmt])
    add(["verify", "--wave", "sine"])
    add(["verify", "--claim", "eq6", "--claim", "eq17"])
    add(["verify", "--type", "double"])
    add(["verify", "extra"])
    add(["verify", "--claim"])


def cat_bad_input(add):
    """Exit status 2 with one line on stderr (or 1 for a solver failure): recorded as they are."""
    base = ["mu", "--wave", "sine"]

    def mu_beta(v):
        return base + ["--beta", v, "--gamma", "0.5"]

    def mu_gamma(v):
        return base + ["--beta", "1", "--gamma", v]

    for v in ("0", "-1", "0.0", "-0", "0e5", "-2.5e-3", "NaN", "nan", "-nan", "inf", "-inf", "Infinity", "1e400",
              "-1e999", "1.5x", "1.5.3", "0x10", " 1", "1 ", "1e", "e5", "--", "-", "1,5", "0,5", "½", "\u00a01",
              "1e1000000000", "1e999999999", "1e-999999999", "1e-5000", ".", "+", "1_000", "٣", "1e+", "0b1"):
        add(mu_beta(v))
    for v in ("NaN", "nan", "inf", "-inf", "1e400", "-1e999", "1.5x", "1.5.3", "0x10", "-1", "-1.5", "-1.0",
              "-1.0000000000000000000001", "-2e308", "x", "0.5 ", "--"):
        add(mu_gamma(v))
    for t in ("double", "long-double", "cpp_bin_float_50"):
        add(mu_beta("1e-5000") + ["--type", t])
    add(base + ["--beta=", "--gamma", "0.5"])
    add(base + ["--beta", "", "--gamma", "0.5"])
    add(base + ["--beta", "1", "--gamma="])
    add(base + ["--beta", "1", "--gamma", ""])
    for w in CATALOGUE + ["power:2", "power:100"]:
        for v in ("-1", "-1.5", "-100"):
            add(["mu", "--wave", w, "--beta", "1", "--gamma", v])
    for w in ("power:", "power:abc", "power:0", "power:-2", "power:0.5", "power:0.999999999999", "power:2x",
              "power:nan", "power:inf", "power:1e400", "power:1e-5000", "power: 2", "power:2:3", "POWER:2"):
        add(["mu", "--wave", w, "--beta", "1", "--gamma", "0.5"])
    for v in ("0", "10001", "-5", "abc", "2.5", "", "1e3", "99999999999999999999", "+5", "05", " 5"):
        add(mu_gamma("0.5") + ["--digits", v])
    add(mu_gamma("0.5") + ["--digits", "20", "--type", "double"])
    add(mu_gamma("0.5") + ["--type", "long-double", "--digits", "20"])
    add(mu_gamma("0.5") + ["--type", "cpp_bin_float_50", "--digits", "50"])
    for v in ("float", "Double", "", "mpfr50", "quad", "bin50", "cpp_bin_float_200", "long_double", "double "):
        add(mu_gamma("0.5") + ["--type", v])
    for w in ("foo", "sin", "SINE", "power", "tri ", "", "fourier:", "samples:", "sine:2", "sine\r",
              "\ufeffsine", "sine\t", "sawtooth", "triangle-left", "sq", "samples", "fourier",
              "sine\udcff", "café"):
        add(["mu", "--wave", w, "--beta", "1", "--gamma", "0.5"])
    # commands and flags
    add(["frobnicate", "--wave", "sine"])
    add(["MU", "--wave", "sine", "--beta", "1", "--gamma", "0.5"])
    add(["--wave", "sine"])
    add([""])
    add(["mu\r"])
    add(mu_gamma("0.5") + ["--bogus", "3"])
    add(mu_gamma("0.5") + ["--bogus=3"])
    add(mu_gamma("0.5") + ["--Beta", "3"])
    add(["psi", "--wave", "sine", "--beta", "1", "--gamma", "1"])
    add(mu_gamma("0.5") + ["--threads", "1"])
    add(mu_gamma("0.5") + ["-x"])
    add(mu_gamma("0.5") + ["extra"])
    add(mu_gamma("0.5") + ["--"])
    add(mu_gamma("0.5") + ["---beta", "1"])
    add(base + ["--beta", "1", "--beta", "2", "--gamma", "0.5"])
    add(base + ["--beta=1", "--gamma", "0.5", "--gamma=0.5"])
    add(["mu", "--wave", "sine", "--wave", "tri", "--beta", "1", "--gamma", "0"])
    add(base + ["--beta", "1", "--gamma"])
    add(base + ["--beta", "--gamma", "0"])
    add(mu_gamma("0.5") + ["--digits"])
    add(mu_gamma("0.5") + ["--digits", "--type", "double"])
    add(["mu", "--beta", "1", "--gamma", "0.5"])
    add(["mu", "--wave", "sine", "--gamma", "0.5"])
    add(["mu", "--wave", "sine", "--beta", "1"])
    add(["mu"])
    add(["psi", "--wave", "sine"])
    add(["psi", "--beta", "1"])
    add(["psi", "--wave", "sine", "--beta", "nan"])
    add(["psi", "--wave", "triangle", "--beta", "0"])
    add(["psi", "--wave", "triangle", "--beta", "-1", "--type", "double"])
    for v in ("banana", "", "2", "TRUE", "on"):
        add(mu_gamma("0.5") + ["--type", "double", "--no-escalate=" + v])
        add(mu_gamma("0.5") + ["--diagnostics=" + v])
    add(mu_gamma("0.5") + ["--no-escalate", "true"])
    for v in ("fast", "", "Exact", "quad"):
        add(mu_gamma("0.5") + ["--area", v])
    for v in ("0", "100001", "-1", "x", "1.5", ""):
        add(mu_gamma("0.5") + ["--max-iterations", v])
    for v in ("3", "31", "0", "x"):
        add(mu_gamma("0.5") + ["--max-levels", v])
    for v in ("0", "1", "-1e-3", "nan", "2", "x", "1e-400"):
        add(mu_gamma("0.5") + ["--quadrature-tolerance", v])
    for fmt in ("xml", "", "JSON", "tsv"):
        add(mu_gamma("0.5") + ["--format", fmt])
        add(["psi", "--wave", "sine", "--beta", "1", "--format", fmt])
    # sweep ranges and γ lists
    sw = ["sweep", "--wave", "sine"]
    for beta in ("0:1:0", "1:2:0", "1:2:-3", "1:2:2.5", "2:1:5", "1:1:3", "1:2", "a:b:c", "1:2:3:4", "1:x:3",
                 "0:1:3", "nan:1:3", "1", "log:0:1:3", "log:-1:1:3", "log:1:2", "log:", "1:2:1", "1:2:1000001",
                 ":2:3", "1::3", "1:2:", "-1:1:3", "1:inf:3", "1e400:1e401:2", "LOG:1:2:3"):
        add(sw + ["--beta", beta, "--gamma", "0.5", "--threads", "1"])
    for gamma in ("1:0:x", "0.5,,1", "0.5,x", "0.5,", ",0.5", "0.5,-1", "nan,0.5", "", "1:1:2", "-2:0:3", "0:1",
                  "0.5;1"):
        add(sw + ["--beta", "1:2:3", "--gamma", gamma, "--threads", "1"])
    add(sw + ["--beta", "1:2:3", "--threads", "1"])
    add(sw + ["--beta", "1:2:2", "--gamma", "0.5", "--format", "text", "--threads", "1"])
    add(sw + ["--beta", "1:2:2", "--gamma", "0.5", "--format", "xml", "--threads", "1"])
    add(["sweep", "--wave", "tri", "--quantity", "psi", "--beta", "1:2:2", "--gamma", "1", "--threads", "1"])
    add(sw + ["--beta", "1:2:2", "--gamma", "0.5", "--quantity", "foo", "--threads", "1"])
    for th in ("-1", "x", "1025", "", "1.5"):
        add(sw + ["--beta", "1:2:3", "--gamma", "0.5", "--threads", th])
    add(sw + ["--beta", "1:2:3", "--gamma", "0.5", "--threads", "1", "--points", "3"])
    # physical
    for flag, value in (("--radius", "-0.001"), ("--radius", "0"), ("--nu1", "0.50001"), ("--nu2", "-1"),
                        ("--E1", "0"), ("--E2", "nan"), ("--v0", "-1"), ("--f", "inf"), ("--A", "0"),
                        ("--mu0", "0"), ("--mu0", "-0.5"), ("--u-mean", "-0.00001"), ("--u-mean", "-1"),
                        ("--G1", "-5"), ("--G2", "0"), ("--nu1", "0.70000000000000000000000000001"),
                        ("--E1", "1e400"), ("--v0", "x")):
        args = physical("--digits", "12")
        if flag in args:
            args[args.index(flag) + 1] = value
        else:
            args += [flag, value]
        add(args)
    add(physical("--digits", "12", "--F-N", "10"))
    add(physical("--digits", "12", mean=("--F-N", "-5")))
    add(physical("--digits", "12", mean=("--F-N", "0")))
    add(physical("--digits", "12", mean=()))
    no_mu0 = physical("--digits", "12")
    i = no_mu0.index("--mu0")
    add(no_mu0[:i] + no_mu0[i + 2:])
    add(physical("--digits", "12", shape=[]))
    add(physical("--digits", "12", "--gamma", "0.5"))
    add(physical("--digits", "12", "--beta", "1"))
    add(physical("--digits", "12", "--format", "xml"))
    add(physical("--digits", "12", "--profile", "sphere"))
    for shape in (["--shape", "sphere"], ["--shape", "sphere", "--R", "0"], ["--shape", "sphere", "--R", "-1"],
                  ["--shape", "cone"], ["--shape", "cone", "--half-angle", "0"], ["--shape", "cone", "--half-angle", "90"],
                  ["--shape", "cone", "--half-angle", "-10"], ["--shape", "wearflat", "--R", "0.01"],
                  ["--shape", "wearflat", "--flat-radius", "1e-4"],
                  ["--shape", "wearflat", "--R", "0.01", "--flat-radius", "0"],
                  ["--shape", "ball", "--R", "0.01"], ["--shape", "power:3"], ["--shape", "profile:"],
                  ["--shape", "profile:" + data("no-such-file.txt")],
                  ["--shape", "profile:" + data("profile-bad-concave.txt")],
                  ["--shape", "profile:" + data("profile-bad-short.txt")],
                  ["--shape", "sphere", "--R", "0.01", "--radius", "1e-3"],
                  ["--shape", "flat", "--R", "0.01"], ["--shape", "cone", "--half-angle", "60", "--R", "0.01"],
                  ["--shape", "Sphere", "--R", "0.01"]):
        add(physical("--digits", "12", shape=shape))
    # trace
    tr = ["trace", "--wave", "sine", "--beta", "1", "--gamma", "0"]
    for v in ("1", "0", "-5", "1000001", "x", "2.5", ""):
        add(tr + ["--points", v])
    for v in ("0", "10001", "x"):
        add(tr + ["--digits", v])
    add(["trace", "--wave", "sine", "--beta", "x", "--gamma", "0"])
    add(["trace", "--wave", "sine", "--beta", "0", "--gamma", "0"])
    add(["trace", "--wave", "sine", "--beta", "1", "--gamma", "-1"])
    add(["trace", "--wave", "sine", "--beta", "1"])
    add(tr + ["--type", "double"])
    add(tr + ["--format", "json"])
    add(tr + ["--profile", "sphere"])
    add(tr + ["--area", "quadrature"])


def cat_fuzz_tool(add):
    for args in fuzz_tool_seeds():
        add(args)


def cat_readme(add):
    dollar, plain = readme_examples(os.path.join(ROOT, "README.md"))
    for args in dollar:
        if args[-1:] == ["2>&1"]:          # stdout and stderr are recorded apart
            args = args[:-1]
        if args == ["verify"]:             # CPU times in the output (scope-numerics), and slow
            continue
        add(args)
    for args in plain:
        if args[0] == "sweep" and "--threads" not in args:
            args = args + ["--threads", "1"]
        add(args)


CATEGORIES = [
    ("help", cat_help), ("version", cat_version), ("readme", cat_readme), ("fuzz-tool-seeds", cat_fuzz_tool),
    ("mu-grid", cat_mu_grid), ("mu-power", cat_mu_power), ("mu-aliases", cat_mu_aliases),
    ("mu-corners", cat_mu_corners), ("mu-digits", cat_mu_digits), ("mu-escalate", cat_mu_escalate),
    ("mu-solver", cat_mu_solver), ("mu-syntax", cat_mu_syntax), ("formats", cat_formats), ("psi", cat_psi),
    ("user-waves", cat_user_waves), ("profiles", cat_profiles), ("sweep", cat_sweep), ("physical", cat_physical),
    ("trace", cat_trace), ("fit", cat_fit), ("verify", cat_verify), ("bad-input", cat_bad_input),
]


def corpus():
    """[(category, args)] in corpus order; a command already in an earlier category is not repeated."""
    out, seen = [], set()
    for name, build in CATEGORIES:
        def add(args, name=name):
            args = list(args)
            key = json.dumps(args)
            if key not in seen:
                seen.add(key)
                out.append((name, args))
        build(add)
    return out


# --------------------------------------------------------------------------------------------
# Running, comparing, listing
# --------------------------------------------------------------------------------------------

ENV = {"LC_ALL": "C", "PATH": "/usr/local/bin:/usr/bin:/bin"}


def show_arg(a):
    """One argument for a shell (bash): shlex quoting, or $'...' with \\xNN escapes when it holds
    control characters or bytes that are not UTF-8, so that every command is one line."""
    raw = a.encode("utf-8", "surrogateescape")
    if not any(b < 0x20 or b == 0x7F for b in raw) and not any(0xDC80 <= ord(c) <= 0xDCFF for c in a):
        return shlex.quote(a)
    out = "".join(chr(b) if 0x20 <= b < 0x7F and chr(b) not in "\\'" else "\\x%02x" % b for b in raw)
    return "$'" + out + "'"


def show(args):
    return " ".join(show_arg(a) for a in args)


def decode(b):
    return b.decode("utf-8", "surrogateescape")


def encode_arg(a):
    return a.encode("utf-8", "surrogateescape")


def run_one(tool, args):
    start = time.monotonic()
    try:
        p = subprocess.run([tool] + [encode_arg(a) for a in args], cwd=ROOT, env=ENV, stdin=subprocess.DEVNULL,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=TIMEOUT)
        rec = {"args": args, "rc": p.returncode, "stdout": decode(p.stdout), "stderr": decode(p.stderr)}
    except subprocess.TimeoutExpired:
        rec = {"args": args, "rc": TIMEOUT_RC, "stdout": "", "stderr": "record.py: timeout after %d s\n" % TIMEOUT}
    return rec, time.monotonic() - start


def record(tool, out_path, jobs, only, times_path):
    tool = os.path.abspath(tool)
    if not os.access(tool, os.X_OK):
        sys.exit("record.py: %s is not an executable" % tool)
    cmds = corpus()
    if only:
        cmds = [c for c in cmds if c[0] in only]
    results = [None] * len(cmds)
    started = time.monotonic()
    done = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = {pool.submit(run_one, tool, args): i for i, (_, args) in enumerate(cmds)}
        for fut in concurrent.futures.as_completed(futures):
            results[futures[fut]] = fut.result()
            done += 1
            if done % 250 == 0 or done == len(cmds):
                sys.stderr.write("record.py: %d/%d commands, %.0f s\n" % (done, len(cmds), time.monotonic() - started))
    with open(out_path, "w", encoding="utf-8") as f:
        for rec, _ in results:
            f.write(json.dumps(rec, ensure_ascii=True) + "\n")
    total = time.monotonic() - started
    per_cat, rcs = {}, {}
    for (cat, args), (rec, sec) in zip(cmds, results):
        n, s = per_cat.get(cat, (0, 0.0))
        per_cat[cat] = (n + 1, s + sec)
        rcs[rec["rc"]] = rcs.get(rec["rc"], 0) + 1
    if times_path:
        with open(times_path, "w", encoding="utf-8", errors="surrogateescape") as f:
            for (cat, args), (rec, sec) in zip(cmds, results):
                f.write("%.4f\t%s\t%d\t%s\n" % (sec, cat, rec["rc"], show(args)))
    sys.stderr.write("record.py: %d commands in %.1f s (wall, --jobs %d) to %s\n" % (len(cmds), total, jobs, out_path))
    for cat, (n, s) in per_cat.items():
        sys.stderr.write("  %-16s %5d commands %7.1f s\n" % (cat, n, s))
    sys.stderr.write("  exit statuses: %s\n" % ", ".join("%d: %d" % (k, v) for k, v in sorted(rcs.items())))
    slow = sorted(zip(results, cmds), key=lambda x: -x[0][1])[:5]
    for (rec, sec), (cat, args) in slow:
        sys.stderr.write("  slow: %.2f s  %s\n" % (sec, show(args)))
    return 0


def load(path):
    out = []
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if line.strip():
                out.append(json.loads(line))
    return out


def short_diff(name, a, b, limit=12):
    lines = list(difflib.unified_diff(a.splitlines(True), b.splitlines(True), "A " + name, "B " + name, n=1))
    shown = lines[:limit]
    text = "".join(("    " + l if l.endswith("\n") else "    " + l + "\n") for l in shown)
    if len(lines) > limit:
        text += "    ... (%d more diff lines)\n" % (len(lines) - limit)
    if a and b and a.rstrip("\n") == b.rstrip("\n"):
        text += "    (differ in trailing newlines only)\n"
    return text


def compare(path_a, path_b, common_only):
    a, b = load(path_a), load(path_b)
    key = lambda r: json.dumps(r["args"])
    index_b = {key(r): r for r in b}
    keys_a = {key(r) for r in a}
    same = differ = 0
    for ra in a:
        rb = index_b.get(key(ra))
        cmd = "vibrofric " + show(ra["args"])
        if rb is None:
            if common_only:
                continue
            differ += 1
            print("DIFFER %s\n    only in %s" % (cmd, path_a))
            continue
        if ra["rc"] == rb["rc"] and ra["stdout"] == rb["stdout"] and ra["stderr"] == rb["stderr"]:
            same += 1
            continue
        differ += 1
        print("DIFFER " + cmd)
        if ra["rc"] != rb["rc"]:
            print("    rc: %d -> %d" % (ra["rc"], rb["rc"]))
        for stream in ("stdout", "stderr"):
            if ra[stream] != rb[stream]:
                sys.stdout.write(short_diff(stream, ra[stream], rb[stream]))
    if not common_only:
        for rb in b:
            if key(rb) not in keys_a:
                differ += 1
                print("DIFFER vibrofric %s\n    only in %s" % (show(rb["args"]), path_b))
    print("%d identical, %d differ" % (same, differ))
    return 1 if differ else 0


def main():
    # Arguments and outputs may hold bytes that are not UTF-8 (kept as surrogates): print them as they are.
    sys.stdout.reconfigure(encoding="utf-8", errors="surrogateescape")
    sys.stderr.reconfigure(encoding="utf-8", errors="backslashreplace")
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--tool", help="the vibrofric binary to record (with --out)")
    mode.add_argument("--compare", nargs=2, metavar=("A.jsonl", "B.jsonl"), help="compare two recordings")
    mode.add_argument("--list", action="store_true", help="print the commands and their count")
    mode.add_argument("--categories", action="store_true", help="print the number of commands per category")
    ap.add_argument("--out", help="the JSONL file to write")
    ap.add_argument("--jobs", type=int, default=1, help="commands run in parallel (default 1)")
    ap.add_argument("--only", action="append", metavar="CATEGORY",
                    help="record only this category (repeatable; for checks of a subset)")
    ap.add_argument("--times", metavar="FILE.tsv", help="also write each command's run time (seconds) here")
    ap.add_argument("--common", action="store_true",
                    help="--compare: ignore commands present in one file only (e.g. a subset recording)")
    a = ap.parse_args()
    if a.compare:
        return compare(a.compare[0], a.compare[1], a.common)
    if a.list:
        cmds = corpus()
        for _, args in cmds:
            print("vibrofric " + show(args))
        print("%d commands" % len(cmds))
        return 0
    if a.categories:
        counts = {}
        for cat, args in corpus():
            counts[cat] = counts.get(cat, 0) + 1
        for cat, _ in CATEGORIES:
            print("%-16s %5d" % (cat, counts.get(cat, 0)))
        print("%-16s %5d" % ("total", sum(counts.values())))
        return 0
    if not a.out:
        ap.error("--tool needs --out FILE.jsonl")
    if a.only:
        unknown = set(a.only) - {c for c, _ in CATEGORIES}
        if unknown:
            ap.error("unknown category: %s" % ", ".join(sorted(unknown)))
    return record(a.tool, a.out, a.jobs, set(a.only or ()), a.times)


if __name__ == "__main__":
    sys.exit(main())
