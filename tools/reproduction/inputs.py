"""What the checker reads: the transcribed tables (tables/*.tsv), the list of known deviations,
and the reproduction targets' documents (<results>/<target>/<target>.json, reproduce/README.md)."""
import csv
import json
import os

TIERS = ("smoke", "quick", "paper")          # weakest first
TABLE_TARGET = {"pat0": "tab_pat0", "pat1": "tab_pat1", "pat2": "tab_pat2"}
COEFS = ("mu_s", "mu_d")


def table_target(row_id):
    """The reproduction target that simulates a published row (pat1_r04 -> tab_pat1)."""
    return TABLE_TARGET[row_id.split("_")[0]]


def read_tsv(path):
    with open(path) as f:
        lines = [ln for ln in f if ln.strip() and not ln.startswith("#")]
    return list(csv.DictReader(lines, delimiter="\t"))


def published_rows(tables):
    """row_id -> the transcribed row, in the printed order of the three tables."""
    rows = {}
    for t in TABLE_TARGET:
        for r in read_tsv(os.path.join(tables, f"published_tab_{t}.tsv")):
            rows[r["row_id"]] = r
    return rows


def load_claims(tables):
    return {c["claim_id"]: c for c in read_tsv(os.path.join(tables, "figure_claims.tsv"))}


class KnownDeviations:
    """tables/known_deviations.tsv: (row_id, coef) or (claim_id, "claim") -> reason, expected only
    at the listed tiers ("all": every tier). A deviation that only the paper tier's statistics
    resolve must not be expected at a tier whose tolerance is too wide to see it."""

    def __init__(self, path):
        self.entries = {}
        for r in read_tsv(path):
            tiers = r["tiers"].strip()
            listed = set(TIERS) if tiers == "all" else {x.strip() for x in tiers.split(",") if x.strip()}
            unknown = listed - set(TIERS)
            if unknown:
                raise ValueError(f"{path}: {r['row_id']} {r['coef']}: unknown tier(s) {sorted(unknown)}")
            self.entries[(r["row_id"], r["coef"])] = (listed, r["reason"])

    def reason(self, key, tier):
        """The reason if key is an expected deviation at this tier, else None."""
        if key not in self.entries:
            return None
        tiers, why = self.entries[key]
        return why if tier in tiers else None


class Results:
    """Lazy, cached access to the targets' documents under one results directory."""

    def __init__(self, root):
        self.root, self.docs = root, {}

    def doc(self, target):
        """The target's document, or None when it was not produced."""
        if target not in self.docs:
            path = os.path.join(self.root, target, f"{target}.json")
            if os.path.exists(path):
                with open(path) as f:
                    self.docs[target] = json.load(f)
            else:
                self.docs[target] = None
        return self.docs[target]

    def need(self, target):
        d = self.doc(target)
        if d is None:
            raise LookupError(f"no results for target {target} under {self.root}")
        return d

    def scene(self, target, sid):
        for s in self.need(target)["scenes"]:
            if s["id"] == sid:
                return s
        raise LookupError(f"{target} has no scene {sid}")

    def tier(self, target):
        d = self.doc(target)
        return None if d is None else d["tier"]

    def produced(self):
        """Targets whose documents were read so far."""
        return sorted(t for t, d in self.docs.items() if d is not None)


def statistic(scene, coef):
    """(mean, sem, sd, n) of a coefficient of one scene; LookupError when it has no value
    (no macroscopic slip) or fewer than two repetitions carry one (then no standard error)."""
    r = scene["result"][coef]
    if r["mean"] is None or r["n"] < 2 or r["sem"] is None:
        raise LookupError(f"{scene['id']}: {coef} has {r['n']} value(s): no mean with a standard error")
    return r["mean"], r["sem"], r["std"], r["n"]
