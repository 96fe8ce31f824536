#!/usr/bin/python3
"""Literate reproduction report: build/paper/report.md and a self-contained report.html.

For every figure and table, in the paper's order: the narrative written at the top of its
reproduction driver (reproduce/<target>.cpp), our figure, and published against reproduced
numbers with the deviation in sigmas and the check tool's verdict. Then the summary counts,
the open modelling choices (paper/choices.md), the sensitivity and accuracy/cost studies and
the known deviations. Every number is read from a file at build time; nothing is typed in.

The document is built once as a list of blocks and rendered twice (Markdown and HTML), so
the two outputs cannot drift apart and no Markdown converter is needed.
"""
import argparse
import base64
import csv
import html
import json
import math
import os
import re
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO / "tables"))
import render_tables  # noqa: E402

# Paper order: the model schematic, section II figures, section III figures, then the tables.
ORDER = ["schematics", "fig1", "fig_s1", "fig_s2", "fig2", "fig_p1", "fig3", "fig4", "fig5",
         "fig_p2", "fig_p3", "tab_pat0", "tab_pat1", "tab_pat2"]
TITLES = {
    "schematics": "Model schematics (figs. figmodel, figmodel2, figmodel3)",
    "fig1": "Fig. 1: friction force against time, smooth surface",
    "fig_s1": "Fig. S1: friction coefficients against N at fixed block length",
    "fig_s2": "Fig. S2: friction coefficients against K_int/K_s",
    "fig2": "Fig. 2: macroscopic mu_d against the microscopic ratio, with eq. (9)",
    "fig_p1": "Fig. P1: regular pattern, coefficients against groove size",
    "fig3": "Fig. 3: stress profiles along patterned surfaces",
    "fig4": "Fig. 4: static friction against pawl and groove size",
    "fig5": "Fig. 5: friction force against time, smooth / one level / two levels",
    "fig_p2": "Fig. P2: adding hierarchical levels under a fixed first level",
    "fig_p3": "Fig. P3: one level against two levels at equal contact fraction",
    "tab_pat0": "Table tpat0 (appendix)",
    "tab_pat1": "Table tpat1 (appendix)",
    "tab_pat2": "Table tpat2 (appendix)",
}


# ---------------------------------------------------------------- inputs

def load_json(path):
    try:
        return json.loads(Path(path).read_text())
    except (OSError, ValueError):
        return None


def read_tsv(path):
    try:
        with open(path) as f:
            lines = [ln for ln in f if ln.strip() and not ln.startswith("#")]
    except OSError:
        return None
    return list(csv.DictReader(lines, delimiter="\t"))


def narrative(target):
    """The `/* NARRATIVE ... */` block of reproduce/<target>.cpp split into its parts."""
    src = REPO / "reproduce" / f"{target}.cpp"
    try:
        text = src.read_text()
    except OSError:
        return None
    m = re.search(r"/\*\s*NARRATIVE\s*\n(.*?)\*/", text, re.S)
    if not m:
        return None
    parts, key = {}, None
    for line in m.group(1).splitlines():
        hit = re.match(r"\s*(Claim|Scene|Checked):\s*(.*)", line)
        if hit:
            key = hit.group(1)
            parts[key] = hit.group(2).strip()
        elif key:
            parts[key] += " " + line.strip()
    return parts


# One tolerant number parser for the report and the tables it embeds.
fnum = render_tables.fnum


def f3(x, d=3):
    return f"{x:.{d}f}" if math.isfinite(x) else "–"


def dig(obj, dotted, default=None):
    for k in dotted.split("."):
        if not isinstance(obj, dict) or k not in obj:
            return default
        obj = obj[k]
    return obj


# ---------------------------------------------------------------- document model
# Blocks: ("h", level, text) ("p", text) ("list", [text]) ("table", head, rows)
#         ("img", path, alt) ("raw", markdown, html) ("quote", [(label, text)])

def md_inline(t):
    return t


def html_inline(t):
    """Escape, then the little inline Markdown choices.md uses: `code` and **bold**."""
    t = html.escape(t)
    t = re.sub(r"`([^`]+)`", r"<code>\1</code>", t)
    return re.sub(r"\*\*([^*]+)\*\*", r"<strong>\1</strong>", t)


