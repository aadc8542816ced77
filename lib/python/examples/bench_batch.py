#!/usr/bin/python3
"""Per-point cost of a double batch through the Python module against the C++ tool's sweep of the
same grid (whole-process time minus the tool's start-up), both on all cores.

    PYTHONPATH=build/release/lib/python /usr/bin/python3 lib/python/examples/bench_batch.py \
        build/release/lib/vibrofric [--points 100000] [--wave sine] [--repeat 3]
"""
import argparse
import os
import subprocess
import time

import numpy as np

import vibrofric


def best_of(repeat, fn):
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tool", help="path of the vibrofric tool")
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--wave", default="sine")
    ap.add_argument("--gammas", default="1,0.6,0.2,-0.2,-0.6,0.8,0.4,0,-0.4,-0.8")
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()

    gammas = [float(g) for g in a.gammas.split(",")]
    nb = a.points // len(gammas)
    n = nb * len(gammas)
    lo, hi = 0.02, 7.0
    # The sweep's grid: beta_i = lo + i (hi - lo)/(nb - 1), gamma the outer loop.
    beta = lo + np.arange(nb) * ((hi - lo) / (nb - 1))
    cmd = [a.tool, "sweep", "--wave", a.wave, "--beta", f"{lo}:{hi}:{nb}", "--gamma", a.gammas, "--type", "double"]
    null = open(os.devnull, "w")

    startup = best_of(a.repeat, lambda: subprocess.run([a.tool, "version"], stdout=null, check=True))
    sweep = best_of(a.repeat, lambda: subprocess.run(cmd, stdout=null, check=True))
    g = np.array(gammas)[:, None]
    module = best_of(a.repeat, lambda: vibrofric.mu(a.wave, beta, g))
    mu = vibrofric.mu(a.wave, beta, g)
    assert mu.shape == (len(gammas), nb) and np.all(np.isfinite(mu))

    tool_per_point = (sweep - startup) / n
    module_per_point = module / n
    print(f"{n} points, wave {a.wave}, type double, {os.cpu_count()} cores, best of {a.repeat}")
    print(f"C++ sweep:     {sweep * 1e3:9.1f} ms process, {startup * 1e3:.1f} ms start-up -> {tool_per_point * 1e6:.3f} us/point")
    print(f"Python module: {module * 1e3:9.1f} ms call                         -> {module_per_point * 1e6:.3f} us/point")
    print(f"module / sweep: {module_per_point / tool_per_point:.3f}")


if __name__ == "__main__":
    main()
