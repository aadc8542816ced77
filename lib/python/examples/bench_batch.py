#!/usr/bin/python3
"""Per-point cost of a double batch through the Python module against the C++ tool's sweep of the
same grid, both on all cores (or --threads N), side by side in one run: the two are interleaved repetition by
repetition (load that comes and goes hits both), and the median of each is reported. The tool's
time is its whole process minus its start-up (the median of `vibrofric version`). Noise control:
the same comparison for the triangle, whose mu/mu0 is closed-form (Eq. 19) and costs little per
point, so that fixed per-point overheads (text, conversion, output) show; and the load average
before and after.

    PYTHONPATH=build/release/lib/python /usr/bin/python3 lib/python/examples/bench_batch.py \
        build/release/lib/vibrofric [--points 100000] [--repeat 7] [--waves sine,triangle] [--threads 0]
"""
import argparse
import os
import statistics
import subprocess
import time

import numpy as np

import vibrofric


def timed(fn):
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tool", help="path of the vibrofric tool")
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--waves", default="sine,triangle")
    ap.add_argument("--gammas", default="1,0.6,0.2,-0.2,-0.6,0.8,0.4,0,-0.4,-0.8")
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--threads", type=int, default=0, help="worker threads of both; 0: all cores")
    a = ap.parse_args()

    gammas = [float(g) for g in a.gammas.split(",")]
    nb = a.points // len(gammas)
    n = nb * len(gammas)
    lo, hi = 0.02, 7.0
    # The sweep's grid: beta_i = lo + i (hi - lo)/(nb - 1), gamma the outer loop (rows gamma-major).
    beta = lo + np.arange(nb) * ((hi - lo) / (nb - 1))
    g = np.array(gammas)[:, None]
    null = open(os.devnull, "w")
    load_before = os.getloadavg()

    startup = statistics.median(
        timed(lambda: subprocess.run([a.tool, "version"], stdout=null, check=True)) for _ in range(a.repeat))
    threads = f"{a.threads} worker thread(s)" if a.threads else f"all {os.cpu_count()} cores"
    print(f"{n} points ({len(gammas)} gamma x {nb} beta), type double, {threads}, "
          f"median of {a.repeat} interleaved runs; tool start-up {startup * 1e3:.1f} ms")
    print(f"{'wave':10} {'C++ sweep us/pt':>16} {'module us/pt':>13} {'module/sweep':>13}   (min tool, min module us/pt)")
    for wave in a.waves.split(","):
        cmd = [a.tool, "sweep", "--wave", wave, "--beta", f"{lo}:{hi}:{nb}", "--gamma", a.gammas, "--type", "double",
               "--threads", str(a.threads)]
        mu = vibrofric.mu(wave, beta, g)  # warm-up, and the check that every value is there
        assert mu.shape == (len(gammas), nb) and np.all(np.isfinite(mu))
        tool, module = [], []
        for _ in range(a.repeat):
            tool.append(timed(lambda: subprocess.run(cmd, stdout=null, check=True)) - startup)
            module.append(timed(lambda: vibrofric.mu(wave, beta, g, threads=a.threads)))
        t, m = statistics.median(tool) / n * 1e6, statistics.median(module) / n * 1e6
        print(f"{wave:10} {t:16.3f} {m:13.3f} {m / t:13.3f}   ({min(tool) / n * 1e6:.3f}, {min(module) / n * 1e6:.3f})")
    print(f"load average (1, 5, 15 min): before {load_before[0]:.2f} {load_before[1]:.2f} {load_before[2]:.2f}, "
          f"after {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
