"""vibrofric.fit (a Fourier series through samples) and Wave.normalisation: coefficients of a known
trigonometric polynomial recovered, the fitted sine's mu equal to the sine's, the fourier text read
back to the same wave, normalisations computed by hand; bad inputs."""
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import vibrofric

mpmath = pytest.importorskip("mpmath")

# y = 0.7 + sum_k a_k cos 2 pi k phi + b_k sin 2 pi k phi
A0, A, B = "0.7", ["0.25", "-1.5", "0", "0.125"], ["2", "0.375", "-0.0625", "0"]


def poly(phi, dps=50):
    """The polynomial at phi (a Fraction) to dps digits, as a decimal string."""
    with mpmath.workdps(dps):
        x = 2 * mpmath.pi * mpmath.mpf(phi.numerator) / phi.denominator
        v = mpmath.mpf(A0) + sum(mpmath.mpf(a) * mpmath.cos(k * x) + mpmath.mpf(b) * mpmath.sin(k * x)
                                 for k, (a, b) in enumerate(zip(A, B), start=1))
        return mpmath.nstr(v, dps - 5, strip_zeros=False)


def check_coefficients(w, bound):
    """Each fitted coefficient within bound of the polynomial's (k = 0 the mean)."""
    want = [(0, Decimal(A0), Decimal(0))] + [(k, Decimal(a), Decimal(b)) for k, (a, b) in enumerate(zip(A, B), 1)]
    want += [(k, Decimal(0), Decimal(0)) for k in range(len(want), len(w.harmonics))]
    assert [h[0] for h in w.harmonics] == [k for k, _, _ in want]
    for (k, a, b), (k2, fa, fb) in zip(want, w.harmonics):
        assert abs(Fraction(fa) - Fraction(a)) <= bound and abs(Fraction(fb) - Fraction(b)) <= bound, (k, fa, fb)
    # the text holds 17 significant digits of each: within a unit of the 17th digit
    rows = [line.split() for line in w.fourier_text().splitlines() if line[:1].isdigit()]
    for (k, a, b), (k2, ta, tb) in zip(want, rows):
        assert int(k2) == k
        for got, exact in ((Decimal(ta), a), (Decimal(tb), b)):
            assert abs(got - exact) <= Decimal("1e-16") * max(abs(exact), Decimal("1e-22")), (k, got, exact)


def test_uniform_samples_recover_coefficients():
    # N = 20 samples at j/N given as 45-digit decimals: the DFT is exact least squares (2K < N), and
    # a polynomial of degree 4 <= K is recovered to the samples' digits; the 17 digits written are
    # the exact coefficients correctly rounded (bound: half a unit in the 17th digit, relative).
    n = 20
    y = [poly(Fraction(j, n)) for j in range(n)]
    w = vibrofric.fit(y, 5)
    assert w.kind == "fourier" and w.name == "fit" and "DFT" in w.method
    assert len(w.harmonics) == 6 and w.harmonics[5][1:] == (0.0, 0.0)
    check_coefficients(w, Fraction(1, 10 ** 16) * 2)
    assert w.rms_residual <= 1e-30 and w.max_residual <= 1e-30
    # from doubles: the samples' rounding (1.1e-16 relative, max|y| < 4) bounds the coefficients' error
    wd = vibrofric.fit(np.array([float(v) for v in y]), 4)
    for (k, a, b), (_, fa, fb) in zip([(0, A0, "0")] + list(zip(range(1, 5), A, B)), wd.harmonics):
        assert abs(fa - float(a)) <= 1e-15 and abs(fb - float(b)) <= 1e-15, k


def test_time_stamped_samples_recover_coefficients():
    # 15 samples at irregular times over a period of 3.2 s, plus the end point: least squares by QR.
    t = [Fraction(0)] + sorted(Fraction(j, 5) + Fraction((7 * j) % 5, 50) for j in range(1, 15)) + [Fraction(16, 5)]
    y = [poly(x / Fraction(16, 5)) for x in t]
    y[-1] = y[0]
    w = vibrofric.fit(y, 4, t=[str(Decimal(x.numerator) / Decimal(x.denominator)) for x in t])
    assert "least squares" in w.method
    check_coefficients(w, Fraction(1, 10 ** 16) * 2)


