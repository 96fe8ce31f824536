"""springblock.design answers the query `springblock design` answers, with the same numbers, and
refuses what the command line refuses, naming the keyword."""
import threading

import numpy as np
import pytest

import springblock as sb

QUERY = dict(N=40, seed=5, top=3, verify_reps=3, verify_max_reps=6, family="given",
             candidates=["periodic:2,6", "periodic:3,1", "periodic:1,1", "hierarchical:4,2"], target_mu_s=0.6)
ARGS = ["--N", 40, "--seed", 5, "--top", 3, "--verify-reps", 3, "--verify-max-reps", 6, "--family", "given",
        "--candidates", "periodic:2,6", "periodic:3,1", "periodic:1,1", "hierarchical:4,2", "--target-mu-s", "0.6"]
VOLATILE = {"wall_s", "wall_seconds", "cpu_s", "wall_share_s", "provenance"}


def stable(x):
    """The design JSON without what the clock decides."""
    if isinstance(x, dict):
        return {k: stable(v) for k, v in x.items() if k not in VOLATILE}
    if isinstance(x, list):
        return [stable(v) for v in x]
    return x


@pytest.fixture(scope="module")
def answer():
    return sb.design(**QUERY)


def test_same_answers_as_the_command_line(cli, answer):
    expected = cli("design", *ARGS, "--json")
    assert len(answer.best) == 3
    assert stable(answer.best) == stable(expected["best"])
    assert stable(answer.json["search"]) == stable(expected["search"])
    assert answer.feasible == expected["feasible"]
    got, want = stable(answer.json), stable(expected)
    assert got.keys() == want.keys()
    assert {k: v for k, v in got.items() if k != "command_line"} == {k: v for k, v in want.items() if k != "command_line"}


def test_masks_as_arrays_are_candidates_too(answer):
    mask = np.array([1, 1, 0, 0, 0, 0, 0, 0] * 5)  # periodic:2,6 laid out pawl first
    result = sb.design(**{**QUERY, "candidates": [mask, "periodic:3,1"], "top": 2})
    assert {b["pattern"].startswith("mask:") for b in result.best} == {True, False}


def test_records_data_frame_and_progress(tmp_path):
    seen = []
    result = sb.design(**QUERY, out=tmp_path / "d.json", progress=lambda p: seen.append((threading.get_ident(), p)))
    rows = result.records()
    assert [r["pattern"] for r in rows] == [b["pattern"] for b in result.best]
    assert rows[0]["mu_s_mean"] == result.best[0]["mu_s"]["mean"]
    assert (tmp_path / "d.json").exists()
    assert {ident for ident, _ in seen} <= {threading.get_ident()}
    pandas = pytest.importorskip("pandas")
    assert list(result.to_pandas()["pattern"]) == [r["pattern"] for r in rows]


@pytest.mark.parametrize("change, field", [
    (dict(pattern="periodic:2,2"), "pattern"),
    (dict(reps=4), "reps"),
    (dict(N=0), "N"),
    (dict(top="three"), "top"),
    (dict(target_mu_s="abc"), "target_mu_s"),
    (dict(minimise="mu_s", maximise="mu_d"), "maximise"),
    (dict(family="spiral"), "family"),
    (dict(colour="red"), "colour"),
])
def test_bad_keywords_are_named(tmp_path, change, field):
    with pytest.raises(sb.InputError) as e:
        sb.design(**{**QUERY, **change}, out=tmp_path / "d.json")
    assert e.value.field == field
    assert list(tmp_path.iterdir()) == []
