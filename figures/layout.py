#!/usr/bin/python3
"""Layout study: mu_s of every appendix row for each candidate pattern layout, as its deviation
from the published value in combined standard errors, z = (ours - paper)/sqrt(err^2 + sem^2).
One panel per table; the dotted band is the detection threshold +-k. The chosen layout (by the
criterion in the study document) is drawn with filled markers. Below, the fraction of the 142
z-scores within 1, 2 and 3 for each layout against a standard normal.
Data: the optional study `layout` (paper/data/layout.json, tools/layout_study.py)."""
from figures import style

a = style.arguments(__doc__)
doc = style.load_study(a.data, "layout")
fig, axes = style.plt.subplots(4, 1, figsize=(7.0, 8.2), gridspec_kw={"height_ratios": [1, 1, 1, 0.8]})
if not doc:
    for ax in axes:
        style.not_produced(ax, "layout study")
else:
    variants = [v["variant"] for v in doc["variants"]]
    for p, (ax, table) in enumerate(zip(axes[:3], ("pat0", "pat1", "pat2"))):
        ids = sorted({r["row_id"] for r in doc["variants"][0]["rows"] if r["row_id"].startswith(table)})
        x = {rid: i for i, rid in enumerate(ids)}
        ks = []
        for j, v in enumerate(doc["variants"]):
            rows = [r for r in v["rows"] if r["coef"] == "mu_s" and r["row_id"] in x and r["z"] is not None]
            ks += [r["k"] for r in rows]
            chosen = v["variant"] == doc["chosen"]
            off = (j - (len(variants) - 1) / 2) * 0.13
            ax.plot([x[r["row_id"]] + off for r in rows], [r["z"] for r in rows], "o" if chosen else "o",
                    ms=3.2 if chosen else 2.6, mfc=style.COLOURS[j % 8] if chosen else "white",
                    color=style.COLOURS[j % 8], lw=0, label=v["variant"] + (" (chosen)" if chosen else ""))
        if ks:
            k = min(ks)
            ax.axhspan(-k, k, color="0.92", zorder=0)
        ax.axhline(0, color="0.5", lw=0.6)
        ax.set_xticks(range(len(ids)))
        ax.set_xticklabels([i.split("_r")[1] for i in ids], fontsize=5.5)
        ax.set_ylabel(f"t{table}: z of mu_s")
        if p == 0:
            # Above the panel: inside it, the legend hid the outliers of the worst layouts.
            ax.legend(fontsize=6, ncol=5, loc="lower center", bbox_to_anchor=(0.5, 1.0), frameon=False)
    ax = axes[3]
    cuts = ["1", "2", "3"]
    for j, v in enumerate(doc["variants"]):
        z = v["z_distribution"]
        ax.plot([1, 2, 3], [z["within"][c] for c in cuts], "o-", color=style.COLOURS[j % 8], ms=3,
                label=f"{v['variant']}: sd {z['sd']:.2f}")
    normal = doc["variants"][0]["z_distribution"]["normal"]
    ax.plot([1, 2, 3], [normal[c] for c in cuts], "k--", lw=0.8, label="standard normal")
    ax.set_xticks([1, 2, 3])
    ax.set_xticklabels(["|z| <= 1", "|z| <= 2", "|z| <= 3"])
    ax.set_ylabel("fraction of the 142")
    ax.legend(fontsize=5.5, ncol=2)
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, f"layout study; chosen: {doc['chosen']}" if doc else "layout study")
style.save(fig, a.out, "layout")