def render_md(blocks):
    out = []
    for b in blocks:
        k = b[0]
        if k == "h":
            out.append("#" * b[1] + " " + b[2])
        elif k == "p":
            out.append(b[1])
        elif k == "list":
            out.append("\n".join(("  " * depth) + "- " + text for depth, text in b[1]))
        elif k == "table":
            out.append("| " + " | ".join(b[1]) + " |\n|" + "|".join("---" for _ in b[1]) + "|\n" +
                       "\n".join("| " + " | ".join(str(c).replace("|", "\\|") for c in r) + " |" for r in b[2]))
        elif k == "img":
            out.append(f"![{b[2]}]({b[1]})" if b[1] else f"*{b[2]}: figure not produced*")
        elif k == "raw":
            out.append(b[1])
        elif k == "quote":
            out.append("\n".join(f"> **{lab}** {txt}" for lab, txt in b[1]))
    return "\n\n".join(out) + "\n"


def render_html(blocks, title):
    body = []
    for b in blocks:
        k = b[0]
        if k == "h":
            anchor = re.sub(r"[^a-z0-9]+", "-", b[2].lower()).strip("-")
            body.append(f'<h{b[1]} id="{anchor}">{html_inline(b[2])}</h{b[1]}>')
        elif k == "p":
            body.append(f"<p>{html_inline(b[1])}</p>")
        elif k == "list":
            body.append(nested_list_html(b[1]))
        elif k == "table":
            body.append('<table class="cmp"><thead><tr>' + "".join(f"<th>{html.escape(h)}</th>" for h in b[1]) +
                        "</tr></thead><tbody>" +
                        "".join("<tr>" + "".join(cell_html(c) for c in r) + "</tr>" for r in b[2]) +
                        "</tbody></table>")
        elif k == "img":
            if b[1] and Path(b[1]).is_file():
                data = base64.b64encode(Path(b[1]).read_bytes()).decode()
                body.append(f'<figure><img alt="{html.escape(b[2])}" src="data:image/png;base64,{data}">'
                            f"<figcaption>{html.escape(b[2])}</figcaption></figure>")
            else:
                body.append(f'<p class="missing">{html.escape(b[2])}: figure not produced</p>')
        elif k == "raw":
            body.append(b[2])
        elif k == "quote":
            body.append('<div class="narrative">' + "".join(
                f"<p><strong>{html.escape(lab)}</strong> {html_inline(txt)}</p>" for lab, txt in b[1]) + "</div>")
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{html.escape(title)}</title>"
            f"<style>{CSS}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")


def nested_list_html(items):
    out, depth = [], -1
    for d, text in items:
        while depth < d:
            out.append("<ul>")
            depth += 1
        while depth > d:
            out.append("</ul>")
            depth -= 1
        out.append(f"<li>{html_inline(text)}</li>")
    out += ["</ul>"] * (depth + 1)
    return "".join(out)


VERDICT_CLASS = {"agree": "ok", "disagree": "bad", "known_deviation": "known", "not produced": "bad"}


def cell_html(c):
    c = str(c)
    cls = VERDICT_CLASS.get(c)
    return f'<td class="{cls}">{html.escape(c)}</td>' if cls else f"<td>{html.escape(c)}</td>"


CSS = """
body{font-family:system-ui,-apple-system,'Segoe UI',sans-serif;max-width:60rem;margin:2rem auto;padding:0 1rem;
line-height:1.45;color:#222}
h1{border-bottom:2px solid #0072B2}h2{border-bottom:1px solid #ccc;margin-top:2.5rem}
table.cmp{border-collapse:collapse;font-size:.8rem;margin:1rem 0;display:block;overflow-x:auto}
table.cmp th,table.cmp td{border:1px solid #ccc;padding:.15rem .4rem;text-align:right;white-space:nowrap}
table.cmp th{background:#f0f4f8}table.cmp caption{font-weight:bold;text-align:left;padding:.3rem 0}
td.ok{background:#e6f4ea}td.bad{background:#fde7e7}td.known{background:#fff4d6}td.flag{background:#fff4d6}
figure{margin:1rem 0}figure img{max-width:100%;border:1px solid #eee}figcaption{font-size:.8rem;color:#555}
.narrative{background:#f7f7f7;border-left:4px solid #0072B2;padding:.2rem 1rem;font-size:.9rem}
.missing{color:#B00000;font-weight:bold}p.note{font-size:.8rem;color:#555}code{background:#f3f3f3;padding:0 .2rem}
"""


