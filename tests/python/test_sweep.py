"""springblock.sweep runs the library's sweep: the same files and numbers as `springblock sweep`,
the same checkpoint (a sweep stopped in Python resumes in Python or on the command line), a
progress callback on the calling thread, and results as records and DataFrames."""
import json
import os
import shutil
import signal
import threading

import pytest

import springblock as sb

SWEEP = """[base]
N = 60
duration = "8t0"
velocity = "5cm/s"
reps = 4
seed = 3
[axes]
pattern = ["smooth", "periodic:3,1", "hierarchical:2,2"]
"""
# Long enough (about 1 s on one thread) for progress to be reported before it ends.
LONG = SWEEP.replace("N = 60", "N = 100").replace('"8t0"', '"30t0"')
AS_DICT = {"base": {"N": 60, "duration": "8t0", "velocity": "5cm/s", "reps": 4, "seed": 3},
           "axes": {"pattern": ["smooth", "periodic:3,1", "hierarchical:2,2"]}}
UNITS = 12
# What differs between two runs of the same sweep: times, and which rank ran a unit.
VOLATILE = {"wall_s", "cpu_s", "rank"}


def lines(path):
    with open(path) as f:
        return [json.loads(line) for line in f]


def stable(scene_line):
    """A results line without what the clock or the scheduler decides."""
    out = {k: v for k, v in scene_line.items() if k not in VOLATILE}
    if "runs" in out:
        out["runs"] = [{k: v for k, v in run.items() if k not in VOLATILE} for run in out["runs"]]
    return out


