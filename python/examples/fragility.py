"""Pounding fragility of the preset's two buildings, notebook style.

An incremental dynamic analysis (IDA) runs 20 simulated records at every
intensity level from 0.02 g to 1 g; each limit state's counts of exceedance
are fitted with a lognormal fragility P(exceed | PGA = x) = Φ(ln(x/θ)/β)
(SPEC §12). The figure shows the fragility of pounding itself, and of a
ductility demand above 2 with pounding and for the same buildings apart.

    pip install ./python matplotlib
    python python/examples/fragility.py [OUT.png]

matplotlib is this example's dependency only, not the module's.
"""

import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import pounding  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "fragility.png"

# In a notebook, this cell is the whole study: about a second for 1,000 runs.
f = pounding.fragility(
    suite="synthetic:20",
    levels="0.02:1.0:0.02",
    preset="two-buildings",
    ductility="2",
)
levels = f["levels"]  # numpy array of intensities (g)


def curve(fit, x):
    """The fitted lognormal fragility at x, or None without a fit."""
    if fit["outcome"] != "fitted":
        return None
    z = np.log(x / fit["theta"]) / fit["beta"]
    return 0.5 * (1.0 + np.vectorize(math.erf)(z / math.sqrt(2.0)))


x = np.linspace(levels[0] / 2, levels[-1], 400)
fig, ax = plt.subplots(figsize=(7, 4.2), dpi=100)
styles = {"pounding": "C3", "ductility>2 (either)": "C0"}
for state in f["fragility"]:
    name = state["limit_state"]
    color = styles.get(name, "C2")
    counts = state["counts"]
    ax.plot(levels, counts["exceeded"] / counts["runs"], "o", color=color, ms=3.5, alpha=0.6)
    fit = state["fragility"]
    y = curve(fit, x)
    if y is not None:
        label = f"{name}: θ = {fit['theta']:.3f} g, β = {fit['beta']:.2f}"
        ax.plot(x, y, "-", color=color, label=label)
    apart = state.get("no_pounding_fragility")
    if apart is not None:
        y = curve(apart, x)
        c = state["no_pounding_counts"]
        ax.plot(levels, c["exceeded"] / c["runs"], "s", mfc="none", color=color, ms=3.5, alpha=0.6)
        if y is not None:
            label = f"{name}, buildings apart: θ = {apart['theta']:.3f} g, β = {apart['beta']:.2f}"
            ax.plot(x, y, "--", color=color, label=label)

ax.set_xlabel("PGA (g)")
ax.set_ylabel("P(exceed | PGA)")
ax.set_title(f"Fragility, preset {f['preset']}, suite {f['suite']} ({f['records_per_level']} records)")
ax.set_ylim(-0.02, 1.02)
ax.grid(alpha=0.3)
ax.legend(fontsize=8, loc="center right")
fig.tight_layout()
fig.savefig(out)
print(f"wrote {out}")
for state in f["fragility"]:
    print(state["limit_state"], state["fragility"])
