#!/usr/bin/python3
"""Regenerates reports/VERIFICATION.md and reports/figures/ from the vibrofric tool, gnuplot and the
benchmark JSON. Every number in the report comes from a program run here; nothing is typed in.

usage: generate.py --tool PATH [--bench-json PATH] [--out DIR] [--digits D]
"""
import argparse
import concurrent.futures
import csv
import datetime
import json
import math
import os
import platform
import subprocess
import sys
from fractions import Fraction

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GAMMAS_FIG = ["1", "0.8", "0.6", "0.4", "0.2", "0", "-0.2", "-0.4", "-0.6", "-0.8", "-0.999"]


def csv_rows(text):
    """The rows of the tool's CSV (RFC 4180: a field may be quoted and hold a comma)."""
    return list(csv.reader(text.strip().splitlines()))


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        sys.exit("generate.py: %s failed (exit %d): %s" % (" ".join(cmd), r.returncode, r.stderr.strip()))
    return r.stdout


class Report:
    def __init__(self, tool, out, digits):
        self.tool, self.out, self.digits = tool, out, digits
        self.fig = os.path.join(out, "figures")
        self.data = os.path.join(self.fig, "data")
        os.makedirs(self.data, exist_ok=True)

    def sweep(self, wave, beta, gammas, extra=()):
        """(beta, gamma, mu) rows of `vibrofric sweep`, by the CSV header (with --profile the tool adds a
        profile column)."""
        text = run([self.tool, "sweep", "--wave", wave, "--beta", beta, "--gamma", ",".join(gammas)] + list(extra))
        rows = csv_rows(text)
        head = rows[0]
        ib, ig, im = head.index("beta"), head.index("gamma"), head.index("mu_over_mu0")
        return [(r[ib], r[ig], r[im]) for r in rows[1:]]

    def mu(self, wave, beta, gamma, extra=()):
        return run([self.tool, "mu", "--wave", wave, "--beta", beta, "--gamma=" + gamma] + list(extra)).strip()

    def write_data(self, name, blocks, header):
        """blocks: list of (title, rows); gnuplot data blocks separated by two blank lines."""
        path = os.path.join(self.data, name)
        with open(path, "w") as f:
            f.write("# %s\n" % header)
            for title, rows in blocks:
                f.write("# %s\n" % title)
                for r in rows:
                    f.write(" ".join(str(v) for v in r) + "\n")
                f.write("\n\n")
        return path

    def gnuplot(self, name, script):
        """Renders one figure to SVG (for the report) and PNG (to look at)."""
        gp = os.path.join(self.data, name + ".gp")
        body = "set encoding utf8\nset key box opaque\nset grid\n" + script
        with open(gp, "w") as f:
            f.write(body)
        for term, ext in (("svg size 1000,600 dynamic font 'Helvetica,15' background rgb 'white'", "svg"),
                          ("pngcairo size 1200,800 font 'Helvetica,15'", "png")):
            run(["gnuplot", "-e", "set terminal %s; set output '%s'" % (term, os.path.join(self.fig, name + "." + ext)), gp],
                cwd=self.data)
        return "figures/%s.svg" % name


# ---------------------------------------------------------------------------------------------- figures

def fig2_trace(r):
    blocks = []
    for gamma, beta in (("1.5", "2"), ("0", "2")):
        rows = run([r.tool, "trace", "--wave", "sine", "--beta", beta, "--gamma", gamma, "--points", "800", "--digits", "12"])
        rows = csv_rows(rows)[1:]
        blocks.append(("gamma = %s, beta = %s" % (gamma, beta), rows))
    r.write_data("fig2_trace.dat", blocks, "phi n s (sine wave; units of k_z A and mu0 k_z A)")
    return r.gnuplot("fig2_stick_slip", """
set multiplot layout 1,2 title 'Stick–slip over one period, harmonic wave, β = 2'
set xlabel 'phase φ = f t'
set ylabel 'force / (μ_0 k_z A)'
set xrange [0:1]
set yrange [0:*]
set title 'γ = 1.5 (no jumping)'
plot 'fig2_trace.dat' index 0 using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'μ_0 F_z (normal, n)', \\
     '' index 0 using 1:3 with lines lw 2 dt 2 lc rgb '#d62728' title 'F_x (tangential, s)'
set title 'γ = 0 (jumping: no contact while n = 0)'
plot 'fig2_trace.dat' index 1 using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'μ_0 F_z (normal, n)', \\
     '' index 1 using 1:3 with lines lw 2 dt 2 lc rgb '#d62728' title 'F_x (tangential, s)'
unset multiplot
""")


def by_gamma(rows):
    out = {}
    for b, g, m in rows:
        out.setdefault(g, []).append((b, m))
    return out


# The paper's colours for GAMMAS_FIG (γ = 1 dark red, negative γ blue), as a dark diverging scale dark red ->
# purple -> dark blue with no light middle: CIELAB L* 22 (γ = 1), 52 (γ = 0, purple) and 20 (γ = -0.999), hue and
# chroma interpolated in LCh, so that every curve prints on white paper (grey levels 37/255 to 128/255).
# In greyscale the two halves look alike: γ > 0 is drawn solid, γ = 0 dash-dot and γ < 0 dashed.
GAMMA_COLOURS = ["#77000c", "#8b002e", "#991950", "#a13473", "#a24e94", "#9e67b3", "#805ba8", "#62509c", "#42458f",
                 "#183b81", "#003072"]


def gamma_style(g):
    """lw/lc/dt of the curve of gamma g (one of GAMMAS_FIG) in Figs. 3, 4 and the ball figure."""
    dt = "1" if float(g) > 0 else ("(12,5,2,5)" if float(g) == 0 else "(10,6)")
    return "lw 2 lc rgb '%s' dt %s" % (GAMMA_COLOURS[GAMMAS_FIG.index(g)], dt)


def palette_plot(datafile, gammas, using="1:2"):
    return ", \\\n     ".join("'%s' index %d using %s with lines %s title 'γ = %s'" %
                              (datafile if i == 0 else "", i, using, gamma_style(g), g) for i, g in enumerate(gammas))


def merged_grid(parts):
    """rows (beta, gamma, mu) of several sweeps/points -> {gamma: [(beta, mu)] sorted by beta, one row per beta}."""
    out = {}
    for b, g, m in parts:
        out.setdefault(g, {}).setdefault(Fraction(b), (b, m))
    return {g: [v for _, v in sorted(d.items())] for g, d in out.items()}


def fig3_square(r):
    # Eq. 22 is a straight line up to its kink at β = 2(1+γ) and 1 − (1+γ)/β after it; the kink of every curve is a
    # grid point (exact decimals), γ = −0.999 (kink at β = 0.002) gets a fine grid from β = 1e-4, and the main grid
    # (step 0.005, about half a pixel of the PNG) stays below one pixel per segment: pngcairo snaps segments that are
    # exactly horizontal in its integer coordinates and longer than a pixel to the pixel grid, which made the
    # γ = −0.999 curve, rising by a fraction of a pixel near μ̄ = 1, wobble at the old step of 0.02 (2 pixels).
    from decimal import Decimal
    digits = ["--digits", "12"]
    rows = r.sweep("square", "0.0001:0.02:200", GAMMAS_FIG, digits) + r.sweep("square", "0.005:8:1600", GAMMAS_FIG, digits)
    for g in GAMMAS_FIG:
        kink = str(2 * (1 + Decimal(g)))
        rows.append((kink, g, r.mu("square", kink, g, digits)))
    rows = merged_grid(rows)
    r.write_data("fig3_square.dat", [("gamma = " + g, rows[g]) for g in GAMMAS_FIG], "beta mu/mu0 (square wave)")
    return r.gnuplot("fig3_square", """
set title 'Square wave, 11 values of γ (Fig. 3; γ = −1 drawn at −0.999, where contact still exists)'
set xlabel 'β = k_x v_0 / (μ_0 k_z A f)'
set ylabel 'μ̄ / μ_0'
set key outside right top
set xrange [0:8]
set yrange [0:1.02]
plot %s
""" % palette_plot("fig3_square.dat", GAMMAS_FIG))


