"""Shared look and plumbing for every figure script.

One place decides fonts, colours, the footer stamp and how results are read, so that all
figures look alike and a change of the data contract is made once. Reading is defensive on
purpose: a reproduction target that failed or was skipped must give a figure that says
"not produced", never a traceback that hides the other figures.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # off-screen: figures are built in CI and over ssh
import matplotlib.pyplot as plt  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
TABLES = REPO / "tables"

# Colour-blind safe (Okabe-Ito); ours vs published must stay distinguishable in greyscale,
# so they also differ by marker fill.
COLOURS = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#F0E442", "#000000"]
PUBLISHED_COLOUR = "#555555"

plt.rcParams.update({
    "font.size": 9,
    "axes.titlesize": 9,
    "axes.labelsize": 9,
    "legend.fontsize": 7,
    "xtick.labelsize": 8,
    "ytick.labelsize": 8,
    "axes.prop_cycle": matplotlib.cycler(color=COLOURS),
    "figure.dpi": 150,
    "savefig.dpi": 150,
    "pdf.fonttype": 42,  # embed TrueType so the PDF text stays searchable
    "axes.grid": True,
    "grid.alpha": 0.25,
})


def warn(msg):
    print(f"[{Path(sys.argv[0]).name}] {msg}", file=sys.stderr)


def arguments(description, extra=None):
    """Common command line: every script reads --data and writes into --out."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--data", required=True, help="directory holding <target>/<target>.json")
    p.add_argument("--out", required=True, help="directory for the PNG and PDF")
    p.add_argument("--springblock", default=None,
                   help="a program with the simulator's `pattern` command (springblock_pattern or springblock), "
                        "for the masks; default: $SPRINGBLOCK_EXE, else DATA/../src/springblock_pattern")
    if extra:
        extra(p)
    a = p.parse_args()
    a.data, a.out = Path(a.data), Path(a.out)
    a.out.mkdir(parents=True, exist_ok=True)
    return a


# ---------------------------------------------------------------- reading results

def load_study(data_dir, study):
    """An optional study's JSON (`make studies`): the build tree's copy if it ran there, else the
    committed one under paper/data/. None (with a message) when neither exists."""
    path = Path(data_dir) / study / f"{study}.json"
    if not path.is_file():
        path = Path(__file__).resolve().parent.parent / "paper" / "data" / f"{study}.json"
    if not path.is_file():
        warn(f"{study}: optional study not run (make studies) and not committed")
        return None
    with open(path) as f:
        return json.load(f)


def load_target(data_dir, target):
    """The target's JSON as a dict, or None (with a message) if it is missing or unreadable."""
    path = Path(data_dir) / target / f"{target}.json"
    if not path.is_file():
        warn(f"{target}: not produced ({path} missing)")
        return None
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        warn(f"{target}: unreadable {path}: {e}")
        return None


def dig(obj, dotted, default=None):
    """obj['a']['b']['c'] for 'a.b.c', or default if any level is missing."""
    for key in dotted.split("."):
        if not isinstance(obj, dict) or key not in obj:
            return default
        obj = obj[key]
    return obj


def scenes(doc):
    return list(doc.get("scenes") or []) if isinstance(doc, dict) else []


def stat(scene, name):
    """(mean, sem) of a result statistic; NaNs when absent so plotting simply skips it."""
    m = dig(scene, f"result.{name}.mean")
    s = dig(scene, f"result.{name}.sem")
    return (float(m) if m is not None else math.nan, float(s) if s is not None else math.nan)


def pattern_of(scene):
    return dig(scene, "result.scene.pattern", None) or dig(scene, "x.pattern", "?")


def n_of(scene):
    return dig(scene, "result.scene.geometry.N", None) or dig(scene, "x.N", None)


def commit_and_tier(doc):
    if not isinstance(doc, dict):
        return "unknown", "unknown"
    return dig(doc, "provenance.commit", "unknown"), doc.get("tier", "unknown")


# ---------------------------------------------------------------- published numbers

def read_published(table):
    """Rows of tables/published_<table>.tsv as dicts with numbers converted."""
    rows = []
    with open(TABLES / f"published_{table}.tsv") as f:
        lines = [ln for ln in f if not ln.startswith("#") and ln.strip()]
    for r in csv.DictReader(lines, delimiter="\t"):
        for k in ("mu_s", "mu_s_err", "mu_d", "mu_d_err", "L_x_cm"):
            r[k] = float(r[k])
        for k in ("N", "S_over_Stot_num", "S_over_Stot_den"):
            r[k] = int(r[k])
        rows.append(r)
    return rows


def published_lookup():
    """(pattern, N) -> published row, over all three tables; first printing wins."""
    out = {}
    for t in ("tab_pat0", "tab_pat1", "tab_pat2"):
        for r in read_published(t):
            out.setdefault((r["pattern"], r["N"]), r)
    return out


# ---------------------------------------------------------------- contact masks

def springblock_exe(args):
    # springblock_pattern first: reproduce-all builds it, not the whole command-line tool.
    cands = [args.springblock, os.environ.get("SPRINGBLOCK_EXE")]
    for src in (Path(args.data).resolve().parent / "src", REPO / "build" / "src"):
        cands += [str(src / "springblock_pattern"), str(src / "springblock")]
    for c in cands:
        if c and os.access(c, os.X_OK):
            return c
    return None


