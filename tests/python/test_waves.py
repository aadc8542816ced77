"""Waves and profiles from arrays: vibrofric.samples, vibrofric.fourier, vibrofric.profile give the
same values, string for string, as the same numbers written to samples:/fourier:/profile: files,
and the catalogue's closed forms where the array is a catalogue wave."""
import math

import numpy as np
import pytest

import vibrofric
from closed_forms import mu_triangle, nearest_double

BETAS = np.array([0.2, 0.9, 1.7, 3.3, 5.0])
GAMMAS = np.array([[0.8], [0.0], [-0.4]])


def write(path, lines):
    path.write_text("".join(line + "\n" for line in lines))
    return str(path)


def same_strings(wave_a, wave_b, **kw):
    for digits in (None, 30):
        a = vibrofric.mu(wave_a, BETAS, GAMMAS, digits=digits, strings=True, **kw)
        b = vibrofric.mu(wave_b, BETAS, GAMMAS, digits=digits, strings=True, **kw)
        assert a.shape == (3, 5)
        assert list(a.ravel()) == list(b.ravel())


def test_samples_equal_file(tmp_path):
    rng = np.random.default_rng(20240516)
    y = rng.normal(size=37) * 3.7 + 11.0
    f = write(tmp_path / "y.txt", [repr(float(v)) for v in y])
    same_strings(vibrofric.samples(y), "samples:" + f)
    same_strings(vibrofric.samples(list(y)), "samples:" + f)


def test_samples_with_time_equal_file(tmp_path):
    rng = np.random.default_rng(7)
    t = np.cumsum(rng.uniform(0.5, 1.5, size=21))
    y = rng.normal(size=21)
    y[-1] = y[0]  # one period with its end point
    f = write(tmp_path / "ty.csv", ["time,value"] + [f"{float(a)!r},{float(b)!r}" for a, b in zip(t, y)])
    same_strings(vibrofric.samples(y, t=t), "samples:" + f)


def test_samples_daq_stamps_without_end_point(tmp_path):
    # A DAQ's record: t_j = j dt, no end point. Uniform stamps give phi = j/N and period N dt,
    # the values of the same samples without a time column, as from the file.
    rng = np.random.default_rng(11)
    y = rng.normal(size=40)
    t = np.arange(40) / 48000.0
    same_strings(vibrofric.samples(y, t=t), vibrofric.samples(y))
    f = write(tmp_path / "daq.csv", ["time [s],disp"] + [f"{float(a)!r},{float(b)!r}" for a, b in zip(t, y)])
    same_strings(vibrofric.samples(y, t=t), vibrofric.wave("samples:" + f, column="disp"))
    d = vibrofric.samples(y, t=t).normalisation()
    assert d["end_point"] == "none (uniform stamps: period N dt)" and d["samples"] == 40
    assert abs(float(d["period"]) - 40 / 48000.0) <= 1e-15 * 40 / 48000.0


def test_samples_decimal_strings_equal_file(tmp_path):
    y = ["0.1", "0.35", "1.000000000000000000000000001", "-0.2", "-0.7"]
    f = write(tmp_path / "y.txt", y)
    same_strings(vibrofric.samples(y), "samples:" + f)


def test_fourier_equal_file(tmp_path):
    a = [0.3, 0.0, -0.05]
    b = [1.0, 0.2, 0.01]
    f = write(tmp_path / "c.txt", [f"{k} {a[k - 1]!r} {b[k - 1]!r}" for k in (1, 2, 3)])
    same_strings(vibrofric.fourier(a, b), "fourier:" + f)
    f0 = write(tmp_path / "c0.txt", ["0 2.5 0"] + [f"{k} {a[k - 1]!r} {b[k - 1]!r}" for k in (1, 2, 3)])
    same_strings(vibrofric.fourier(np.array(a), np.array(b), a0=2.5), "fourier:" + f0)


def test_samples_of_a_triangle_follow_eq19():
    # -1, 0, 1, 0 at phi = j/4, linear between: the triangle shifted by a quarter period, and with
    # an offset and a scale that the normalisation removes (phase shifts do not change mu).
    for y in ([-1, 0, 1, 0], [1.5, 2.0, 2.5, 2.0], ["10", "30", "50", "30"]):
        w = vibrofric.samples(y)
        assert w.kind == "samples" and len(w) == 4
        for b in (0.3, 1.0, 2.5):
            for g in (0.5, -0.5):
                assert vibrofric.mu(w, b, g) == nearest_double(mu_triangle(b, g)), (y, b, g)