def fig4_harmonic(r):
    # Step 0.005 (about half a pixel of the PNG; see fig3_square for the pixel snapping of longer flat segments).
    rows = by_gamma(r.sweep("sine", "0.005:7:1400", GAMMAS_FIG, ["--digits", "12"]))
    r.write_data("fig4_harmonic.dat", [("gamma = " + g, rows[g]) for g in GAMMAS_FIG], "beta mu/mu0 (sine)")
    # Eq. 23 relative to γ0 = −0.3: μ̄(β, γ) ≈ μ̄(ξ, γ0), ξ = β √((1 + γ0)/(1 + γ)), for γ < γ0.
    eq23 = ["-0.4", "-0.6", "-0.8", "-0.999"]
    dots = []
    for g in eq23:
        c = math.sqrt(0.7 / (1 + float(g)))
        lo, hi, n = 0.25, 7.0, 28
        xi = csv_rows(run([r.tool, "sweep", "--wave", "sine", "--beta", "%.15g:%.15g:%d" % (lo * c, hi * c, n), "--gamma", "-0.3",
                  "--digits", "12"]))[1:]
        dots.append(("Eq. 23 dots for gamma = " + g,
                     [(lo + (hi - lo) * i / (n - 1), row[3]) for i, row in enumerate(xi)]))
    r.write_data("fig4_eq23.dat", dots, "beta mu(xi_2(beta, gamma), -0.3)")
    # Each γ's markers: filled in the colour of its curve, one shape per γ (square, circle, triangle, diamond), with a
    # black outline of the same shape drawn over it; the key names the γ of each shape.
    shapes = [(5, 4), (7, 6), (9, 8), (13, 12)]
    marks = []
    for i, g in enumerate(eq23):
        filled, outline = shapes[i]
        marks.append("'fig4_eq23.dat' index %d using 1:2 with points pt %d ps 1.3 lc rgb '%s' title 'Eq. 23, γ = %s'" %
                     (i, filled, GAMMA_COLOURS[GAMMAS_FIG.index(g)], g))
        marks.append("'' index %d using 1:2 with points pt %d ps 1.3 lw 1 lc rgb 'black' notitle" % (i, outline))
    # The curves of γ = 0.2 … 1 lie within 0.06 of each other and cross: an inset draws their
    # distance from γ = 1, μ̄(β, γ) − μ̄(β, 1), on the same grid.
    close = ["0.8", "0.6", "0.4", "0.2"]
    ones = dict(rows["1"])
    r.write_data("fig4_close.dat", [("gamma = " + g, [(b, "%.6e" % (float(m) - float(ones[b]))) for b, m in rows[g]])
                                    for g in close], "beta mu/mu0(beta, gamma) - mu/mu0(beta, 1) (sine)")
    return r.gnuplot("fig4_harmonic", """
set multiplot
set title 'Harmonic wave, 11 values of γ (Fig. 4); markers: Eq. 23 relative to γ_0 = −0.3'
set xlabel 'β = k_x v_0 / (μ_0 k_z A f)'
set ylabel 'μ̄ / μ_0'
set key outside right top
set xrange [0:7]
set yrange [0:1.02]
plot %s, \\
     %s
set origin 0.36, 0.13
set size 0.33, 0.42
set title 'inset: μ̄(β, γ) − μ̄(β, 1), γ = 0.2 … 0.8' font ',12'
set xlabel 'β' font ',12'
set ylabel ''
set xtics 2 font ',11'
set ytics font ',11'
set format y '%%.0e'
set xrange [0:7]
set yrange [*:*]
unset key
set object 1 rectangle from graph 0, graph 0 to graph 1, graph 1 behind fillcolor rgb 'white' fillstyle solid noborder
plot %s
unset multiplot
""" % (palette_plot("fig4_harmonic.dat", GAMMAS_FIG), ", \\\n     ".join(marks), palette_plot("fig4_close.dat", close)))


def fig_power_collapse(r):
    p = 3.0
    gammas = ["0", "-0.3", "-0.6", "-0.9", "-0.99"]
    rows = by_gamma(r.sweep("power:3", "0.01:12:300", gammas, ["--digits", "12"]))
    blocks = []
    for g in gammas:
        h = 1 + float(g)
        pts = [(float(b), float(b) * h ** (-(p - 1) / p), float(b) * h ** (-1 / p), m) for b, m in rows[g]]
        blocks.append(("gamma = " + g, pts))
    r.write_data("power_collapse.dat", blocks, "beta  beta*h^-((p-1)/p)  beta*h^-(1/p)  mu/mu0  (power:3, h = 1+gamma)")
    cols = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"]
    def plot(col):
        return ", \\\n     ".join("'%s' index %d using %d:4 with lines lw 2 lc rgb '%s' title 'γ = %s'" %
                                  ("power_collapse.dat" if i == 0 else "", i, col, cols[i], g) for i, g in enumerate(gammas))
    return r.gnuplot("power_collapse", """
set multiplot layout 1,2 title 'power:3 — collapse under the self-similar remapping (left), not under Eq. 24 as printed (right)'
set ylabel 'μ̄ / μ_0'
set key right bottom
set yrange [0:1.02]
set xrange [0:12]
set xlabel 'β (1+γ)^{−(p−1)/p}  (self-similar, proved)'
plot %s
set xlabel 'β (1+γ)^{−1/p}  (Eq. 24 as printed)'
set xrange [0:30]
plot %s
unset multiplot
""" % (plot(2), plot(3)))


# ---------------------------------------------------------------------------------------------- curved contacts

def fig4_ball(r):
    """Fig. 4 for a sphere (MDR, model.md): the harmonic wave for the paper's 11 values of gamma, beside the
    flat punch (the data of fig4_harmonic, written first)."""
    rows = by_gamma(r.sweep("sine", "0.02:7:100", GAMMAS_FIG, ["--profile", "sphere", "--digits", "12"]))
    r.write_data("fig4_ball.dat", [("gamma = " + g, rows[g]) for g in GAMMAS_FIG], "beta mu/mu0 (sine, sphere, MDR)")
    return r.gnuplot("fig4_ball", """
set multiplot layout 1,2 title 'Harmonic wave, 11 values of γ: flat punch (left, Fig. 4) and sphere (right, MDR)'
set xlabel 'β = G^* v_0 / (μ_0 E^* A f)   (on the punch k_x/k_z = G^*/E^*)'
set ylabel 'μ̄ / μ_0'
set xrange [0:7]
set yrange [0:1.02]
set key right bottom font ',11' spacing 0.9
set title 'flat-ended cylinder'
plot %s
set title 'sphere (σ = x²)'
plot %s
unset multiplot
""" % (palette_plot("fig4_harmonic.dat", GAMMAS_FIG), palette_plot("fig4_ball.dat", GAMMAS_FIG)))


RIG_WAVES = ["sine", "triangle", "square", "sawtooth-left"]
RIG_OMEGAS = ["0.3", "1", "2", "4", "10", "30", "100", "300", "1000"]
RIG_KAPPAS = ["0.1", "0.3", "1", "3", "10", "30", "100"]


def fig_rig_map(r):
    """Where the quasi-static model holds for a rig (model.md, "Rig dynamics"): the relative distance of the
    rig's mu (`vibrofric mu --kappa K --omega W --zeta 0.1`) from its quasi-static limit g_w(beta K/(1 + K),
    gamma), over (Omega, kappa), beta = 1, gamma = 0.5, per catalogue wave; the 1 % contour drawn."""
    import concurrent.futures
    import math
    jobs = [(wave, o, k) for wave in RIG_WAVES for o in RIG_OMEGAS for k in RIG_KAPPAS]

    def one(job):
        wave, o, k = job
        dyn = float(r.mu(wave, "1", "0.5", ["--kappa", k, "--omega", o, "--zeta", "0.1", "--type", "double"]).splitlines()[0])
        beta_eff = "%.17g" % (float(k) / (1 + float(k)))
        qs = float(r.mu(wave, beta_eff, "0.5", ["--type", "double"]))
        return job, abs(dyn - qs) / qs
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        dist = dict(pool.map(one, jobs))
    blocks = []
    for wave in RIG_WAVES:
        rows = []
        for o in RIG_OMEGAS:
            for k in RIG_KAPPAS:
                rows.append((math.log10(float(o)), math.log10(float(k)), math.log10(max(dist[(wave, o, k)], 1e-12))))
            rows.append(())
        blocks.append((wave, rows))
    # an empty row is a blank line: gnuplot's grid format, rows of constant Omega
    r.write_data("rig_map.dat", blocks, "log10(Omega) log10(kappa) log10(|mu - mu_qs|/mu_qs), beta = 1, gamma = 0.5, zeta = 0.1")
    panels = ""
    for i, wave in enumerate(RIG_WAVES):
        panels += ("set title '%s'\nsplot 'rig_map.dat' index %d using 1:2:3 with pm3d notitle, "
                   "'' index %d using 1:2:3 with lines lw 3 lc rgb 'black' nosurface notitle\n" % (wave, i, i))
    fig = r.gnuplot("rig_map", """
set multiplot layout 2,2 title 'Rig dynamics against its quasi-static limit: log10 |μ̄ − g_w(βκ/(1+κ), γ)| / g_w, β = 1, γ = 0.5, ζ = 0.1 (black: 1 %%)'
set view map
set pm3d at b
set contour base
set cntrparam levels discrete -2
unset clabel
set xlabel 'log10 Ω = log10 √(k_x/m)/(2πf)'
set ylabel 'log10 κ = log10 k_s/k_x'
set cbrange [-6:0]
set xrange [-0.5:3]
set yrange [-1:2]
set palette defined (-6 '#1a9850', -2 '#ffffbf', 0 '#d73027')
unset key
%s
unset multiplot
""" % panels)
    return fig, dist


