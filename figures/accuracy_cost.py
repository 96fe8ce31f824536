#!/usr/bin/python3
"""Work-precision diagram: numerical error of mu_s / mu_d against wall time (a) and against
right-hand-side evaluations (b), log-log, one line per integration method. RHS evaluations are
machine independent; wall time is what a user pays. A method or setting that failed is named
in the legend, not dropped, so a missing line is never mistaken for a method that was not tried."""
import math

import style


def method(s):
    return str(style.dig(s, "x.method") or style.dig(s, "result.method") or "?")


def setting(s):
    for k in ("setting", "dt", "tol"):
        v = style.dig(s, f"x.{k}")
        if v is not None:
            return v
    return style.dig(s, "result.dt") if method(s) == "rk4" else style.dig(s, "result.tol")


def error(s):
    """Largest absolute error against the reference, wherever the target put it."""
    for path in ("x.error", "error", "result.error", "x.err_max", "result.err_max"):
        v = style.dig(s, path)
        if isinstance(v, dict):
            v = max((abs(x) for x in v.values() if isinstance(x, (int, float))), default=None)
        if isinstance(v, (int, float)) and math.isfinite(v):
            return abs(v)
    return None


def cost(s, what):
    if what == "wall":
        return style.dig(s, "x.wall_seconds") or style.dig(s, "result.wall_seconds")
    return style.dig(s, "x.rhs_evals") or style.dig(s, "result.rhs_evals_total")


def failed(s):
    return bool(s.get("failed")) or s.get("status") not in (None, "ok") or error(s) is None


a = style.arguments(__doc__)
doc = style.load_target(a.data, "accuracy_cost")
sc = style.scenes(doc)
fig, (pa, pb) = style.plt.subplots(1, 2, figsize=(7.0, 3.3), sharey=True)
pa.set_title("(a)", loc="left")
pb.set_title("(b)", loc="left")
if not sc:
    style.not_produced(pa, "accuracy_cost")
    style.not_produced(pb, "accuracy_cost")
else:
    for i, (m, items) in enumerate(style.group_by(sc, method).items()):
        ok = [s for s in items if not failed(s)]
        bad = [s for s in items if failed(s)]
        c = style.COLOURS[i % len(style.COLOURS)]
        label = m + (f" (failed: {', '.join(f'{setting(s):g}' if isinstance(setting(s), (int, float)) else str(setting(s)) for s in bad)})" if bad else "")
        for ax, what in ((pa, "wall"), (pb, "rhs")):
            pts = sorted((cost(s, what), error(s), setting(s)) for s in ok if cost(s, what))
            if pts:
                ax.plot([p[0] for p in pts], [max(p[1], 1e-16) for p in pts], "o-", color=c, ms=3.5, label=label)
                for p in pts:
                    ax.annotate(f"{p[2]:g}" if isinstance(p[2], (int, float)) else str(p[2]), (p[0], max(p[1], 1e-16)),
                                fontsize=5.5, xytext=(3, 3), textcoords="offset points", color=c)
            elif ax is pa:
                ax.plot([], [], "x", color=c, label=label + " (no successful run)")
    for ax in (pa, pb):
        ax.set_xscale("log")
        ax.set_yscale("log")
    pa.set_xlabel("wall time (s)")
    pb.set_xlabel("right-hand-side evaluations")
    pa.set_ylabel(r"max |error| of $(\mu_s)_M$, $(\mu_d)_M$")
    pa.legend(fontsize=6)
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, "labels: step dt (rk4) or tolerance (event)")
style.save(fig, a.out, "accuracy_cost")
