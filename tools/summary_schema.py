"""summary.json: the one definition of the checker's verdicts, written and read only here.

The checker (tools/check_reproduction.py) writes it; the report, the tables, the z-score figure,
the README check and the reproduce-all driver read it. Every reader goes through load(), which
validates every key and every count, so a reader never needs a default for a missing key: a
summary that is not exactly this shape is an error that names the key.

API (small on purpose):
  load(path) -> dict                 validated summary; SummaryError names what is wrong
  write(path, summary)               validate, then write atomically (temp file + rename)
  write_tsv(path, summary)           the published numbers, one line each, for people
  target_counts(summary, target)     {"rows": {verdict: n}, "claims": {verdict: n}} of one target
  format_counts(counts)              "4 numbers: 4 agree; 2 claims: 2 hold" (one line per target)
  ROW_VERDICTS, CLAIM_VERDICTS, LINE_STATUSES   the vocabularies

Shape (schema version 2):
  schema_version   2
  tier             tier of the results: smoke | quick | paper (the weakest, if targets differ)
  target_tiers     {target: tier} of every produced target
  tier_reps        {tier: repetitions}, as the targets' documents state it
  thresholds       alpha_familywise, n_published, n_pub_reps_assumed, alpha_equivalence, z95,
                   delta {mu_s, mu_d}
  rows             one per published number (ROW_KEYS); numeric fields are null only when missing
  claims           one per figure claim (CLAIM_KEYS); lines [{status, text}]
  counts           {"rows": {ROW_VERDICTS: n}, "claims": {CLAIM_VERDICTS: n}}
  counts_per_target {target: same shape}: rows count for their table target (tab_pat0/1/2),
                   a claim for every target it needs; every produced target is present
  stale            ["pat0_r03 mu_s", "C14 claim", ...]: known deviations that no longer deviate
  resolution       {tier: {reps, mu_s: RESOLUTION_KEYS, mu_d: ...}}: what each tier can resolve
  z_distribution   n, within {"1","2","3"}, normal {"1","2","3"}, mean, sd of all z-scores,
                   sd_by_coef {mu_s, mu_d}
"""
import json
import os
import tempfile

SCHEMA_VERSION = 2
TIERS = ("smoke", "quick", "paper")
COEFS = ("mu_s", "mu_d")
ROW_VERDICTS = ("agree", "disagree_known", "disagree_new", "not_resolved", "missing")
CLAIM_VERDICTS = ("holds", "fails_known", "fails_new", "not_resolved", "missing")
LINE_STATUSES = ("ok", "fail", "unresolved")

TOP_KEYS = ("schema_version", "tier", "target_tiers", "tier_reps", "thresholds", "rows", "claims", "counts",
            "counts_per_target", "stale", "resolution", "z_distribution")
THRESHOLD_KEYS = ("alpha_familywise", "n_published", "n_pub_reps_assumed", "alpha_equivalence", "z95", "delta")
ROW_KEYS = ("row_id", "coef", "target", "tier", "published", "err", "ours", "sem", "sd", "n", "d", "sigma", "z", "k",
            "dof", "detection", "equivalence", "delta", "verdict", "known_deviation", "stale", "note")
ROW_MEASURED = ("ours", "sem", "sd", "n", "d", "sigma", "z", "k", "dof", "detection", "equivalence")
CLAIM_KEYS = ("claim_id", "figure", "statement", "targets", "tier", "k_c", "lines", "verdict", "known_deviation",
              "stale", "note")
RESOLUTION_KEYS = ("rows", "certifiable", "median_detection", "median_equivalence")
Z_KEYS = ("n", "within", "normal", "mean", "sd", "sd_by_coef")
Z_CUTS = ("1", "2", "3")


class SummaryError(ValueError):
    pass


def _need(obj, keys, where):
    if not isinstance(obj, dict):
        raise SummaryError(f"{where}: expected an object, found {type(obj).__name__}")
    for k in keys:
        if k not in obj:
            raise SummaryError(f"{where}: missing key '{k}'")


def _number(x, where, nullable=False):
    if x is None and nullable:
        return
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        raise SummaryError(f"{where}: expected a number, found {x!r}")


def empty_counts():
    return {"rows": {v: 0 for v in ROW_VERDICTS}, "claims": {v: 0 for v in CLAIM_VERDICTS}}


def count(rows, claims):
    """Counts of a list of row records and claim records."""
    c = empty_counts()
    for r in rows:
        c["rows"][r["verdict"]] += 1
    for cl in claims:
        c["claims"][cl["verdict"]] += 1
    return c


def counts_per_target(rows, claims, targets):
    """Every target in `targets`, plus every target owning a row or needed by a claim."""
    names = set(targets) | {r["target"] for r in rows} | {t for cl in claims for t in cl["targets"]}
    return {t: count([r for r in rows if r["target"] == t], [cl for cl in claims if t in cl["targets"]])
            for t in sorted(names)}


def _one_of(value, allowed, where, key):
    if value not in allowed:
        raise SummaryError(f"{where}: {key} {value!r} not one of {allowed}")


def _validate_row(r, i):
    _need(r, ROW_KEYS, f"rows[{i}]")
    where = f"rows[{i}] ({r['row_id']} {r['coef']})"
    _one_of(r["coef"], COEFS, where, "coef")
    _one_of(r["verdict"], ROW_VERDICTS, where, "verdict")
    for k in ("published", "err", "delta"):
        _number(r[k], f"{where}.{k}")
    for k in ROW_MEASURED:
        _number(r[k], f"{where}.{k}", nullable=r["verdict"] == "missing")
    if not isinstance(r["stale"], bool):
        raise SummaryError(f"{where}.stale: expected true/false")