INPLANE_AMPLITUDES = ["1", "10", "100"]
RATCHET_AMPLITUDES = ["0.5", "1", "2"]
TRANSVERSE_AMPLITUDES = ["1", "3", "10"]


def fig_inplane(r):
    """In-plane oscillation (model.md): mu/mu0 against xi = beta/(2 pi a) for a longitudinal sine drive at
    a constant normal force (`vibrofric sweep --wave constant --longitudinal A`) with the rigid limit
    (2/pi) arcsin xi; and the ratchet's mean force against the phase P at beta = 0 (sine normal force,
    gamma = 0.5; `vibrofric mu --longitudinal A --phase P`)."""
    import math
    blocks = []
    for a in INPLANE_AMPLITUDES:
        hi = "%.17g" % (2 * math.pi * float(a) * 1.5)
        text = run([r.tool, "sweep", "--wave", "constant", "--beta", "0.001:%s:151" % hi, "--longitudinal", a,
                    "--type", "double"])
        rows = csv_rows(text)
        ib, im = rows[0].index("beta"), rows[0].index("mu_over_mu0")
        blocks.append(("a = " + a, [(float(x[ib]) / (2 * math.pi * float(a)), x[im]) for x in rows[1:]]))
    blocks.append(("rigid", [(k / 100, 2 / math.pi * math.asin(min(k / 100, 1.0))) for k in range(0, 151)]))
    r.write_data("inplane_xi.dat", blocks, "xi = beta/(2 pi a), mu/mu0; constant normal force, sine drive")
    styles = ["lw 2 lc rgb '#d73027'", "lw 2 lc rgb '#4575b4'", "lw 2 lc rgb '#1a9850'"]
    plots = ", ".join("'inplane_xi.dat' index %d using 1:2 with lines %s title 'a = %s'" % (i, styles[i], a)
                      for i, a in enumerate(INPLANE_AMPLITUDES))
    fig_xi = r.gnuplot("inplane_xi", """
set title 'Longitudinal oscillation at a constant normal force: μ̄/μ0 against ξ = v0/(2π f u_x)'
set xlabel 'ξ = β/(2πa)'
set ylabel 'μ̄/μ0'
set key bottom right
set xrange [0:1.5]
set yrange [0:1.05]
plot %s, 'inplane_xi.dat' index %d using 1:2 with lines lw 2 dt 2 lc rgb 'black' title 'rigid: (2/π) arcsin ξ'
""" % (plots, len(INPLANE_AMPLITUDES)))
    blocks, phases = [], ["%.17g" % (k / 32) for k in range(33)]
    for a in RATCHET_AMPLITUDES:
        rows = []
        for p in phases:
            out = r.mu("sine", "0", "0.5", ["--longitudinal", a, "--phase", p, "--type", "double"]).splitlines()
            rows.append((p, out[0]))
        blocks.append(("a = " + a, rows))
    r.write_data("inplane_ratchet.dat", blocks, "P (periods), mu/mu0 at beta = 0; sine normal force, gamma = 0.5, sine drive")
    plots = ", ".join("'inplane_ratchet.dat' index %d using 1:2 with linespoints pt 7 ps 0.6 %s title 'a = %s'" %
                      (i, styles[i], a) for i, a in enumerate(RATCHET_AMPLITUDES))
    fig_ratchet = r.gnuplot("inplane_ratchet", """
set title 'The ratchet: mean force ∫s/∫n at β = 0 against the phase P of the longitudinal oscillation (γ = 0.5)'
set xlabel 'P (periods)'
set ylabel '∫s dφ / ∫n dφ at β = 0'
set key bottom right
set xrange [0:1]
plot %s
""" % plots)
    # The transverse drive (planar.hpp): 31 points a curve (about a second each in double).
    blocks = []
    for a in TRANSVERSE_AMPLITUDES:
        hi = "%.17g" % (2 * math.pi * float(a) * 1.5)
        lo = "%.17g" % (2 * math.pi * float(a) * 0.02)
        text = run([r.tool, "sweep", "--wave", "constant", "--beta", "%s:%s:31" % (lo, hi), "--transverse", a,
                    "--type", "double"])
        rows = csv_rows(text)
        ib, im = rows[0].index("beta"), rows[0].index("mu_over_mu0")
        blocks.append(("a = " + a, [(float(x[ib]) / (2 * math.pi * float(a)), x[im]) for x in rows[1:]]))
    def ellipk(k):
        # K(k) = pi / (2 AGM(1, sqrt(1 - k^2))): the arithmetic-geometric mean converges quadratically
        a, b = 1.0, math.sqrt(1 - k * k)
        for _ in range(40):  # (a - b) squares each step: 40 steps reach double's rounding from any k < 1
            a, b = (a + b) / 2, math.sqrt(a * b)
        return math.pi / (2 * a)
    rigid = []
    for k in range(1, 151):
        xi = k / 100
        rigid.append((xi, 2 / math.pi * xi / math.sqrt(1 + xi * xi) * ellipk(1 / math.sqrt(1 + xi * xi))))
    blocks.append(("rigid", rigid))
    r.write_data("inplane_xi_transverse.dat", blocks, "xi = beta/(2 pi a), mu/mu0; constant normal force, transverse sine drive")
    plots = ", ".join("'inplane_xi_transverse.dat' index %d using 1:2 with linespoints pt 7 ps 0.5 %s title 'a = %s'" %
                      (i, styles[i], a) for i, a in enumerate(TRANSVERSE_AMPLITUDES))
    fig_transverse = r.gnuplot("inplane_xi_transverse", """
set title 'Transverse oscillation at a constant normal force: μ̄/μ0 against ξ = v0/(2π f u_y)'
set xlabel 'ξ = β/(2πa)'
set ylabel 'μ̄/μ0'
set key bottom right
set xrange [0:1.5]
set yrange [0:1.05]
plot %s, 'inplane_xi_transverse.dat' index %d using 1:2 with lines lw 2 dt 2 lc rgb 'black' title 'rigid: (2/π) ξ/√(1+ξ²) K(1/√(1+ξ²))'
""" % (plots, len(TRANSVERSE_AMPLITUDES)))
    return fig_xi, fig_ratchet, fig_transverse


