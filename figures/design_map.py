#!/usr/bin/python3
"""Design map (issue 17): the macroscopic mu_s (a) and mu_d (b) of the paper's chain (N = 360,
L_x = 7.2 cm) over a grid of single-level periodic surfaces periodic:n_p,n_g, as heat maps with
each cell's value. Cells the paper itself simulated (table tpat0) are outlined. Lines of equal
contact fraction n_p/(n_p+n_g) run along the diagonals: mu_s falls towards large grooves along
them and rises as the contact fraction falls; mu_d changes only where few blocks touch.
Data: the optional study `design_map` (`make studies`; committed as paper/data/design_map.json)."""
import math

from figures import style

a = style.arguments(__doc__)
doc = style.load_study(a.data, "design_map")
fig, axes = style.plt.subplots(1, 2, figsize=(8.6, 4.0))
cells = {}
for s in style.scenes(doc):
    np_, ng = style.dig(s, "x.n_p"), style.dig(s, "x.n_g")
    if np_ and ng:
        cells[(int(np_), int(ng))] = (style.stat(s, "mu_s"), style.stat(s, "mu_d"))
if not cells:
    for ax in axes:
        style.not_produced(ax, "design_map")
else:
    nps = sorted({k[0] for k in cells})
    ngs = sorted({k[1] for k in cells})
    paper = {r["pattern"] for r in style.read_published("tab_pat0")}
    for ax, idx, name in ((axes[0], 0, "$\\mu_s$"), (axes[1], 1, "$\\mu_d$")):
        grid = [[cells.get((p, g), ((math.nan, math.nan), (math.nan, math.nan)))[idx][0] for g in ngs] for p in nps]
        im = ax.imshow(grid, origin="lower", cmap="viridis", aspect="auto")
        fig.colorbar(im, ax=ax, label=f"macroscopic {name}")
        for i, p in enumerate(nps):
            for j, g in enumerate(ngs):
                v = grid[i][j]
                if math.isfinite(v):
                    ax.text(j, i, f"{v:.3f}", ha="center", va="center", fontsize=5.5,
                            color="white" if v < (min(map(min, grid)) + max(map(max, grid))) / 2 else "black")
                if f"periodic:{p},{g}" in paper:
                    ax.add_patch(style.matplotlib.patches.Rectangle((j - 0.5, i - 0.5), 1, 1, fill=False,
                                                                    ec="#D55E00", lw=1.2))
        ax.set_xticks(range(len(ngs)), [str(g) for g in ngs])
        ax.set_yticks(range(len(nps)), [str(p) for p in nps])
        ax.set_xlabel("groove size $n_g$ (blocks)")
        ax.set_ylabel("pawl size $n_p$ (blocks)")
        ax.grid(False)
    axes[0].set_title("(a) $\\mu_s$; outlined: in the paper's table tpat0", loc="left")
    axes[1].set_title("(b) $\\mu_d$", loc="left")
reps = style.dig(style.scenes(doc)[0], "result.mu_s.n") if style.scenes(doc) else "?"
style.stamp(fig, __file__, doc, note=f"{reps} repetitions per cell")
fig.tight_layout()
style.save(fig, a.out, "design_map")
