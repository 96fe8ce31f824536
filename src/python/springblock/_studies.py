"""Whole studies from Python: sweep() and design() run the library's own sweep and design query
(the code behind `springblock sweep` and `springblock design`), so they write the same files and
give the same numbers; their results read back as records and DataFrames."""
import json
import math
import numbers
import os

from springblock import _core
from springblock._tables import data_frame, flatten


def _command_line(call, arguments):
    """How provenance records a call from Python: 'python: springblock.sweep(...)'."""
    shown = ", ".join(f"{k}={v!r}" for k, v in arguments.items() if v is not None and v is not False)
    return f"python: springblock.{call}({shown})"


class SweepResult:
    """What sweep() returns: the results file, read back. ``SweepResult(path)`` reads any sweep's
    results file, the command line's too.

    Attributes: ``path`` (the results file, JSON lines), ``header`` (its first line: the sweep,
    units computed now and resumed, ranks, threads, provenance), ``scenes`` (one dict per scene:
    ``varied``, every observable's ``{mean, std, sem, n}``, reps, seed, method, ..., ``scene_json``
    and ``runs``, the per-repetition records); from sweep(), also ``report`` (counts and wall time
    of the call) and ``summary`` (the table ``springblock sweep`` prints), else None.
    """

    def __init__(self, path, report=None):
        self.path = os.fspath(path)
        self.report = report
        self.summary = report["summary"] if report else None
        with open(path) as f:
            lines = [json.loads(line) for line in f if line.strip()]
        self.header, self.scenes = lines[0], lines[1:]

    def __len__(self):
        return len(self.scenes)

    def __repr__(self):
        h = self.header
        return (f"springblock.SweepResult({len(self.scenes)} scenes, {h['units']} units "
                f"({h['computed_units']} computed, {h['resumed_units']} resumed), path={self.path!r})")

    @staticmethod
    def _with_varied(varied, row):
        # The varied fields first, by their own names; one named like an entry of the row (a
        # sweep over the micro mu_s, beside the observable mu_s) keeps the prefix varied_.
        out = {}
        for key, value in varied.items():
            out[f"varied_{key}" if key in row else key] = value
        out.update(row)
        return out

    def records(self):
        """One flat dict per scene: the varied fields, then scene (its index), each observable's
        mean, std, sem and n (mu_s_mean, mu_s_sem, ...), reps, seed, method, contact_fraction,
        wall_s. Numbers as the results file holds them (None where undefined)."""
        rows = []
        for line in self.scenes:
            row = flatten({k: v for k, v in line.items() if k not in ("varied", "scene_json", "runs")})
            rows.append(self._with_varied(line["varied"], row))
        return rows

    def run_records(self):
        """One flat dict per repetition (work unit): the varied fields of its scene, then its record
        (unit, scene, rep, seed, every observable, work_* counters, wall_s, cpu_s, rank)."""
        return [self._with_varied(line["varied"], flatten(run)) for line in self.scenes for run in line["runs"]]

    def to_pandas(self, runs=False):
        """records() (or, with runs=True, run_records()) as a pandas DataFrame (needs pandas)."""
        return data_frame(self.run_records() if runs else self.records())


def sweep(spec, out=None, *, units=None, threads=0, resume=False, progress=None):
    """Run every scene of a sweep, as ``springblock sweep`` does, and return a SweepResult.

    ``spec`` is a sweep file's path (.toml or .json, as the command line takes it) or a dict of the
    same form (``{"base": {...}, "scenes": [{...}, ...], "axes": {"key": [values] or {"from", "to",
    "steps", "scale"}}}``). One work unit per repetition, over ``threads`` threads (0 = all cores);
    the numbers are those of the command line, whatever the thread count.

    Files, as the command line writes them: the results go to ``out`` (default: the sweep file with
    .results.jsonl; a dict needs ``out``), OUT.partial grows a line per complete scene while it
    runs, OUT.checkpoint holds every finished unit until the sweep completes; ``units`` names a
    file for every unit's record. If the call is stopped (Ctrl-C, or an exception raised by
    ``progress``), the finished units stay in the checkpoint and the exception is raised; the same
    call with ``resume=True`` (or ``springblock sweep --resume``: the checkpoints are the same)
    computes only the units it lacks and gives the same results.

    ``progress``, if given, is called about 5 times a second, and once at the end, with a dict
    (done, total, computed, fraction, elapsed_s, eta_s, ranks, threads), on the calling thread with
    the GIL held. Bad input raises InputError naming the field (and its line in a file); nothing
    runs and no file is written.
    """
    arguments = {"spec": spec if not isinstance(spec, dict) else "<dict>", "out": out, "units": units,
                 "threads": threads or None, "resume": resume}
    if isinstance(spec, dict):
        file, text = "", json.dumps(_sweep_dict(spec), allow_nan=False)
    elif isinstance(spec, (str, os.PathLike)):
        file, text = os.fspath(spec), ""
    else:
        raise _input_error("sweep", f"a sweep is a file's path or a dict, got {type(spec).__name__}")
    report = _core.sweep(file, text, "sweep dict", os.fspath(out) if out is not None else "",
                         os.fspath(units) if units is not None else "", int(threads), bool(resume), progress,
                         _command_line("sweep", arguments))
    return SweepResult(report["out"], report)