def choices_blocks(path):
    """paper/choices.md as blocks: headings, paragraphs and (nested) bullet lists."""
    try:
        lines = Path(path).read_text().splitlines()
    except OSError:
        return [("p", f"{path} missing.")]
    blocks, para, items = [], [], []

    def flush():
        if para:
            blocks.append(("p", " ".join(para)))
            para.clear()
        if items:
            blocks.append(("list", list(items)))
            items.clear()
    for ln in lines:
        h = re.match(r"(#+)\s+(.*)", ln)
        li = re.match(r"(\s*)- (.*)", ln)
        if h:
            flush()
            blocks.append(("h", len(h.group(1)) + 1, h.group(2)))  # nested under the report's section
        elif li:
            if para:
                blocks.append(("p", " ".join(para)))
                para.clear()
            items.append((len(li.group(1)) // 2, li.group(2)))
        elif not ln.strip():
            flush()
        elif items:
            d, t = items[-1]
            items[-1] = (d, t + " " + ln.strip())
        else:
            para.append(ln.strip())
    flush()
    return [b for b in blocks if not (b[0] == "h" and b[1] == 2)]  # its own title is ours


# ---------------------------------------------------------------- sections

def status_row(target, doc):
    if doc is None:
        return [target, "not produced", "–", "–", "–", "–"]
    return [target, "produced", doc.get("tier", "?"), doc.get("method", "?"), len(doc.get("scenes") or []),
            f3(fnum(doc.get("wall_seconds")), 1)]


def published_rows_for(doc, summary, pub):
    """Published against reproduced for the scenes of a figure target that have printed
    numbers (matched by row_id, else by pattern and N)."""
    rows = []
    for s in (doc or {}).get("scenes") or []:
        rid = dig(s, "x.row_id")
        row = pub.get(rid) if rid else None
        if row is None:
            pat = dig(s, "result.scene.pattern") or dig(s, "x.pattern")
            n = dig(s, "result.scene.geometry.N") or dig(s, "x.N")
            row = pub.get((pat, n))
        if row is None:
            continue
        for c in ("mu_s", "mu_d"):
            m, sem = fnum(dig(s, f"result.{c}.mean")), fnum(dig(s, f"result.{c}.sem"))
            p, e = fnum(row[c]), fnum(row[c + "_err"])
            chk = (summary or {}).get((row["row_id"], c))
            if chk:
                z, v = fnum(chk.get("z")), chk.get("verdict", "?")
            else:
                den = math.hypot(e, sem)
                z = (m - p) / den if den > 0 and math.isfinite(m) else math.nan
                v = "unchecked"
            rows.append([row["row_id"], row["pattern"], c, f"{f3(p)} ± {f3(e)}", f"{f3(m)} ± {f3(sem)}",
                         f"{z:+.1f}" if math.isfinite(z) else "–", v])
    return rows


def sensitivity_rows(doc):
    rows = []
    scenes = (doc or {}).get("scenes") or []
    base = {dig(s, "x.surface"): s for s in scenes if dig(s, "x.choice") == "baseline"}
    for s in scenes:
        b = base.get(dig(s, "x.surface"))
        if b is None or s is b:
            continue
        d = [fnum(dig(s, f"result.{c}.mean")) - fnum(dig(b, f"result.{c}.mean")) for c in ("mu_s", "mu_d")]
        rows.append([dig(s, "x.surface", "?"), dig(s, "x.choice", "?"), f"{dig(s, 'x.key', '')}={dig(s, 'x.value', '')}",
                     f"{d[0]:+.4f}", f"{d[1]:+.4f}", f3(fnum(dig(b, "result.mu_s.sem")), 4),
                     f3(fnum(dig(b, "result.mu_d.sem")), 4)])
    return rows


def build(args):
    data, figs = Path(args.data), Path(args.figures)
    summary_rows = read_tsv(data / "summary.tsv")
    summary = {(r["row_id"], r["coef"]): r for r in summary_rows} if summary_rows else None
    summary_json = load_json(data / "summary.json")
    tables = render_tables.render(data)
    pub = {}
    for t in ("tab_pat0", "tab_pat1", "tab_pat2"):
        for r in read_tsv(REPO / "tables" / f"published_{t}.tsv") or []:
            pub.setdefault(r["row_id"], r)
            pub.setdefault((r["pattern"], int(r["N"])), r)
    docs = {t: load_json(data / t / f"{t}.json") for t in ORDER + ["sensitivity", "accuracy_cost"]
            if t != "schematics"}

    B = [("h", 1, "Static and dynamic friction of hierarchical surfaces: reproduction report"),
         ("p", "Reproduction of Costagliola, Bosia and Pugno, Phys. Rev. E 94, 063003 (2016), with the "
               "springblock simulator. Each section below gives the claim the paper makes, the scene we simulate, "
               "our figure, and the published numbers next to ours. Deviations are given in sigmas, "
               "z = (ours − published)/√(err² + sem²).")]
    # Summary first: a reader wants the verdict before the detail.
    B.append(("h", 2, "Summary"))
    if summary_rows is None:
        B.append(("p", f"summary.tsv not produced ({data / 'summary.tsv'} missing): the verdicts below are "
                       "recomputed z values marked 'unchecked'."))
    else:
        n = {}
        for r in summary_rows:
            n[r.get("verdict", "?")] = n.get(r.get("verdict", "?"), 0) + 1
        B.append(("table", ["verdict", "published numbers"], [[k, v] for k, v in sorted(n.items())] +
                  [["total", len(summary_rows)]]))
    produced = [d for d in docs.values() if d]
    total_wall = sum(fnum(d.get("wall_seconds")) for d in produced if math.isfinite(fnum(d.get("wall_seconds"))))
    commits = sorted({str(dig(d, "provenance.commit", "?")) for d in produced})
    B.append(("p", f"Targets produced: {len(produced)} of {len(docs)}. Total wall time of the reproduction "
                   f"(sum over the target files): {total_wall:.0f} s ({total_wall / 3600:.2f} h). "
                   f"Simulator commit(s): {', '.join(commits) or '–'}."))
    B.append(("table", ["target", "status", "tier", "method", "scenes", "wall s"],
              [status_row(t, docs.get(t)) for t in docs]))

    for t in ORDER:
        B.append(("h", 2, TITLES[t]))
        nar = narrative(t)
        if nar:
            B.append(("quote", [(k + ":", nar[k]) for k in ("Claim", "Scene", "Checked") if k in nar]))
        elif t != "schematics":
            B.append(("p", f"No narrative block found in reproduce/{t}.cpp."))
        if t.startswith("tab_"):
            B.append(("raw", tables[t]["md"], tables[t]["html"]))
            continue
        png = figs / f"{t}.png"
        B.append(("img", str(png) if png.is_file() else None, f"{t}: figures/{t}.py"))
        if t == "schematics":
            continue
        if docs.get(t) is None:
            B.append(("p", f"{t}: not produced ({data / t / (t + '.json')} missing)."))
            continue
        rows = published_rows_for(docs[t], summary, pub)
        if rows:
            B.append(("table", ["row", "pattern", "coef", "published", "ours", "z", "verdict"], rows))
        claims = dig(summary_json, "claims") if isinstance(summary_json, dict) else None
        ids = re.findall(r"C\d\d", (nar or {}).get("Checked", ""))
        if isinstance(claims, list) and ids:
            crow = [[c.get("claim_id", c.get("id")), c.get("verdict", "?"), c.get("detail", "")] for c in claims
                    if c.get("claim_id", c.get("id")) in ids]
            if crow:
                B.append(("table", ["claim", "verdict", "detail"], crow))

    B.append(("h", 2, "Modelling choices the paper leaves open"))
    B += choices_blocks(REPO / "paper" / "choices.md")

    B.append(("h", 2, "Sensitivity to the open choices"))
    if docs.get("sensitivity") is None:
        B.append(("p", "sensitivity: not produced."))
    else:
        B.append(("img", str(figs / "sensitivity.png") if (figs / "sensitivity.png").is_file() else None,
                  "sensitivity: figures/sensitivity.py"))
        B.append(("table", ["surface", "choice", "variant", "Δmu_s", "Δmu_d", "sem mu_s (base)", "sem mu_d (base)"],
                  sensitivity_rows(docs["sensitivity"])))

    B.append(("h", 2, "Accuracy and cost"))
    if docs.get("accuracy_cost") is None:
        B.append(("p", "accuracy_cost: not produced."))
    else:
        B.append(("img", str(figs / "accuracy_cost.png") if (figs / "accuracy_cost.png").is_file() else None,
                  "accuracy_cost: figures/accuracy_cost.py"))
        # The driver's work_precision table: one row per setting and study, errors against the
        # converged event reference (first peak: per-seed max; mu_d: ensemble mean over its sem).
        wp = docs["accuracy_cost"].get("work_precision") or []
        rows = []
        for r in wp:
            if r.get("study") == "first_peak":
                err = f"mu_s {fnum(r.get('error_mu_s')):.2g}, t_slip {fnum(r.get('error_t_slip_s')):.2g} s"
            else:
                err = f"mu_d {fnum(r.get('error_mu_d')):.2g} = {fnum(r.get('error_mu_d_over_sem')):.2f} sem"
            rows.append([r.get("study"), r.get("setting"), err, f"{fnum(r.get('wall_seconds')):.2f}",
                         f"{fnum(r.get('rhs_evals_total')):.3g}"])
        for f in docs["accuracy_cost"].get("failed") or []:
            rows.append([f.get("study"), f.get("setting"), "failed: " + str(f.get("reason")), "-", "-"])
        B.append(("table", ["study", "setting", "error against the reference", "wall s", "rhs evaluations"],
                  rows if rows else [["-", "accuracy_cost.json has no work_precision table", "-", "-", "-"]]))
    B.append(("p", f"Wall time of the whole reproduction (all targets, as recorded in their files): {total_wall:.0f} s."))

    B.append(("h", 2, "Known deviations"))
    kd = read_tsv(REPO / "tables" / "known_deviations.tsv")
    if kd is None:
        B.append(("p", "tables/known_deviations.tsv not present."))
    elif not kd:
        B.append(("p", "tables/known_deviations.tsv lists no deviations."))
    else:
        B.append(("p", "Each entry names the result tiers at which it is expected: a deviation that only the "
                       "paper tier's 20 repetitions resolve lies inside the CI tier's wider tolerance."))
        B.append(("table", ["row", "coef", "tiers", "reason"],
                  [[r.get("row_id"), r.get("coef"), r.get("tiers") or "all", r.get("reason")] for r in kd]))
    return B


def write_atomic(path, text):
    fd, tmp = tempfile.mkstemp(dir=Path(path).parent, prefix="." + Path(path).name)
    with os.fdopen(fd, "w") as f:
        f.write(text)
    os.chmod(tmp, 0o644)  # mkstemp makes it private; the report is meant to be shared
    os.replace(tmp, path)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--data", required=True, help="build/reproduce")
    p.add_argument("--figures", required=True, help="build/figures (PNG files)")
    p.add_argument("--out", required=True, help="build/paper")
    a = p.parse_args()
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    blocks = build(a)
    # In Markdown the figures are linked relative to the report, so the .md stays light.
    md_blocks = [("img", os.path.relpath(b[1], out) if b[1] else None, b[2]) if b[0] == "img" else b for b in blocks]
    write_atomic(out / "report.md", render_md(md_blocks))
    write_atomic(out / "report.html", render_html(blocks, "springblock reproduction report"))
    print(out / "report.md")
    print(out / "report.html")


if __name__ == "__main__":
    main()
