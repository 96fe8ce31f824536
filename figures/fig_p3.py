#!/usr/bin/python3
"""Fig. P3: one-level against two-level surfaces with the same contact fraction and the same
largest groove (tpat0 vs tpat2, N=360), each with its groove profile."""
from figures import categories
from figures import style

a = style.arguments(__doc__)
doc = style.load_target(a.data, "fig_p3")
fig = categories.draw(a, doc, "fig_p3", "one level vs two levels at equal contact fraction")
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, "ours mean ± sem; published ± printed error")
style.save(fig, a.out, "fig_p3")
