"""Rig dynamics from Python (kappa, omega, zeta; model.md): the tool's digits, the quasi-static
model untouched without them, arrays, and the refusals."""
import os
import subprocess

import numpy as np
import pytest

import vibrofric

TOOL = os.environ.get("VIBROFRIC_TOOL")
RIG = dict(kappa="3", omega="10", zeta="0.1")


def tool(*args):
    return subprocess.run([TOOL, *args], check=True, stdout=subprocess.PIPE, text=True).stdout.splitlines()[0]


@pytest.mark.usefixtures("tool_path")
def test_the_tools_digits():
    args = ["mu", "--wave", "triangle", "--beta", "2", "--gamma", "-0.4", "--kappa", "3", "--omega", "10", "--zeta", "0.1"]
    assert vibrofric.mu("triangle", 2, -0.4, digits=25, strings=True, **RIG) == tool(*args, "--digits", "25")
    assert vibrofric.mu("triangle", 2, -0.4, **RIG) == float(tool(*args, "--type", "double"))


def test_without_the_rig_the_paper_and_with_it_another_value():
    plain = vibrofric.mu("triangle", 2, -0.4)
    assert plain == vibrofric.mu("triangle", 2, -0.4, kappa=None, omega=None)
    # the series stiffness k_s k_x/(k_s + k_x) lowers beta to 1.5; the body's mass adds 2.0e-3 at omega = 10
    series = vibrofric.mu("triangle", 1.5, -0.4)
    assert 1.5e-3 < vibrofric.mu("triangle", 2, -0.4, **RIG) - series < 2.5e-3


def test_arrays_broadcast_like_mu():
    values = vibrofric.mu("sine", [0.5, 1.0], 2.0, kappa=1, omega=2, zeta=0.02)
    assert values.shape == (2,)
    assert values[0] == vibrofric.mu("sine", 0.5, 2.0, kappa=1, omega=2, zeta=0.02)


@pytest.mark.parametrize("kw, words", [
    (dict(kappa=1), ("omega",)),
    (dict(omega=1, zeta=0.1), ("kappa",)),
    (dict(kappa=0, omega=1), ("kappa", "> 0")),
    (dict(kappa=1, omega=-1), ("omega", "> 0")),
    (dict(kappa=1, omega=1, zeta=-0.5), ("zeta", ">= 0")),
    (dict(kappa=1, omega=1, zeta=float("nan")), ("zeta",)),

    (dict(kappa=1, omega=1, certify=True, profile="sphere"), ("certify", "flat punch")),
])
def test_refusals_are_one_line(kw, words):
    with pytest.raises(ValueError) as info:
        vibrofric.mu("sine", 1.0, 0.5, **kw)
    msg = str(info.value)
    assert "\n" not in msg
    for w in words:
        assert w in msg, (w, msg)


def test_power_has_no_closed_form_motion():
    with pytest.raises(ValueError, match="closed form"):
        vibrofric.mu("power:3", 1.0, 0.5, kappa=1, omega=2)


@pytest.mark.usefixtures("tool_path")
def test_physical_with_a_mass_is_the_tools():
    kw = dict(E1=210e9, nu1=0.3, E2=70e9, nu2=0.33, radius=1e-3, v0=1e-3, f=20000, A=2e-6, u_mean=1e-6, mu0=0.3)
    out = vibrofric.physical("sine", mass=0.01, k_system=1e7, damping=5, strings=True, **kw)
    args = ["physical", "--wave", "sine"] + [x for k, v in kw.items() for x in ("--" + k.replace("_", "-"), repr(v))]
    lines = subprocess.run([TOOL, *args, "--mass", "0.01", "--k-system", "10000000.0", "--damping", "5", "--type", "double"],
                           check=True, stdout=subprocess.PIPE, text=True).stdout.splitlines()
    printed = dict(line.split(" = ") for line in lines)
    for name in ("kappa", "omega", "zeta", "mu_over_mu0", "stick_fraction", "flight_fraction"):
        assert out[name] == printed[name], name
    with pytest.raises(ValueError, match="k_system"):
        vibrofric.physical("sine", mass=0.01, **kw)


@pytest.mark.usefixtures("tool_path")
def test_rig_report_is_the_tools_json():
    import json
    args = ["mu", "--wave", "sine", "--beta", "1.61", "--gamma", "1.01", "--kappa", "0.39", "--omega", "7.49",
            "--zeta", "0.0429", "--digits", "20", "--format", "json"]
    want = json.loads(subprocess.run([TOOL, *args], check=True, stdout=subprocess.PIPE, text=True).stdout)
    got = vibrofric.rig("sine", "1.61", "1.01", kappa="0.39", omega="7.49", zeta="0.0429", digits=20, strings=True)
    for name, value in got.items():
        assert want[name] == value, name
    assert float(got["backward_slip_fraction"]) > 0  # this rig slips backward
    assert vibrofric.rig("sine", 1.61, 1.01, kappa=0.39, omega=7.49, zeta=0.0429)["mu_over_mu0"] == \
        vibrofric.mu("sine", 1.61, 1.01, kappa=0.39, omega=7.49, zeta=0.0429)
    with pytest.raises(TypeError, match="omega"):
        vibrofric.rig("sine", 1, 0.5, kappa=1)


