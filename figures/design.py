#!/usr/bin/python3
"""A design query's answer (`springblock design --out RESULT.json`) in the (mu_s, mu_d) plane:
every candidate the search evaluated at its screening estimate (those run only to their first
slip have no mu_d: they are the rug of ticks along the mu_s axis), the verified answers with
their fresh mu_s and mu_d +- 1 SEM, the target region, and the paper's published surfaces of
the same chain (tables/published_tab_pat*.tsv) for orientation.

Usage: python3 -m figures.design RESULT.json --out DIR [--name design_query]"""
import argparse
import json
import math
from pathlib import Path

from figures import style


def finite(x):
    return isinstance(x, (int, float)) and math.isfinite(x)


def interval(t, key, lo_default, hi_default):
    iv = (t or {}).get(key)
    if not iv:
        return None
    lo = iv["lo"] if finite(iv.get("lo")) else lo_default
    hi = iv["hi"] if finite(iv.get("hi")) else hi_default
    return lo, hi


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("result", help="JSON written by springblock design --out")
    p.add_argument("--out", required=True, help="directory for the PNG and PDF")
    p.add_argument("--name", default="design_query", help="file name without extension")
    a = p.parse_args()
    Path(a.out).mkdir(parents=True, exist_ok=True)
    doc = json.load(open(a.result))
    ev = doc.get("evaluated", [])
    fig, ax = style.plt.subplots(figsize=(5.6, 4.4))
    both = [e for e in ev if finite(e.get("mu_s")) and finite(e.get("mu_d"))]
    only_s = [e["mu_s"] for e in ev if finite(e.get("mu_s")) and not finite(e.get("mu_d"))]
    if both:
        ax.scatter([e["mu_s"] for e in both], [e["mu_d"] for e in both], s=6, c="#999999", alpha=0.6,
                   label=f"screened, mu_s and mu_d ({len(both)})")
    best = [b for b in doc.get("best", []) if finite(b["mu_s"].get("mean")) and finite(b["mu_d"].get("mean"))]
    ys = [b["mu_d"]["mean"] for b in best] + [e["mu_d"] for e in both]
    pub = [r for t in ("tab_pat0", "tab_pat1", "tab_pat2") for r in style.read_published(t)
           if r["N"] == style.dig(doc, "scene.geometry.N")
           and abs(r["L_x_cm"] - 100 * (style.dig(doc, "scene.geometry.L_x_m") or 0)) < 1e-9]
    ys += [r["mu_d"] for r in pub]
    xs = [b["mu_s"]["mean"] for b in best] + [e["mu_s"] for e in both] + only_s + [r["mu_s"] for r in pub]
    x0, x1 = (min(xs) - 0.02, max(xs) + 0.02) if xs else (0.4, 1.0)
    y0, y1 = (min(ys) - 0.01, max(ys) + 0.01) if ys else (0.45, 0.7)
    t = doc.get("target", {})
    xs_t, yd_t = interval(t, "mu_s", x0, x1), interval(t, "mu_d", y0, y1)
    rx = xs_t or (x0, x1)
    ry = yd_t or (y0, y1)
    if xs_t or yd_t:
        w = max(rx[1] - rx[0], 0.002)
        h = max(ry[1] - ry[0], 0.001)
        ax.add_patch(style.matplotlib.patches.Rectangle((rx[0] - (w - (rx[1] - rx[0])) / 2, ry[0] - (h - (ry[1] - ry[0])) / 2),
                                                        w, h, fc="#E69F00", alpha=0.25, ec="#E69F00",
                                                        label="target " + ", ".join(
                                                            f"{k} {t[k]['text']}" for k in ("mu_s", "mu_d") if t.get(k))))
    if pub:
        ax.scatter([r["mu_s"] for r in pub], [r["mu_d"] for r in pub], marker="s", s=16, facecolors="none",
                   edgecolors=style.PUBLISHED_COLOUR, lw=0.7, label="paper's surfaces (published)")
    for i, b in enumerate(best):
        ax.errorbar(b["mu_s"]["mean"], b["mu_d"]["mean"], xerr=b["mu_s"]["sem"] or 0, yerr=b["mu_d"]["sem"] or 0,
                    fmt="o" if b["meets_target"] else "x", ms=5, color=style.COLOURS[0 if b["meets_target"] else 1],
                    label=("verified (fresh reps), meets target" if b["meets_target"] else "verified, misses target")
                    if i == 0 or b["meets_target"] != best[i - 1]["meets_target"] else None)
        ax.annotate(b["pattern"].replace("periodic:", "p:"), (b["mu_s"]["mean"], b["mu_d"]["mean"]), fontsize=6,
                    xytext=(4, 3), textcoords="offset points")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    if only_s:  # mu_s only (run to the first slip): a rug at the bottom
        ax.plot(only_s, [y0 + 0.004 * (y1 - y0)] * len(only_s), "|", color="#BBBBBB", ms=6, alpha=0.5,
                label=f"screened, mu_s only ({len(only_s)})")
    ax.set_xlabel("macroscopic $\\mu_s$")
    ax.set_ylabel("macroscopic $\\mu_d$")
    n = len(ev)
    ax.set_title(f"design: {style.dig(doc, 'search.family', '?')} family, {n} candidates evaluated, "
                 f"feasible = {doc.get('feasible')}")
    ax.legend(loc="upper left", fontsize=6)
    style.stamp(fig, __file__, doc, note=f"seed {doc.get('seed')}, {doc.get('wall_seconds', 0):.0f} s")
    fig.tight_layout()
    style.save(fig, a.out, a.name)


if __name__ == "__main__":
    main()
