"""vibrofric.mu and vibrofric.psi against the paper's closed forms, computed here in exact rationals.

Tolerances: in double the module must return exactly the nearest double of the exact value
(correctly rounded: 0 ulp from float(Fraction)); at digits = D the decimal it returns must be the
exact value correctly rounded to D significant digits (round half even).
"""
import math
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import vibrofric
from closed_forms import (exact, mu_sawtooth_left, mu_sawtooth_right, mu_square, mu_triangle, nearest_double,
                          psi_sawtooth_left, psi_sawtooth_right, psi_triangle, rounded)

BETAS = [0.05, 0.1, 0.3, 0.5, 1.0, 1.7, 2.5, 3.0, 3.9, 4.0, 6.0]
GAMMAS = [1.0, 0.6, 0.25, 0.0, -0.3, -0.5, -0.9]


def test_triangle_eq19_correctly_rounded_double():
    b, g = np.meshgrid(BETAS, GAMMAS, indexing="ij")
    got = vibrofric.mu("triangle", b, g)
    assert got.dtype == np.float64 and got.shape == b.shape
    for i, j in np.ndindex(b.shape):
        want = nearest_double(mu_triangle(float(b[i, j]), float(g[i, j])))
        assert got[i, j] == want, (b[i, j], g[i, j], got[i, j], want)


def test_square_eq22_correctly_rounded_double():
    b, g = np.meshgrid(BETAS, GAMMAS, indexing="ij")
    got = vibrofric.mu("square", b, g)
    want = np.vectorize(lambda x, y: nearest_double(mu_square(float(x), float(y))))(b, g)
    assert np.array_equal(got, want), np.argwhere(got != want)


def test_sawtooth_eq19_correctly_rounded_double():
    betas = np.array(BETAS)
    for g in (1.0, 0.0, -0.6):
        got_r = vibrofric.mu("sawtooth-right", betas, g)
        got_l = vibrofric.mu("stl", betas, g)
        for k, b in enumerate(BETAS):
            assert got_r[k] == nearest_double(mu_sawtooth_right(b, g)), (b, g)
            assert got_l[k] == nearest_double(mu_sawtooth_left(b, g)), (b, g)


def test_psi_eq17_correctly_rounded_double():
    got = vibrofric.psi("triangle", BETAS)
    assert got.shape == (len(BETAS),)
    for k, b in enumerate(BETAS):
        assert got[k] == nearest_double(psi_triangle(b)), b
    for k, b in enumerate(BETAS):
        assert vibrofric.psi("str", b) == nearest_double(psi_sawtooth_right(b))
        assert vibrofric.psi("sawtooth-left", b) == nearest_double(psi_sawtooth_left(b))


def test_eq13_psi_and_mu_agree_without_jumping():
    # Eq. 13 with Eq. 17: mu_tri(beta, gamma >= 1) = 1 - Psi_tri(beta)/gamma, exactly.
    for b in (0.5, 2.0, 3.5):
        for g in (1.5, 2.0, 10.0):
            want = 1 - psi_triangle(b) / exact(g)
            assert vibrofric.mu("triangle", b, g) == nearest_double(want)


@pytest.mark.parametrize("digits", [40, 7, 100])
def test_closed_forms_at_digits(digits):
    cases = [("triangle", "0.3", "-0.5", mu_triangle), ("square", "1.25", "0.2", mu_square),
             ("square", "3", "-0.25", mu_square), ("str", "1.1", "0.7", mu_sawtooth_right)]
    for wave, b, g, form in cases:
        got = vibrofric.mu(wave, b, g, digits=digits, strings=True)
        assert isinstance(got, str)
        want = rounded(form(b, g), digits)
        assert Decimal(got) == want, (wave, b, g, got, want)
        assert len(got.replace("-", "").replace(".", "").lstrip("0")) >= digits - 1
    got = vibrofric.psi("triangle", "1", digits=digits, strings=True)
    assert Decimal(got) == rounded(Fraction(3, 5), digits)


def test_decimal_strings_are_exact_inputs():
    # '0.1' as a string and 0.1 as a float are the same decimal; a 45-digit beta is read exactly.
    assert vibrofric.mu("triangle", "0.1", "0.5") == vibrofric.mu("triangle", 0.1, 0.5)
    b = "0.123456789012345678901234567890123456789012345"
    got = vibrofric.mu("triangle", b, "0", digits=40, strings=True)
    assert Decimal(got) == rounded(mu_triangle(b, "0"), 40)