def inplane_section(w, figs, claims_table, inplane, tool):
    """In-plane oscillation (model.md, "In-plane and combined oscillation"): the figures and the claims."""
    w("## In-plane oscillation")
    w("")
    w("`vibrofric mu --longitudinal A --phase P --in-plane-wave W` (and `--wave constant`) oscillate the far end of "
      "the tangential spring along the sliding direction (`core/inplane/inplane.hpp`): the stop operator of the "
      "drive D = βφ + A p(φ + P) in [−n, n], events on segments where each wave is one monotone branch, exact "
      "areas, the periodic state as the one-period map's fixed point checked from a second start, the value printed "
      "where two mpfr precisions agree. Checked by `tests/unit/test_inplane.cpp` (the catching-up scheme within its "
      "step bound, closed forms, symmetries, the paper's model at A = 0) and by an independent mpmath implementation "
      "(`tests/reference/inplane_mpmath.py`, 43 cases at 30 digits). `--transverse A` adds the drive across the "
      "sliding direction (`core/inplane/planar.hpp`): Moreau's sweeping process in the disc |s| ≤ n, slip's angle "
      "equation integrated by Radau IIA collocation (L-stable: the rigid limit is reached at a = 10^6) with step "
      "doubling, checked against an independent catching-up reference (`tests/reference/planar_catchup.py`). `--profile P` takes "
      "either drive to a curved contact, the MDR row of in-plane springs (`core/inplane/inplane_curved.hpp`), "
      "checked against a direct simulation of the spring row (`tests/reference/row_catchup.py`, 1e-10).")
    w("")
    for key, cap in (("inplane_xi", "Longitudinal oscillation at a constant normal force: μ̄/μ0 against "
                      "ξ = β/(2πa) = v0/(2πf u_x) at a = 1, 10, 100, and the rigid limit (2/π) arcsin ξ "
                      "(`vibrofric sweep --wave constant --longitudinal A --type double`)."),
                     ("inplane_xi_transverse", "Transverse oscillation at a constant normal force: μ̄/μ0 "
                      "against ξ = β/(2πa) at a = 1, 3, 10, and the rigid limit (2/π) ξ/√(1+ξ²) K(1/√(1+ξ²)): no "
                      "critical velocity, and the finite stiffness's excess falls as 1/a² "
                      "(`vibrofric sweep --wave constant --transverse A --type double`)."),
                     ("inplane_ratchet", "The ratchet: ∫s/∫n at β = 0 against the phase P for a sine normal "
                      "force (γ = 0.5) and a sine longitudinal drive of amplitude a (`vibrofric mu --longitudinal A "
                      "--phase P --type double`); below 0 the oscillation pushes the body.")):
        w("![%s](%s)" % (cap, figs[key]))
        w("")
        w("*%s*" % cap)
        w("")
    # The certified rung of the longitudinal drive, computed here (a proof that fails stops the report).
    cmd = ["mu", "--wave", "triangle", "--gamma", "0.5", "--beta", "0", "--longitudinal", "1", "--in-plane-wave",
           "triangle", "--phase", "0.25", "--type", "double", "--certify", "--format", "json"]
    ex = json.loads(run([tool] + cmd))
    w("With piecewise-linear waves (and a constant or oscillating normal force) every event of the longitudinal "
      "drive is the root of a linear function, so at decimal inputs μ̄/μ0 and the fractions are rational: "
      "`core/inplane/inplane_exact.hpp` walks the segments where n and D are linear in GMP rationals (the one-period "
      "map is clamp(s + β, L, U), so one period from the largest start ends on the state), and `mu --certify` proves "
      "the printed value its correct rounding. It shares no code with the event solver; "
      "`tests/unit/test_inplane_exact.cpp` sets the two against each other on every field at 60 digits (270 random "
      "drives) and against states worked out by hand. The ratchet on triangles (n = max(0.5 + w, 0), a triangle "
      "drive of amplitude 1 a quarter period late, β = 0), computed for this report (`vibrofric %s`): μ̄/μ0 = %s "
      "exactly (the double %s, proven), stick %s, slip %s (backward %s), flight %s; its free velocity %s (not "
      "certified)." % (" ".join(cmd[:-2]), ex["exact"], ex["mu_over_mu0"], ex["exact_stick_fraction"],
                       ex["exact_slip_fraction"], ex["exact_backward_slip_fraction"], ex["exact_flight_fraction"],
                       ex["free_velocity"]))
    w("")
    claims_table(inplane)
    for c in inplane:
        w("- **%s**: %s" % (c["id"], c["how"]))
        for m in c["measured"]:
            w("  - %s: %s" % (m["name"], m["value"]))
    w("")


WEARFLAT_CASES = [("sine", "1.5"), ("sine", "0.5"), ("sine", "-0.5"), ("square", "1.5"), ("square", "-0.5"),
                  ("triangle", "1.5")]


def fig_wearflat(r):
    """|mu(wearflat:lambda) - mu(flat)| against lambda = b^2/(R A), log-log, beta = 1, at 20 digits
    (the smallest difference plotted is ~1e-11: 20 digits leave 9 in it)."""
    lambdas = ["%.6g" % (10 ** (k / 4)) for k in range(17)]
    jobs = []
    for wave, g in WEARFLAT_CASES:
        jobs.append((wave, g, None))
        jobs += [(wave, g, lam) for lam in lambdas]
    def one(job):
        wave, g, lam = job
        extra = ["--digits", "20"] + (["--profile", "wearflat:" + lam] if lam else [])
        return r.mu(wave, "1", g, extra)
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        values = dict(zip(jobs, pool.map(one, jobs)))
    blocks = []
    for wave, g in WEARFLAT_CASES:
        flat = Fraction(values[(wave, g, None)])
        blocks.append(("%s, gamma = %s" % (wave, g),
                       [(lam, "%.6e" % float(abs(Fraction(values[(wave, g, lam)]) - flat))) for lam in lambdas]))
    r.write_data("wearflat.dat", blocks, "lambda |mu_wearflat - mu_flat| (beta = 1, units of mu0)")
    cols = ["#1f77b4", "#2ca02c", "#9467bd", "#d62728", "#ff7f0e", "#8c564b"]
    plots = ", \\\n     ".join("'%s' index %d using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '%s' title '%s, γ = %s'" %
                               ("wearflat.dat" if i == 0 else "", i, cols[i], w, g)
                               for i, (w, g) in enumerate(WEARFLAT_CASES))
    return r.gnuplot("wearflat", """
set title 'Sphere with a wear flat against the flat punch, β = 1 (the triangle with γ ≤ 1 is exact at every λ)'
set xlabel 'λ = b² / (R A)   (b: flat radius, R: sphere radius, A: amplitude)'
set ylabel '|μ̄_{wear flat} − μ̄_{flat}| / μ_0'
set logscale xy
set format x '10^{%%L}'
set format y '10^{%%L}'
set key left bottom
plot %s, \\
     [1:1e4] 0.05/x**2 with lines dt 2 lw 1.5 lc rgb 'black' title '∝ λ^{−2}'
""" % plots)


def closed_form_rows(claims):
    """The closed forms of curved contacts (curved_closed_forms.hpp) against the solver: the fields of the
    measurements "closed form: ..." (wave, profile, beta, gamma, closed_form, solver, relative_difference)."""
    keys = ("wave", "profile", "beta", "gamma", "closed_form", "solver", "relative_difference")
    return [tuple(m["fields"][k] for k in keys)
            for c in claims for m in c["measured"] if m["name"].startswith("closed form: ")]


def ulp_error(value_text, ref_text, bits):
    """|value − ref| in units of the last place of ref in a binary type with `bits` mantissa bits."""
    v, ref = Fraction(value_text), Fraction(ref_text)
    if ref == 0:
        return float(abs(v))
    e = math.floor(math.log2(abs(float(ref))))
    ulp = Fraction(2) ** (e - bits + 1)
    return float(abs(v - ref) / ulp)


def fig_ulp(r):
    """Error over β of each double path of the tool (raw solver, guaranteed solver) and of long double,
    against 40-digit mpfr, for the sine at two γ and for the square wave's closed form (Eq. 22)."""
    blocks, summary = [], []
    cases = [("sine", "0.5"), ("sine", "-0.9")]
    betas = ["%.6g" % (10 ** (-6 + 6.8 * i / 119)) for i in range(120)]
    for wave, g in cases:
        paths = {"raw double": (["--type", "double", "--no-escalate=1"], 53),
                 "guaranteed double": (["--type", "double"], 53),
                 "raw long double": (["--type", "long-double", "--no-escalate=1"], 64)}
        # β is log-spaced, and sweep's grid is linear: one 'mu' call per point.
        vals = {}
        for name, (flags, _) in list(paths.items()) + [("reference", (["--digits", "40"], 0))]:
            out = []
            for b in betas:
                out.append(run([r.tool, "mu", "--wave", wave, "--beta", b, "--gamma", g] + flags).strip())
            vals[name] = out
        for name, (_, bits) in paths.items():
            errs = [ulp_error(v, ref_v, bits) for v, ref_v in zip(vals[name], vals["reference"])]
            blocks.append(("%s, gamma = %s: %s" % (wave, g, name), [(b, max(e, 1e-3)) for b, e in zip(betas, errs)]))
            rms = math.sqrt(sum(e * e for e in errs) / len(errs))
            worst = max(range(len(errs)), key=lambda i: errs[i])
            summary.append((wave, g, name, max(errs), rms, betas[worst]))
    r.write_data("ulp_error.dat", blocks, "beta error_in_ulp (floored at 1e-3 for the log scale)")
    cols = {"raw double": "#d62728", "guaranteed double": "#1f77b4", "raw long double": "#2ca02c"}
    plots = []
    idx = 0
    for wave, g in cases:
        for name in cols:
            plots.append("'%s' index %d using 1:2 with linespoints pt 7 ps 0.4 lw 1 lc rgb '%s' dt %d title '%s, γ = %s'" %
                         ("ulp_error.dat" if idx == 0 else "", idx, cols[name], 1 if g == "0.5" else 2, name, g))
            idx += 1
    fig = r.gnuplot("ulp_error", """
set title 'Error of the fixed-precision paths of vibrofric mu (sine), against 40-digit mpfr'
set xlabel 'β'
set ylabel 'error in ulp of the type (floored at 10^{−3})'
set logscale xy
set format y '10^{%%L}'
set format x '10^{%%L}'
# The key sits below the plot, clear of every point (inside, it hid the largest errors at small β); the y range
# is the data's plus 4 %% of the plot height either way, so that neither the largest errors nor the floored ones lie
# on the border.
set key at screen 0.5, screen 0.01 center bottom vertical maxrows 3
set bmargin 7.5
set autoscale y noextend
set offsets 0, 0, graph 0.04, graph 0.04
plot %s
""" % ", \\\n     ".join(plots))
    return fig, summary


