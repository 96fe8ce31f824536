#!/usr/bin/python3
"""Fig. S2: mu_s (a) and mu_d (b) against K_int/K_s (varied through l_x), one line per N.
K_int/K_s is recomputed from the derived stiffnesses when the scene does not give it, so the
x coordinate always matches what was simulated."""
from figures import style
from figures import sweep


def ratio(s):
    r = style.dig(s, "x.K_int_over_K_s")
    if r is None:
        ki = style.dig(s, "result.scene.derived.K_int_N_per_m")
        ks = style.dig(s, "result.scene.derived.K_s_N_per_m")
        r = ki / ks if ki and ks else None
    return r


a = style.arguments(__doc__)
doc = style.load_target(a.data, "fig_s2")
fig, pa, pb = sweep.two_panels()
sc = style.scenes(doc)
if not sc:
    style.not_produced(pa, "fig_s2")
    style.not_produced(pb, "fig_s2")
else:
    groups = style.group_by(sc, lambda s: f"N = {style.n_of(s)}")
    sweep.plot_groups(pa, pb, groups, "K_int_over_K_s", xfun=ratio)
    for p in (pa, pb):
        p.set_xscale("log")
        p.set_xlabel(r"$K_{int}/K_s$")
        # The paper's two regimes meet where the stiffnesses are equal.
        p.axvline(1.0, color="k", lw=0.6, ls=":")
    pa.legend()
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, "mean ± sem of repetitions")
style.save(fig, a.out, "fig_s2")
