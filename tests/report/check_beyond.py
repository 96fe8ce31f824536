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


def weighted_slope(N, y, sem):
    """The log-linear fit's change per decade and its standard error, by the normal equations
    (independent of paper/scaling_fits.py's curve_fit)."""
    u = [math.log10(n) for n in N]
    w = [1 / s ** 2 for s in sem]
    sw = sum(w)
    ub = sum(wi * ui for wi, ui in zip(w, u)) / sw
    yb = sum(wi * yi for wi, yi in zip(w, y)) / sw
    suu = sum(wi * (ui - ub) ** 2 for wi, ui in zip(w, u))
    b = sum(wi * (ui - ub) * (yi - yb) for wi, ui, yi in zip(w, u, y)) / suu
    return b, 1 / math.sqrt(suu)


def check_size_scaling(md, data, repo, tables, fail):
    """The trends table against slopes recomputed from the scenes; the collapse table against
    paper/scaling_fits.py; the driver's rules (whole runs only up to largest_whole_run, mu_d not
    measured beyond, repetitions as recorded) on the document."""
    from paper import scaling_fits as sf

    doc = load(data, repo, "size_scaling")
    all_tables = tables(md)
    trend = next((b for h, b in all_tables if h[:4] == ["surface", "family", "quantity", "N"]), None)
    coll = next((b for h, b in all_tables if h[:3] == ["surface", "quantity", "candidate X"]), None)
    if (doc is None) != (trend is None) or (doc is None) != (coll is None):
        fail(f"size scaling: document {doc is not None}, tables {trend is not None} {coll is not None}")
    if doc is None or trend is None or coll is None:
        return
    for s in doc["scenes"]:
        x, r = s["x"], s["result"]
        whole = x["N"] <= doc["largest_whole_run"]
        if x["whole_run"] != whole or r["scene"].get("stop_after_mu_s", False) == whole:
            fail(f"size scaling: {s['id']} whole_run {x['whole_run']} for N {x['N']}")
        if not whole and (r.get("mu_d") or {}).get("n", 0) != 0:
            fail(f"size scaling: {s['id']} stopped at its first slip but has mu_d")
        if len(r.get("runs", [])) != r["reps"]:
            fail(f"size scaling: {s['id']} {len(r.get('runs', []))} runs for {r['reps']} repetitions")
    rows = {(r[0], r[1], r[2]): r for r in trend}
    expected = 0
    for surface in sf.surfaces(doc):
        for family in sf.FAMILIES:
            for key in sf.QUANTITIES:
                pts = sf.points(doc, surface, family, key)
                if not pts:
                    continue
                expected += 1
                row = rows.get((surface, family, key))
                if row is None:
                    fail(f"size scaling: no trend row for {surface} {family} {key}")
                    continue
                if row[3] != f"{pts[0][0]['N']}-{pts[-1][0]['N']}":
                    fail(f"size scaling: {row[:4]} N range != {pts[0][0]['N']}-{pts[-1][0]['N']}")
                if len(pts) < 3:
                    continue
                b, se = weighted_slope([p[0]["N"] for p in pts], [p[1] for p in pts], [p[2] for p in pts])
                printed_b, printed_se = row[6].split(" ± ")
                if not (same(printed_b, b) and same(printed_se, se)):
                    fail(f"size scaling: {row[:3]} change per decade {row[6]} != recomputed {b} ± {se}")
    if len(trend) != expected:
        fail(f"size scaling: {len(trend)} trend rows for {expected} series")
    mine = sf.collapses(doc)
    if len(coll) != len(mine):
        fail(f"size scaling: {len(coll)} collapse rows for {len(mine)} tests")
    for row, c in zip(coll, mine):
        if row[:3] != [c["surface"], c["quantity"], c["candidate"]] or row[5] != ("yes" if c["collapses"] else "no"):
            fail(f"size scaling: collapse row {row} != "
                 f"{c['surface']} {c['quantity']} {c['candidate']} {c['collapses']}")
