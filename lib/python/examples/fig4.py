#!/usr/bin/python3
"""Fig. 4 of the paper: mu/mu0 against beta for the harmonic wave, one curve per gamma (the paper's
11 values from 1 to -1; gamma = -1 itself has no contact, so the last curve is at -0.999).

    PYTHONPATH=build/release/lib/python /usr/bin/python3 lib/python/examples/fig4.py fig4.png
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import vibrofric


def main(out):
    beta = np.linspace(0.02, 7.0, 350)
    gamma = np.array([1, 0.8, 0.6, 0.4, 0.2, 0, -0.2, -0.4, -0.6, -0.8, -0.999])
    mu = vibrofric.mu("sine", beta, gamma[:, None])  # (11, 350), one batch on all cores (Eq. 15)
    fig, ax = plt.subplots(figsize=(6.4, 4.8), dpi=120)
    colors = plt.cm.viridis(np.linspace(0, 0.9, len(gamma)))
    for g, row, c in zip(gamma, mu, colors):
        ax.plot(beta, row, color=c, lw=1.2, label=f"γ = {g:g}")
    ax.set_xlabel("β")
    ax.set_ylabel("μ̄ / μ0")
    ax.set_xlim(0, 7)
    ax.set_ylim(0, 1.02)
    ax.set_title("Harmonic oscillation (Fig. 4)")
    ax.legend(fontsize=7, ncol=2, loc="lower right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out)
    print(f"wrote {out}: {mu.size} points")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: fig4.py OUTPUT.png")
    main(sys.argv[1])
