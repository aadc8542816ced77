"""vibrofric.trace: n(phi) and s(phi) over one period (Fig. 2) against n = max(0, gamma + w(phi))
computed here, s <= n, s = 0 out of contact, and the contact boundaries with n = s = 0 exactly."""
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import vibrofric
from closed_forms import rounded

mpmath = pytest.importorskip("mpmath")


def n_sine(phi, gamma, digits):
    """max(0, gamma + sin 2 pi phi) to `digits` + 20 digits (mpmath)."""
    with mpmath.workdps(digits + 20):
        v = mpmath.mpf(gamma) + mpmath.sin(2 * mpmath.pi * mpmath.mpf(phi.numerator) / phi.denominator)
        if abs(v) < mpmath.mpf(10) ** -(digits + 10):  # gamma + sin 2 pi phi = 0 exactly (sin pi = 0)
            return mpmath.mpf(0)
        return max(v, mpmath.mpf(0))


def round17(v):
    """The double of v rounded to 17 significant digits (the tool's text at --digits 17)."""
    d = Decimal(mpmath.nstr(v, 40, strip_zeros=False))
    return float(rounded(Fraction(d), 17)) if d else 0.0


@pytest.mark.parametrize("beta,gamma", [(1.0, 0.5), (0.3, -0.4), (2.5, 1.2), (7.0, 0.0)])
def test_sine_equally_spaced_phases(beta, gamma):
    points = 40
    phi, n, s = vibrofric.trace("sine", beta, gamma, points=points)
    assert phi.dtype == n.dtype == s.dtype == np.float64 and phi.shape == n.shape == s.shape
    assert np.all(np.diff(phi) > 0) and phi[0] == 0 and phi[-1] == 1
    # every i/points is a row, with n = max(0, gamma + sin 2 pi phi) (17 digits: 1e-16 relative)
    for i in range(points + 1):
        k = int(np.searchsorted(phi, i / points))
        assert phi[k] == i / points
        want = round17(n_sine(Fraction(i, points), str(gamma), 17))
        assert n[k] == want, (i, n[k], want)
    # s never exceeds n (Coulomb with mu0: |s| <= n in units of mu0), and is 0 without contact
    assert np.all(s >= 0)
    assert np.all(s <= n + 2e-16 * np.maximum(1.0, n))
    assert np.all(s[n == 0] == 0)
    # the period closes: phi = 0 and phi = 1 are the same state
    assert n[0] == n[-1] and s[0] == s[-1]


def test_sine_decimal_strings_at_30_digits():
    points = 12
    phi, n, s = vibrofric.trace("sine", "1.5", "0.25", points=points, digits=30, strings=True)
    assert phi.dtype == object and all(isinstance(x, str) for x in phi)
    for i in range(points + 1):
        q = Fraction(i, points)
        k = [Decimal(x) for x in phi].index(rounded(q, 30)) if i else 0
        want = n_sine(q, "0.25", 30)
        assert abs(Decimal(n[k]) - Decimal(mpmath.nstr(want, 40))) <= Decimal("1e-29") * max(1, abs(Decimal(n[k]))), i
    for a, b in zip(n, s):
        assert Decimal(b) <= Decimal(a) * (1 + Decimal("1e-29"))


def test_contact_boundaries():
    # gamma + sin 2 pi phi = 0 at phi = 7/12 and 11/12 for gamma = 1/2: rows with n = s = 0 exactly.
    phi, n, s = vibrofric.trace("sine", 1.0, 0.5, points=10)
    for edge in (7 / 12, 11 / 12):
        k = int(np.argmin(abs(phi - edge)))
        assert abs(phi[k] - edge) <= 1e-16
        assert n[k] == 0.0 and s[k] == 0.0
    # in contact between the boundaries' complement only
    inside = (phi > 7 / 12 + 1e-12) & (phi < 11 / 12 - 1e-12)
    assert np.all(n[inside] == 0) and np.all(s[inside] == 0)
    assert np.all(n[~inside & ((phi < 7 / 12 - 1e-12) | (phi > 11 / 12 + 1e-12))] > 0)


def test_stick_phase_ends_are_rows():
    # gamma = 2 (always in contact), beta = 1 < beta_c = 2 pi: one slip phase (where n falls
    # fastest), whose two ends are rows besides the 98 equally spaced phases; s = n in it, s < n
    # (stick) outside.
    points = 97
    phi, n, s = vibrofric.trace("sine", 1.0, 2.0, points=points)
    grid = np.arange(points + 1) / points
    ends = [k for k, p in enumerate(phi) if np.min(abs(grid - p)) > 1e-12]
    assert len(ends) == 2 and len(phi) == points + 3
    a, b = ends
    assert 0.5 < phi[a] < phi[b] < 0.8
    assert np.allclose(s[a:b + 1], n[a:b + 1], rtol=4e-16, atol=0)
    stick = np.r_[0:a, b + 1:len(phi)]
    assert np.all(s[stick] < n[stick])
    assert np.all(n >= 1.0 - 1e-15) and np.all(n <= 3.0 + 1e-15)  # gamma + sin in [1, 3]


def test_bad_inputs():
    with pytest.raises(ValueError, match="points"):
        vibrofric.trace("sine", 1.0, 0.5, points=1)
    with pytest.raises(ValueError, match="digits"):
        vibrofric.trace("sine", 1.0, 0.5, digits=0)
    with pytest.raises(ValueError, match="beta"):
        vibrofric.trace("sine", -1.0, 0.5)
    with pytest.raises(ValueError, match="gamma"):
        vibrofric.trace("sine", 1.0, -1.5)
    with pytest.raises(ValueError, match="nan"):
        vibrofric.trace("sine", float("nan"), 0.5)


def test_curved_profile_is_the_tools_and_closes_on_mu(tool_path):
    """profile=: n and s summed over the MDR half-row, digit for digit the tool's `trace --profile`;
    N at a phase is the closed form c X - X^3/3 on the sphere (c = gamma + w, X = sqrt c)."""
    import subprocess
    phi, n, s = vibrofric.trace("sine", "0.5", "0.2", profile="sphere", points=8, digits=15, strings=True)
    lines = subprocess.run([tool_path, "trace", "--wave", "sine", "--beta", "0.5", "--gamma", "0.2", "--profile", "sphere",
                            "--points", "8", "--digits", "15"], check=True, stdout=subprocess.PIPE, text=True).stdout
    assert len(phi) > 8
    assert [list(c) for c in (phi, n, s)] == [list(c) for c in zip(*(r.split(",") for r in lines.splitlines()[1:]))]
    for p, nv in zip(phi, n):
        if nv == "0":  # out of contact, or the centre's contact boundary (phi printed to 15 digits)
            continue
        c = n_sine(Fraction(Decimal(p)), "0.2", 15)
        want = c * mpmath.sqrt(c) * 2 / 3
        assert abs(Decimal(nv) - Decimal(mpmath.nstr(want, 30))) <= Decimal("1e-14") * max(Decimal(nv), Decimal("1e-30")), p
    fphi, fn, fs = vibrofric.trace("sine", 0.5, 0.2, profile="sphere", points=2000)
    assert np.all(fs <= fn) and np.all(fs >= 0)
    ratio = np.trapz(fs, fphi) / np.trapz(fn, fphi)
    assert abs(ratio - vibrofric.mu("sine", 0.5, 0.2, profile="sphere")) < 1e-6  # trapezoid, h = 1/2000
