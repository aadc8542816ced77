"""vibrofric.physical against the tool's `physical --format json` (string for string, same keys in
the same order) and against Eqs. 1, 5 and 14 computed here in exact rationals; bad inputs.

The tool is the one this build made: ctest passes its path in VIBROFRIC_TOOL (tests/python's
CMakeLists.txt); without it (pytest by hand) the comparisons with the tool fail (conftest.py).
"""
import json
import os
import subprocess
from decimal import Decimal
from fractions import Fraction

import pytest

import vibrofric
from closed_forms import exact, rounded

TOOL = os.environ.get("VIBROFRIC_TOOL")
needs_tool = pytest.mark.usefixtures("tool_path")  # fails, never skips, without the tool

# Steel on aluminium, a 1 mm punch, 100 Hz at 1 um: beta = 1.0096 (Eq. 5).
BASE = dict(E1=210e9, nu1=0.3, E2=70e9, nu2=0.33, v0=5e-5, f=100, A=1e-6, mu0=0.4)
CASES = {
    "flat": dict(BASE, radius=1e-3, u_mean=0.3e-6),
    "sphere": dict(BASE, shape="sphere", R=0.01, u_mean=0.2e-6),
    "flat_load": dict(BASE, radius=1e-3, F_N=20),
    "sphere_load": dict(BASE, shape="sphere", R=0.01, F_N=0.5),
    "flat_shear_moduli": dict(BASE, G1=80e9, G2=26e9, radius=2e-3, u_mean=-0.4e-6),
}
FLAGS = {"u_mean": "u-mean", "F_N": "F-N", "half_angle": "half-angle", "flat_radius": "flat-radius", "u_x": "u-x",
         "u_y": "u-y", "in_plane_wave": "in-plane-wave"}


def tool_json(wave, inputs, precision):
    cmd = [TOOL, "physical", "--wave", wave, "--format", "json"] + precision
    for name, value in inputs.items():
        # The text the module reads for a float: its shortest round-trip decimal (repr).
        cmd += ["--" + FLAGS.get(name, name), value if isinstance(value, str) else repr(value)]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    return json.loads(out, object_pairs_hook=list)  # keeps the order of the keys


@needs_tool
@pytest.mark.parametrize("case", sorted(CASES))
def test_equals_tool_double(case):
    inputs = CASES[case]
    want = tool_json("sine", inputs, ["--type", "double"])
    got = vibrofric.physical("sine", strings=True, **inputs)
    assert list(got.items()) == want
    floats = vibrofric.physical("sine", **inputs)
    assert list(floats) == [k for k, _ in want]
    for k, v in want:
        if k == "shape":
            assert floats[k] == v
        else:
            assert type(floats[k]) is float and floats[k] == float(v), (k, floats[k], v)


@needs_tool
@pytest.mark.parametrize("case", ["flat", "sphere", "flat_load"])
def test_equals_tool_digits(case):
    inputs = CASES[case]
    want = tool_json("triangle", inputs, ["--digits", "25"])
    got = vibrofric.physical("triangle", digits=25, strings=True, **inputs)
    assert list(got.items()) == want


@needs_tool
def test_equals_tool_for_decimal_strings_and_other_shapes():
    inputs = dict(BASE, shape="wearflat", R="0.01", flat_radius="3e-5", u_mean="0.1e-6", E1="2.1e11")
    assert list(vibrofric.physical("square", digits=20, strings=True, **inputs).items()) == \
        tool_json("square", inputs, ["--digits", "20"])
    inputs = dict(BASE, shape="cone", half_angle=80, u_mean=0.5e-6)
    assert list(vibrofric.physical("sine", strings=True, **inputs).items()) == \
        tool_json("sine", inputs, ["--type", "double"])


def eq1_eq5(i):
    """Eq. 1: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2)
    with G = E/(2(1 + nu)) unless given, k_z = 2 E* a, k_x = 2 G* a; Eq. 5: beta = G* v0/(mu0 E* A f);
    Eq. 14: gamma = u_mean/A. Exact rationals of the decimals the module reads."""
    E1, nu1, E2, nu2 = (exact(i[k]) for k in ("E1", "nu1", "E2", "nu2"))
    G1 = exact(i["G1"]) if "G1" in i else E1 / (2 * (1 + nu1))
    G2 = exact(i["G2"]) if "G2" in i else E2 / (2 * (1 + nu2))
    E = 1 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)
    G = 1 / ((2 - nu1) / (4 * G1) + (2 - nu2) / (4 * G2))
    a = exact(i["radius"])
    beta = G * exact(i["v0"]) / (exact(i["mu0"]) * E * exact(i["A"]) * exact(i["f"]))
    return {"E_star_Pa": E, "G_star_Pa": G, "k_z_N_per_m": 2 * E * a, "k_x_N_per_m": 2 * G * a, "beta": beta,
            "gamma": exact(i["u_mean"]) / exact(i["A"])}


