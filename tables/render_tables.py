#!/usr/bin/python3
"""Published against reproduced numbers for the paper's three appendix tables, as Markdown and
HTML fragments (tab_pat0.md / .html, ...), also imported by paper/build_report.py.

Every number and verdict comes from the checker's summary.json (read through
tools/summary_schema.py), so the tables and the check cannot disagree; without a summary there
is no table. The one thing the summary does not carry is the simulated contact fraction S/S_tot,
read from the table target's document and flagged where it differs from the printed one."""
import argparse
import html
import json
import os
import sys
import tempfile
from fractions import Fraction
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from tools import summary_schema as schema  # noqa: E402
from tools.reproduction.inputs import read_tsv  # noqa: E402  (one reader of the tables)

HERE = Path(__file__).resolve().parent

TABLES = ("tab_pat0", "tab_pat1", "tab_pat2")
CAPTIONS = {
    "tab_pat0": "Table tpat0: smooth surface and single-level periodic patterns, N = 360, L_x = 7.2 cm",
    "tab_pat1": "Table tpat1: one-, two- and three-level hierarchical patterns, N = 120, L_x = 2.4 cm",
    "tab_pat2": "Table tpat2: one-, two- and three-level hierarchical patterns, N = 360, L_x = 7.2 cm",
}
NOT_MEASURED = "–"  # a cell of a missing result (its verdict cell says "missing" and why)

# The columns of one published number, the same in every table of the report: the published and
# reproduced values, the difference, and the two thresholds behind the verdict.
DETAIL_HEAD = ["coef", "published", "ours", "n", "d", "z", "k", "k·σ (detect)", "t95·σ (equiv.)", "Δ", "verdict"]
VERDICT_CLASS = {"agree": "ok", "disagree_known": "known", "disagree_new": "bad", "not_resolved": "unres",
                 "missing": "bad", "holds": "ok", "fails_known": "known", "fails_new": "bad"}


def verdict_text(rec):
    return rec["verdict"] + (" STALE" if rec["stale"] else "")


def detail_cells(rec):
    """The cells of DETAIL_HEAD for one row record of the summary."""
    pub = f"{rec['published']:.3f} ± {rec['err']:.3f}"
    if rec["verdict"] == "missing":
        return [rec["coef"], pub] + [NOT_MEASURED] * 7 + [f"{rec['delta']:.2f}", verdict_text(rec)]
    return [rec["coef"], pub, f"{rec['ours']:.4f} ± {rec['sem']:.4f}", str(rec["n"]), f"{rec['d']:+.4f}",
            f"{rec['z']:+.2f}", f"{rec['k']:.2f}", f"{rec['detection']:.4f}", f"{rec['equivalence']:.4f}",
            f"{rec['delta']:.2f}", verdict_text(rec)]


def contact_fractions(data, table):
    """row_id -> simulated S/S_tot, or None when the target was not produced."""
    p = Path(data) / table / f"{table}.json"
    if not p.is_file():
        return None
    doc = json.loads(p.read_text())
    return {s["id"]: Fraction(s["result"]["contact_fraction"]).limit_denominator(1000) for s in doc["scenes"]}


HEAD = ["row", "pattern", "S/S_tot printed", "S/S_tot ours"] + DETAIL_HEAD


def table_lines(data, table, summary):
    """[(cells, flagged)] per published number of one table, in the printed order."""
    recs = {(r["row_id"], r["coef"]): r for r in summary["rows"]}
    fractions = contact_fractions(data, table)
    out = []
    for r in read_tsv(HERE / f"published_{table}.tsv"):
        printed = Fraction(int(r["S_over_Stot_num"]), int(r["S_over_Stot_den"]))
        ours = None if fractions is None else fractions[r["row_id"]]
        flagged = ours is not None and ours != printed
        s_ours = "not produced" if ours is None else str(ours) + (" ⚑" if flagged else "")
        for coef in ("mu_s", "mu_d"):
            out.append(([r["row_id"], r["pattern"], str(printed), s_ours] + detail_cells(recs[(r["row_id"], coef)]),
                        flagged))
    return out


def note(lines):
    flagged = sorted({cells[0] for cells, f in lines if f})
    if not flagged:
        return ""
    return ("⚑ simulated S/S_tot differs from the printed value: " + ", ".join(flagged) +
            " (tables/README.md: the printed fraction is not reachable with whole subdivision units).")


def markdown(table, lines):
    out = [f"**{CAPTIONS[table]}**", "", "| " + " | ".join(HEAD) + " |", "|" + "|".join("---" for _ in HEAD) + "|"]
    out += ["| " + " | ".join(cells) + " |" for cells, _ in lines]
    n = note(lines)
    return "\n".join(out + ([""] + [n] if n else [])) + "\n"


def cell_html(text, cls=""):
    return f'<td class="{cls}">{html.escape(text)}</td>' if cls else f"<td>{html.escape(text)}</td>"


def html_table(table, lines):
    verdict_col, s_col = HEAD.index("verdict"), HEAD.index("S/S_tot ours")
    h = [f'<table class="cmp"><caption>{html.escape(CAPTIONS[table])}</caption>',
         "<thead><tr>" + "".join(f"<th>{html.escape(c)}</th>" for c in HEAD) + "</tr></thead><tbody>"]
    for cells, flagged in lines:
        tds = [cell_html(c, VERDICT_CLASS[c.split()[0]] if i == verdict_col else
                         "flag" if i == s_col and flagged else "") for i, c in enumerate(cells)]
        h.append("<tr>" + "".join(tds) + "</tr>")
    h.append("</tbody></table>")
    n = note(lines)
    if n:
        h.append(f'<p class="note">{html.escape(n)}</p>')
    return "\n".join(h) + "\n"


def render(data, summary):
    """{table: {"md", "html"}} for every table."""
    out = {}
    for t in TABLES:
        lines = table_lines(data, t, summary)
        out[t] = {"md": markdown(t, lines), "html": html_table(t, lines)}
    return out


def write_atomic(path, text):
    fd, tmp = tempfile.mkstemp(dir=Path(path).parent, prefix="." + Path(path).name)
    with os.fdopen(fd, "w") as f:
        f.write(text)
    os.chmod(tmp, 0o644)  # mkstemp makes it private
    os.replace(tmp, path)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--data", required=True, help="build/reproduce (summary.json, tab_pat*/tab_pat*.json)")
    p.add_argument("--out", required=True, help="directory for tab_pat*.md and tab_pat*.html")
    a = p.parse_args()
    try:
        summary = schema.load(Path(a.data) / "summary.json")
    except schema.SummaryError as e:
        sys.exit(f"render_tables: {e}")
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    for t, r in render(a.data, summary).items():
        write_atomic(out / f"{t}.md", r["md"])
        write_atomic(out / f"{t}.html", r["html"])
        print(out / f"{t}.md", schema.format_counts(schema.target_counts(summary, t)))


if __name__ == "__main__":
    main()
