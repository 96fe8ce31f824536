"""Shared drawing for fig_p2 and fig_p3: one column per surface, reproduced mu_s / mu_d beside
the printed value, and under each column the surface's groove profile from the simulator's
own pattern builder."""
from figures import style


def draw(args, doc, target, title):
    sc = style.scenes(doc)
    fig, (pa, pb, pc) = style.plt.subplots(3, 1, figsize=(7.0, 5.4), sharex=True, height_ratios=(1, 1, 0.55))
    pa.set_ylabel(r"$(\mu_s)_M$")
    pb.set_ylabel(r"$(\mu_d)_M$")
    if not sc:
        style.not_produced(pa, target)
        return fig
    pub = style.published_lookup()
    exe = style.springblock_exe(args)
    names = []
    for i, s in enumerate(sc):
        pattern, n = style.pattern_of(s), style.n_of(s)
        names.append(f"{pattern.replace('hierarchical:', 'h:').replace('periodic:', 'p:')}\nN={n}")
        row = pub.get((pattern, n))
        for ax, key in ((pa, "mu_s"), (pb, "mu_d")):
            m, e = style.stat(s, key)
            style.errorbar(ax, [i - 0.12], [m], [e], colour=style.COLOURS[0],
                           label="reproduced" if i == 0 else None)
            if row:
                style.errorbar(ax, [i + 0.12], [row[key]], [row[key + "_err"]], published=True,
                               label="published" if not ax.get_legend_handles_labels()[1][1:] else None)
        got = style.pattern_mask(exe, pattern, n)
        if got:
            mask, frac = got
            # Each profile occupies its own column slot [i-0.4, i+0.4] of the bottom strip.
            w = 0.8 / len(mask)
            xs, ys = [], []
            for j, c in enumerate(mask):
                xs += [i - 0.4 + j * w, i - 0.4 + (j + 1) * w]
                ys += [c, c]
            pc.plot(xs, ys, color="black", lw=0.6, drawstyle="default")
            # The fraction alone: "S/S_tot = ..." in every slot overlaps its neighbours.
            pc.text(i, -0.55, f"{frac:.3g}", ha="center", va="top", fontsize=6)
        else:
            pc.text(i, 0.5, "profile\nunavailable", ha="center", va="center", fontsize=6, color="#B00000")
    pc.set_ylim(-1.2, 1.4)
    pc.set_yticks([])
    pc.grid(False)
    pc.set_ylabel("profile,\nS/S$_{tot}$ below", fontsize=7)
    pc.set_xticks(range(len(sc)))
    pc.set_xticklabels(names, fontsize=6.5)
    pa.legend(fontsize=6)
    pa.set_title(title, loc="left")
    return fig
