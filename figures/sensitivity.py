#!/usr/bin/python3
"""Sensitivity of mu_s and mu_d to the choices the paper leaves open (extraction rules, run
length, integrator accuracy): the shift of each variant from the baseline of its surface.
The grey band is ± the baseline's standard error: shifts inside it are below the noise of one
ensemble (variants share the seed, so the real paired noise is smaller still)."""
from figures import style


def key(s):
    return style.dig(s, "x.surface", "all")


def variant(s):
    c, k, v = style.dig(s, "x.choice", s.get("label", "?")), style.dig(s, "x.key", ""), style.dig(s, "x.value", "")
    if not k:
        return str(c)
    return f"{k}={v}" if k == c else f"{c}: {k}={v}"


a = style.arguments(__doc__)
doc = style.load_target(a.data, "sensitivity")
sc = style.scenes(doc)
groups = style.group_by(sc, key)
cols = max(1, len(groups))
fig, axes = style.plt.subplots(1, cols, figsize=(2.6 * cols + 1.6, 3.4), sharey=True, squeeze=False)
if not sc:
    style.not_produced(axes[0][0], "sensitivity")
for ax, (surface, items) in zip(axes[0], groups.items()):
    base = next((s for s in items if style.dig(s, "x.choice") == "baseline"), None)
    variants = [s for s in items if s is not base]
    ax.set_title(str(surface), fontsize=8)
    if base is None:
        style.not_produced(ax, f"{surface} baseline")
        continue
    for j, (name, off, c) in enumerate((("mu_s", -0.18, style.COLOURS[0]), ("mu_d", 0.18, style.COLOURS[1]))):
        b, be = style.stat(base, name)
        if be == be:
            ax.axvspan(-be, be, color="#DDDDDD", zorder=0)
        ys, xs, es = [], [], []
        for i, s in enumerate(variants):
            m, e = style.stat(s, name)
            ys.append(i + off), xs.append(m - b), es.append(e)
        ax.errorbar(xs, ys, xerr=es, fmt="o", ms=3.5, capsize=2, color=c,
                    label=r"$\Delta(\mu_s)_M$" if name == "mu_s" else r"$\Delta(\mu_d)_M$")
    ax.set_yticks(range(len(variants)))
    ax.set_yticklabels([variant(s) for s in variants], fontsize=7)
    ax.axvline(0, color="k", lw=0.6)
    ax.set_xlabel("shift from baseline")
    ax.xaxis.set_major_locator(style.matplotlib.ticker.MaxNLocator(4))
axes[0][0].invert_yaxis()
axes[0][0].legend(fontsize=6)
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, "error bars: sem of the variant; band: sem of the baseline")
style.save(fig, a.out, "sensitivity")
