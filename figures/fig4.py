#!/usr/bin/python3
"""Fig. 4: single-level patterns, mu_s against groove size n_g for each contact fraction
S/S_tot = n_p/(n_p+n_g) (a), and reproduced against published for every tpat0 row (b).
Grouping by contact fraction separates the paper's two competing effects: at fixed S larger
grooves lower mu_s, at fixed groove size a smaller S raises it."""
from fractions import Fraction

from figures import style


def sizes(pattern, scene=None):
    npv = style.dig(scene, "x.n_p") if scene else None
    ngv = style.dig(scene, "x.n_g") if scene else None
    if npv and ngv:
        return int(npv), int(ngv)
    kind, _, args = str(pattern).partition(":")
    if kind == "periodic":
        a, b = (int(v) for v in args.split(","))
        return a, b
    return None


a = style.arguments(__doc__)
doc = style.load_target(a.data, "fig4") or style.load_target(a.data, "tab_pat0")
pub = [r for r in style.read_published("tab_pat0") if r["pattern"].startswith("periodic:")]
fig, (pa, pb) = style.plt.subplots(1, 2, figsize=(7.4, 4.0), width_ratios=(1.5, 1))
pa.set_title("(a)", loc="left")
pb.set_title("(b)", loc="left")

fractions = sorted({Fraction(r["S_over_Stot_num"], r["S_over_Stot_den"]) for r in pub}, reverse=True)
# Nine contact fractions outnumber the colour cycle; a sequential map also orders them.
cmap = style.plt.get_cmap("viridis")
colour = {f: cmap(0.9 * i / max(1, len(fractions) - 1)) for i, f in enumerate(fractions)}
for f in fractions:
    rows = sorted((r for r in pub if Fraction(r["S_over_Stot_num"], r["S_over_Stot_den"]) == f),
                  key=lambda r: sizes(r["pattern"])[1])
    style.errorbar(pa, [sizes(r["pattern"])[1] for r in rows], [r["mu_s"] for r in rows],
                   [r["mu_s_err"] for r in rows], published=True, colour=colour[f])

sc = style.scenes(doc)
ours = {}
for s in sc:
    sz = sizes(style.pattern_of(s), s)
    if sz:
        ours[sz] = style.stat(s, "mu_s")
if not ours:
    style.not_produced(pb, "fig4 / tab_pat0")
else:
    for f in fractions:
        pts = sorted((ng, *ours[(np_, ng)]) for (np_, ng) in ours if Fraction(np_, np_ + ng) == f)
        if pts:
            style.errorbar(pa, [p[0] for p in pts], [p[1] for p in pts], [p[2] for p in pts],
                           label=f"S/S$_{{tot}}$ = {f}", colour=colour[f])
    xs, ys, ex, ey, cs = [], [], [], [], []
    for r in pub:
        o = ours.get(sizes(r["pattern"]))
        if o:
            xs.append(r["mu_s"]), ex.append(r["mu_s_err"]), ys.append(o[0]), ey.append(o[1])
            cs.append(colour[Fraction(r["S_over_Stot_num"], r["S_over_Stot_den"])])
    pb.errorbar(xs, ys, xerr=ex, yerr=ey, fmt="none", ecolor="#999999", lw=0.6)
    pb.scatter(xs, ys, c=cs, s=12, zorder=3)
    lo, hi = min(xs + ys) - 0.01, max(xs + ys) + 0.01
    pb.plot([lo, hi], [lo, hi], color="k", lw=0.6)
    pb.set_xlim(lo, hi)
    pb.set_ylim(lo, hi)
    pb.set_aspect("equal")
pa.set_xscale("log")
pa.set_xlabel(r"$n_g$ (blocks per groove)")
pa.set_ylabel(r"$(\mu_s)_M$")
pa.legend(ncol=5, fontsize=6, title="filled: ours; open: published", title_fontsize=6,
          loc="upper center", bbox_to_anchor=(0.75, -0.17))
pb.set_xlabel(r"published $(\mu_s)_M$")
pb.set_ylabel(r"reproduced $(\mu_s)_M$")
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, "N=360, L_x=7.2 cm")
style.save(fig, a.out, "fig4")
