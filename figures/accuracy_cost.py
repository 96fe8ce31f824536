#!/usr/bin/python3
"""Work-precision diagram of the first macroscopic peak (N = 360, periodic:10,10, per-seed error of
mu_s against the converged event reference): error against wall time (a) and against
right-hand-side evaluations (b), log-log, one line per integration method and stepper (the event method's
exact stepper evaluates no right-hand side: in panel (b) its error level is a dashed line). RHS evaluations are
machine independent; wall time is what a user pays. The reference's own convergence (tol 1e-11
against 1e-12) is drawn as a horizontal line: errors below it are not resolved. Settings that
failed are named in the legend, not dropped. (c): cost of the event method per simulated second
against the number of blocks N at the paper's block size, log-log, one line per surface with the
power law fitted by the driver (exponent and its standard error in the legend). Data:
accuracy_cost.json, blocks `work_precision` and `scaling`."""
from figures import style


def work_precision_panels(pa, pb, doc, extra):
    # RK4 below the paper's step is the optional study rk4_refinement: drawn with the same method's
    # points (same scenes, seeds and reference), its commit named in the stamp.
    rows = [r for d in (doc, extra) for r in (d or {}).get("work_precision", [])
            if r.get("study") == "first_peak" and not (d is extra and (r.get("reference") or r.get("reference_check")))]
    failed = [f for f in (doc or {}).get("failed", []) if f.get("study") == "first_peak"]
    if not rows:
        style.not_produced(pa, "accuracy_cost")
        style.not_produced(pb, "accuracy_cost")
        return
    floor = [r["error"] for r in rows if r.get("reference_check")]
    # One line per method and stepper: the event method's exact and Dormand-Prince steppers are
    # different integrators (drawn as one line, their labels fell on top of each other).
    def line_of(r):
        return r["method"] + (f" ({r['stepper']})" if r.get("stepper") else "")

    def line_of_failed(f):
        # Settings are named "rk4 h=...", "dopri5 tol=..." or "exact tol=..." (reproduce/work_precision.cpp).
        first = f["setting"].split()[0]
        return first if first == "rk4" else f"event ({first})"

    lines = sorted({line_of(r) for r in rows} | {line_of_failed(f) for f in failed})
    for i, m in enumerate(lines):
        c = style.COLOURS[i % len(style.COLOURS)]
        bad = [f["setting"] for f in failed if line_of_failed(f) == m]
        label = m + (f" (failed: {', '.join(bad)})" if bad else "")
        pts = [r for r in rows if line_of(r) == m and not r.get("reference") and not r.get("reference_check")
               and r.get("error", 0) > 0]
        for ax, key in ((pa, "wall_seconds"), (pb, "rhs_evals_total")):
            p = sorted((r for r in pts if r[key] > 0), key=lambda r: r[key])
            if p:
                ax.plot([r[key] for r in p], [r["error"] for r in p], "o-", color=c, ms=3.5, label=label)
                # Settings whose points coincide (the exact stepper has no step-size error, so its
                # tolerance does not move it) share one label instead of printing over each other.
                tags = {}
                for r in p:
                    tag = f"h={r['dt_s']:g}" if r["method"] == "rk4" else f"tol={r['tol']:g}"
                    spot = next((q for q in tags if abs(q[0] / r[key] - 1) < 0.5 and abs(q[1] / r["error"] - 1) < 0.5),
                                (r[key], r["error"]))
                    tags.setdefault(spot, []).append(tag)
                # Slanted labels: on these falling curves, labels written level from neighbouring
                # points run into each other; slanted ones stay parallel.
                for (x, y), names in tags.items():
                    ax.annotate(", ".join(names), (x, y), fontsize=5.5, xytext=(3, 3), textcoords="offset points",
                                color=c, rotation=35, rotation_mode="anchor")
            elif ax is pb and pts:
                # No right-hand side evaluated: no point on this axis; its error level is drawn
                # across the panel so the comparison is still there.
                err = max(r["error"] for r in pts)
                ax.axhline(err, color=c, lw=1.0, ls="--", label=f"{m}: no RHS evaluations")
            elif ax is pa:
                ax.plot([], [], "x", color=c, label=label + " (no successful run)")
    for ax in (pa, pb):
        if floor and floor[0] > 0:
            ax.axhline(floor[0], color="0.5", lw=0.8, ls=":", label="reference check (tol 1e-11)" if ax is pa else None)
        ax.set_xscale("log")
        ax.set_yscale("log")
    pa.set_xlabel("wall time (s)")
    pb.set_xlabel("right-hand-side evaluations")
    pa.set_ylabel(r"max over seeds |error| of first-peak $(\mu_s)_M$")
    pa.legend(fontsize=6)
    pb.legend(fontsize=6, loc="center right", bbox_to_anchor=(1.0, 0.3))


def fit_label(pattern, fit):
    b, se = fit.get("exponent"), fit.get("exponent_se")
    if b is None:
        return f"{pattern} (no fit)"
    return f"{pattern}: $N^{{{b:.2f} \\pm {se:.2f}}}$" if se is not None else f"{pattern}: $N^{{{b:.2f}}}$"


def scaling_panel(ax, doc):
    block = (doc or {}).get("scaling")
    if not block or not block.get("surfaces"):
        style.not_produced(ax, "accuracy_cost (scaling)")
        return
    for i, s in enumerate(block["surfaces"]):
        c = style.COLOURS[i % len(style.COLOURS)]
        pts = [p for p in s["points"] if p.get("cpu_s_per_simulated_s") and "excluded" not in p]
        if not pts:
            continue
        n = [p["N"] for p in pts]
        ax.plot(n, [p["cpu_s_per_simulated_s"] for p in pts], "o", color=c, ms=4, label=fit_label(s["pattern"], s["fit"]))
        f = s["fit"]
        if f.get("exponent") is not None:
            ax.plot([min(n), max(n)], [f["prefactor"] * x ** f["exponent"] for x in (min(n), max(n))], "-", color=c, lw=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("blocks N (block size fixed, L_x = N x 0.2 mm)")
    ax.set_ylabel("CPU s per simulated s")
    reps = f"{block['reps']} repetition" + ("" if block["reps"] == 1 else "s")
    ax.set_title(f"(c) event method, tol {block['tol']:g}, {block['duration_s']:g} s simulated, {reps} per point",
                 loc="left")
    ax.legend(fontsize=6, title="fitted cost", title_fontsize=6)


a = style.arguments(__doc__)
doc = style.load_target(a.data, "accuracy_cost")
fig = style.plt.figure(figsize=(7.0, 6.4))
grid = fig.add_gridspec(2, 2)
pa = fig.add_subplot(grid[0, 0])
pb = fig.add_subplot(grid[0, 1], sharey=pa)
pc = fig.add_subplot(grid[1, :])
pa.set_title("(a)", loc="left")
pb.set_title("(b)", loc="left")
extra = style.load_study(a.data, "rk4_refinement")
work_precision_panels(pa, pb, doc, extra)
scaling_panel(pc, doc)
fig.tight_layout(rect=(0, 0.03, 1, 1))
note = "(a, b) first macroscopic peak, N = 360, periodic:10,10"
if extra:
    note += f"; RK4 h < 1e-7 s from rk4_refinement at {extra['provenance']['commit']}"
style.stamp(fig, __file__, doc, note)
style.save(fig, a.out, "accuracy_cost")
