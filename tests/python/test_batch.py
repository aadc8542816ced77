"""Batches through evaluate_stream: every argument layout numpy allows (broadcast, strided,
Fortran order, integers, decimal strings, objects) gives, element for element, the value of the
same point alone; the GIL is released while a batch runs."""
import threading
import time

import numpy as np
import pytest

import vibrofric


def one_by_one(wave, beta, gamma, **kw):
    b, g = np.broadcast_arrays(np.asarray(beta), np.asarray(gamma))
    out = np.empty(b.shape, dtype=object if kw.get("strings") or kw.get("digits") else float)
    for idx in np.ndindex(b.shape):
        x, y = b[idx], g[idx]
        out[idx] = vibrofric.mu(wave, x.item() if hasattr(x, "item") else x, y.item() if hasattr(y, "item") else y, **kw)
    return out


@pytest.mark.parametrize("layout", ["outer", "strided", "fortran", "transposed", "ints", "strings", "objects", "3d"])
def test_layouts_equal_single_points(layout):
    base = np.linspace(0.1, 6.0, 12)
    gam = np.array([0.9, 0.2, -0.5])
    if layout == "outer":
        beta, gamma = base, gam[:, None]
    elif layout == "strided":
        beta, gamma = np.linspace(0.1, 6.0, 24)[::2], gam[::-1][:, None]
    elif layout == "fortran":
        beta = np.asfortranarray(np.tile(base, (3, 1)))
        gamma = np.asfortranarray(np.tile(gam[:, None], (1, 12)))
    elif layout == "transposed":
        beta, gamma = np.tile(base, (3, 1)).T, gam
    elif layout == "ints":
        beta, gamma = np.arange(1, 7, dtype=np.int32), np.array([[1], [0]], dtype=np.uint64)
    elif layout == "strings":
        beta, gamma = np.array(["0.5", "1.25", "3"]), np.array([["0.1"], ["-0.25"]])
    elif layout == "objects":
        beta, gamma = np.array([0.5, "1.25", 3, np.float32(2.5)], dtype=object), 0.3
    else:
        beta, gamma = base.reshape(2, 3, 2), gam[:, None, None][:2]
    got = vibrofric.mu("sine", beta, gamma)
    want = one_by_one("sine", beta, gamma)
    assert got.dtype == np.float64 and got.shape == np.broadcast(np.asarray(beta), np.asarray(gamma)).shape
    assert np.array_equal(got, want.astype(float))
    strings = vibrofric.mu("triangle", beta, gamma, strings=True)
    assert strings.dtype == object and strings.shape == got.shape
    assert list(strings.ravel()) == list(one_by_one("triangle", beta, gamma, strings=True).ravel())


def test_psi_and_high_precision_batches():
    beta = np.array([[0.5, 1.0], [2.0, 3.5]])
    got = vibrofric.psi("sine", beta, digits=25, strings=True)
    assert got.shape == (2, 2)
    for idx in np.ndindex(2, 2):
        assert got[idx] == vibrofric.psi("sine", float(beta[idx]), digits=25, strings=True)
    ld = vibrofric.mu("sine", beta, 0.5, type="long-double")
    assert ld.dtype == np.longdouble and ld.shape == (2, 2)
    mp = vibrofric.mu("sine", [0.5, 1.0], 0.5, digits=20)
    assert mp.dtype == object and len(mp) == 2


def test_shapes_empty_scalar_and_threads():
    assert vibrofric.mu("sine", np.empty((0, 3)), 0.5).shape == (0, 3)
    assert isinstance(vibrofric.mu("sine", 1.0, 0.5), float)
    with pytest.raises(ValueError):
        vibrofric.mu("sine", np.ones(3), np.ones(4))  # shapes that do not broadcast
    beta = np.linspace(0.05, 7, 5000)
    assert np.array_equal(vibrofric.mu("sine", beta, 0.4, threads=1), vibrofric.mu("sine", beta, 0.4, threads=0))


def test_failing_point_fails_the_batch():
    beta = np.linspace(0.1, 5.0, 20000)
    beta[15000] = -1.0
    with pytest.raises(ValueError, match="-1"):
        vibrofric.mu("sine", beta, 0.5)


def test_gil_released_while_a_batch_runs():
    beta = np.linspace(0.02, 7.0, 20000)
    gamma = np.array([[0.9], [0.1], [-0.7]])
    done = []
    worker = threading.Thread(target=lambda: done.append(vibrofric.mu("sine", beta, gamma, threads=1)))
    ticks = 0
    start = time.perf_counter()
    worker.start()
    while worker.is_alive():  # Python bytecode on this thread while the batch computes
        ticks += 1
        time.sleep(0)
    elapsed = time.perf_counter() - start
    worker.join()
    assert done and done[0].shape == (3, 20000)
    # With the GIL held for the whole batch (0.4 s on one core) this loop would run once or twice
    # (before the batch starts and after it ends); released, thousands of times.
    assert elapsed < 0.02 or ticks >= 50, (ticks, elapsed)