@pytest.mark.parametrize("case", ["flat", "flat_shear_moduli"])
def test_eq1_eq5_eq14_closed_forms(case):
    inputs = CASES[case]
    want = eq1_eq5(inputs)
    # 40 digits: each value is the exact one correctly rounded to 40 significant digits.
    got = vibrofric.physical("sine", digits=40, strings=True, **inputs)
    for k, q in want.items():
        assert Decimal(got[k]) == rounded(q, 40), (k, got[k], rounded(q, 40))
    # double: the nearest double of the 17-digit rounding (the tool's --type double text)
    floats = vibrofric.physical("sine", **inputs)
    for k, q in want.items():
        assert floats[k] == float(rounded(q, 17)), (k, floats[k])
        assert abs(Fraction(floats[k]) - q) <= abs(q) * Fraction(1, 10 ** 16), k


def test_relations_between_outputs():
    d = vibrofric.physical("sine", digits=30, strings=True, **CASES["flat_load"])
    F_N, mu0, A = Decimal(20), Decimal("0.4"), Decimal("1e-6")
    tol = Decimal("1e-28")
    assert abs(Decimal(d["F_N_mean_N"]) - F_N) <= tol * F_N  # gamma solves <F_N>(gamma) = F_N
    assert abs(Decimal(d["u_mean_m"]) - Decimal(d["gamma"]) * A) <= tol * abs(Decimal(d["u_mean_m"]))
    assert abs(Decimal(d["mu"]) - mu0 * Decimal(d["mu_over_mu0"])) <= tol
    assert abs(Decimal(d["F_x_mean_N"]) - Decimal(d["mu"]) * F_N) <= tol * 10
    # mu/mu0 at the same beta and gamma as mu() computes it
    m = vibrofric.mu("sine", d["beta"], d["gamma"], digits=25, strings=True)
    assert abs(Decimal(m) - Decimal(d["mu_over_mu0"])) <= Decimal("1e-24")
    assert 0 <= Decimal(d["stick_fraction"]) <= Decimal(d["contact_fraction"]) <= 1


def test_mpf_and_types():
    d = vibrofric.physical("sine", digits=30, **CASES["flat"])
    try:
        import mpmath
    except ImportError:
        assert isinstance(d["beta"], str)
    else:
        assert isinstance(d["beta"], mpmath.mpf)
    assert d["shape"] == "flat"
    inf = vibrofric.physical("square", **CASES["flat"])["beta_c"]  # an upward jump of n: stick at every beta
    assert inf == float("inf")


def raises(names, **kw):
    with pytest.raises(ValueError) as info:
        vibrofric.physical("sine", **kw)
    msg = str(info.value)
    assert "\n" not in msg and msg
    assert "--" not in msg, msg  # named by the keywords, not by the tool's flags
    for n in names:
        assert n in msg, (n, msg)
    return msg


def test_bad_inputs():
    inputs = dict(BASE, radius=1e-3)
    raises(("missing u_mean", "F_N"), **inputs)
    raises(("u_mean and F_N both",), u_mean=1e-7, F_N=3, **inputs)
    raises(("E1 = -1", "> 0"), **dict(inputs, E1=-1.0, u_mean=1e-7))
    raises(("nu2", "0.7"), **dict(inputs, nu2=0.7, u_mean=1e-7))
    raises(("missing radius",), **dict(BASE, u_mean=1e-7))  # the punch needs its radius
    raises(("radius does not apply to shape sphere",), **dict(BASE, shape="sphere", radius=1e-3, R=0.01, u_mean=1e-7))
    raises(("half_angle = 95", "degrees"), **dict(BASE, shape="cone", half_angle=95, u_mean=1e-7))
    raises(("u_mean = -2e-06 with A = ", "no contact"), **dict(inputs, u_mean=-2e-6))
    raises(("ball",), **dict(inputs, shape="ball", u_mean=1e-7))
    raises(("gamma",), **dict(inputs, u_mean=-2e-6))  # no contact: gamma = -2
    raises(("v0", "nan"), **dict(inputs, v0=float("nan"), u_mean=1e-7))
    with pytest.raises(TypeError):
        vibrofric.physical("sine", **dict(inputs, E1=True, u_mean=1e-7))
    with pytest.raises(TypeError):
        vibrofric.physical("sine", **dict(inputs, shape=3, u_mean=1e-7))
    with pytest.raises(TypeError):  # keyword-only, E1 required
        vibrofric.physical("sine", nu1=0.3)