@pytest.mark.usefixtures("tool_path")
def test_trace_is_the_tools():
    args = ["trace", "--wave", "sine", "--beta", "0.5", "--gamma", "0.3", "--kappa", "1", "--omega", "2", "--zeta", "0.1",
            "--points", "8", "--digits", "12"]
    lines = subprocess.run([TOOL, *args], check=True, stdout=subprocess.PIPE, text=True).stdout.splitlines()
    rows = [line.split(",") for line in lines[1:]]
    columns = vibrofric.trace("sine", "0.5", "0.3", kappa="1", omega="2", zeta="0.1", points=8, digits=12, strings=True)
    assert len(columns) == 6
    assert [list(c) for c in columns] == [list(c) for c in zip(*rows)]
    phi, n, s, lag, rate, mode = vibrofric.trace("sine", 0.5, 0.3, kappa=1, omega=2, zeta=0.1, points=8, digits=12)
    assert phi.dtype == np.float64 and mode.dtype == object
    assert np.all(np.abs(s) <= n) and set(mode) == {"stick", "slip", "flight"}


def test_trace_needs_both_rig_keywords():
    with pytest.raises(ValueError, match="missing omega"):
        vibrofric.trace("sine", 0.5, 0.3, kappa=1)


def test_rig_parameters_broadcast_like_beta_and_gamma():
    # Each element is the scalar call's value (the tool's rig at that kappa, omega, zeta), with numpy's
    # broadcasting over all five arguments; a bad element names its index.
    omega = np.array([0.118, 1.0])
    got = vibrofric.mu("sine", 0.5, 0.2, kappa=0.18, omega=omega)
    assert got.shape == (2,)
    assert list(got) == [vibrofric.mu("sine", 0.5, 0.2, kappa=0.18, omega=o) for o in omega]
    beta = np.array([[0.5], [1.0]])
    grid = vibrofric.mu("sine", beta, 0.2, kappa=[0.18, 0.5], omega=1.0, zeta=[0.1, 0.0], strings=True, digits=15)
    assert grid.shape == (2, 2)
    for i, b in enumerate((0.5, 1.0)):
        for j, (k, z) in enumerate(((0.18, 0.1), (0.5, 0.0))):
            assert grid[i, j] == vibrofric.mu("sine", b, 0.2, kappa=k, omega=1.0, zeta=z, strings=True, digits=15)
    with pytest.raises(ValueError, match=r"at index \(1,\): omega = -1"):
        vibrofric.mu("sine", 0.5, 0.2, kappa=0.18, omega=np.array([0.118, -1.0]))
    with pytest.raises(ValueError, match="broadcast"):
        vibrofric.mu("sine", [0.5, 1.0, 2.0], 0.2, kappa=[0.18, 0.5], omega=1.0)


def test_quasi_static_value_and_resonance_warning():
    # The paper's value at the same point beside the rig's; near the stick resonance
    # (omega sqrt(1 + kappa) = 1.086) a UserWarning names it; a stiff light rig warns nothing.
    quasi = vibrofric.mu("sine", 0.5, 0.2, strings=True)
    with pytest.warns(UserWarning, match=r"stick oscillator, omega sqrt\(1 \+ kappa\) = 1.09, near 1"):
        r = vibrofric.rig("sine", 0.5, 0.2, kappa=0.18, omega=1.0, strings=True)
    assert r["quasi_static_mu_over_mu0"] == quasi
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = vibrofric.rig("sine", 0.5, 0.2, kappa=10000, omega=100, strings=True)
    assert abs(float(r["mu_over_mu0"]) / float(quasi) - 1) < 1e-4