def test_fitted_sine_is_the_sine(tmp_path):
    y = np.sin(2 * np.pi * np.arange(64) / 64)
    w = vibrofric.fit(y, 3)
    betas = np.array([0.1, 0.5, 1.0, 2.0, 4.0, 6.5])
    gammas = np.array([[1.0], [0.3], [-0.3], [-0.8]])
    got, want = vibrofric.mu(w, betas, gammas), vibrofric.mu("sine", betas, gammas)
    assert np.all(abs(got - want) <= 1e-13 * abs(want)), abs(got - want).max()
    # the fourier file the tool writes, read back: the same wave, string for string
    path = tmp_path / "fit.txt"
    path.write_text(w.fourier_text())
    assert list(vibrofric.mu(w, betas, gammas, strings=True).ravel()) == \
        list(vibrofric.mu("fourier:" + str(path), betas, gammas, strings=True).ravel())
    assert w.fourier_text().startswith("# Fourier series fitted by vibrofric to samples\n")
    assert "source: rig" not in w.fourier_text(source="rig") and "to rig\n" in w.fourier_text(source="rig")


def test_fit_of_a_samples_file_column(tmp_path):
    path = tmp_path / "rig.csv"
    force = [np.sin(2 * np.pi * j / 10) + 3 for j in range(10)] + [3.0]  # one period and its end point
    rows = ["time,force,gap"] + [f"{j / 10!r},{force[j]!r},{j % 3}" for j in range(11)]
    path.write_text("\n".join(rows) + "\n")
    wave = vibrofric.wave("samples:" + str(path), column="force")
    assert wave.kind == "samples" and wave.name.endswith("#force") and len(wave) == 10
    w = vibrofric.fit(wave, 2)
    assert abs(w.harmonics[0][1] - 3) <= 1e-15 and abs(w.harmonics[1][2] - 1) <= 1e-15
    assert vibrofric.wave("samples:" + str(path), column=2).name == wave.name


def test_normalisation_by_hand():
    # uniform phases: mean 3, min 1, max 5, scale (5 - 1)/2 = 2, factor 1/2
    d = vibrofric.samples([1, 4, 2, 5]).normalisation()
    assert d == {"samples": 4, "end_point": "none", "time_column": "none", "period": "1 (uniform phases)",
                 "column": "1", "raw_mean": 3.0, "raw_min": 1.0, "raw_max": 5.0, "scale": 2.0, "factor": 0.5}
    # time stamps 0, 1, 3, 4 (period 4), y = 0, 2, 2, 0, linear between: mean of the piecewise-linear
    # signal = (1 (0 + 2)/2 + 2 (2 + 2)/2 + 1 (2 + 0)/2)/4 = 1.5
    d = vibrofric.samples([0, 2, 2, 0], t=[0, 1, 3, 4]).normalisation()
    assert d["end_point"] == "dropped" and d["time_column"] == "time" and d["samples"] == 3
    assert (d["period"], d["raw_mean"], d["raw_min"], d["raw_max"], d["scale"], d["factor"]) == (4.0, 1.5, 0.0, 2.0, 1.0, 1.0)
    # 1 + 2 sin: mean 1 removed, peak to peak 4, scale 2; at 30 digits as strings
    d = vibrofric.fourier([0], [2], a0=1).normalisation(digits=30, strings=True)
    assert d["harmonics"] == "1"
    assert [Decimal(d[k]) for k in ("mean_removed", "peak_to_peak", "scale", "factor")] == [1, 4, 2, Decimal("0.5")]
    # a third: 1/3 to 25 digits
    d = vibrofric.samples([0, 3, 0, 1]).normalisation(digits=25, strings=True)
    assert d["factor"] == "0." + "6" * 24 + "7" and Decimal(d["raw_mean"]) == 1
    assert vibrofric.wave("sine").normalisation() == {
        "normalisation": "none (catalogue wave, already zero mean and max - min = 2)"}


def test_bad_inputs():
    def raises(fn, *args, names=(), **kw):
        with pytest.raises(ValueError) as info:
            fn(*args, **kw)
        for n in names:
            assert n in str(info.value), (n, str(info.value))

    y = np.sin(2 * np.pi * np.arange(8) / 8)
    raises(vibrofric.fit, y, 4, names=("4 harmonics", "8 samples", "K <= 3"))  # 2K + 1 <= N
    raises(vibrofric.fit, y, 0, names=("K = 0",))
    raises(vibrofric.fit, y, -2, names=("harmonics = -2",))
    raises(vibrofric.fit, y, 10001, names=("10001",))
    raises(vibrofric.fit, [1.0, 1.0, 1.0], 1, names=("constant",))
    raises(vibrofric.fit, vibrofric.wave("sine"), 1, names=("sine", "samples"))
    raises(vibrofric.fit, vibrofric.samples(y), 1, t=[0, 1], names=("t",))
    raises(vibrofric.samples(y).fourier_text, names=("fit",))
    with pytest.raises(FileNotFoundError, match="/nonexistent.csv"):
        vibrofric.wave("samples:/nonexistent.csv", column="x")
    raises(vibrofric.samples(y).normalisation, digits=0, names=("digits",))
    with pytest.raises(TypeError):
        vibrofric.fit(y, 2.5)
    with pytest.raises(TypeError):
        vibrofric.fit(y, None)