# Wear-flat sphere against the MDR of model.md ("Curved contacts"), computed here with mpmath:
# f(r) = max(0, (r^2 - b^2)/2R) maps to g(x) = 0 for |x| <= b, (|x|/R) sqrt(x^2 - b^2) beyond. At
# indentation d > 0 the contact radius a solves g(a) = d, i.e. a^2 = (b^2 + sqrt(b^4 + 4 R^2 d^2))/2,
# and F(d) = 2 E* int_0^a (d - g(x)) dx = 2 E* [d a - (a^2 - b^2)^(3/2)/(3R)]. Triangle wave at
# gamma = u_mean/A <= 1 (Eq. 14): d = A (gamma + w), w uniform on [-1, 1], so
# <F_N> = (1/2) int_{-gamma}^{1} F(A (gamma + w)) dw; mu/mu0 = 2 beta/(4 + beta) on every profile
# (Eq. 19, model.md MDR: every spring is a punch at the same beta), <F_x> = mu0 (mu/mu0) <F_N>;
# largest contact radius a(A (1 + gamma)). b = 1 mm: b^2 = 100 R A (near the punch); b = 10 um:
# b^2 = R A/100 (near Hertz). The outputs are homogeneous of degree 1 in the MDR length unit
# (<F_N> = 2 E* A L int N dxi, radius = L xi_max, with L = b), so L = sqrt(R A) instead of b would
# scale all three by sqrt(R A)/b = 0.1 and 10 here.
@pytest.mark.parametrize("b", [1e-3, 1e-5])
def test_wearflat_forces_and_contact_radius_against_mdr(b):
    mpmath = pytest.importorskip("mpmath")
    inputs = dict(E1=210e9, nu1=0.3, E2=210e9, nu2=0.3, v0=1e-4, f=100, A=1e-6, mu0=0.5, u_mean=5e-7,
                  shape="wearflat", R=0.01, flat_radius=b)  # steel on steel, beta = 28/17
    with mpmath.workdps(45):
        q = eq1_eq5(dict(inputs, radius=1))  # E*, beta, gamma exact (the radius only enters k_z, k_x)
        E, beta, gamma = (mpmath.mpf(q[k].numerator) / q[k].denominator for k in ("E_star_Pa", "beta", "gamma"))
        A, R, b_ = (mpmath.mpf(repr(inputs[k])) for k in ("A", "R", "flat_radius"))
        assert -1 < gamma <= 1 and beta < 4

        def radius(d):
            return mpmath.sqrt((b_ ** 2 + mpmath.sqrt(b_ ** 4 + 4 * R ** 2 * d ** 2)) / 2)

        def F(d):
            a = radius(d)
            return 2 * E * (d * a - (a * a - b_ * b_) ** mpmath.mpf(1.5) / (3 * R))

        want = {"F_N_mean_N": mpmath.quad(lambda w: F(A * (gamma + w)), [-gamma, 1]) / 2}
        want["F_x_mean_N"] = mpmath.mpf("0.5") * 2 * beta / (4 + beta) * want["F_N_mean_N"]
        want["contact_radius_max_m"] = radius(A * (1 + gamma))
        floats = vibrofric.physical("triangle", **inputs)
        fine = vibrofric.physical("triangle", digits=30, strings=True, **inputs)
        for k, v in want.items():
            assert abs(floats[k] - v) <= 1e-14 * v, (k, floats[k], v)  # measured: 1e-16
            assert abs(mpmath.mpf(fine[k]) - v) <= mpmath.mpf("1e-28") * v, (k, fine[k], v)  # measured: 1e-30


