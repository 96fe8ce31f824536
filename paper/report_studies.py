"""The report's section on the optional studies (`make studies`): each is read from the build
tree if it ran there, else from its committed copy under paper/data/, and shown with the commit
that made it. Blocks in the shape paper/build_report.py renders."""
import json
import math
from pathlib import Path

from tools.reproduction import stats
from tools.reproduction.inputs import published_rows

REPO = Path(__file__).resolve().parent.parent

STUDIES = ("layout", "extraction", "method_bias", "rk4_refinement")


def load_study(data, name):
    """(document, where it came from) or (None, None)."""
    for path in (Path(data) / name / f"{name}.json", REPO / "paper" / "data" / f"{name}.json"):
        if path.is_file():
            return json.loads(path.read_text()), path
    return None, None


def provenance_text(doc, path):
    prov = doc["provenance"]
    return f"Data: `{path.relative_to(REPO) if REPO in path.parents else path}`, commit {prov['commit']}, {prov['utc']}."


def figure(figs, name):
    png = Path(figs) / f"{name}.png"
    return ("img", str(png) if png.is_file() else None, f"{name}: figures/{name}.py")


def layout_blocks(doc, path, figs):
    B = [("p", "Where a level's pawls and grooves start on the run they divide is not stated in the paper. "
               f"Criterion, fixed before any variant was run: {doc['criterion']} "
               f"Chosen: **{doc['chosen']}**. " + provenance_text(doc, path)),
         figure(figs, "layout")]
    rows = []
    for v in doc["variants"]:
        c = v["counts"]
        rows.append([v["variant"], f"{v['S_matches_counted']}/{v['S_counted_rows']}",
                     f"{v['S_matches_all']}/{v['S_rows']}", f"{v['not_disagree']}/142", f"{v['sum_z2']:.1f}",
                     f"{v['z_distribution']['within']['2']:.2f}", f"{v['z_distribution']['sd']:.2f}",
                     f"{c['claims']['holds']}/35", "chosen" if v["variant"] == doc["chosen"] else ""])
    B.append(("table", ["layout", "S/S_tot counted rows", "S/S_tot all rows", "|z| <= k", "sum z^2",
                        "|z| <= 2", "sd of z", "claims hold", ""], rows))
    return B


def extraction_blocks(doc, path):
    pub = published_rows(REPO / "tables")
    by_rule = {}
    for s in doc["scenes"]:
        by_rule.setdefault(s["x"]["rule"], []).append(s)
    readings = [(rule, "mu_s") for rule in by_rule] + [("all_slipped", "mu_s_signed")]
    rows = []
    for rule, key in readings:
        z2, ok, within2, n = 0.0, 0, 0, 0
        for s in by_rule[rule]:
            rid = s["x"]["row_id"]
            st = s["result"][key]
            if st["mean"] is None:
                continue
            c = stats.compare(float(pub[rid]["mu_s"]), float(pub[rid]["mu_s_err"]), st["mean"], st["sem"] or 0.0,
                              st["n"], "mu_s")
            n += 1
            z2 += c["z"] ** 2
            ok += c["verdict"] != "disagree"
            within2 += abs(c["z"]) <= 2
        label = f"{rule}" + (" (signed sum)" if key == "mu_s_signed" else "")
        rows.append([label, str(n), f"{ok}/{n}", f"{within2 / n:.2f}" if n else "-", f"{z2:.1f}"])
    return [("p", "mu_s of all 71 rows under each reading of the first load peak, judged against the printed "
                  "values with the checker's detection rule (no known deviations applied). " +
             provenance_text(doc, path)),
            ("table", ["reading", "rows", "|z| <= k", "|z| <= 2", "sum z^2"], rows)]


def method_bias_blocks(doc, path):
    pub = published_rows(REPO / "tables")
    pairs = {}
    for s in doc["scenes"]:
        pairs.setdefault(s["x"]["row_id"], {})[s["x"]["method"]] = s
    rows = []
    for rid in sorted(pairs):
        ev, rk = pairs[rid]["event"]["result"], pairs[rid]["rk4"]["result"]
        diffs = [a["mu_s"] - b["mu_s"] for a, b in zip(rk["runs"], ev["runs"])
                 if a["mu_s"] is not None and b["mu_s"] is not None]
        mean = sum(diffs) / len(diffs)
        sd = math.sqrt(sum((x - mean) ** 2 for x in diffs) / (len(diffs) - 1)) if len(diffs) > 1 else math.nan
        rows.append([rid, pub[rid]["pattern"], f"{float(pub[rid]['mu_s']):.3f} ± {float(pub[rid]['mu_s_err']):.3f}",
                     f"{ev['mu_s']['mean']:.3f} ± {ev['mu_s']['sem']:.3f}",
                     f"{rk['mu_s']['mean']:.3f} ± {rk['mu_s']['sem']:.3f}",
                     f"{mean:+.4f} ± {sd / math.sqrt(len(diffs)):.4f}"])
    return [("p", "Every deviating row with the paper's method (RK4, h = 1e-4 ms) beside ours, same draws, "
                  "each repetition up to its first macroscopic slip. " + provenance_text(doc, path)),
            ("table", ["row", "pattern", "paper", "event (ours)", "RK4 (paper's)", "RK4 - event, paired"], rows)]


def study_blocks(data, figs):
    B = [("h", 2, "Optional studies"),
         ("p", "Expensive studies that change only when the model does: `make studies` runs them and commits "
               "their documents under `paper/data/`; each names the commit that made it.")]
    titles = {"layout": "Pattern layout", "extraction": "Reading mu_s off the loading curve",
              "method_bias": "The paper's integrator on the deviating rows",
              "rk4_refinement": "RK4 below the paper's step"}
    for name in STUDIES:
        B.append(("h", 3, titles[name]))
        doc, path = load_study(data, name)
        if doc is None:
            B.append(("p", f"{name}: not run (`make studies`) and not committed."))
        elif name == "layout":
            B += layout_blocks(doc, path, figs)
        elif name == "extraction":
            B += extraction_blocks(doc, path)
        elif name == "method_bias":
            B += method_bias_blocks(doc, path)
        else:
            B.append(("p", "Drawn with accuracy_cost's settings in the accuracy figure above. " +
                      provenance_text(doc, path)))
    return B