@pytest.mark.usefixtures("tool_path")
def test_a_ball_on_the_rig():
    # model.md's curved rig (sphere, measured independently: 0.35215); the row's springs reported
    with pytest.warns(UserWarning, match="resonance"):
        r = vibrofric.rig("sine", 1.37, 0.42, kappa=2.6, omega=3.3, zeta=0.3, profile="sphere")
    assert abs(r["mu_over_mu0"] - 0.35215) < 5e-6
    assert r["springs"] >= 200
    assert abs(r["stick_fraction"] + r["slip_fraction"] + r["flight_fraction"] - 1) < 1e-4
    # mu() with the same keywords broadcasts, its floats the larger row's value (rig() has the
    # digits the two rows agree on: 8 here)
    got = vibrofric.mu("sine", [1.37, 1.37], 0.42, kappa=2.6, omega=3.3, zeta=0.3, profile="sphere")
    assert got.shape == (2,) and got[0] == got[1]
    assert abs(got[0] - r["mu_over_mu0"]) <= 5e-9
    strings = vibrofric.mu("sine", 1.37, 0.42, kappa=2.6, omega=3.3, zeta=0.3, profile="sphere", strings=True)
    assert str(strings) == "0.35214873"
    # trace on the row: nine arrays, the tool's rows string for string
    arrays = vibrofric.trace("sine", 1.37, 0.42, kappa=2.6, omega=3.3, zeta=0.3, profile="sphere", points=8, strings=True)
    assert len(arrays) == 9
    lines = subprocess.run([TOOL, "trace", "--wave", "sine", "--beta", "1.37", "--gamma", "0.42", "--kappa", "2.6",
                            "--omega", "3.3", "--zeta", "0.3", "--profile", "sphere", "--points", "8"], check=True,
                           stdout=subprocess.PIPE, text=True).stdout.splitlines()
    assert [list(c) for c in arrays] == [list(c) for c in zip(*(line.split(",") for line in lines[1:]))]
    # a contact that never opens carries the row's states: the stiff, light rig is its quasi-static
    # value (measured 2e-7 apart)
    closed = vibrofric.rig("sine", 1.0, 1.5, kappa=1e6, omega=100, zeta=0.5, profile="sphere")
    assert abs(closed["mu_over_mu0"] - closed["quasi_static_mu_over_mu0"]) < 1e-4


def test_certified_rig_state():
    # mu(certify=True) with a rig: (lo, hi) holding the rig's value at 40 digits (the same solver at
    # twice the digits), the double value inside; arrays of beta point by point; rig(certify=True)
    # the whole certificate, its enclosures holding the report's fractions.
    from fractions import Fraction
    lo, hi = vibrofric.mu("sine", 0.5, 0.3, kappa=2, omega=3, zeta=0.1, certify=True, digits=20)
    ref = Fraction(vibrofric.mu("sine", 0.5, 0.3, kappa=2, omega=3, zeta=0.1, digits=40, strings=True))
    assert lo <= ref <= hi and hi - lo < Fraction(1, 10**25)
    # in double: the enclosure proves the double's rounding, so both its ends round to that double
    dlo, dhi = vibrofric.mu("sine", 0.5, 0.3, kappa=2, omega=3, zeta=0.1, certify=True)
    assert float(dlo) == float(dhi) == vibrofric.mu("sine", 0.5, 0.3, kappa=2, omega=3, zeta=0.1)
    assert dlo <= ref <= dhi
    los, his = vibrofric.mu("triangle", [2, 1.5], -0.4, certify=True, **RIG)
    for k, beta in enumerate((2, 1.5)):
        one = vibrofric.mu("triangle", beta, -0.4, certify=True, **RIG)
        assert (los[k], his[k]) == one
    d = vibrofric.rig("square", 2, 1.05, kappa=0.6, omega=1, zeta=0.05, certify=True, digits=20, strings=True)
    assert d["correctly_rounded"] == "proven" and d["periodic_state"].startswith("proven to exist")
    assert d["stability"].startswith("proven stable")
    assert d["cite"].startswith(d["mu_over_mu0"][:-1]) and d["lower"] < d["upper"] < d["lower"] * (1 + Fraction(1, 10**25))
    for name in ("stick_fraction", "slip_fraction", "backward_slip_fraction", "flight_fraction"):
        a, b = (Fraction(x) for x in d[name + "_enclosure"].strip("[]").split(", "))
        x = Fraction(d[name])
        assert a - Fraction(1, 10**16) <= x <= b + Fraction(1, 10**16), name
    assert Fraction(d["backward_slip_fraction_enclosure"].strip("[]").split(", ")[0]) > Fraction("0.09")


@pytest.mark.parametrize("call, words", [
    (lambda: vibrofric.mu("sine", 0.5, 0.3, kappa=[2, 3], omega=3, certify=True), ["one rig at a time"]),
    (lambda: vibrofric.rig("sine", 0.5, 0.3, kappa=2, omega=3, certify=True, profile="sphere"), ["flat punch"]),
    (lambda: vibrofric.rig("power:3", 0.5, 0.3, kappa=2, omega=3, certify=True), ["power:3", "Fourier"]),
])
def test_certified_rig_refusals(call, words):
    with pytest.raises(ValueError) as e:
        call()
    assert "\n" not in str(e.value) and all(w in str(e.value) for w in words), str(e.value)