def test_arrays_broadcast_like_mu():
    # Every element of a broadcast call is the scalar call's value (the same function per element),
    # in every form; shape stays one string.
    import numpy as np
    v0 = np.array([1e-5, 5e-5, 2e-4])
    A = np.array([[1e-6], [2e-6]])
    for kw in (dict(), dict(digits=25, strings=True), dict(type="long-double")):
        got = vibrofric.physical("sine", **dict(CASES["flat"], v0=v0, A=A), **kw)
        assert got["shape"] == "flat"
        for name, arr in got.items():
            if name == "shape":
                continue
            assert arr.shape == (2, 3), name
            for i in range(2):
                for j in range(3):
                    one = vibrofric.physical("sine", **dict(CASES["flat"], v0=v0[j], A=A[i, 0]), **kw)
                    assert arr[i, j] == one[name], (name, i, j, kw)
    # A list broadcasts like an array; a sweep of v0 at a given load (gamma solved once) on a sphere.
    got = vibrofric.physical("sine", **dict(CASES["sphere_load"], v0=[1e-5, 1e-4]))
    for j, v in enumerate([1e-5, 1e-4]):
        assert got["mu"][j] == vibrofric.physical("sine", **dict(CASES["sphere_load"], v0=v))["mu"]


def test_arrays_name_the_failing_index_or_give_nan():
    import numpy as np
    u = np.array([0.3e-6, -2e-6, 0.1e-6])  # u_mean = -2 um < -A max w: no contact at index 1
    with pytest.raises(ValueError, match=r"at index \(1,\): .*u_mean"):
        vibrofric.physical("sine", **dict(BASE, radius=1e-3, u_mean=u))
    got = vibrofric.physical("sine", **dict(BASE, radius=1e-3, u_mean=u), nan_on_error=True)
    assert np.isnan(got["mu"][1]) and np.isnan(got["gamma"][1])
    for j in (0, 2):
        assert got["mu"][j] == vibrofric.physical("sine", **dict(BASE, radius=1e-3, u_mean=u[j]))["mu"]
    s = vibrofric.physical("sine", **dict(BASE, radius=1e-3, u_mean=u), nan_on_error=True, strings=True)
    assert s["mu"][1] is None and isinstance(s["mu"][0], str)
    with pytest.raises(ValueError, match="every element failed"):
        vibrofric.physical("sine", **dict(BASE, radius=1e-3, u_mean=[-2e-6, -3e-6]), nan_on_error=True)


def test_implausible_inputs_warn():
    # GPa written as Pa: a UserWarning naming the keyword, the value still the model's.
    with pytest.warns(UserWarning, match="E1 = 210 is outside"):
        got = vibrofric.physical("sine", **dict(CASES["flat"], E1=210))
    assert got["mu"] > 0
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        vibrofric.physical("sine", **CASES["flat"])  # plausible: no warning


def test_f_agrees_with_the_time_stamps():
    # Samples with time stamps (no unit: seconds) have their own period; f must agree within 1 %.
    import numpy as np
    y = np.sin(2 * np.pi * np.arange(8) / 8)
    w = vibrofric.samples(y, t=np.arange(8) / 800.0)  # 8 samples, dt 1.25 ms: period 10 ms, 100 Hz
    assert vibrofric.physical(w, **CASES["flat"])["mu"] > 0  # f = 100
    with pytest.raises(ValueError, match=r"f = 50 Hz, but the time column .* 0\.0100000 s"):
        vibrofric.physical(w, **dict(CASES["flat"], f=50))


def test_amplitude_from_the_record():
    # unit='um': A is half the samples' peak-to-peak (here 0.5 um), returned as A_m; every other
    # output that of A = 5e-7. A and unit together, or unit for a catalogue wave, are refused.
    import numpy as np
    w = vibrofric.samples(np.array([0.0, 0.5, 0.0, -0.5]))
    inputs = {k: v for k, v in CASES["flat"].items() if k != "A"}
    got = vibrofric.physical(w, unit="um", digits=30, strings=True, **inputs)
    ref = vibrofric.physical(w, A="5e-7", digits=30, strings=True, **inputs)
    assert Fraction(got.pop("A_m")) == Fraction("5e-7")
    assert got == ref
    with pytest.raises(ValueError, match="A and unit both given"):
        vibrofric.physical(w, unit="um", **CASES["flat"])
    with pytest.raises(ValueError, match="samples"):
        vibrofric.physical("sine", unit="um", **inputs)
    with pytest.raises(TypeError, match="unit = 3"):
        vibrofric.physical(w, unit=3, **inputs)