@pytest.fixture
def sweep_file(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(SWEEP)
    return path


@pytest.fixture
def cli_results(cli, sweep_file, tmp_path):
    out = tmp_path / "cli.jsonl"
    done = cli("sweep", sweep_file, "--threads", 2, "--out", out, check=False)
    assert done.returncode == 0, done.stderr
    return lines(out)


def test_same_results_as_the_command_line(sweep_file, tmp_path, cli_results):
    result = sb.sweep(sweep_file, tmp_path / "py.jsonl", threads=1)
    assert len(result) == 3 and result.report["computed"] == UNITS
    mine = lines(tmp_path / "py.jsonl")
    assert [stable(x) for x in mine[1:]] == [stable(x) for x in cli_results[1:]]
    assert mine[0]["file"] == cli_results[0]["file"] and mine[0]["units"] == UNITS
    assert result.scenes[0]["mu_s"] == cli_results[1]["mu_s"]
    assert not (tmp_path / "py.jsonl.checkpoint").exists()  # complete: the results hold every unit
    assert "mu_s" in result.summary


def test_a_dict_is_the_same_sweep(tmp_path, cli_results):
    result = sb.sweep(AS_DICT, tmp_path / "d.jsonl", threads=2)
    assert [stable(x) for x in result.scenes] == [stable(x) for x in cli_results[1:]]
    assert result.header["file"] == "sweep dict"


def test_stopped_by_the_callback_then_resumed(tmp_path, cli):
    sweep_file, out = tmp_path / "long.toml", tmp_path / "r.jsonl"
    sweep_file.write_text(LONG)
    done = cli("sweep", sweep_file, "--threads", 2, "--out", tmp_path / "clean.jsonl", check=False)
    assert done.returncode == 0, done.stderr
    clean = lines(tmp_path / "clean.jsonl")
    calls = []

    class Enough(Exception):
        pass

    def stop_early(p):
        calls.append((threading.get_ident(), p))
        if p["done"] >= 2:
            raise Enough()

    with pytest.raises(Enough):
        sb.sweep(sweep_file, out, threads=1, progress=stop_early)
    assert {ident for ident, _ in calls} == {threading.get_ident()}  # the calling thread, never a worker
    assert not out.exists() and (tmp_path / "r.jsonl.checkpoint").exists()
    checkpointed = sum('"unit"' in line for line in open(tmp_path / "r.jsonl.checkpoint"))
    assert 2 <= checkpointed < UNITS
    # The same checkpoint resumes on the command line as in Python: both compute only what is missing.
    shutil.copy(tmp_path / "r.jsonl.checkpoint", tmp_path / "c.jsonl.checkpoint")
    done = cli("sweep", sweep_file, "--out", tmp_path / "c.jsonl", "--resume", check=False)
    assert done.returncode == 0, done.stderr
    resumed = sb.sweep(sweep_file, out, resume=True)
    assert resumed.report["computed"] == UNITS - checkpointed
    assert resumed.header["resumed_units"] == checkpointed
    assert [stable(x) for x in resumed.scenes] == [stable(x) for x in clean[1:]]
    assert [stable(x) for x in lines(tmp_path / "c.jsonl")[1:]] == [stable(x) for x in clean[1:]]


def test_ctrl_c_leaves_the_checkpoint(tmp_path):
    sweep_file, out = tmp_path / "long.toml", tmp_path / "i.jsonl"
    sweep_file.write_text(LONG)

    def press_ctrl_c(p):
        if p["done"] >= 1:
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        sb.sweep(sweep_file, out, threads=1, progress=press_ctrl_c)
    assert not out.exists() and (tmp_path / "i.jsonl.checkpoint").exists()
    assert (tmp_path / "i.jsonl.partial").exists()  # the scenes complete so far, marked partial
    resumed = sb.sweep(sweep_file, out, resume=True)
    assert 0 < resumed.report["resumed"] < UNITS and resumed.report["computed"] == UNITS - resumed.report["resumed"]


def test_units_file_is_the_command_lines(sweep_file, tmp_path, cli):
    done = cli("sweep", sweep_file, "--out", tmp_path / "c.jsonl", "--units", tmp_path / "c.units", check=False)
    assert done.returncode == 0, done.stderr
    sb.sweep(sweep_file, tmp_path / "p.jsonl", units=tmp_path / "p.units")
    mine, theirs = lines(tmp_path / "p.units"), lines(tmp_path / "c.units")
    assert len(mine) == UNITS
    assert sorted((stable(x) for x in mine), key=lambda x: x["unit"]) == \
        sorted((stable(x) for x in theirs), key=lambda x: x["unit"])


def test_progress_reaches_the_end(sweep_file, tmp_path):
    seen = []
    sb.sweep(sweep_file, tmp_path / "p.jsonl", progress=seen.append)
    assert seen and seen[-1]["done"] == seen[-1]["total"] == UNITS and seen[-1]["fraction"] == 1


def test_records_and_data_frames(sweep_file, tmp_path):
    result = sb.sweep(sweep_file, tmp_path / "t.jsonl")
    rows = result.records()
    assert [r["pattern"] for r in rows] == ["smooth", "periodic:3,1", "hierarchical:2,2"]
    assert [r["mu_s_mean"] for r in rows] == [s["mu_s"]["mean"] for s in result.scenes]
    runs = result.run_records()
    assert len(runs) == UNITS and runs[5]["mu_s"] == result.scenes[1]["runs"][1]["mu_s"]
    pandas = pytest.importorskip("pandas")
    frame = result.to_pandas()
    assert isinstance(frame, pandas.DataFrame) and list(frame["mu_s_mean"]) == [r["mu_s_mean"] for r in rows]
    assert len(result.to_pandas(runs=True)) == UNITS


def test_a_varied_field_named_like_an_observable_keeps_a_prefix(tmp_path):
    result = sb.sweep({"base": {"N": 20, "reps": 1, "duration": "3t0"}, "axes": {"mu_s": ["1.0,0.1", "1.2,0.1"]}},
                      tmp_path / "m.jsonl")
    row = result.records()[1]
    assert row["mu_s"] == "1.2,0.1" and "mu_s_mean" in row
    assert result.run_records()[1]["varied_mu_s"] == "1.2,0.1"


@pytest.mark.parametrize("spec, out, field", [
    ({"base": {"N": 0}}, "x.jsonl", "N"),
    ({"base": {"N": 20}, "axes": {"pattern": []}}, "x.jsonl", "pattern"),
    ({"base": {"N": 20}}, None, "out"),
    (42, "x.jsonl", "sweep"),
])
def test_bad_input_names_the_field_and_writes_nothing(tmp_path, spec, out, field):
    with pytest.raises(sb.InputError) as e:
        sb.sweep(spec, tmp_path / out if out else None)
    assert e.value.field == field
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("threads", [-1, 4097])
def test_a_thread_count_outside_the_command_lines_range_is_refused(tmp_path, threads):
    with pytest.raises(sb.InputError) as e:
        sb.sweep({"base": {"N": 20, "reps": 1}}, tmp_path / "x.jsonl", threads=threads)
    assert e.value.field == "threads" and "[0, 4096]" in str(e.value)
    assert list(tmp_path.iterdir()) == []


def test_a_results_file_of_the_command_line_reads_back(tmp_path, cli_results):
    path = tmp_path / "cli.jsonl"
    result = sb.SweepResult(path)
    assert result.report is None and result.header == cli_results[0] and len(result) == 3
    assert [r["mu_d_mean"] for r in result.records()] == [s["mu_d"]["mean"] for s in cli_results[1:]]


def test_numpy_values_and_mask_arrays_in_a_dict_are_the_file_it_stands_for(tmp_path):
    import numpy as np
    mask = np.arange(20) % 4 != 3
    text = "mask:" + "".join("1" if b else "0" for b in mask)
    base = {"N": 20, "duration": "2t0", "velocity": "5cm/s", "reps": 2, "seed": 3}
    plain = sb.sweep({"base": {**base, "pattern": text}, "axes": {"pressure": [1e6, 2e6]}}, tmp_path / "a.jsonl")
    numpy = sb.sweep({"base": {**base, "pattern": mask}, "axes": {"pressure": np.array([1e6, 2e6])}},
                     tmp_path / "b.jsonl")
    strip = lambda r: [{k: v for k, v in row.items() if k not in VOLATILE} for row in r.run_records()]
    assert strip(numpy) == strip(plain) and len(plain.run_records()) == 4
    on_axis = sb.sweep({"base": base, "axes": {"pattern": [mask, "smooth"]}}, tmp_path / "c.jsonl")
    assert [s["varied"]["pattern"] for s in on_axis.scenes] == [text, "smooth"]


@pytest.mark.parametrize("base, field", [({"length": float("nan")}, "length"),
                                         ({"pressure": float("inf")}, "pressure"),
                                         ({"velocity": object()}, "velocity"),
                                         ({"pattern": [0, 2, 1]}, "pattern")])
def test_a_value_a_sweep_file_cannot_hold_is_refused_naming_its_field(tmp_path, base, field):
    with pytest.raises(sb.InputError) as e:
        sb.sweep({"base": {"N": 20, "reps": 1, **base}}, tmp_path / "x.jsonl")
    assert e.value.field == field, str(e.value)
    assert list(tmp_path.iterdir()) == []