def crosscheck(r):
    """The solver at 40 digits against the independent mpmath implementation
    (tests/reference/mu_mpmath.py: closed-form events, mpmath.findroot, antiderivatives) at 50."""
    ref = os.path.join(ROOT, "tests", "reference", "mu_mpmath.py")
    python = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
    gammas = ["2", "0.5", "-0.5", "-0.9"]
    rows, worst_all = [], (0.0, "")
    for wave in ("sine", "triangle", "sawtooth-left", "square", "power:3"):
        ours = r.sweep(wave, "0.1:7:70", gammas, ["--digits", "40"])
        text = run([python, ref, "sweep", "--wave", wave, "--beta", "0.1:7:70", "--gamma", ",".join(gammas),
                    "--digits", "50"])
        theirs = csv_rows(text)[1:]
        if len(theirs) != len(ours):
            sys.exit("generate.py: mpmath returned %d points for %s, expected %d" % (len(theirs), wave, len(ours)))
        worst = (0.0, "")
        for (b, g, m), t in zip(ours, theirs):
            if abs(Fraction(b) - Fraction(t[1])) > Fraction(1, 10 ** 30) or Fraction(g) != Fraction(t[2]):
                sys.exit("generate.py: point mismatch %s %s / %s %s" % (b, g, t[1], t[2]))
            ref_v = Fraction(t[3])
            dev = float(abs(Fraction(m) - ref_v) / abs(ref_v)) if ref_v else float(abs(Fraction(m)))
            if dev >= worst[0]:
                worst = (dev, "β = %s, γ = %s" % (b, g))
        rows.append((wave, len(ours), worst[0], worst[1]))
    return rows


def certified(r):
    """`sweep --certify` over a grid with the corners (β from 1e-6 to 20, γ from −0.999 to 2) for
    every wave with certified values, in double, long double and at 30 digits: every value the
    guaranteed path prints must be proven the correct rounding (a failure exits the tool with 1, and
    this script with it). Returns (wave, type, points, exact or enclosure, the widest enclosure
    relative to its value, seconds)."""
    import time
    rows = []
    gammas = "-0.999,-0.9,-0.5,0,0.5,0.999,1,2"
    waves = ["sine", "power:3", "power:1.5", "fourier:" + os.path.join(ROOT, "tests", "tool", "data", "odd-series.txt"),
             "triangle", "sawtooth-right", "sawtooth-left", "square", "power:1",
             "samples:" + os.path.join(ROOT, "tests", "tool", "data", "rig.csv") + "#2"]
    for wave in waves:
        for prec in (["--type", "double"], ["--type", "long-double"], ["--digits", "30"]):
            name = ("samples:tests/tool/data/rig.csv, column 2" if wave.startswith("samples:") else
                    "fourier:tests/tool/data/odd-series.txt" if wave.startswith("fourier:") else wave)
            args = [r.tool, "sweep", "--wave", wave.split("#")[0], "--beta", "log:1e-6:20:41", "--gamma", gammas,
                    "--certify"] + prec
            if "#" in wave:
                args += ["--column", wave.split("#")[1]]
            start = time.perf_counter()
            text = run(args)
            seconds = time.perf_counter() - start
            table = csv_rows(text)
            head, body = table[0], table[1:]
            if any(row[head.index("correctly_rounded")] != "proven" for row in body):
                sys.exit("generate.py: a certified sweep row is not proven: %s" % " ".join(args))
            widest = 0.0
            if "lower" in head:
                for row in body:
                    lo, hi = Fraction(row[head.index("lower")]), Fraction(row[head.index("upper")])
                    if hi > 0:
                        widest = max(widest, float((hi - lo) / hi))
            rows.append((name, " ".join(prec).replace("--type ", "").replace("--digits ", "digits "), len(body),
                         "enclosure" if "lower" in head else "exact", widest, seconds))
    return rows


# ---------------------------------------------------------------------------------------------- report

def md_escape(text):
    return text.replace("|", "\\|")


