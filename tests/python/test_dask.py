"""vibrofric on Dask (python3-dask, python3-distributed): a dask.array map of mu evaluated block by
block on a local distributed cluster of worker processes gives the single-process values, float
for float and string for string, for a catalogue wave and for a measured Wave shipped to the
workers by pickle (README, "Python": "More than one machine")."""
import numpy as np
import pytest

import vibrofric

da = pytest.importorskip("dask.array")
distributed = pytest.importorskip("dask.distributed")


def _mu_block(beta, gamma, wave, kw):
    return vibrofric.mu(wave, beta, gamma, threads=1, **kw)


@pytest.fixture(scope="module")
def client():
    # Worker processes (no fork of this threaded process: the spawn start method), one thread each.
    import dask
    with dask.config.set({"distributed.worker.multiprocessing-method": "spawn"}):
        with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
            with distributed.Client(cluster) as c:
                yield c


def test_blocks_on_a_local_cluster_equal_one_process(client):
    beta, gamma = np.meshgrid(np.logspace(-2, 1, 24), np.linspace(-0.9, 0.9, 10))
    rng = np.random.default_rng(30)
    measured = vibrofric.samples(np.sin(2 * np.pi * np.arange(64) / 64) + rng.normal(0, 0.02, 64))
    # A ball at 20 digits (decimal strings) on a smaller grid: a curved point costs a row of springs.
    for wave, kw, dtype, rows, cols in (("sine", {}, float, 10, 24), (measured, {}, float, 10, 24),
                                        ("sine", {"profile": "sphere", "digits": 20, "strings": True}, object, 2, 4)):
        b = da.from_array(beta[:rows, :cols], chunks=(5, 8) if rows > 2 else (1, 2))
        g = da.from_array(gamma[:rows, :cols], chunks=b.chunks)
        lazy = da.map_blocks(_mu_block, b, g, wave=wave, kw=kw, dtype=dtype)
        got = client.compute(lazy).result()
        want = vibrofric.mu(wave, beta[:rows, :cols], gamma[:rows, :cols], **kw)
        assert got.shape == want.shape == (rows, cols)
        assert got.dtype == want.dtype
        assert (got == want).all()
