#!/usr/bin/python3
"""The CPU time of the repetitions a `make reproduce-all` run's targets ran, by integrator, from
their documents (<build>/reproduce/<target>/<target>.json, runs[].cpu_s). One reading for the
documentation's cost page (tools/readme_cost.py) and the report (paper/build_report.py).

A scene one target borrows from another (borrowed_from), and a document that only shows another
target's results (source), are counted where they ran, so no repetition counts twice.
"""
import json
import os

# How the documents name an integrator (result.method, and result.stepper for the event method),
# in the order the tables show them.
INTEGRATORS = (("event", "exact", "event, exact stepper"), ("event", "dopri5", "event, Dormand-Prince"),
               ("rk4", None, "RK4 (the paper's scheme)"))


def integrator(result):
    return next((label for m, st, label in INTEGRATORS
                 if result.get("method") == m and (st is None or result.get("stepper") == st)),
                result.get("method", "?"))


def cpu_by_integrator(reproduce_dir, targets):
    """({target: {integrator label: CPU seconds}}, the labels in table order) over the targets
    whose documents exist; targets that ran nothing of their own are left out."""
    cpu = {}
    for target in targets:
        path = os.path.join(reproduce_dir, target, f"{target}.json")
        if not os.path.exists(path):
            continue
        with open(path) as f:
            doc = json.load(f)
        if "source" in doc:
            continue
        for sc in doc.get("scenes", []):
            r = sc.get("result")
            if "borrowed_from" in sc or not r:
                continue
            row = cpu.setdefault(target, {})
            label = integrator(r)
            row[label] = row.get(label, 0.0) + sum(x.get("cpu_s", 0.0) for x in r.get("runs", []))
    labels = [lab for _, _, lab in INTEGRATORS if any(lab in v for v in cpu.values())]
    labels += sorted({lab for v in cpu.values() for lab in v} - set(labels))
    return cpu, labels


def column_sums(cpu, labels):
    """Each integrator's CPU seconds over all targets, in the labels' order."""
    return [sum(v.get(lab, 0.0) for v in cpu.values()) for lab in labels]