def versions(tool):
    v = dict(line.split(" ", 1) for line in run([tool, "version"]).strip().splitlines())
    try:
        v["ginac"] = run(["pkg-config", "--modversion", "ginac"]).strip()
    except SystemExit:
        v["ginac"] = "not found"
    git = lambda *a: subprocess.run(["git", "-C", ROOT] + list(a), capture_output=True, text=True).stdout.strip()
    v["commit"] = git("rev-parse", "--short=12", "HEAD") or "unknown"
    if git("status", "--porcelain", "--untracked-files=no"):
        v["commit"] += " (with uncommitted changes)"
    cpu = "unknown"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    v["machine"] = "%s, %d cores, %s %s" % (cpu, os.cpu_count() or 0, platform.system(), platform.release())
    return v


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tool", required=True)
    ap.add_argument("--bench-json", default=os.path.join(ROOT, "bench", "results", "latest.json"))
    ap.add_argument("--out", default=os.path.join(ROOT, "reports"))
    ap.add_argument("--digits", type=int, default=50)
    a = ap.parse_args()
    r = Report(os.path.abspath(a.tool), a.out, a.digits)
    # The tree's state before this run writes its figures (tracked files): the commit it reports.
    v = versions(r.tool)
    r.commit = v["commit"]

    claims = json.loads(run([r.tool, "verify", "--digits", str(a.digits), "--format", "json"]))["claims"]
    figs = {"fig2": fig2_trace(r), "fig3": fig3_square(r), "fig4": fig4_harmonic(r), "power": fig_power_collapse(r)}
    figs["ball"], figs["wearflat"] = fig4_ball(r), fig_wearflat(r)
    figs["ulp"], ulp_summary = fig_ulp(r)
    figs["rig"], rig_dist = fig_rig_map(r)
    figs["inplane_xi"], figs["inplane_ratchet"], figs["inplane_xi_transverse"] = fig_inplane(r)
    cross = crosscheck(r)
    cert = certified(r)

    L = []
    w = L.append
    w("# Verification report: friction under large-amplitude normal oscillations")
    w("")
    w("<!-- Generated by reports/generate.py from the vibrofric tool; do not edit by hand. -->")
    w("")
    w("## Summary")
    w("")
    paper = [c for c in claims if c["source"] == "paper"]
    inplane = [c for c in claims if c["key"].startswith("inplane-")]
    ours = [c for c in claims if c["source"] not in ("paper", "Part II (abstract)") and not c["key"].startswith("inplane-")]
    part2 = [c for c in claims if c["source"] == "Part II (abstract)"]
    counts = {}
    for c in paper:
        counts[c["verdict"]] = counts.get(c["verdict"], 0) + 1
    w("Every statement of M. Popov, *Friction under large-amplitude normal oscillations*, that `model.md` lists, "
      "decided by the vibrofric solver at **%d significant digits** (the solver carries guard digits and raises "
      "its precision until its own rounding bound meets the request). Where a claim is a closed form or a "
      "derivation it is also proved symbolically in [`proofs/`](../proofs/README.md) (GiNaC); the solver is "
      "cross-checked by an independent mpmath implementation, an exact rational lower-envelope algorithm and a "
      "grid envelope (`tests/`)." % a.digits)
    w("")
    w("**The paper's %d claims:** %s. Corrections to our own documents and our extensions (curved contacts) "
      "are listed apart and not counted here." % (len(paper), ", ".join("%d %s" % (n, k) for k, n in sorted(counts.items()))))
    w("")
    w("| | |")
    w("|---|---|")
    w("| vibrofric | %s, commit `%s` |" % (v.get("vibrofric", "?"), v["commit"]))
    w("| compiler | %s |" % v.get("compiler", "?"))
    w("| Boost / MPFR / GMP / GiNaC | %s / %s / %s / %s |" % (v.get("boost"), v.get("mpfr"), v.get("gmp"), v["ginac"]))
    w("| machine | %s |" % v["machine"])
    w("| build stamp | %s |" % datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"))
    w("")

    def claims_table(rows):
        w("| claim | statement | method | cases | deviation (unit) | verdict | evidence |")
        w("|---|---|---|---|---|---|---|")
        for c in rows:
            ev = []
            if c["proof"]:
                ev.append("[%s](../%s)" % (os.path.basename(c["proof"]), c["proof"]))
            ev.append("test `%s`" % c["key"])
            verdict = "**%s**" % c["verdict"]
            if c["verdict"] != "holds approximately":
                verdict = "**%s (%s)**" % (c["verdict"], c["certification"])
            if c["scope"]:
                verdict += " — " + c["scope"]
            if c["fails_where"]:
                verdict += "; fails: " + c["fails_where"]
            w("| %s | %s | %s | %d | %s (%s) | %s | %s |" % (
                c["id"], md_escape(c["statement"]), c["method"], c["cases"], c["deviation"],
                md_escape(c["deviation_unit"]), md_escape(verdict), ", ".join(ev)))
        w("")

    w("## The paper's claims")
    w("")
    w("Statements as the paper makes them, decided at %d digits. Each deviation is written with its unit; a "
      "deviation is printed at the working precision (three significant digits, any exponent). Test: the ctest "
      "name is `Catalogue/Claim.VerdictIsTheEstablishedOne/KEY` in [`tests/unit/test_claims.cpp`]"
      "(../tests/unit/test_claims.cpp)." % a.digits)
    w("")
    claims_table(paper)
    w("## Errata: where the paper is wrong")
    w("")
    for c in paper:
        if c["verdict"] != "fails":
            continue
        w("### %s" % c["id"])
        w("")
        w("- **As stated:** %s" % c["statement"])
        # A clean counterexample the check names (exact values at a simple point) leads; the grid's
        # worst case, often an extreme corner, follows as the largest deviation.
        clean = [m for m in c["measured"] if m["name"].startswith(("smallest counterexample", "counterexample"))]
        clean.sort(key=lambda m: not m["name"].startswith("smallest"))
        for m in clean[:1]:
            # The check's name for it, without the word the heading already says.
            name = m["name"]
            for word in ("smallest counterexample", "counterexample"):
                if name.startswith(word):
                    name = name[len(word):].lstrip(" :")
                    break
            w("- **Counterexample%s:** %s" % (" (the smallest)" if m["name"].startswith("smallest") else "",
                                             (name + ": " if name else "") + m["value"]))
        w("- **%s** (deviation %s, %s): %s" % ("Largest deviation on the grid" if clean else "Counterexample",
                                              c["deviation"], c["deviation_unit"], c["worst"]))
        if c["scope"]:
            w("- **Where it holds:** %s" % c["scope"])
        if c["fails_where"]:
            w("- **Where it fails:** %s" % c["fails_where"])
        w("- **Corrected:** %s — largest measured deviation %s at %d digits%s" % (
            c["corrected"], c["corrected_deviation"], a.digits,
            " ([proof](../%s))" % c["proof"] if c["proof"] else ""))
        for m in c["measured"]:
            if m not in clean[:1]:
                w("- %s: %s" % (m["name"], m["value"]))
        w("")
    w("## Corrections to our own documents and our extensions")
    w("")
    w("Not the paper's claims: statements of `model.md` that the suite checks, and where it found `model.md` "
      "wrong (now corrected there).")
    w("")
    claims_table(ours)
    for c in ours:
        if c["verdict"] != "fails":
            continue
        w("### model.md: %s" % c["statement"])
        w("")
        w("- **Counterexample** (deviation %s, %s): %s" % (c["deviation"], c["deviation_unit"], c["worst"]))
        if c["scope"]:
            w("- **Where it holds:** %s" % c["scope"])
        w("- **Corrected:** %s — largest measured deviation %s%s" % (
            c["corrected"], c["corrected_deviation"], " ([proof](../%s))" % c["proof"] if c["proof"] else ""))
        w("")
    found = os.path.join(ROOT, "proofs", "foundations_envelope.md")
    if os.path.exists(found):
        w("### model.md: steady state from any start")
        w("")
        w("See [foundations_envelope.md](../proofs/foundations_envelope.md): the steady state is unique and "
          "equals the lower envelope, but one period suffices only from starts at most β below it (for example "
          "any start in slip); a start further below needs ⌈(s_∞(φ0) − s0)/β⌉ periods.")
        w("")
    w("## Approximate statements, measured")
    w("")
    for c in claims:
        if c["verdict"] != "holds approximately":
            continue
        w("### %s — %s%s" % (c["id"], c["statement"], "" if c["source"] == "paper" else " (%s, not the paper)" % c["source"]))
        w("")
        w("- **Checked:** %s" % c["how"])
        w("- **Criterion:** %s" % c["criterion"])
        w("- **Largest deviation:** %s (%s) at %s" % (c["deviation"], c["deviation_unit"], c["worst"]))
        if c["scope"]:
            w("- **Holds over:** %s" % c["scope"])
        w("- **Fails over:** %s" % (c["fails_where"] or "nowhere on the grid checked"))
        if c["corrected"]:
            w("- **What holds:** %s" % c["corrected"])
        # The closed forms of curved contacts have their own table (section "Curved contacts").
        rows = [(m["name"], m["value"]) for m in c["measured"] if not m["name"].startswith("closed form: ")]
        if rows:
            w("")
            w("| measured | value |")
            w("|---|---|")
            for name, value in rows:
                w("| %s | %s |" % (md_escape(name), md_escape(value)))
        w("")
    w("## Exact claims: how each was checked")
    w("")
    w("A verdict is *certified* where a certified computation decides it on the claim's grid (exact rationals, "
      "`core/exact.hpp`, or interval enclosures, `core/enclosure.hpp`: the closed form equal to the exact value or "
      "inside the enclosure, a counterexample outside it), *numerical* where it rests on the high-precision solver and "
      "its error estimate; each entry says how, or what keeps it numerical.")
    w("")
    for c in claims:
        if c["verdict"] == "holds approximately":
            continue
        w("- **%s** (%s, %s): %s. *Criterion:* %s. *%s:* %s." % (
            c["id"], c["verdict"], c["certification"], c["how"], c["criterion"], c["certification"].capitalize(),
            c["certification_note"]))
        for m in c["measured"]:
            if c["verdict"] != "fails":
                w("  - %s: %s" % (m["name"], m["value"]))
    w("")
    w("## Independent cross-check")
    w("")
    w("The solver at 40 digits against [`tests/reference/mu_mpmath.py`](../tests/reference/mu_mpmath.py), an "
      "independent mpmath implementation (closed-form events, `findroot`, antiderivatives; no shared code), at "
      "50 digits (a deviation up to 5e-40 is the rounding of the 40-significant-digit output), β = 0.1, 0.2, …, 7 and γ = 2, 0.5, −0.5, −0.9. The test suite adds the exact rational lower "
      "envelope for piecewise-linear waves, the grid envelope and the time-stepping baseline for random waves "
      "(`ctest -L verification`).")
    w("")
    w("| wave | points | largest relative deviation | at |")
    w("|---|---|---|---|")
    for wave, n, dev, where in cross:
        w("| %s | %d | %.2e | %s |" % (wave, n, dev, where))
    w("")
    w("## Certified values")
    w("")
    w("`--certify` proves that a printed value is the correct rounding of the exact one (README, \"Precision\"): "
      "exact rationals for the piecewise-linear waves (`core/exact.hpp`, the running minimum of n − βφ in GMP), "
      "interval enclosures for the sine, power:P and Fourier series (`core/enclosure.hpp`, MPFI; each structural "
      "decision certain, every event a simple root with a certain sign change, the bits doubled until both ends round "
      "alike). Every point of `sweep --certify --beta log:1e-6:20:41 "
      "--gamma -0.999,-0.9,-0.5,0,0.5,0.999,1,2` below was proven; a point that was not would stop this report. "
      "The Fourier series is sin 2πφ + sin(6πφ)/2, odd, so n touches zero at γ = 1 (there the enclosure is widened by "
      "the dip no precision decides). Curved contacts have no certified values yet.")
    w("")
    w("| wave | precision | points proven | certified by | widest enclosure (relative) | seconds |")
    w("|---|---|---|---|---|---|")
    for wave, prec, n, how, widest, sec in cert:
        w("| %s | %s | %d | %s | %s | %.2f |" % (wave, prec, n, how, "%.1e" % widest if how == "enclosure" else "0",
                                                 sec))
    w("")
    w("## Figures")
    w("")
    w("Data and gnuplot scripts: [`figures/data/`](figures/data/). PNG versions sit beside each SVG.")
    w("")
    for key, caption in (("fig2", "Fig. 2 — normal force μ0F_z and tangential force F_x over one period, harmonic "
                                   "wave, β = 2, without and with jumping."),
                         ("fig3", "Fig. 3 — square wave, Eq. 22, for the paper's 11 values of γ."),
                         ("fig4", "Fig. 4 — harmonic wave for the paper's 11 values of γ, with Eq. 23 relative to "
                                  "γ0 = −0.3 as markers: one shape per γ, filled in its curve's colour (see the key). The "
                                  "curves of γ = 0.2 to 1 lie within 0.06 of each other: the inset draws their distance "
                                  "from γ = 1 (darker: γ nearer 1)."),
                         ("power", "Power-law family p = 3: the curves for five γ collapse onto one under "
                                   "β(1+γ)^−(p−1)/p (the remapping that holds) and not under Eq. 24 as printed."),
                         ("ulp", "Error in ulps over β of the fixed-precision paths of `vibrofric mu`.")):
        w("![%s](%s)" % (caption, figs[key]))
        w("")
        w("*%s*" % caption)
        w("")
    w("### Fixed-precision paths of the tool (sine), error against 40-digit mpfr")
    w("")
    w("| wave | γ | path | max error (ulp) | RMS (ulp) | worst β |")
    w("|---|---|---|---|---|---|")
    for wave, g, name, mx, rms, wb in ulp_summary:
        w("| %s | %s | %s | %.3g | %.3g | %s |" % (wave, g, name, mx, rms, wb))
    w("")
    curved_section(w, claims, figs, a.bench_json)
    rig_section(w, r, figs, rig_dist, part2, claims_table)
    inplane_section(w, figs, claims_table, inplane, r.tool)
    bench_section(w, a.bench_json, r)
    mutation_section(w, os.path.join(ROOT, "tests", "mutation", "results", "latest.md"))
    w("## Reproduce")
    w("")
    w("On Debian 12, from a clone (the README's main command):")
    w("")
    w("```")
    w(readme_command("main-command"))
    w("```")
    with open(os.path.join(a.out, "VERIFICATION.md"), "w") as f:
        f.write("\n".join(L) + "\n")


def claim(claims, key):
    for c in claims:
        if c["key"] == key:
            return c
    return None


def curved_section(w, claims, figs, bench_json):
    """Curved contacts (model.md, "Curved contacts (MDR)"): Fig. 4 for the ball, the wear flat's approach to
    the flat punch, the closed forms, the static coefficient and the cost, from the tool and `verify`."""
    w("## Curved contacts")
    w("")
    w("By the method of dimensionality reduction (`model.md`, \"Curved contacts (MDR)\") a curved indenter is a "
      "row of flat-punch springs at the shifted mean indentations γ' = γ − σ(x), and μ̄/μ0 = ∫Φ dx / ∫N dx "
      "(`curved.hpp`, `vibrofric mu|sweep --profile`). The claims about curved contacts are in the table above: "
      "the abstract's scope statement in its two halves (`scope-wearflat`, `scope-numerics`), Eq. 6 and Sec. 3 for "
      "a row of springs (`curved-eq6-sec3`) and the flat-punch limit of the power-law profiles "
      "(`curved-power-flat`); their derivations head [`lib/verification/src/claims/curved.cpp`](../lib/verification/src/claims/curved.cpp).")
    w("")
    cap = ("Fig. 4 for a ball: harmonic wave, the paper's 11 values of γ (−1 drawn at −0.999), flat punch (left) and "
           "sphere (right), `vibrofric sweep --wave sine --profile sphere --beta 0.02:7:100 --gamma … --digits 12`.")
    w("![%s](%s)" % (cap, figs["ball"]))
    w("")
    w("*%s*" % cap)
    w("")
    wf = claim(claims, "scope-wearflat")
    cap = ("A sphere with a wear flat of radius b against the flat punch, β = 1, over λ = b²/(R A) (`vibrofric mu "
           "--profile wearflat:λ --digits 20`); the dashed line has slope −2.")
    w("![%s](%s)" % (cap, figs["wearflat"]))
    w("")
    w("*%s*" % cap)
    w("")
    if wf:
        w("**Abstract, scope (wear flat): %s.** %s. %s" % (wf["verdict"], wf["scope"][:1].upper() + wf["scope"][1:],
                                                           "What holds: " + wf["corrected"] + "." if wf["corrected"] else ""))
        w("")
        rows = [m["fields"] for m in wf["measured"] if "D(1)" in m["fields"]]
        if rows:
            w("| wave, γ | D(1) | D(10) | D(100) | D(10³) | D(10⁴) | order | C(β) = lim λ²(μ_wf − μ_flat) |")
            w("|---|---|---|---|---|---|---|---|")
            for f in rows:
                ds = [f["D(%s)" % lam] for lam in ("1", "10", "100", "1000", "10000")]
                cs = [(k[len("C(beta = "):-1], v) for k, v in f.items() if k.startswith("C(beta = ")]
                w("| %s, gamma = %s | %s | %s | %s (β = %s) |" % (f["wave"], f["gamma"], " | ".join(ds), f["order"],
                                                                   ", ".join(v for _, v in cs), ", ".join(b for b, _ in cs)))
            w("")
            w("D(λ): the largest |μ_wf − μ_flat| over β, in units of μ0; C from the derived first moments "
              "(`curved.cpp`). %s" % "; ".join("%s: %s" % (m["name"], m["value"]) for m in wf["measured"]
                                               if m["name"].startswith("largest relative |lambda^2")
                                               or m["name"].startswith("triangle, gamma <= 1")))
            w("")
    w("### Closed forms for curved contacts")
    w("")
    rows = closed_form_rows(claims)
    if rows:
        w("The closed forms of [`curved_closed_forms.hpp`](../lib/verification/include/vibrofric/verification/curved_closed_forms.hpp) (triangle and "
          "square; power-law profiles σ = xⁿ and the wear-flat sphere) against the curved solver, at the report's "
          "digits (`verify`, claim `scope-wearflat`):")
        w("")
        w("| wave | profile | β | γ | closed form | solver | relative difference |")
        w("|---|---|---|---|---|---|---|")
        for row in rows:
            w("| %s |" % " | ".join(row))
        w("")
    else:
        w("> **Placeholder.** No closed forms in this build: `lib/verification/include/vibrofric/verification/curved_closed_forms.hpp` was not "
          "present when `vibrofric` was built, so `verify` measured none. When it is, this table lists them against "
          "the solver (measured fields `closed form: …` of the claim `scope-wearflat`).")
        w("")
    st = claim(claims, "curved-eq6-sec3")
    if st:
        w("### Static coefficient of a curved contact")
        w("")
        w("**%s: %s.** %s." % (st["id"], st["verdict"], st["scope"][:1].upper() + st["scope"][1:]))
        w("")
        w("| case | static coefficient μ_s (derived) / μ̄(β) |")
        w("|---|---|")
        for m in st["measured"]:
            if "mu_s" in m["fields"]:
                f = m["fields"]
                w("| %s | %s / %s |" % (md_escape(f["case"]), f["mu_s"], f["mu"]))
        w("")
    nu = claim(claims, "scope-numerics")
    if nu:
        w("### Cost")
        w("")
        w("**%s: %s** — %s." % (nu["id"], nu["verdict"], nu["scope"]))
        for m in nu["measured"]:
            if m["name"].startswith(("CPU time", "slowest", "largest relative error")):
                w("- %s: %s" % (m["name"], m["value"]))
        w("")
        curved_bench_table(w, bench_json)


def rig_section(w, r, figs, dist, part2, claims_table):
    """Rig dynamics (model.md, "Rig dynamics: mass and system stiffness"): how it is checked, the map of
    where the quasi-static model holds, and Part II's two claims (the verify rows `part2`)."""
    w("## Rig dynamics: mass and system stiffness")
    w("")
    w("`vibrofric mu --kappa K --omega W --zeta Z` (and `physical --mass --k-system --damping`) put a body of mass m "
      "on a system spring k_s between the drive and the contact spring (`core/dynamics.hpp`): motion in closed form "
      "between events, the sweeping-process rules at jumps, kinks and touch-down, the periodic state by Newton on the "
      "one-period map from two starts, the value printed where two mpfr precisions agree. Checked by "
      "`tests/unit/test_rig.cpp` against an independent time-stepping peer (`rig_peer.hpp`), the Ω → ∞ limit at the "
      "rate model.md measured independently, the square wave's jump that keeps μ̄ off it, the energy balance and "
      "the mean force, long double against 60 digits, and the exact resonance.")
    w("")
    cap = ("Where a rig is quasi-static: the relative distance of the rig's μ̄ from its quasi-static limit "
           "g_w(βκ/(1+κ), γ) (the paper's model at the series stiffness) over Ω and κ, β = 1, γ = 0.5, ζ = 0.1, "
           "`vibrofric mu --kappa K --omega W --zeta 0.1 --type double`; inside the black 1 % contour the paper's "
           "model applies to the rig.")
    w("![%s](%s)" % (cap, figs["rig"]))
    w("")
    w("*%s*" % cap)
    w("")
    w("| wave | smallest Ω within 1 % at κ = 0.1 | at κ = 1 | at κ = 10 | at κ = 100 |")
    w("|---|---|---|---|---|")
    for wave in RIG_WAVES:
        cells = []
        for k in ("0.1", "1", "10", "100"):
            # the smallest Omega from which on every larger Omega of the grid is within 1 %
            ok = None
            for o in reversed(RIG_OMEGAS):
                if dist[(wave, o, k)] <= 0.01:
                    ok = o
                else:
                    break
            cells.append(ok if ok else "none ≤ 1000")
        w("| %s | %s |" % (wave, " | ".join(cells)))
    w("")
    # Part II (Mao, V.L. Popov, Starcevic, M. Popov, Friction 5 (2017)), the abstract's two claims: rows of
    # `verify` (lib/verification/src/claims/rig.cpp), as the paper's are.
    w("### The abstract of Part II, decided")
    w("")
    w("Mao, V.L. Popov, Starcevic, M. Popov, *Reduction of friction by normal oscillations II. In-plane system "
      "dynamics*, Friction 5 (2017) 194–206: its full text is not available here, so its abstract's two claims are "
      "decided with our model (`verify --claim part2-limits`, `--claim part2-resonance`).")
    w("")
    claims_table(part2)
    for c in part2:
        w("- **%s**: %s" % (c["id"], c["how"]))
        for m in c["measured"]:
            w("  - %s: %s" % (m["name"], m["value"]))
    w("")


def curved_bench_table(w, path):
    """The curved-contact benchmarks of bench/results (speed/<wave>+<profile>/<path>), if the run has them."""
    if not os.path.exists(path):
        return
    doc = json.load(open(path))
    curved = doc.get("vibrofric", {}).get("summary", {}).get("curved", {})
    if not curved:
        return
    w("From the benchmark run (`bench/run`, CPU time per evaluation, median; see the benchmark section below):")
    w("")
    w("| case | path | CPU time | relative error | note |")
    w("|---|---|---|---|---|")
    for case, paths in sorted(curved.items()):
        for name, e in paths.items():
            t = e.get("cpu_ns")
            err = e.get("rel_error")
            # M, N: the spring row (solver_mpfr_D counts springs per evaluation, and has no steps)
            if e.get("how"):
                note = e["how"]
            elif "steps" in e:
                note = "M = %d, N = %d" % (e["springs"], e["steps"])
            elif "springs" in e:
                note = "%.0f springs per evaluation" % e["springs"]
            else:
                note = ""
            w("| %s | %s | %s | %s | %s |" % (case, name, fmt_time(t), "-" if err is None else "%.1e" % err,
                                              md_escape(note)))
    w("")


def fmt_time(ns):
    if ns is None:
        return "-"
    if ns >= 1e9:
        return "%.3g s" % (ns / 1e9)
    if ns >= 1e6:
        return "%.3g ms" % (ns / 1e6)
    if ns >= 1e3:
        return "%.3g µs" % (ns / 1e3)
    return "%.3g ns" % ns


def readme_command(marker):
    """The command under <!-- marker --> in README.md, as .ci/run reads it."""
    lines = open(os.path.join(ROOT, "README.md")).read().splitlines()
    i = lines.index("<!-- %s -->" % marker)
    start = lines.index("```sh", i) + 1
    return "\n".join(lines[start:lines.index("```", start)])


def bench_section(w, path, r):
    w("## Accuracy and speed (benchmarks)")
    w("")
    if not os.path.exists(path):
        w("No benchmark results at `%s`: run `bench/run` (see [bench/README.md](../bench/README.md))." %
          os.path.relpath(path, ROOT))
        w("")
        return
    doc = json.load(open(path))
    meta = doc.get("vibrofric", {})
    before = meta.get("machine_before", {})
    w("From [`%s`](../%s), written by `bench/run` (Google Benchmark; see [bench/README.md](../bench/README.md) for "
      "the paths, the grid and its corners, and how the references are made and checked), started %s at commit "
      "`%s`%s, mode %s. Errors are in ulp (ε) of the type against mpfr at twice its digits or more." % (
          os.path.relpath(path, ROOT), os.path.relpath(path, ROOT), meta.get("started", "?"),
          str(before.get("git_commit", "?"))[:12], " (dirty)" if before.get("git_dirty") else "",
          meta.get("mode", "?")))
    w("")
    report_commit = r.commit if hasattr(r, "commit") else None
    bench_commit = str(before.get("git_commit", "?"))
    if report_commit and not bench_commit.startswith(report_commit[:12]) and not report_commit.startswith(bench_commit[:12]):
        w("**These timings come from commit `%s`, not from the report's commit `%s`**: the benchmarks are re-run "
          "on a quiet machine when the solver's code changes; the claims and figures above are from the report's "
          "commit." % (bench_commit[:12], report_commit[:12]))
        w("")
    md = os.path.splitext(path)[0] + ".md"
    if os.path.exists(md):
        for line in open(md).read().splitlines():
            w("#" + line if line.startswith("#") else line)
        w("")
    # Cost against digits, from the same JSON.
    speed = meta.get("summary", {}).get("speed", {})
    blocks = []
    for wave, paths in sorted(speed.items()):
        pts = [(d, paths["solver_mpfr_%d" % d]["cpu_ns"] / 1000.0) for d in (50, 100, 300, 1000)
               if "solver_mpfr_%d" % d in paths]
        if pts:
            blocks.append((wave, pts))
    cdc = meta.get("summary", {}).get("curved_digits_cost")
    if cdc:
        blocks.append(("sphere + sine (curved)", [(d, t / 1000.0) for d, t in cdc["points_cpu_ns"]]))
    if blocks:
        r.write_data("cost_digits.dat", blocks, "digits cpu_us (solver in mpfr, one evaluation, from %s)" %
                     os.path.relpath(path, ROOT))
        plots = ", \\\n     ".join("'%s' index %d using 1:2 with linespoints lw 2 pt 7 title '%s'" %
                                   ("cost_digits.dat" if i == 0 else "", i, wave) for i, (wave, _) in enumerate(blocks))
        fig = r.gnuplot("cost_digits", """
set title 'Cost of one evaluation of μ̄ against working precision (mpfr)'
set xrange [15:1200]
set xlabel 'working precision (decimal digits)'
set ylabel 'CPU time per evaluation (µs)'
set logscale xy
set key left top
plot %s
""" % plots)
        w("![Cost against digits](%s)" % fig)
        w("")
        w("*Cost of one solver evaluation in mpfr against digits, per wave, and of one curved evaluation "
          "(sphere + sine, mean over the bench's three inputs) (log–log).*")
        w("")


def mutation_section(w, path):
    w("## The suite's power (mutation testing)")
    w("")
    w("Each mutant of [`tests/mutation/`](../tests/mutation/README.md) is one small bug patched into `lib/`; "
      "`tests/mutation/run.py` rebuilds a copy of the tree with it and runs `ctest`. A mutant is killed when a "
      "test fails. The run takes hours, so it is not part of this report's command; this is the last run's "
      "summary, written by `run.py`, with its own commit and dates.")
    w("")
    if not os.path.exists(path):
        w("No mutation results at `%s`: run `tests/mutation/run.py`." % os.path.relpath(path, ROOT))
        w("")
        return
    for line in open(path).read().splitlines():
        w("#" + line if line.startswith("#") else line)
    w("")


if __name__ == "__main__":
    main()