def test_mpmath_values_at_digits():
    mpmath = pytest.importorskip("mpmath")
    got = vibrofric.mu("triangle", 1, -0.5, digits=40)
    assert isinstance(got, mpmath.mpf)
    with mpmath.workdps(60):
        err = abs(got - mpmath.mpf(2) / 5)
        assert err <= mpmath.mpf(10) ** -40
    arr = vibrofric.mu("square", [0.5, 1.0], 0.0, digits=30)
    assert arr.dtype == object and all(isinstance(x, mpmath.mpf) for x in arr)


def test_other_number_types():
    got = vibrofric.mu("triangle", [1.0, 2.0], 0.5, type="long-double")
    assert got.dtype == np.longdouble
    assert got[0] == np.longdouble(2) / np.longdouble(5)
    s = vibrofric.mu("triangle", 1.0, 0.5, type="cpp_bin_float_50", strings=True)
    assert Decimal(s) == rounded(Fraction(2, 5), 50)
    s = vibrofric.mu("triangle", 1.0, 0.5, type="double", strings=True)
    assert float(s) == 0.4


def test_broadcasting_shapes():
    b = np.array([[0.5], [1.0], [2.0]])        # (3, 1)
    g = np.array([1.0, 0.5, 0.0, -0.5])        # (4,)
    got = vibrofric.mu("triangle", b, g)
    assert got.shape == (3, 4)
    for i, j in np.ndindex(3, 4):
        assert got[i, j] == vibrofric.mu("triangle", float(b[i, 0]), float(g[j]))
    assert vibrofric.mu("square", [0.5, 1.0], [[0.0], [0.5]]).shape == (2, 2)
    assert vibrofric.mu("square", np.ones((2, 3, 4)), 0.5).shape == (2, 3, 4)
    assert vibrofric.mu("square", np.zeros((0, 3)) + 1, 0.5).shape == (0, 3)
    assert vibrofric.psi("triangle", np.full((2, 2), 1.0)).shape == (2, 2)
    with pytest.raises(ValueError):
        vibrofric.mu("square", [1.0, 2.0, 3.0], [0.0, 0.5])


def test_scalars_in_scalar_out():
    assert isinstance(vibrofric.mu("sine", 1.0, -0.3), float)
    assert isinstance(vibrofric.mu("sine", np.float64(1.0), np.array(-0.3)), float)
    assert isinstance(vibrofric.psi("sine", 2), float)
    assert isinstance(vibrofric.mu("sine", [1.0], -0.3), np.ndarray)
    # integers are read exactly
    assert vibrofric.mu("triangle", 1, 0) == vibrofric.mu("triangle", 1.0, 0.0) == 0.4


def test_sine_matches_the_tool_readme_values():
    # README: vibrofric mu --wave sine --beta 1 --gamma=-0.3 (50 digits and --type double).
    assert vibrofric.mu("sine", 1, -0.3) == 0.37786747521330566
    s = vibrofric.mu("sine", 1, -0.3, digits=50, strings=True)
    assert s == "0.37786747521330564905187721232674471196550064417422"
    # The double is the nearest double of the 50-digit value.
    assert vibrofric.mu("sine", 1, -0.3) == float(Decimal(s))


def test_threads_give_the_same_values():
    b = np.linspace(0.05, 7, 200)
    one = vibrofric.mu("sine", b, 0.2, threads=1)
    many = vibrofric.mu("sine", b, 0.2, threads=0)
    assert np.array_equal(one, many)
    assert np.all(np.isfinite(one)) and np.all(one > 0) and np.all(one <= 1)


def test_curved_profiles():
    # README: vibrofric mu --wave triangle --beta 1 --gamma=-0.5 --profile cone: Eq. 19 holds on
    # every profile while the centre jumps (2/5).
    assert vibrofric.mu("triangle", 1, -0.5, profile="cone") == 0.4
    assert vibrofric.mu("triangle", 1, 0.5, profile="sphere") == 0.4
    got = vibrofric.mu("sine", 1, 0.5, profile="sphere", digits=40, strings=True)
    assert got == "0.3277956009610709120574149598203810342366"


