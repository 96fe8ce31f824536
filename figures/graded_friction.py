#!/usr/bin/python3
"""Graded micro friction: mu_s of each block a linear ramp along the chain (total change from the
first block to the last, the block index growing in the slider's direction), its mean over the
contact blocks 1.0. Paired difference from the uniform chain (same draws, repetition by
repetition) of (a) the macroscopic mu_s and (b) mu_d, mean +- standard error; the paper's chain
(N = 360, 7.2 cm), smooth and periodic:10,10, event method.
Data: the optional study `graded_friction` (`make studies`; committed as paper/data/graded_friction.json)."""
from figures import style

a = style.arguments(__doc__)
doc = style.load_study(a.data, "graded_friction")
fig, axes = style.plt.subplots(1, 2, figsize=(8.6, 3.5))
cmp = [c for c in doc.get("comparisons", []) if c["what"] == "graded - uniform"] if doc else []
if not cmp:
    for ax in axes:
        style.not_produced(ax, "graded_friction")
else:
    slope = {s["id"].rsplit("_", 1)[1]: s["x"]["slope"] for s in style.scenes(doc)}
    surfaces = list(dict.fromkeys(c["surface"] for c in cmp))
    label = {s["id"].rsplit("_", 1)[0]: s["x"]["pattern"] for s in style.scenes(doc)}
    for ax, key, title in zip(axes, ("mu_s", "mu_d"), ("(a) macroscopic mu_s", "(b) macroscopic mu_d")):
        for k, surface in enumerate(surfaces):
            rows = sorted([c for c in cmp if c["surface"] == surface and c["quantity"] == key],
                          key=lambda c: slope[c["a"]])
            x = [slope[c["a"]] + 0.01 * (k - 0.5) for c in rows]  # side by side, not on top
            ax.errorbar(x, [c["diff"] for c in rows], yerr=[c["sem"] for c in rows], marker="o", ms=4, capsize=2,
                        lw=1.2, color=style.COLOURS[k], label=label[surface])
        ax.axhline(0, color="#999999", lw=0.8)
        ax.set_xlabel("change of micro mu_s from the first block to the last")
        ax.set_ylabel(f"{key}(graded) - {key}(uniform), paired")
        ax.set_title(title, loc="left")
        ax.legend(loc="best")
reps = cmp[0]["n"] if cmp else "?"
style.stamp(fig, __file__, doc, note=f"{reps} paired repetitions per point, mean +- standard error")
fig.tight_layout()
style.save(fig, a.out, "graded_friction")