def pattern_mask(exe, spec, n):
    """Mask from the simulator's own pattern builder (never re-implemented here, so the
    drawing cannot disagree with what was simulated). None if unavailable."""
    if not exe or spec is None or n is None or str(spec).startswith("random"):
        return None
    try:
        out = subprocess.run([exe, "pattern", "--N", str(int(n)), "--pattern", str(spec)],
                             capture_output=True, text=True, check=True, timeout=30).stdout.split()
        return [int(c) for c in out[0]], float(out[1])
    except (OSError, subprocess.SubprocessError, IndexError, ValueError) as e:
        warn(f"pattern {spec} N={n}: {e}")
        return None


def draw_profile(ax, mask, y0=0.0, height=0.06, colour="black", transform_axes=True):
    """Groove profile as a strip in axes coordinates at [y0, y0+height]: pawls as a raised
    black line, grooves as a gap, i.e. the surface seen from the side."""
    if not mask:
        return
    n = len(mask)
    xs, ys = [], []
    for i, m in enumerate(mask):
        y = y0 + (height if m else 0.0)
        xs += [i / n, (i + 1) / n]
        ys += [y, y]
    ax.plot(xs, ys, color=colour, lw=0.8, transform=ax.transAxes, clip_on=False, solid_joinstyle="miter")


# ---------------------------------------------------------------- output

def stamp(fig, script, doc, note=None):
    """Footer naming the script that drew the figure, the commit and tier of its data."""
    commit, tier = commit_and_tier(doc)
    text = f"{Path(script).name}  |  data commit {commit}  |  tier {tier}"
    if note:
        text += f"  |  {note}"
    fig.text(0.995, 0.003, text, ha="right", va="bottom", fontsize=5.5, color="#777777")


def not_produced(ax, what):
    ax.text(0.5, 0.5, f"{what}\nnot produced", ha="center", va="center", transform=ax.transAxes,
            fontsize=10, color="#B00000", bbox=dict(fc="#FFF0F0", ec="#B00000"))
    ax.set_xticks([])
    ax.set_yticks([])


def save(fig, out_dir, name):
    """PNG (150 dpi) and PDF, each written to a temporary file and renamed, so a reader
    (make, the report) never sees half a figure."""
    out_dir = Path(out_dir)
    for ext in ("png", "pdf"):
        fd, tmp = tempfile.mkstemp(prefix=f".{name}.", suffix=f".{ext}", dir=out_dir)
        os.close(fd)
        try:
            fig.savefig(tmp, format=ext, dpi=150)
            os.chmod(tmp, 0o644)  # mkstemp makes it private
            os.replace(tmp, out_dir / f"{name}.{ext}")
        finally:
            if os.path.exists(tmp):
                os.unlink(tmp)
    plt.close(fig)
    print(out_dir / f"{name}.png")


def errorbar(ax, x, y, e, label=None, published=False, colour=None, **kw):
    """Ours: filled markers and a line; published: open grey squares, no line."""
    if published:
        kw = dict(fmt="s", mfc="white", mec=colour or PUBLISHED_COLOUR, ecolor=colour or PUBLISHED_COLOUR,
                  ms=4, capsize=2, lw=0.8, **kw)
    else:
        kw = dict(fmt="o-", ms=3.5, capsize=2, lw=1.0, color=colour, **kw)
    return ax.errorbar(x, y, yerr=e, label=label, **kw)


def group_by(items, key):
    """Order-preserving grouping."""
    groups = {}
    for it in items:
        groups.setdefault(key(it), []).append(it)
    return groups


def friction_label(scene):
    f = dig(scene, "result.scene.friction", {}) or {}
    try:
        return (f"$(\\mu_s)_m$={f['mu_s_mean']:g}({f['mu_s_sd']:g}), "
                f"$(\\mu_d)_m$={f['mu_d_mean']:g}({f['mu_d_sd']:g})")
    except (KeyError, TypeError, ValueError):
        return "friction ?"


# ---------------------------------------------------------------- series, stress, masks per scene
# The reproduction drivers attach the trace and the stress snapshots to the scene they belong
# to; an older draft of the contract kept them in document-level dicts keyed by label. Both are
# accepted so the figures do not depend on which one a data set was written with.

def all_series(doc):
    """[(label, series dict, scene or None)] in document order."""
    out = []
    for s in scenes(doc):
        if isinstance(s.get("series"), dict) and s["series"].get("t_s"):
            out.append((s.get("label", s.get("id", "?")), s["series"], s))
    if not out and isinstance(doc, dict) and isinstance(doc.get("series"), dict):
        by_label = {s.get("label"): s for s in scenes(doc)}
        for label, ser in doc["series"].items():
            out.append((label, ser, by_label.get(label)))
    return out


def all_stress(doc):
    """[(label, snapshot {t_s, f_over_Fn, sigma_over_P, contact}, scene or None)]."""
    out = []
    for s in scenes(doc):
        snaps = s.get("stress")
        if isinstance(snaps, dict):
            snaps = [snaps]
        for snap in snaps or []:
            snap = dict(snap)
            if not snap.get("contact") and s.get("contact_mask"):
                snap["contact"] = [int(c) for c in s["contact_mask"]]
            out.append((s.get("label", s.get("id", "?")), snap, s))
    if not out and isinstance(doc, dict) and isinstance(doc.get("stress"), dict):
        by_label = {s.get("label"): s for s in scenes(doc)}
        for label, snap in doc["stress"].items():
            out.append((label, snap, by_label.get(label)))
    return out


def scene_mask(scene, exe):
    """(mask, S/S_tot) of a scene: the mask stored with the result if there is one, else the
    simulator's pattern builder."""
    m = scene.get("contact_mask") if isinstance(scene, dict) else None
    if m:
        mask = [int(c) for c in m]
        return mask, sum(mask) / len(mask)
    return pattern_mask(exe, pattern_of(scene) if scene else None, n_of(scene) if scene else None)