# certify=True: the exact value as (lo, hi) of Fractions, equal to the closed forms exactly.
def test_certify_gives_the_closed_forms_exactly():
    b, g = np.meshgrid(BETAS, GAMMAS, indexing="ij")
    for wave, form in (("triangle", mu_triangle), ("square", mu_square), ("sawtooth-right", mu_sawtooth_right),
                       ("sawtooth-left", mu_sawtooth_left)):
        lo, hi = vibrofric.mu(wave, b, g, certify=True)
        assert lo.shape == b.shape and hi.shape == b.shape
        for i, j in np.ndindex(b.shape):
            want = form(float(b[i, j]), float(g[i, j]))
            assert lo[i, j] == want and hi[i, j] == want, (wave, b[i, j], g[i, j], lo[i, j], want)
    for beta in BETAS:
        assert vibrofric.psi("triangle", beta, certify=True) == (psi_triangle(beta), psi_triangle(beta))
        assert vibrofric.psi("sawtooth-left", str(beta), certify=True, digits=40) == (psi_sawtooth_left(beta),) * 2
    # float() of the exact value is the correctly rounded double, the module's own value.
    assert float(vibrofric.mu("triangle", 0.1, 0.3, certify=True)[0]) == vibrofric.mu("triangle", 0.1, 0.3)


def test_certify_enclosures_hold_the_40_digit_value():
    for beta, gamma in ((1.0, 0.2), (0.37, -0.9), (5.5, 2.0), (7.0, 0.5)):
        lo, hi = vibrofric.mu("sine", beta, gamma, certify=True)
        assert isinstance(lo, Fraction) and lo <= hi
        want = Fraction(vibrofric.mu("sine", beta, gamma, digits=40, strings=True))
        assert lo - Fraction(1, 10**39) <= want <= hi + Fraction(1, 10**39), (beta, gamma, lo, hi, want)
        assert float(lo) == float(hi) == vibrofric.mu("sine", beta, gamma)
    lo, hi = vibrofric.psi("sine", [0.5, 7.0], certify=True)
    assert hi[1] == lo[1] == 0 and lo[0] < hi[0] and float(hi[0]) == vibrofric.psi("sine", 0.5)
    # A Fourier series of three harmonics, jumping and not.
    three = vibrofric.fourier([0, 0.1, 0], [1, -0.05, 0.333])
    for beta, gamma in ((1.5, 0.3), (0.01, -0.2), (4.0, 1.5)):
        lo, hi = vibrofric.mu(three, beta, gamma, certify=True)
        want = Fraction(vibrofric.mu(three, beta, gamma, digits=40, strings=True))
        assert lo - Fraction(1, 10**39) <= want <= hi + Fraction(1, 10**39), (beta, gamma, lo, hi, want)
        assert float(lo) == float(hi) == vibrofric.mu(three, beta, gamma)


def test_certify_curved_enclosures_hold_the_40_digit_value():
    # The sine on curved profiles (the row's integral enclosed by Taylor models), array arguments too.
    for profile in ("sphere", "cone", "power:2.5", "wearflat:0.5"):
        lo, hi = vibrofric.mu("sine", [1.0, 0.3], [0.5, -0.6], profile=profile, certify=True)
        for i, (beta, gamma) in enumerate(((1.0, 0.5), (0.3, -0.6))):
            want = Fraction(vibrofric.mu("sine", beta, gamma, profile=profile, digits=40, strings=True))
            assert lo[i] - Fraction(1, 10**39) <= want <= hi[i] + Fraction(1, 10**39), (profile, beta, gamma)
            assert float(lo[i]) == float(hi[i]) == vibrofric.mu("sine", beta, gamma, profile=profile)
    assert vibrofric.mu("sine", 7, 0.5, profile="sphere", certify=True) == (1, 1)


@pytest.mark.parametrize("call, words", [
    (lambda: vibrofric.mu("sine", 1, 0, certify=True, nan_on_error=True), ["nan_on_error=True"]),
    (lambda: vibrofric.mu("sine", 1, 0, profile=vibrofric.profile([0, 1, 2], [0, 0.5, 2]), certify=True),
     ["measured profile"]),
    (lambda: vibrofric.mu("triangle", 1, 0, profile="sphere", certify=True), ["'sphere'", "flat punch"]),
    (lambda: vibrofric.mu("triangle", 1, 0, escalate=False, certify=True), ["escalate=False"]),
    (lambda: vibrofric.mu("triangle", [1, 2], [0, -3], certify=True), ["at index (1,)", "-3"]),
])
def test_certify_refusals(call, words):
    with pytest.raises(ValueError) as e:
        call()
    for w in words:
        assert w in str(e.value), (w, str(e.value))
