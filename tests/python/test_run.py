"""springblock.run gives the command line's numbers for the same scene and seed."""
import threading
import time

import numpy as np
import pytest

import springblock as sb

FIELDS = dict(N=40, reps=4, seed=7, pattern="periodic:2,6", duration="3t0")
ARGS = ["--N", 40, "--reps", 4, "--seed", 7, "--pattern", "periodic:2,6", "--duration", "3t0"]
# The series at the default spacing is 4.8 million rows (167 MB of TSV; the test below took 42 s);
# every 0.1 ms, 48,001 rows make the same row-by-row check.
SERIES_FIELDS = dict(FIELDS, sample_dt="0.1ms")
SERIES_ARGS = ARGS + ["--sample-dt", "0.1ms"]


@pytest.fixture(scope="module")
def result():
    return sb.run(sb.Scene(**FIELDS))


@pytest.fixture(scope="module")
def with_series():
    return sb.run(sb.Scene(**SERIES_FIELDS), series=True)


def test_same_seed_same_numbers_as_the_cli(cli, result):
    expected = cli("run", *ARGS, "--json")
    for name in ("mu_s", "mu_d"):
        assert getattr(result, name).mean == expected[name]["mean"]
        assert getattr(result, name).sem == expected[name]["sem"]
        assert getattr(result, name).n == expected[name]["n"]
    assert list(result.mu_s.values) == [run["mu_s"] for run in expected["runs"]]
    assert list(result.mu_d.values) == [run["mu_d"] for run in expected["runs"]]


def test_with_series_same_numbers_as_the_cli_with_series(cli, with_series, tmp_path):
    # Keeping mu(t) changes no statistic: the same numbers as the command line with or without it.
    expected = cli("run", *SERIES_ARGS, "--series", tmp_path / "mu.tsv", "--json")
    assert expected["mu_s"] == cli("run", *SERIES_ARGS, "--json")["mu_s"]
    assert list(with_series.mu_s.values) == [run["mu_s"] for run in expected["runs"]]
    assert with_series.mu_d.mean == expected["mu_d"]["mean"]
    # The TSV's t and mu columns are the series' t and mu, written with 9 significant digits.
    rows = [line.split("\t") for line in (tmp_path / "mu.tsv").read_text().splitlines()
            if line and not line.startswith("#")]
    assert [float(row[0]) for row in rows[1:]] == [float(f"{x:.9g}") for x in with_series.series.t]
    assert [float(row[1]) for row in rows[1:]] == [float(f"{x:.9g}") for x in with_series.series.mu]


def test_results_json_is_the_clis(cli, result):
    expected = cli("run", *ARGS, "--json")
    got = result.to_json()
    for volatile in ("provenance", "wall_seconds", "runs"):
        expected.pop(volatile, None), got.pop(volatile, None)
    assert got == expected


def test_every_observable_is_an_attribute(result):
    for name, unit in sb.observables():
        stat = getattr(result, name)
        assert stat.name == name and stat.unit == unit
        assert isinstance(stat.values, np.ndarray) and stat.values.shape == (4,)
        assert stat.n <= 4


def test_series_of_repetition_zero(with_series):
    result = with_series
    s = result.series
    assert len(s.t) == len(s.mu) == len(s.mu_signed) == len(s.n_sliding) > 100
    assert np.all(np.diff(s.t) > 0)
    # mu_s is the running maximum of these very samples.
    assert result.mu_s.values[0] == np.max(s.mu[s.t <= result.t_peak_s.values[0]])


def test_series_is_left_out_by_default(result):
    assert len(result.series.t) == 0


def test_stress_snapshots_when_asked():
    r = sb.run(sb.Scene(FIELDS, stress_times="1ms,2ms"))
    assert [snap["t"] for snap in r.stress] == pytest.approx([1e-3, 2e-3])
    assert all(snap["f_over_Fn"].shape == (40,) for snap in r.stress)
    assert sb.run(sb.Scene(**FIELDS)).stress == []


def test_thread_count_does_not_change_the_numbers(result):
    one = sb.run(sb.Scene(FIELDS, threads=1))
    assert list(one.mu_s.values) == list(result.mu_s.values)


def test_run_many_equals_run(result):
    other = sb.Scene(FIELDS, seed=8)
    many = sb.run_many([sb.Scene(**FIELDS), other])
    assert list(many[0].mu_d.values) == list(result.mu_d.values)
    assert many[1].mu_s.mean == sb.run(other).mu_s.mean


def test_nothing_measured_is_nan_with_the_reason():
    # The command line exits 3 here; the module returns NaN statistics that say why.
    r = sb.run(sb.Scene(FIELDS, duration="0.05t0", mu_d_skip=0))
    assert r.mu_s.n == 0 and np.isnan(r.mu_s.mean) and np.all(np.isnan(r.mu_s.values))
    assert "loading phase" in r.mu_s.not_measured
    assert sb.run(sb.Scene(FIELDS, stop_after_mu_s=True)).mu_d.not_measured == "stop_after_mu_s"


def test_gil_is_released_during_a_run():
    ticks = 0
    worker = threading.Thread(target=sb.run, args=(sb.Scene(FIELDS, N=200, reps=2, threads=1),))
    worker.start()
    while worker.is_alive():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    assert ticks > 10


def test_slip_events_are_the_clis(cli):
    # Each repetition's events as numpy columns, the same as `run --slip-events true --json`.
    r = sb.run(sb.Scene(FIELDS, slip_events=True))
    expected = cli("run", *ARGS, "--slip-events", "true", "--json")
    assert len(r.slip_events) == 4
    for mine, theirs in zip(r.slip_events, (run["slip_events"] for run in expected["runs"])):
        assert mine["blocks"].dtype.kind == "i" and len(mine["blocks"]) > 0
        for key in ("t_start_s", "duration_s", "blocks", "episodes", "slip_m"):
            assert list(mine[key]) == theirs[key]
        assert mine["unfinished"] == theirs["unfinished"] and (mine["under_way"] is None) == (not mine["unfinished"])
    assert r.to_json()["slip_events"] == expected["slip_events"]


def test_slip_events_are_none_unless_asked(result):
    assert result.slip_events is None
    assert "slip_events" not in result.to_json()
