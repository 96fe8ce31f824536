#!/usr/bin/python3
"""Size scaling: (a) macroscopic mu_s and (b) mu_d against the number of blocks N, at a fixed
length L_x = 7.2 cm (filled markers, solid: finer blocks; patterned surfaces keep their physical
pawl and groove sizes) and at a fixed block size l_x = 0.02 cm (open markers, dashed: a longer
body), smooth, periodic:10,10 and hierarchical:30,10 (as laid out on N = 360 over 7.2 cm);
mean +- standard error, lines the fit mu = a + b N^-c of paper/scaling_fits.py (thin where the
chi^2 rule finds it inadequate). (c) and (d): mu_s against the two elastic candidates for a
collapse, the chain's length in elastic lengths Lambda = L_x / ell and the blocks per elastic
length n_e = ell / l_x (ell = l_z sqrt(E/G), about 0.17 cm).
Data: the optional study `size_scaling` (`make studies`; committed as paper/data/size_scaling.json)."""
import numpy as np

from figures import style
from paper import scaling_fits as sf

a = style.arguments(__doc__)
doc = style.load_study(a.data, "size_scaling")
fig, axes = style.plt.subplots(2, 2, figsize=(9.0, 7.0))
axes = axes.ravel()
if not doc or not style.scenes(doc):
    for ax in axes:
        style.not_produced(ax, "size_scaling")
else:
    fits = {(t["surface"], t["family"], t["quantity"]): t["power_law"] for t in sf.trends(doc)}
    colour = {s: style.COLOURS[k] for k, s in enumerate(sf.surfaces(doc))}
    label = {s["x"]["surface"]: s["x"]["pattern"] if s["x"]["surface"] == "smooth" else
             s["x"]["surface"].replace("_", ":", 1).replace("_", ",") for s in doc["scenes"]}
    dash = {"fixed_length": "-", "fixed_block": "--"}
    panels = [("mu_s", "N", "(a) macroscopic mu_s against N"), ("mu_d", "N", "(b) macroscopic mu_d against N"),
              ("mu_s", "Lambda", "(c) mu_s against Lambda = L_x / ell"),
              ("mu_s", "n_e", "(d) mu_s against n_e = ell / l_x")]
    for ax, (key, var, title) in zip(axes, panels):
        for surface in sf.surfaces(doc):
            for family in sf.FAMILIES:
                pts = sf.points(doc, surface, family, key)
                if not pts:
                    continue
                x = np.array([sf.candidate(p[0], var) for p in pts])
                filled = family == "fixed_length"
                ax.errorbar(x, [p[1] for p in pts], yerr=[p[2] for p in pts], fmt="o" if filled else "s", ms=4,
                            capsize=2, color=colour[surface], mfc=colour[surface] if filled else "white",
                            ls="none", label=f"{label[surface]}, {family.replace('_', ' ')}" if var == "N" else None)
                fit = fits.get((surface, family, key))
                if var == "N" and fit and fit["converged"]:
                    t = np.geomspace(x.min(), x.max(), 100)
                    A, B, C = fit["params"]
                    ax.plot(t, A + B * t ** -C, dash[family], color=colour[surface], lw=1.2 if fit["adequate"] else 0.5)
        ax.set_xscale("log")
        ax.set_xlabel({"N": "number of blocks N", "Lambda": "Lambda = L_x / ell", "n_e": "n_e = ell / l_x"}[var])
        ax.set_ylabel(f"macroscopic {key}")
        ax.set_title(title, loc="left", fontsize=9)
    axes[0].legend(loc="best", fontsize=6)
style.stamp(fig, __file__, doc, note="filled: fixed L_x = 7.2 cm; open: fixed l_x = 0.02 cm; large N to the first slip")
fig.tight_layout()
style.save(fig, a.out, "size_scaling")