def test_fourier_sine_is_the_sine():
    w = vibrofric.fourier([0.0], [1.0])
    assert w.kind == "fourier" and len(w) == 1
    got = vibrofric.mu(w, BETAS, GAMMAS, digits=30)
    want = vibrofric.mu("sine", BETAS, GAMMAS, digits=30)
    for x, y in zip(got.ravel(), want.ravel()):
        assert abs(x - y) <= 1e-29 * abs(y)
    assert np.array_equal(vibrofric.mu(w, BETAS, GAMMAS), vibrofric.mu("sine", BETAS, GAMMAS))


def test_profile_equal_file(tmp_path):
    r = np.linspace(0.0, 3.0, 31)
    f = r ** 2 / 2  # a sphere, sampled
    path = write(tmp_path / "p.txt", [f"{float(a)!r} {float(b)!r}" for a, b in zip(r, f)])
    p = vibrofric.profile(r, f)
    assert len(p) == 31
    a = vibrofric.mu("sine", BETAS, 0.3, profile=p, strings=True)
    b = vibrofric.mu("sine", BETAS, 0.3, profile="profile:" + path, strings=True)
    assert list(a) == list(b)


def test_profile_keeps_the_triangle_closed_form():
    # Eq. 19 holds on every profile while the centre jumps (gamma <= 1).
    r = [0, 1, 2, 3, 4]
    f = [0, 0.25, 1.0, 2.25, 4.0]
    assert vibrofric.mu("triangle", 1.5, 0.2, profile=vibrofric.profile(r, f)) == nearest_double(mu_triangle(1.5, 0.2))


def file_message_as_array(message, path, label, header_lines):
    """The message a file reader gives, in an array's terms: 'samples:PATH' and PATH become the
    label, PATH:LINE becomes label[j] with j = LINE - 1 - header_lines (the array index)."""
    import re
    message = re.sub(re.escape(path) + r":(\d+)", lambda m: "%s[%d]" % (label, int(m.group(1)) - 1 - header_lines), message)
    for prefix in ("samples:", "fourier:", "profile:"):
        message = message.replace(prefix + path, label)
    return message.replace(path, label)


@pytest.mark.parametrize("kind, arrays, lines, header_lines", [
    ("samples", dict(y=[0.0, 1.0, 0.0, 1.0]), ["0", "1", "0", "1"], 0),                     # two periods
    ("samples", dict(y=[0.0, 1.0, 2.0, 0.0]), ["0", "1", "2", "0"], 0),                     # end point repeated
    ("samples", dict(y=[0.0, 1.0, 2.0], t=[0.0, 2.0, 1.0]), ["time,value", "0,0", "2,1", "1,2"], 1),
    ("samples", dict(y=[0.0, 1.0, 2.0], t=[0.0, 1.0, 3.0]), ["time,value", "0,0", "1,1", "3,2"], 1),  # no end point, steps 1, 2
    ("fourier", dict(a=[0.0, 0.0], b=[0.0, 0.0]), ["1 0 0", "2 0 0"], 0),                  # no amplitude
    ("profile", dict(r=[0.0, 1.0, 2.0], f=[0.0, 1.0, 1.5]), ["0 0", "1 1", "2 1.5"], 0),    # concave corner
    ("profile", dict(r=[0.0, 1.0, 1.0], f=[0.0, 1.0, 2.0]), ["0 0", "1 1", "1 2"], 0),      # r not increasing
    ("profile", dict(r=[0.0, 1.0], f=[0.0, 0.0]), ["0 0", "1 0"], 0),                       # flat
])
def test_array_refusals_are_the_file_refusals(tmp_path, kind, arrays, lines, header_lines):
    """An array is refused with the message of a file holding the same numbers, in its own terms
    (the file readers' checks, detail/tables.hpp; no file is written for the array)."""
    path = write(tmp_path / "w.txt", lines)
    with pytest.raises(ValueError) as by_array:
        w = getattr(vibrofric, kind)(**arrays)
        vibrofric.mu(w, 1.0, 0.5) if kind != "profile" else vibrofric.mu("sine", 1.0, 0.5, profile=w)
    with pytest.raises(ValueError) as by_file:
        if kind == "profile":
            vibrofric.mu("sine", 1.0, 0.5, profile="profile:" + path)
        else:
            vibrofric.mu(kind + ":" + path, 1.0, 0.5)
    assert str(by_array.value) == file_message_as_array(str(by_file.value), path, kind, header_lines)


