#!/usr/bin/python3
"""Published against reproduced numbers for the paper's three appendix tables, as Markdown
and HTML fragments (tab_pat0.md / .html, ...), also imported by paper/build_report.py.

Verdicts come from the check tool's summary.tsv, so the tables and the check can never
disagree; only when that file is missing are z values recomputed here, marked "unchecked".
S/S_tot is shown printed and simulated, and flagged where the two differ."""
import argparse
import csv
import html
import json
import math
import os
import tempfile
from fractions import Fraction
from pathlib import Path

HERE = Path(__file__).resolve().parent
TABLES = ("tab_pat0", "tab_pat1", "tab_pat2")
CAPTIONS = {
    "tab_pat0": "Table tpat0: smooth surface and single-level periodic patterns, N = 360, L_x = 7.2 cm",
    "tab_pat1": "Table tpat1: one-, two- and three-level hierarchical patterns, N = 120, L_x = 2.4 cm",
    "tab_pat2": "Table tpat2: one-, two- and three-level hierarchical patterns, N = 360, L_x = 7.2 cm",
}


def read_tsv(path):
    with open(path) as f:
        lines = [ln for ln in f if ln.strip() and not ln.startswith("#")]
    return list(csv.DictReader(lines, delimiter="\t"))


def fnum(v):
    try:
        x = float(v)
        return x if math.isfinite(x) else math.nan
    except (TypeError, ValueError):
        return math.nan


def load_summary(data):
    p = Path(data) / "summary.tsv"
    if not p.is_file():
        return None
    return {(r["row_id"], r["coef"]): r for r in read_tsv(p)}


def load_ours(data, table):
    """row_id -> scene of build/reproduce/<table>/<table>.json, or None if not produced."""
    p = Path(data) / table / f"{table}.json"
    if not p.is_file():
        return None
    try:
        doc = json.loads(p.read_text())
    except ValueError:
        return None
    out = {}
    for s in doc.get("scenes") or []:
        rid = (s.get("x") or {}).get("row_id") or s.get("id")
        out[rid] = s
    return out


def fmt(m, e, digits=3):
    if not math.isfinite(m):
        return "–"
    return f"{m:.{digits}f} ± {e:.{digits}f}" if math.isfinite(e) else f"{m:.{digits}f}"


def rows_of(data, table, summary):
    """One dict per published row with everything the renderers need."""
    ours = load_ours(data, table)
    out = []
    for r in read_tsv(HERE / f"published_{table}.tsv"):
        rid = r["row_id"]
        s = (ours or {}).get(rid)
        printed = Fraction(int(r["S_over_Stot_num"]), int(r["S_over_Stot_den"]))
        cf = (s or {}).get("result", {}).get("contact_fraction")
        sim = Fraction(cf).limit_denominator(1000) if isinstance(cf, (int, float)) else None
        row = {"row_id": rid, "pattern": r["pattern"], "S_printed": printed, "S_ours": sim,
               "S_differs": sim is not None and sim != printed, "produced": s is not None}
        for c in ("mu_s", "mu_d"):
            pub, err = fnum(r[c]), fnum(r[c + "_err"])
            res = ((s or {}).get("result") or {}).get(c) or {}
            m, sem = fnum(res.get("mean")), fnum(res.get("sem"))
            chk = (summary or {}).get((rid, c))
            if chk:
                z, verdict = fnum(chk.get("z")), chk.get("verdict", "?")
                if not math.isfinite(m):
                    m, sem = fnum(chk.get("ours")), fnum(chk.get("sem"))
            else:
                den = math.hypot(err, sem) if math.isfinite(sem) else math.nan
                z = (m - pub) / den if math.isfinite(m) and den > 0 else math.nan
                verdict = "unchecked" if math.isfinite(m) else "not produced"
            row[c] = {"pub": pub, "err": err, "ours": m, "sem": sem, "z": z, "verdict": verdict}
        out.append(row)
    return out, ours is not None


HEAD = ["row", "pattern", "S/S_tot printed", "S/S_tot ours", "mu_s published", "mu_s ours", "z",
        "verdict", "mu_d published", "mu_d ours", "z", "verdict"]