def _input_error(field, message):
    error = _core.InputError(f"invalid {field}: {message}")
    error.field = field
    return error


def _plain(field, value):
    """A sweep dict's value as the JSON a sweep file holds: numpy numbers and arrays as plain
    numbers and lists; a number that is not finite is refused naming its field."""
    if isinstance(value, dict):
        return {k: _plain(k, v) for k, v in value.items()}
    if isinstance(value, (str, bool)) or value is None:
        return value
    if hasattr(value, "tolist"):  # numpy arrays and scalars
        return _plain(field, value.tolist())
    if isinstance(value, (list, tuple)):
        return [_plain(field, v) for v in value]
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        if not math.isfinite(value):
            raise _input_error(field, f"{value!r} is not a finite number; give a number or a string with units")
        return float(value)
    raise _input_error(field, f"{value!r} is not a string, number, boolean, list or dict")


def _sweep_dict(spec):
    """The sweep file a dict stands for: each pattern (in base, in scenes, on an axis) given as
    the blocks themselves becomes its mask text, as Scene(pattern=...) takes it."""
    def scene(fields):
        if not isinstance(fields, dict):
            return fields  # the sweep parser says what it expected
        return {k: _core.pattern_text(v) if k == "pattern" else v for k, v in fields.items()}
    out = dict(spec)
    if "base" in out:
        out["base"] = scene(out["base"])
    if isinstance(out.get("scenes"), (list, tuple)):
        out["scenes"] = [scene(s) for s in out["scenes"]]
    axes = out.get("axes")
    if isinstance(axes, dict) and isinstance(axes.get("pattern"), (list, tuple)):
        out["axes"] = {**axes, "pattern": [_core.pattern_text(p) for p in axes["pattern"]]}
    return _plain("sweep", out)


class DesignResult:
    """What design() returns: the object ``springblock design --json`` prints, as ``json`` (a dict),
    with its answers as ``best`` (the verified candidates in the order printed: by their fresh
    score), ``feasible`` and ``why`` (when infeasible)."""

    def __init__(self, j):
        self.json = j
        self.best = j["best"]
        self.feasible = j["feasible"]
        self.why = j.get("why")

    def __repr__(self):
        answers = ", ".join(f"{b['pattern']} (mu_s {b['mu_s']['mean']:.4g}, mu_d {b['mu_d']['mean']:.4g})"
                            for b in self.best[:3])
        return f"springblock.DesignResult(feasible={self.feasible}, best=[{answers}{', ...' if len(self.best) > 3 else ''}])"

    def records(self):
        """One flat dict per answer, in order: pattern, layout, contact_fraction, mu_s_mean,
        mu_s_sem, ..., ratio_*, meets_target, score, reps, resolved, and the screening estimate."""
        return [flatten(b) for b in self.best]

    def to_pandas(self):
        """records() as a pandas DataFrame (needs pandas)."""
        return data_frame(self.records())


def design(*, out=None, progress=None, **query):
    """Search a pattern family for the surface that meets a target, as ``springblock design`` does,
    and return a DesignResult with the same answers.

    Keywords are the command's options with '_' for '-': the family (``family="periodic"``,
    "hierarchical", "random" or "given" with ``candidates=[...]``: pattern strings or 0/1 arrays),
    the targets (``target_mu_s``, ``target_mu_d``, ``target_ratio``: a number, "LO:HI", ">=X",
    "<=X" or a pair (LO, HI)), ``minimise``/``maximise`` ("mu_s", "mu_d", "ratio"), the space
    (min_np, max_np, min_ng, max_ng, levels, factors, min_fraction, max_fraction, fraction_step,
    min_contact, max_contact, min_feature), the search (top, verify_reps, verify_max_reps,
    resolution, screen_reps, eta, growth, max_reps, final_pool, class_width, class_margin,
    class_prune) and any scene field but pattern, reps and stop_after_mu_s (N, seed, threads, ...).
    ``out`` writes the full JSON to a file (atomically); ``progress`` is called on this thread with
    a dict (stage, fraction, elapsed_s). Bad input raises InputError naming the keyword.
    """
    command_line = _command_line("design", query)
    j = _core.design(query, os.fspath(out) if out is not None else "", progress, command_line)
    return DesignResult(j)


__all__ = ["DesignResult", "SweepResult", "design", "sweep"]
