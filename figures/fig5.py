#!/usr/bin/python3
"""Fig. 5: mu(t) of a smooth, a one-level and a two-level surface (N=360), one panel each
with a common time axis, the groove profile drawn under each trace."""
from figures import style

a = style.arguments(__doc__)
doc = style.load_target(a.data, "fig5")
series = style.all_series(doc)
rows = max(1, len(series))
fig, axes = style.plt.subplots(rows, 1, figsize=(5.6, 1.0 + 1.35 * rows), sharex=True, sharey=True, squeeze=False)
if not series:
    style.not_produced(axes[0][0], "fig5 series")
exe = style.springblock_exe(a)
for i, (label, s, sc) in enumerate(series):
    ax = axes[i][0]
    ax.plot([t * 1e3 for t in s.get("t_s", [])], s.get("mu", []), lw=0.6, color=style.COLOURS[i % 8])
    pattern = style.pattern_of(sc) if sc else label
    text = str(pattern)
    if sc:
        m, e = style.stat(sc, "mu_s")
        d, de = style.stat(sc, "mu_d")
        text += f"   $(\\mu_s)_M$={m:.3f}±{e:.3f}  $(\\mu_d)_M$={d:.3f}±{de:.3f}"
    ax.text(0.99, 0.95, text, transform=ax.transAxes, ha="right", va="top", fontsize=6.5,
            bbox=dict(fc="white", ec="none", alpha=0.85))
    got = style.scene_mask(sc, exe) if sc else None
    if got:
        # Profile inside the bottom of the panel, below the dynamic-phase trace.
        style.draw_profile(ax, got[0], y0=0.03, height=0.07)
    ax.set_ylabel(r"$\mu(t)$")
axes[-1][0].set_xlabel("time (ms)")
axes[0][0].set_ylim(bottom=-0.15 * max((max(v for v in (s.get("mu") or [1]) if v is not None) for _, s, _ in series), default=1))
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, "repetition 0 of each surface")
style.save(fig, a.out, "fig5")