def _validate_claim(c, i):
    _need(c, CLAIM_KEYS, f"claims[{i}]")
    where = f"claims[{i}] ({c['claim_id']})"
    _one_of(c["verdict"], CLAIM_VERDICTS, where, "verdict")
    if not isinstance(c["lines"], list) or (c["verdict"] != "missing" and not c["lines"]):
        raise SummaryError(f"{where}: a judged claim needs its comparison lines")
    for j, ln in enumerate(c["lines"]):
        _need(ln, ("status", "text"), f"{where}.lines[{j}]")
        if ln["status"] not in LINE_STATUSES:
            raise SummaryError(f"{where}.lines[{j}]: status {ln['status']!r} not one of {LINE_STATUSES}")
    _number(c["k_c"], f"{where}.k_c", nullable=True)
    if not isinstance(c["targets"], list) or not c["targets"]:
        raise SummaryError(f"{where}.targets: a claim needs at least one target")


def validate(s):
    """Raise SummaryError naming the first key that is missing, mistyped or inconsistent."""
    _need(s, TOP_KEYS, "summary")
    if s["schema_version"] != SCHEMA_VERSION:
        raise SummaryError(f"summary: schema_version {s['schema_version']!r}, this reader knows {SCHEMA_VERSION}")
    if s["tier"] not in TIERS:
        raise SummaryError(f"summary.tier: {s['tier']!r} not one of {TIERS}")
    _need(s["thresholds"], THRESHOLD_KEYS, "summary.thresholds")
    _need(s["thresholds"]["delta"], COEFS, "summary.thresholds.delta")
    for i, r in enumerate(s["rows"]):
        _validate_row(r, i)
    if len(s["rows"]) != s["thresholds"]["n_published"]:
        raise SummaryError(f"summary.rows: {len(s['rows'])} rows, thresholds.n_published says "
                           f"{s['thresholds']['n_published']}")
    ids = [c["claim_id"] if isinstance(c, dict) and "claim_id" in c else None for c in s["claims"]]
    for i, c in enumerate(s["claims"]):
        _validate_claim(c, i)
    if len(set(ids)) != len(ids):
        raise SummaryError("summary.claims: a claim appears twice")
    # Counts are stored for readers that only want numbers; they must be the records' counts.
    if s["counts"] != count(s["rows"], s["claims"]):
        raise SummaryError("summary.counts: do not match the rows and claims")
    if s["counts_per_target"] != counts_per_target(s["rows"], s["claims"], s["target_tiers"]):
        raise SummaryError("summary.counts_per_target: do not match the rows and claims")
    for tier, res in s["resolution"].items():
        _need(res, ("reps",) + COEFS, f"summary.resolution.{tier}")
        for coef in COEFS:
            _need(res[coef], RESOLUTION_KEYS, f"summary.resolution.{tier}.{coef}")
    if set(s["resolution"]) != set(s["tier_reps"]):
        raise SummaryError("summary.resolution: must have one entry per tier of tier_reps")
    z = s["z_distribution"]
    _need(z, Z_KEYS, "summary.z_distribution")
    _need(z["within"], Z_CUTS, "summary.z_distribution.within")
    _need(z["normal"], Z_CUTS, "summary.z_distribution.normal")
    _need(z["sd_by_coef"], COEFS, "summary.z_distribution.sd_by_coef")


def load(path):
    """The validated summary at path; SummaryError (a ValueError) with a clear message otherwise."""
    try:
        with open(path) as f:
            s = json.load(f)
    except OSError as e:
        raise SummaryError(f"{path}: cannot read the summary ({e.strerror}); run the checker "
                           f"(tools/check_reproduction.py --summary) first") from None
    except ValueError as e:
        raise SummaryError(f"{path}: not valid JSON ({e})") from None
    try:
        validate(s)
    except SummaryError as e:
        raise SummaryError(f"{path}: {e}") from None
    return s


def _atomic(path, text):
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=directory, prefix="." + os.path.basename(path) + ".")
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.chmod(tmp, 0o644)  # mkstemp makes it private; the summary is meant to be read
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def write(path, summary):
    validate(summary)  # a writer's mistake fails here, not in a reader
    _atomic(path, json.dumps(summary, indent=1, allow_nan=False) + "\n")


TSV_COLUMNS = ("row_id", "coef", "published", "err", "ours", "sem", "n", "d", "z", "k", "detection", "equivalence",
               "delta", "verdict", "stale")


def write_tsv(path, summary):
    def cell(v):
        return "" if v is None else f"{v:.6g}" if isinstance(v, float) else str(v)
    lines = ["\t".join(TSV_COLUMNS)]
    lines += ["\t".join(cell(r[c]) for c in TSV_COLUMNS) for r in summary["rows"]]
    _atomic(path, "\n".join(lines) + "\n")


def target_counts(summary, target):
    if target not in summary["counts_per_target"]:
        raise SummaryError(f"summary.counts_per_target: no target '{target}' (not produced?)")
    return summary["counts_per_target"][target]


def format_counts(counts):
    """One line: the published numbers and claims of one target (or of all), by verdict."""
    parts = []
    rows, claims = counts["rows"], counts["claims"]
    if sum(rows.values()):
        parts.append(f"{sum(rows.values())} numbers: " +
                     ", ".join(f"{n} {v.replace('_', ' ')}" for v, n in rows.items() if n))
    if sum(claims.values()):
        parts.append(f"{sum(claims.values())} claims: " +
                     ", ".join(f"{n} {v.replace('_', ' ')}" for v, n in claims.items() if n))
    return "; ".join(parts) if parts else "no published number or claim of its own"
