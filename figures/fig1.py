#!/usr/bin/python3
"""Fig. 1: total friction force over the load, mu(t), of one smooth-surface run, with the
number of sliding blocks. mu_s and mu_d extracted by the simulator are drawn as guides so the
reader can see where on the curve each coefficient comes from."""
from figures import style

a = style.arguments(__doc__)
doc = style.load_target(a.data, "fig1")
# Two stacked panels rather than a twin axis: the sliding count is noisy and would hide mu(t).
fig, (ax, ax2) = style.plt.subplots(2, 1, figsize=(5.0, 4.0), sharex=True, height_ratios=(2.2, 1))
series = style.all_series(doc)
if not series:
    style.not_produced(ax, "fig1 series")
    ax2.set_visible(False)
else:
    label, s, sc0 = series[0]
    t_ms = [t * 1e3 for t in s.get("t_s", [])]
    ax.plot(t_ms, s.get("mu", []), lw=0.7, color=style.COLOURS[0], label=r"$\mu(t)$")
    ax2.set_xlabel("time (ms)")
    ax.set_ylabel(r"friction force / total load")
    if sc0:
        for name, ls in (("mu_s", "--"), ("mu_d", ":")):
            m, e = style.stat(sc0, name)
            if m == m:
                sym = r"\mu_s" if name == "mu_s" else r"\mu_d"
                ax.axhline(m, ls=ls, lw=0.8, color="k", label=f"$({sym})_M$ = {m:.3f} ± {e:.3f} (mean ± sem)")
    if s.get("n_sliding"):
        ax2.plot(t_ms, s["n_sliding"], lw=0.5, color=style.COLOURS[1])
        ax2.set_ylabel("sliding blocks")
    ax.legend(loc="lower right")
    ax.set_title(f"{label}: repetition 0")
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc)
style.save(fig, a.out, "fig1")
