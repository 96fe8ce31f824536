#!/usr/bin/python3
"""Normal quantile plot of the z-scores of all published numbers, z = (ours - published)/sigma,
read from the checker's summary.json. If the published errors and ours described all the
scatter, the points would lie on the diagonal; a slope above one says the differences are larger
than both error bars allow, points far off the line are individual deviations. mu_s and mu_d are
drawn apart (their published errors differ in kind), known deviations are marked."""
import sys

from scipy.stats import norm

from figures import style
from tools import summary_schema as schema

a = style.arguments(__doc__)
try:
    s = schema.load(a.data / "summary.json")
except schema.SummaryError as e:
    sys.exit(f"zscores: {e}")
judged = sorted((r for r in s["rows"] if r["verdict"] != "missing"), key=lambda r: r["z"])
n = len(judged)
# Blom's plotting positions: nearly unbiased normal order statistics for any n.
expected = [float(norm.ppf((i + 1 - 0.375) / (n + 0.25))) for i in range(n)]

fig, ax = style.plt.subplots(figsize=(4.6, 4.2))
if not judged:
    style.not_produced(ax, "z-scores")
else:
    lim = max(3.5, max(abs(r["z"]) for r in judged) + 0.5)
    ax.plot([-lim, lim], [-lim, lim], color="k", lw=0.8, label="standard normal")
    for coef, marker, colour in (("mu_s", "o", style.COLOURS[0]), ("mu_d", "s", style.COLOURS[1])):
        pts = [(x, r["z"]) for x, r in zip(expected, judged) if r["coef"] == coef]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker, ms=3.5, color=colour, ls="none",
                label=f"{coef} ({len(pts)})")
    known = [(x, r) for x, r in zip(expected, judged) if r["verdict"] == "disagree_known"]
    ax.plot([x for x, _ in known], [r["z"] for _, r in known], "o", ms=8, mfc="none", mec="#B00000", mew=1.0,
            ls="none", label=f"known deviation ({len(known)})")
    for x, r in known:
        ax.annotate(r["row_id"], (x, r["z"]), fontsize=5.5, color="#B00000", xytext=(4, -2),
                    textcoords="offset points")
    ax.set_xlim(-3.5, 3.5)
    ax.set_ylim(-lim, lim)
    ax.set_xlabel("standard normal quantile")
    ax.set_ylabel("z = (ours − published) / σ")
    z = s["z_distribution"]
    # Two lines: on one the title ran past the figure's right edge at this width.
    ax.set_title(f"{n} published numbers, tier {s['tier']}\nsd of z = {z['sd']:.2f} "
                 f"(mu_s {z['sd_by_coef']['mu_s']:.2f}, mu_d {z['sd_by_coef']['mu_d']:.2f})", fontsize=9)
    ax.legend(loc="upper left")
fig.tight_layout(rect=(0, 0.03, 1, 1))
# The z-scores are the table targets' numbers: stamp their commit.
style.stamp(fig, __file__, style.load_target(a.data, "tab_pat0"),
            "within ±1, ±2, ±3: " + ", ".join(f"{s['z_distribution']['within'][c]:.2f}" for c in schema.Z_CUTS))
style.save(fig, a.out, "zscores")
