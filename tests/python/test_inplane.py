"""In-plane oscillation from Python (longitudinal, transverse, phase, in_plane_wave, wave 'constant';
model.md): the tool's digits, the paper's model at zero amplitude, arrays, and the refusals."""
import os
import subprocess

import numpy as np
import pytest

import vibrofric

TOOL = os.environ.get("VIBROFRIC_TOOL")


def tool(*args):
    return subprocess.run([TOOL, *args], check=True, stdout=subprocess.PIPE, text=True).stdout.splitlines()[0]


@pytest.mark.usefixtures("tool_path")
@pytest.mark.parametrize("wave, beta, gamma, kw, flags", [
    ("sine", "0", "0.5", dict(longitudinal="1", phase="0.25"), ["--longitudinal", "1", "--phase", "0.25"]),
    ("triangle", "1.3", "0.3", dict(longitudinal="0.7", phase="0.1", in_plane_wave="square"),
     ["--longitudinal", "0.7", "--phase", "0.1", "--in-plane-wave", "square"]),
    ("constant", "3", None, dict(longitudinal="2.5", in_plane_wave="triangle"),
     ["--longitudinal", "2.5", "--in-plane-wave", "triangle"]),
    ("constant", "0.5", None, dict(longitudinal="0.3", transverse="0.7", phase="0.1"),
     ["--longitudinal", "0.3", "--transverse", "0.7", "--phase", "0.1"]),
    ("sine", "2", "1.5", dict(transverse="0.5", phase="0.25"), ["--transverse", "0.5", "--phase", "0.25"]),
    ("sine", "0.3", "-0.3", dict(longitudinal="0.5", phase="0.25", profile="sphere"),
     ["--longitudinal", "0.5", "--phase", "0.25", "--profile", "sphere"]),
])
def test_the_tools_digits(wave, beta, gamma, kw, flags):
    args = ["mu", "--wave", wave, "--beta", beta] + (["--gamma", gamma] if gamma else []) + flags
    assert vibrofric.mu(wave, beta, gamma, digits=25, strings=True, **kw) == tool(*args, "--digits", "25")
    assert vibrofric.mu(wave, beta, gamma, **kw) == float(tool(*args, "--type", "double"))


def test_zero_amplitude_is_the_papers_model():
    for beta, gamma in ((2, 1.5), (0.7, -0.3)):
        assert vibrofric.mu("sine", beta, gamma, longitudinal=0, phase=0.3) == vibrofric.mu("sine", beta, gamma)
        assert vibrofric.mu("sine", beta, gamma, longitudinal=0, profile="cone") == \
            vibrofric.mu("sine", beta, gamma, profile="cone")


def test_arrays_broadcast_like_mu():
    values = vibrofric.mu("sine", np.array([[0.0], [0.5]]), [0.5, 0.8], longitudinal=1, phase=0.25)
    assert values.shape == (2, 2)
    assert values[1, 0] == vibrofric.mu("sine", 0.5, 0.5, longitudinal=1, phase=0.25)
    assert values[0, 0] < 0  # the ratchet (model.md): the oscillation pushes the body forward


@pytest.mark.parametrize("args, kw, words", [
    (("sine", 1, 0.5), dict(longitudinal=-1), ["longitudinal", "-1"]),
    (("sine", 1, 0.5), dict(phase=0.25), ["phase", "longitudinal"]),
    (("sine", 1, 0.5), dict(longitudinal=1, in_plane_wave="sinus"), ["sinus"]),
    (("sine", 1, 0.5), dict(longitudinal=1, kappa=1, omega=2), ["kappa", "in-plane"]),
    (("constant", 1, None), dict(longitudinal=1, profile="sphere"), ["constant", "normal oscillation"]),
    (("constant", 1, 0.5), dict(longitudinal=1), ["gamma", "constant"]),
    (("sine", -1, 0.5), dict(longitudinal=1), ["beta", "-1"]),
])
def test_refusals(args, kw, words):
    with pytest.raises(ValueError) as e:
        vibrofric.mu(*args, **kw)
    for w in words:
        assert w in str(e.value)


