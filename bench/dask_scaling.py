#!/usr/bin/env python3
"""The Dask path's scaling (README, "Python"): one map of mu -- a ball (profile 'sphere') under the
sine at 30 digits, 8 x 8 points -- computed in this process (threads=1), and as dask.array blocks
on a local distributed cluster of 1 and of 2 worker processes (one thread each). Wall times, the
three runs interleaved and repeated (the machine is shared: the spread of the repeats is the noise
control); every run's values are checked equal to the single-process ones.

Usage: PYTHONPATH=build/release/lib/python /usr/bin/python3 bench/dask_scaling.py [REPEATS]
Writes its table to stdout (bench/results/dask_scaling.txt holds the last one)."""
import os
import subprocess
import sys
import time

import numpy as np

import dask
import dask.array as da
import distributed

import vibrofric

KW = dict(profile="sphere", digits=30, strings=True)


def block(beta, gamma):
    return vibrofric.mu("sine", beta, gamma, threads=1, **KW)


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    beta, gamma = np.meshgrid(np.logspace(-1.5, 0.8, 8), np.linspace(-0.8, 0.8, 8))
    reference = vibrofric.mu("sine", beta, gamma, threads=1, **KW)
    times = {"one process": [], "dask, 1 worker": [], "dask, 2 workers": []}
    with dask.config.set({"distributed.worker.multiprocessing-method": "spawn"}):
        clusters = {n: distributed.LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None)
                    for n in (1, 2)}
        clients = {n: distributed.Client(c) for n, c in clusters.items()}
        for c in clients.values():   # warm the workers (import, first solve) outside the timing
            c.compute(da.map_blocks(block, da.from_array(beta[:1, :1]), da.from_array(gamma[:1, :1]), dtype=object)).result()
        for _ in range(repeats):
            t = time.perf_counter()
            got = vibrofric.mu("sine", beta, gamma, threads=1, **KW)
            times["one process"].append(time.perf_counter() - t)
            assert (got == reference).all()
            for n in (1, 2):
                b = da.from_array(beta, chunks=(2, 8))
                g = da.from_array(gamma, chunks=(2, 8))
                t = time.perf_counter()
                got = clients[n].compute(da.map_blocks(block, b, g, dtype=object)).result()
                times["dask, %d worker%s" % (n, "s" if n > 1 else "")].append(time.perf_counter() - t)
                assert (got == reference).all()
        for c in clients.values():
            c.close()
        for c in clusters.values():
            c.close()
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                            cwd=os.path.dirname(os.path.abspath(__file__))).stdout.strip()
    print("# dask_scaling at %s, %d cores: 64 points, sphere, sine, 30 digits; wall seconds, %d repeats interleaved"
          % (commit, os.cpu_count(), repeats))
    base = min(times["one process"])
    for name, ts in times.items():
        print("%-16s min %6.2f  max %6.2f  speed-up (min) %.2f" % (name, min(ts), max(ts), base / min(ts)))


if __name__ == "__main__":
    main()
