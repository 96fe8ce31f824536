#!/usr/bin/python3
"""Fig. S1: smooth surface, mu_s (a) and mu_d (b) against the number of blocks N at fixed
block length, one line per set of microscopic coefficients (the dispersion is the point)."""
from figures import style
from figures import sweep

a = style.arguments(__doc__)
doc = style.load_target(a.data, "fig_s1")
fig, pa, pb = sweep.two_panels()
sc = style.scenes(doc)
if not sc:
    style.not_produced(pa, "fig_s1")
    style.not_produced(pb, "fig_s1")
else:
    sweep.plot_groups(pa, pb, style.group_by(sc, lambda s: style.friction_label(s)), "N",
                      xfun=lambda s: style.dig(s, "x.N") or style.n_of(s))
    for p in (pa, pb):
        p.set_xscale("log")
        p.set_xlabel("N (blocks)")
    pa.legend()
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, "mean ± sem of repetitions")
style.save(fig, a.out, "fig_s1")