def test_certify_gives_the_exact_values_worked_out_by_hand():
    # tests/unit/test_inplane_exact.cpp has the working: the ratchet on triangles -1/3; n = 1 with
    # a triangle drive, 5/6 at a_l = 1/2 and always slipping (1) at beta = 4 a_l = 2.
    from fractions import Fraction
    assert vibrofric.mu("triangle", 0, 0.5, longitudinal=1, phase=0.25, in_plane_wave="triangle",
                        certify=True) == (Fraction(-1, 3), Fraction(-1, 3))
    lo, hi = vibrofric.mu("constant", np.array([1, 2]), None, longitudinal=0.5, in_plane_wave="triangle",
                          certify=True, type="double")
    assert list(lo) == [Fraction(5, 6), Fraction(1)] and list(hi) == list(lo)


@pytest.mark.parametrize("args, kw, words", [
    (("sine", 1, 0.5), dict(longitudinal=1), ["certify=True", "normal wave 'sine'", "piecewise-linear"]),
    (("triangle", 1, 0.5), dict(longitudinal=1), ["certify=True", "in-plane wave 'sine'"]),
    (("triangle", 1, 0.5), dict(transverse=1, in_plane_wave="triangle"), ["certify=True", "transverse"]),
    (("triangle", 1, 0.5), dict(longitudinal=1, in_plane_wave="triangle", profile="sphere"), ["flat punch"]),
])
def test_certify_refusals(args, kw, words):
    with pytest.raises(ValueError) as e:
        vibrofric.mu(*args, certify=True, **kw)
    for w in words:
        assert w in str(e.value)


def test_sticking_through_the_period_is_a_solver_error():
    with pytest.raises(vibrofric.SolverError, match="no unique periodic state"):
        vibrofric.mu("constant", 0, None, longitudinal=0.5)


def test_transverse_refusals():
    with pytest.raises(ValueError, match="transverse"):
        vibrofric.mu("sine", 1, 0.5, transverse=-1)
    with pytest.raises(ValueError, match="without longitudinal or transverse"):
        vibrofric.mu("sine", 1, 0.5, phase=0.25)


@pytest.mark.usefixtures("tool_path")
@pytest.mark.parametrize("wave, beta, gamma, kw, flags", [
    ("sine", "0.3", "0.2", dict(longitudinal="1", phase="0.25"), ["--longitudinal", "1", "--phase", "0.25"]),
    ("constant", "0.5", None, dict(transverse="1"), ["--transverse", "1"]),
    ("triangle", "1", "-0.2", dict(longitudinal="0.4", transverse="0.3", in_plane_wave="square"),
     ["--longitudinal", "0.4", "--transverse", "0.3", "--in-plane-wave", "square"]),
])
def test_trace_is_the_tools(wave, beta, gamma, kw, flags):
    # trace(..., longitudinal=, transverse=) gives the tool's `trace` rows (phi, n, s_x, s_y, mode),
    # string for string; the force stays in the disc |s| <= n, on its rim while slipping.
    args = ["trace", "--wave", wave, "--beta", beta] + ([] if gamma is None else ["--gamma", gamma]) + flags + \
        ["--points", "16", "--digits", "12"]
    lines = subprocess.run([TOOL, *args], check=True, stdout=subprocess.PIPE, text=True).stdout.splitlines()
    assert lines[0] == "phi,n,s_x,s_y,mode"
    columns = vibrofric.trace(wave, beta, gamma, points=16, digits=12, strings=True, **kw)
    assert [list(c) for c in columns] == [list(c) for c in zip(*(line.split(",") for line in lines[1:]))]
    phi, n, sx, sy, mode = vibrofric.trace(wave, float(beta), None if gamma is None else float(gamma), points=16, **kw)
    assert phi.dtype == np.float64 and mode.dtype == object
    assert np.all(np.hypot(sx, sy) <= n * (1 + 1e-12) + 1e-15)
    slipping = np.array([m in ("slip", "backward") for m in mode])
    assert np.allclose(np.hypot(sx, sy)[slipping], n[slipping], rtol=1e-12, atol=1e-15)


def test_trace_refusals():
    with pytest.raises(ValueError, match="gamma=None"):
        vibrofric.trace("constant", 0.5, 0.2, transverse=1)
    with pytest.raises(ValueError, match="kappa/omega with an in-plane"):
        vibrofric.trace("sine", 0.5, 0.2, longitudinal=1, kappa=1, omega=2)
    with pytest.raises(ValueError, match="flat punch's only"):
        vibrofric.trace("sine", 0.5, 0.2, longitudinal=1, profile="sphere")
    with pytest.raises(ValueError, match="phase without"):
        vibrofric.trace("sine", 0.5, 0.2, phase=0.25)
    with pytest.raises(ValueError, match="missing gamma"):
        vibrofric.trace("sine", 0.5)
