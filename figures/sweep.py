"""Shared drawing for the parameter sweeps (fig_s1, fig_s2, fig_p1): mu_s in panel (a) and
mu_d in panel (b) against one plot coordinate, one line per group of scenes."""
import math

from figures import style


def two_panels(title_a="(a)", title_b="(b)", figsize=(7.0, 3.0)):
    fig, (pa, pb) = style.plt.subplots(1, 2, figsize=figsize)
    pa.set_title(title_a, loc="left")
    pb.set_title(title_b, loc="left")
    pa.set_ylabel(r"$(\mu_s)_M$")
    pb.set_ylabel(r"$(\mu_d)_M$")
    return fig, pa, pb


def plot_groups(pa, pb, groups, xkey, xfun=None):
    """groups: {legend label: [scenes]}; x from scene['x'][xkey] (or xfun(scene))."""
    for i, (label, items) in enumerate(groups.items()):
        pts = []
        for s in items:
            x = xfun(s) if xfun else style.dig(s, f"x.{xkey}")
            if x is None:
                continue
            pts.append((float(x), style.stat(s, "mu_s"), style.stat(s, "mu_d")))
        pts.sort()
        if not pts:
            continue
        c = style.COLOURS[i % len(style.COLOURS)]
        xs = [p[0] for p in pts]
        style.errorbar(pa, xs, [p[1][0] for p in pts], [p[1][1] for p in pts], label=label, colour=c)
        style.errorbar(pb, xs, [p[2][0] for p in pts], [p[2][1] for p in pts], label=label, colour=c)


def finite(v):
    return v is not None and isinstance(v, (int, float)) and math.isfinite(v)
