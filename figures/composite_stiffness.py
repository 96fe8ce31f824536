#!/usr/bin/python3
"""Composite chains: segments of L blocks alternate soft and hard (internal springs and masses
c times apart, about the uniform chain's), N = 200 over 4 cm, smooth surface. Paired
difference from the uniform chain (same draws) of (a) mu_s and (b) mu_d against the segment
length, one line per contrast c, mean +- standard error.
Data: the optional study `composite_stiffness` (`make studies`; committed as paper/data/composite_stiffness.json)."""
from figures import style

a = style.arguments(__doc__)
doc = style.load_study(a.data, "composite_stiffness")
fig, axes = style.plt.subplots(1, 2, figsize=(8.6, 3.5))
cmp = doc.get("comparisons", []) if doc else []
if not cmp:
    for ax in axes:
        style.not_produced(ax, "composite_stiffness")
else:
    x_of = {s["id"]: s["x"] for s in style.scenes(doc)}
    contrasts = sorted({x_of[c["id"]]["contrast"] for c in cmp})
    for ax, key, title in zip(axes, ("mu_s", "mu_d"), ("(a) macroscopic mu_s", "(b) macroscopic mu_d")):
        for k, contrast in enumerate(contrasts):
            rows = sorted([c for c in cmp if c["quantity"] == key and x_of[c["id"]]["contrast"] == contrast
                           and c["n"] > 1], key=lambda c: x_of[c["id"]]["segment_blocks"])
            ax.errorbar([x_of[c["id"]]["segment_blocks"] * (1 + 0.04 * k) for c in rows], [c["diff"] for c in rows],
                        yerr=[c["sem"] for c in rows], marker="o", ms=4, capsize=2, lw=1.2, color=style.COLOURS[k],
                        label=f"contrast {contrast:g}")
        ax.axhline(0, color="#999999", lw=0.8)
        ax.set_xscale("log")
        ax.set_xlabel("segment length [blocks]")
        ax.set_ylabel(f"{key}(composite) - {key}(uniform), paired")
        ax.set_title(title, loc="left")
        ax.legend(loc="best")
reps = cmp[0]["n"] if cmp else "?"
method = next((x["result"]["scene"].get("method") for x in doc["scenes"]), "?")
style.stamp(fig, __file__, doc, note=f"{method} method; {reps} paired repetitions per point, mean +- standard error")
fig.tight_layout()
style.save(fig, a.out, "composite_stiffness")