def test_waves_and_profiles_pickle(tmp_path):
    # Wave and Profile cross to other processes (multiprocessing, concurrent.futures, Dask): the
    # unpickled object is the same wave, value for value, without the file it was read from.
    import concurrent.futures
    import os
    import pickle
    rng = np.random.default_rng(3)
    y = rng.normal(size=30)
    path = tmp_path / "rig.csv"
    write(path, ["time,disp"] + ["%r,%r" % (j / 48000.0, float(v)) for j, v in enumerate(y)])
    waves = [vibrofric.wave("sine"), vibrofric.wave("power:3"), vibrofric.samples(y),
             vibrofric.samples(y, t=np.arange(30) / 48000.0), vibrofric.wave("samples:%s" % path, column="disp"),
             vibrofric.fourier([0.3, 0.0], [1.0, 0.2], a0=2.5), vibrofric.fit(y, 3)]
    copies = [pickle.loads(pickle.dumps(w)) for w in waves]
    os.remove(path)
    for w, c in zip(waves, copies):
        assert type(c) is vibrofric.Wave and c.name == w.name and repr(c) == repr(w)
        assert c.normalisation(digits=30, strings=True) == w.normalisation(digits=30, strings=True)
        same_strings(c, w)
    assert copies[-1].fourier_text() == waves[-1].fourier_text() and copies[-1].method == waves[-1].method
    prof = vibrofric.profile([0, 1, 2, 3], [0, 0.25, 1.0, 2.25])
    pc = pickle.loads(pickle.dumps(prof))
    assert len(pc) == 4 and pc.name == prof.name
    a = vibrofric.mu("sine", BETAS, 0.3, profile=prof, strings=True)
    assert list(vibrofric.mu("sine", BETAS, 0.3, profile=pc, strings=True)) == list(a)
    # Shipped to worker processes, as a pool or Dask does (spawned: no fork of a threaded process).
    import multiprocessing
    with concurrent.futures.ProcessPoolExecutor(max_workers=2, mp_context=multiprocessing.get_context("spawn")) as pool:
        got = list(pool.map(_mu_strings, waves[2:4]))
    assert got == [list(vibrofric.mu(w, BETAS, 0.3, strings=True)) for w in waves[2:4]]
    with pytest.raises(ValueError, match="unpickling a Wave"):
        vibrofric.Wave.__new__(vibrofric.Wave).__setstate__((99,))


def _mu_strings(wave):
    return list(vibrofric.mu(wave, BETAS, 0.3, strings=True))


def test_several_periods_refused_or_averaged(tmp_path):
    # Two noisy periods of a sine (uniform phases): refused with what to give; periods=2 is the
    # wave of the two periods' means (exact decimal means, written here), also after pickling;
    # periods=1 takes the record as one period; a file read with periods= is the same wave.
    rng = np.random.default_rng(26)
    y = np.round(np.sin(4 * np.pi * np.arange(400) / 400) + rng.normal(0, 0.01, 400), 6)
    with pytest.raises(ValueError, match="look like 2 periods.*give periods 2"):
        vibrofric.samples(y)
    import pickle
    from decimal import Decimal
    means = [str((Decimal(repr(float(a))) + Decimal(repr(float(b)))) / 2) for a, b in zip(y[:200], y[200:])]
    averaged = vibrofric.samples(y, periods=2)
    same_strings(averaged, vibrofric.samples(np.array(means)))
    same_strings(pickle.loads(pickle.dumps(averaged)), averaged)
    assert averaged.normalisation()["periods"] == "2 (averaged sample by sample)"
    assert len(averaged) == 200
    assert len(vibrofric.samples(y, periods=1)) == 400
    f = write(tmp_path / "two.txt", [repr(float(v)) for v in y])
    same_strings(vibrofric.wave("samples:" + f, periods=2), averaged)
    with pytest.raises(ValueError, match="periods = 3 .*whole number"):
        vibrofric.samples(y, periods=3)
    with pytest.raises(ValueError, match="periods = 0"):
        vibrofric.samples(y, periods=0)


def test_lab_file_as_written(tmp_path):
    # A German lab PC's export: a preamble, ';' and decimal commas, "Zeit [s]", µm in Windows-1252.
    # skip_rows skips the preamble; the wave is that of the same samples written plainly.
    rows = "".join("%s;%s\n" % (t, y) for t, y in (("0", "0,75"), ("0,0000125", "1,5"), ("0,000025", "0,75"), ("0,0000375", "0")))
    path = tmp_path / "lab.csv"
    path.write_bytes(("Messung: Probe 3\nDatum: 05.12.2026\n\nZeit [s];Weg [\u00b5m]\n" + rows).encode("cp1252"))
    plain = vibrofric.samples([0.75, 1.5, 0.75, 0])
    with pytest.raises(ValueError, match="skip them with skip_rows 3"):
        vibrofric.wave("samples:%s" % path)
    w = vibrofric.wave("samples:%s" % path, skip_rows=3)
    assert vibrofric.mu(w, 0.3, 0.2, strings=True) == vibrofric.mu(plain, 0.3, 0.2, strings=True)
    with pytest.raises(ValueError, match="skip_rows = -1"):
        vibrofric.wave("samples:%s" % path, skip_rows=-1)
    with pytest.raises(FileNotFoundError):
        vibrofric.wave("samples:%s" % (tmp_path / "missing.csv"), skip_rows=3)
