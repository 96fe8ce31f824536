#!/usr/bin/python3
"""Fig. P2: mu_s and mu_d when hierarchical levels are added under a fixed first-level groove
(tpat1 families, N=120), each surface with its groove profile."""
from figures import categories
from figures import style

a = style.arguments(__doc__)
doc = style.load_target(a.data, "fig_p2")
fig = categories.draw(a, doc, "fig_p2", "adding levels under a fixed first-level groove")
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, "ours mean ± sem; published ± printed error")
style.save(fig, a.out, "fig_p2")
