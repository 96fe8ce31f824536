"""test_report.py's checks of the materials studies in 'Beyond the paper' (graded friction,
composite chains): each comparison row of the report is its document's, and the document's paired
differences, standard errors and verdicts are recomputed here from its repetitions (the driver's
arithmetic checked independently of it)."""
import json
import math
import os


def load(data, repo, name):
    for path in (os.path.join(data, name, f"{name}.json"), os.path.join(repo, "paper", "data", f"{name}.json")):
        if os.path.isfile(path):
            with open(path) as f:
                return json.load(f)
    return None


def paired(runs_a, runs_b, key):
    d = [a[key] - b[key] for a, b in zip(runs_a, runs_b) if a[key] is not None and b[key] is not None]
    n = len(d)
    if n < 2:
        return n, 0.0, 0.0
    m = sum(d) / n
    return n, m, math.sqrt(sum((x - m) ** 2 for x in d) / (n - 1) / n)


def recomputed(doc, c, a_id, b_id, fail):
    runs = {s["id"]: s["result"]["runs"] for s in doc["scenes"]}
    n, m, se = paired(runs[a_id], runs[b_id], c["quantity"])
    ok = n == c["n"] and abs(m - c["diff"]) <= 1e-12 + 1e-9 * abs(m) and abs(se - c["sem"]) <= 1e-12 + 1e-9 * se
    ok = ok and (n < 2 or c["resolved"] == (se > 0 and abs(m / se) >= 3))
    if not ok:
        fail(f"{doc['target']}: {a_id} - {b_id} {c['quantity']}: document {c} != recomputed n {n} {m} +- {se}")



def same(printed, value):
    try:
        x = float(printed)
    except ValueError:
        return False
    d = len(printed.split(".")[1]) if "." in printed else 0
    return abs(x - value) <= 0.5 * 10 ** -d * (1 + 1e-9) + 1e-12


def check_graded(md, data, repo, tables, fail):
    doc = load(data, repo, "graded_friction")
    table = next((b for h, b in tables(md) if h[:3] == ["surface", "quantity", "comparison"]), None)
    if (doc is None) != (table is None):
        fail(f"graded friction: document {doc is not None}, table {table is not None}")
    if doc is None or table is None:
        return
    if md.find("Question.", md.find("\n## Beyond the paper")) < 0:
        fail("graded friction: no question stated in 'Beyond the paper'")
    if len(table) != len(doc["comparisons"]):
        fail(f"graded friction: {len(table)} rows for {len(doc['comparisons'])} comparisons")
    for row, c in zip(table, doc["comparisons"]):
        recomputed(doc, c, f"{c['surface']}_{c['a']}", f"{c['surface']}_{c['b']}", fail)
        diff, sem = row[4].split(" ± ")
        if not (row[1] == c["quantity"] and row[2] == c["what"] and same(diff, c["diff"]) and same(sem, c["sem"])
                and row[6] == ("resolved" if c["resolved"] else "not resolved")):
            fail(f"graded friction: row {row} != {c}")


def check_composite(md, data, repo, tables, fail):
    doc = load(data, repo, "composite_stiffness")
    table = next((b for h, b in tables(md) if h[:2] == ["contrast", "segment blocks"]), None)
    if (doc is None) != (table is None):
        fail(f"composite: document {doc is not None}, table {table is not None}")
    if doc is None or table is None:
        return
    x_of = {s["id"]: s["x"] for s in doc["scenes"]}
    rows = {(r[0], r[1]): r for r in table}
    for c in doc["comparisons"]:
        recomputed(doc, c, c["id"], "uniform", fail)
        row = rows.get((f"{x_of[c['id']]['contrast']:g}", str(x_of[c["id"]]["segment_blocks"])))
        if row is None:
            fail(f"composite: no row for {c['id']}")
            continue
        cell = 2 if c["quantity"] == "mu_s" else 4
        if c["n"] < 2:
            if row[cell] != "not measured":
                fail(f"composite: {c['id']} {c['quantity']} not measured but printed {row[cell]}")
            continue
        diff, sem = row[cell].split(" ± ")
        if not (same(diff, c["diff"]) and same(sem, c["sem"])
                and row[cell + 1] == ("resolved" if c["resolved"] else "not resolved")):
            fail(f"composite: row {row} != {c}")