def cells(row):
    s_ours = str(row["S_ours"]) if row["S_ours"] is not None else "–"
    if row["S_differs"]:
        s_ours += " ⚑"
    out = [row["row_id"], row["pattern"], str(row["S_printed"]), s_ours]
    for c in ("mu_s", "mu_d"):
        d = row[c]
        out += [fmt(d["pub"], d["err"]), fmt(d["ours"], d["sem"]),
                f"{d['z']:+.1f}" if math.isfinite(d["z"]) else "–", d["verdict"]]
    return out


def counts(rows):
    n = {}
    for r in rows:
        for c in ("mu_s", "mu_d"):
            n[r[c]["verdict"]] = n.get(r[c]["verdict"], 0) + 1
    return n


def note(table, rows, produced):
    parts = []
    if not produced:
        parts.append(f"{table}: not produced (no {table}.json); published values only.")
    flagged = [r["row_id"] for r in rows if r["S_differs"]]
    if flagged:
        parts.append("⚑ simulated S/S_tot differs from the printed value: " + ", ".join(flagged) +
                     " (see tables/README.md: the printed fraction is not reachable with whole subdivision units).")
    return " ".join(parts)


def markdown(table, rows, produced):
    lines = [f"**{CAPTIONS[table]}**", "", "| " + " | ".join(HEAD) + " |",
             "|" + "|".join("---" for _ in HEAD) + "|"]
    lines += ["| " + " | ".join(cells(r)) + " |" for r in rows]
    n = note(table, rows, produced)
    return "\n".join(lines + ([""] + [n] if n else [])) + "\n"


VERDICT_CLASS = {"agree": "ok", "disagree": "bad", "known_deviation": "known"}


def html_table(table, rows, produced):
    h = [f'<table class="cmp"><caption>{html.escape(CAPTIONS[table])}</caption>',
         "<thead><tr>" + "".join(f"<th>{html.escape(c)}</th>" for c in HEAD) + "</tr></thead><tbody>"]
    for r in rows:
        cs = cells(r)
        tds = []
        for i, c in enumerate(cs):
            cls = ""
            if i in (7, 11):
                cls = VERDICT_CLASS.get(c, "")
            if i == 3 and r["S_differs"]:
                cls = "flag"
            tds.append(f'<td class="{cls}">{html.escape(c)}</td>' if cls else f"<td>{html.escape(c)}</td>")
        h.append("<tr>" + "".join(tds) + "</tr>")
    h.append("</tbody></table>")
    n = note(table, rows, produced)
    if n:
        h.append(f'<p class="note">{html.escape(n)}</p>')
    return "\n".join(h) + "\n"


def render(data):
    """{table: {"md", "html", "counts", "produced"}} for every table."""
    summary = load_summary(data)
    out = {}
    for t in TABLES:
        rows, produced = rows_of(data, t, summary)
        out[t] = {"md": markdown(t, rows, produced), "html": html_table(t, rows, produced),
                  "counts": counts(rows), "produced": produced, "rows": rows}
    return out


def write_atomic(path, text):
    fd, tmp = tempfile.mkstemp(dir=Path(path).parent, prefix="." + Path(path).name)
    with os.fdopen(fd, "w") as f:
        f.write(text)
    os.chmod(tmp, 0o644)  # mkstemp makes it private
    os.replace(tmp, path)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--data", required=True, help="build/reproduce (summary.tsv, tab_pat*/tab_pat*.json)")
    p.add_argument("--out", required=True, help="directory for tab_pat*.md and tab_pat*.html")
    a = p.parse_args()
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    if load_summary(a.data) is None:
        print(f"render_tables: {a.data}/summary.tsv missing: z recomputed here, verdicts marked 'unchecked'")
    for t, r in render(a.data).items():
        write_atomic(out / f"{t}.md", r["md"])
        write_atomic(out / f"{t}.html", r["html"])
        print(out / f"{t}.md", r["counts"])


if __name__ == "__main__":
    main()