def test_peak_load_and_pressure():
    # The deepest instant (sine: n = gamma + 1): the punch carries k_z A (gamma + 1) with an
    # unbounded rim pressure; the sphere Hertz's load, a = sqrt(R d), p0 = 3/2 of the mean.
    flat = vibrofric.physical("sine", **CASES["flat"], digits=30, strings=True)
    kz, A, g = Fraction(flat["k_z_N_per_m"]), Fraction("1e-6"), Fraction(flat["gamma"])
    assert abs(Fraction(flat["F_N_peak_N"]) / (kz * A * (g + 1)) - 1) < Fraction(1, 10 ** 28)
    assert flat["p_max_peak_Pa"] == "inf"
    s = vibrofric.physical("sine", **CASES["sphere"], digits=30)
    d = 1e-6 * (float(s["gamma"]) + 1)
    assert s["F_N_peak_N"] == pytest.approx(4 / 3 * float(s["E_star_Pa"]) * 0.01 ** 0.5 * d ** 1.5, rel=1e-14)
    assert s["contact_radius_max_m"] == pytest.approx((0.01 * d) ** 0.5, rel=1e-14)
    assert s["p_max_peak_Pa"] == pytest.approx(1.5 * s["p_mean_peak_Pa"], rel=1e-14)


@needs_tool
@pytest.mark.parametrize("wave, inputs", [
    ("sine", dict(BASE, radius=1e-3, u_mean=0.3e-6, u_x=1e-6, phase=0.25)),
    ("sine", dict(BASE, shape="sphere", R=0.01, u_mean=-0.2e-6, u_x=5e-7, phase=0.25)),
    ("constant", dict(E1=210e9, nu1=0.3, E2=70e9, nu2=0.33, v0=2e-2, f=20000, mu0=0.3, radius=1e-3, F_N=10,
                      u_x=2e-7, in_plane_wave="triangle")),
])
def test_in_plane_equals_tool(wave, inputs):
    # In-plane oscillation (u_x, phase, in_plane_wave; wave 'constant' with F_N): the tool's outputs.
    want = tool_json(wave, inputs, ["--digits", "15"])
    got = vibrofric.physical(wave, digits=15, strings=True, **inputs)
    assert list(got.items()) == want
    assert "longitudinal" in got and "F_y_mean_N" in got


def test_in_plane_refusals():
    with pytest.raises(ValueError, match="u_x"):
        vibrofric.physical("sine", **CASES["flat"], u_x=-1e-6)
    with pytest.raises(ValueError, match="phase"):
        vibrofric.physical("sine", **CASES["flat"], phase=0.25)
    with pytest.raises(ValueError, match="constant"):
        vibrofric.physical("constant", E1=210e9, nu1=0.3, E2=70e9, nu2=0.33, v0=2e-2, f=20000, mu0=0.3,
                           radius=1e-3, F_N=10, A=1e-6, u_x=1e-7)


@needs_tool
def test_trace_is_the_tools():
    # physical(..., trace=True) gives the tool's physical --trace rows, string for string; floats
    # are those strings read; array inputs and rigs are refused.
    kw = dict(E1="210e9", nu1="0.3", E2="70e9", nu2="0.33", F_N="10", v0="2e-3", f="20000", A="1.5e-6", mu0="0.3",
              shape="sphere", R="5e-3")
    args = ["physical", "--wave", "sine", "--E1", "210e9", "--nu1", "0.3", "--E2", "70e9", "--nu2", "0.33", "--F-N", "10",
            "--v0", "2e-3", "--f", "20000", "--A", "1.5e-6", "--mu0", "0.3", "--shape", "sphere", "--R", "5e-3",
            "--trace", "--points", "12", "--digits", "12"]
    lines = subprocess.run([TOOL, *args], check=True, stdout=subprocess.PIPE, text=True).stdout.splitlines()
    got = vibrofric.physical("sine", trace=True, points=12, digits=12, strings=True, **kw)
    assert list(got) == lines[0].split(",")
    assert [list(c) for c in got.values()] == [list(c) for c in zip(*(line.split(",") for line in lines[1:]))]
    floats = vibrofric.physical("sine", trace=True, points=12, digits=12, **kw)
    assert all(list(floats[k]) == [float(x) for x in got[k]] for k in got)
    with pytest.raises(ValueError, match="one point"):
        vibrofric.physical("sine", trace=True, **dict(kw, v0=[1e-3, 2e-3]))
    # with a rig, two more columns: the body's position and the holder's force, as the tool's
    rig = dict(kw, mass="0.05", k_system="2e6")
    lines = subprocess.run([TOOL, *args, "--mass", "0.05", "--k-system", "2e6"], check=True, stdout=subprocess.PIPE,
                           text=True).stdout.splitlines()
    got = vibrofric.physical("sine", trace=True, points=12, digits=12, strings=True, **rig)
    assert list(got) == lines[0].split(",") == ["t_s", "F_N_N", "F_x_N", "u_m", "x_m", "F_s_N"]
    assert [list(c) for c in got.values()] == [list(c) for c in zip(*(line.split(",") for line in lines[1:]))]
