#!/usr/bin/python3
"""A ball on a flat under harmonic oscillation (MDR, model.md "Curved contacts"): mu/mu0 against beta
for several gamma, sphere (solid) against the paper's flat punch (dashed); then one rig in SI
units (vibrofric.physical): a steel ball of radius 5 mm on aluminium pressed with 2 N mean load.

    PYTHONPATH=build/release/lib/python /usr/bin/python3 lib/python/examples/sphere.py sphere.png
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import vibrofric


def main(out):
    beta = np.linspace(0.05, 7.0, 120)
    gamma = np.array([1.0, 0.5, 0.0, -0.5, -0.9])
    sphere = vibrofric.mu("sine", beta, gamma[:, None], profile="sphere")
    flat = vibrofric.mu("sine", beta, gamma[:, None])
    fig, ax = plt.subplots(figsize=(6.4, 4.8), dpi=120)
    colors = plt.cm.plasma(np.linspace(0, 0.85, len(gamma)))
    for g, s, f, c in zip(gamma, sphere, flat, colors):
        ax.plot(beta, s, color=c, lw=1.3, label=f"sphere, γ = {g:g}")
        ax.plot(beta, f, color=c, lw=0.8, ls="--")
    ax.set_xlabel("β")
    ax.set_ylabel("μ̄ / μ0")
    ax.set_ylim(0, 1.02)
    ax.set_title("Sphere (solid) and flat punch (dashed), harmonic wave")
    ax.legend(fontsize=7, loc="lower right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out)
    print(f"wrote {out}: {sphere.size + flat.size} points")
    rig = vibrofric.physical("sine", E1=210e9, nu1=0.3, E2=70e9, nu2=0.33, shape="sphere", R=5e-3,
                             v0=1e-4, f=200, A=1e-6, mu0=0.3, F_N=2.0)
    print("steel ball R = 5 mm on aluminium, F_N = 2 N, A = 1 um at 200 Hz, v0 = 0.1 mm/s:")
    for name in ("beta", "gamma", "u_mean_m", "contact_radius_max_m", "mu_over_mu0", "mu", "F_x_mean_N"):
        print(f"  {name:22} {rig[name]:.6g}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: sphere.py OUTPUT.png")
    main(sys.argv[1])
