#!/usr/bin/python3
"""The three model schematics: (a) the chain of blocks with internal springs K_int, shear
springs K_s to the slider moving at v and the pressure load; (b) a grooved chain, groove blocks
lifted off the plane; (c) two- and three-level hierarchical surfaces.

Every surface is drawn from the mask printed by the simulator's `pattern` command, so the
pictures show exactly the surfaces that were simulated. In (c) a block's groove depth counts
the levels at which it is a groove (the mask of levels 1..k, for every k), so deeper cuts are
the larger, earlier levels."""
import matplotlib.patches as mp
import numpy as np

from figures import style


def spring(ax, x0, y0, x1, y1, turns=5, width=0.08, **kw):
    """Zigzag between two points: a plain line reads as a rod, not as a spring."""
    p0, p1 = np.array([x0, y0]), np.array([x1, y1])
    d = p1 - p0
    length = np.hypot(*d)
    u, nrm = d / length, np.array([-d[1], d[0]]) / length
    pts = [p0, p0 + 0.15 * d]
    for k in range(2 * turns):
        t = 0.15 + 0.7 * (k + 0.5) / (2 * turns)
        pts.append(p0 + t * d + (width if k % 2 == 0 else -width) * nrm)
    pts += [p0 + 0.85 * d, p1]
    pts = np.array(pts)
    ax.plot(pts[:, 0], pts[:, 1], color=kw.get("color", "k"), lw=kw.get("lw", 0.8))


def chain(ax, mask, title, lift=0.25):
    n = len(mask)
    ax.set_title(title, loc="left")
    ax.fill_between([-0.7, n - 0.3], -0.25, 0, color="#CCCCCC", hatch="////", edgecolor="#888888", lw=0)
    ax.plot([-0.7, n - 0.3], [0, 0], color="k", lw=1)
    slider_y = 2.3
    ax.add_patch(mp.Rectangle((-0.6, slider_y), n + 0.2, 0.25, fc="#DDE8F5", ec="k", lw=0.8))
    ax.annotate("", xy=(n + 0.6, slider_y + 0.12), xytext=(n - 0.3, slider_y + 0.12),
                arrowprops=dict(arrowstyle="-|>", lw=1))
    ax.text(n + 0.65, slider_y + 0.12, "$v$", va="center")
    for i, m in enumerate(mask):
        y = 0 if m else lift
        ax.add_patch(mp.Rectangle((i - 0.3, y), 0.6, 0.6, fc="#F2C28A" if m else "#FFFFFF", ec="k", lw=0.8))
        spring(ax, i, y + 0.6, i, slider_y, turns=4, width=0.07)
        if i + 1 < n:
            y2 = 0 if mask[i + 1] else lift
            spring(ax, i + 0.3, y + 0.3, i + 0.7, y2 + 0.3, turns=3, width=0.06)
    for x in np.linspace(0, n - 1, min(n, 6)):
        ax.annotate("", xy=(x, slider_y + 0.25), xytext=(x, slider_y + 0.75),
                    arrowprops=dict(arrowstyle="-|>", lw=0.8, color="#B00000"))
    ax.text(n / 2 - 0.5, slider_y + 0.85, "$P$ (load shared by the contact blocks)", ha="center", fontsize=7,
            color="#B00000")
    ax.text(0.5, 0.95, "$K_{int}$", ha="center", fontsize=7)
    ax.text(-0.05, 1.55, "$K_s$", ha="right", fontsize=7)
    ax.text(0, 0.3, "$m$", ha="center", va="center", fontsize=7)
    ax.set_xlim(-1, n + 1.2)
    ax.set_ylim(-0.4, 3.4)
    ax.set_aspect("equal")
    ax.axis("off")


def levels_depth(exe, levels, n):
    depth = np.zeros(n)
    for k in range(1, len(levels) + 1):
        got = style.pattern_mask(exe, "hierarchical:" + ",".join(str(g) for g in levels[:k]), n)
        if not got:
            return None, None
        depth += 1 - np.array(got[0])
    return depth, got[1]


def hierarchy(ax, exe, levels, n, title):
    depth, frac = levels_depth(exe, levels, n)
    ax.set_title(title, loc="left", fontsize=8)
    if depth is None:
        style.not_produced(ax, "pattern mask (simulator not found)")
        return
    top = len(levels) + 1.5
    xs = np.arange(n + 1)
    # Underside of the body: contact blocks reach y=0, grooves are cut up by their depth.
    bottom = np.repeat(depth, 2)
    xx = np.repeat(xs, 2)[1:-1]
    ax.fill_between(xx, bottom, top, color="#F2C28A", step=None, lw=0)
    ax.plot(xx, bottom, color="k", lw=0.6)
    ax.plot([0, n], [-0.05, -0.05], color="k", lw=1)
    ax.text(n, top + 0.2, f"N={n}, groove sizes {','.join(map(str, levels))} blocks, S/S$_{{tot}}$={frac:.3g}",
            ha="right", fontsize=6.5)
    ax.set_xlim(-1, n + 1)
    ax.set_ylim(-0.5, top + 1.2)
    ax.axis("off")


a = style.arguments(__doc__)
exe = style.springblock_exe(a)
if not exe:
    style.warn("simulator binary not found (--springblock); schematics need its pattern builder")
fig = style.plt.figure(figsize=(7.0, 6.4))
gs = fig.add_gridspec(4, 1, height_ratios=(1.5, 1.5, 0.7, 0.7))
ax_a, ax_b, ax_c1, ax_c2 = (fig.add_subplot(gs[i]) for i in range(4))
for ax, spec, n, title in ((ax_a, "smooth", 10, "(a) chain of blocks on a smooth plane"),
                           (ax_b, "periodic:2,2", 14, "(b) grooved chain, periodic:2,2: groove blocks lose contact")):
    got = style.pattern_mask(exe, spec, n)
    if got:
        chain(ax, got[0], title)
    else:
        ax.set_title(title, loc="left")
        style.not_produced(ax, "pattern mask")
# The caption's lambda = 1/3, 1/15 at N = 120 gives 40,8; its third level 1/75 is not a whole
# number of blocks, so the tables' smallest level (1 block) is drawn instead.
hierarchy(ax_c1, exe, [40, 8], 120, r"(c) two levels, $\lambda_1=1/3$, $\lambda_2=1/15$")
hierarchy(ax_c2, exe, [40, 8, 1], 120, r"    three levels, $\lambda_1=1/3$, $\lambda_2=1/15$, $\lambda_3=1/120$")
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, None, f"masks from {exe or 'springblock'} pattern")
style.save(fig, a.out, "schematics")
