#!/usr/bin/python3
"""Slip events (avalanches) of the paper's chain (N = 360, L_x = 7.2 cm), smooth and periodic:10,10:
(a) how many contact blocks slid in an event, (b) its total slip (the sum over its block-slip
episodes of the distance slid). Events per repetition in logarithmic bins, divided by the bin's
width, mean over the repetitions with its standard error; in (a) the events that set every contact
block sliding (the chain's stick-slip cycles) are the separate points at the right end.
Data: the optional study `slip_events` (`make studies`; committed as paper/data/slip_events.json)."""
import math

from figures import style

a = style.arguments(__doc__)
doc = style.load_study(a.data, "slip_events")
fig, axes = style.plt.subplots(1, 2, figsize=(8.6, 3.7))
scenes = [s for s in style.scenes(doc) if s.get("slip_event_bins")] if doc else []


def mean_sem(rows):
    """Mean over repetitions of each column, and its standard error."""
    n = len(rows)
    means = [sum(col) / n for col in zip(*rows)]
    sems = [math.sqrt(sum((x - m) ** 2 for x in col) / (n - 1) / n) if n > 1 else 0.0
            for col, m in zip(zip(*rows), means)]
    return means, sems


def positive(xs, ys, es):
    """The bins with events (a log axis has no zero)."""
    kept = [(x, y, e) for x, y, e in zip(xs, ys, es) if y > 0]
    return [k[0] for k in kept], [k[1] for k in kept], [min(k[2], 0.999 * k[1]) for k in kept]


if not scenes:
    for ax in axes:
        style.not_produced(ax, "slip_events")
else:
    for c, s in enumerate(scenes):
        b = s["slip_event_bins"]
        colour = style.COLOURS[c]
        # (a) size in blocks: bin [e_k, e_k+1) holds e_k+1 - e_k sizes; centre at the geometric mean.
        edges = b["size_edges"]
        width = [hi - lo for lo, hi in zip(edges, edges[1:])]
        centre = [math.sqrt(lo * (hi - 1)) for lo, hi in zip(edges, edges[1:])]
        m, e = mean_sem(b["size_counts"])
        x, y, err = positive(centre, [v / w for v, w in zip(m, width)], [v / w for v, w in zip(e, width)])
        axes[0].errorbar(x, y, yerr=err, marker="o", ms=3.5, lw=1.2, capsize=2, color=colour,
                         label=f"{s['label']} ({b['n_contact']} contact blocks)")
        sm, se = mean_sem([[v] for v in b["spanning"]])
        axes[0].errorbar([b["n_contact"]], sm, yerr=se, marker="s", ms=5, mfc="white", mew=1.3, capsize=2,
                         color=colour, ls="none")
        # (b) total slip: per decade.
        edges = b["slip_edges_m"]
        decades = [math.log10(hi / lo) for lo, hi in zip(edges, edges[1:])]
        centre = [math.sqrt(lo * hi) for lo, hi in zip(edges, edges[1:])]
        m, e = mean_sem(b["slip_counts"])
        x, y, err = positive(centre, [v / d for v, d in zip(m, decades)], [v / d for v, d in zip(e, decades)])
        n_events = sum(map(sum, b["slip_counts"])) / len(b["slip_counts"])
        axes[1].errorbar(x, y, yerr=err, marker="o", ms=3.5, lw=1.2, capsize=2, color=colour,
                         label=f"{s['label']}: {n_events:.0f} events per repetition")
    axes[0].set_xscale("log")
    axes[0].set_yscale("log")
    axes[0].set_xlabel("contact blocks that slid in the event")
    axes[0].set_ylabel("events per repetition per block")
    axes[0].set_title("(a) event size; squares: every contact block slid", loc="left")
    axes[0].legend(loc="lower left")
    axes[1].set_xscale("log")
    axes[1].set_yscale("log")
    axes[1].set_xlabel("total slip of the event [m]")
    axes[1].set_ylabel("events per repetition per decade")
    axes[1].set_title("(b) total slip", loc="left")
    bottom, top = axes[1].get_ylim()
    axes[1].set_ylim(bottom / 20, top)  # room below the data for the legend
    axes[1].legend(loc="lower center")
reps = len(scenes[0]["slip_event_bins"]["spanning"]) if scenes else "?"
style.stamp(fig, __file__, doc, note=f"{reps} repetitions per surface, mean +- standard error")
fig.tight_layout()
style.save(fig, a.out, "slip_events")
