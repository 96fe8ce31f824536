"""Results as tables: records() needs nothing beyond the package, to_pandas() imports pandas only
when called and says how to get it when it is missing."""
import subprocess
import sys

import pytest

import springblock as sb


@pytest.fixture(scope="module")
def result():
    return sb.run(sb.Scene(N=30, reps=3, seed=2, duration="3t0"))


def test_records_are_the_runs_flattened(result):
    rows = result.records()
    assert len(rows) == 3
    assert [r["mu_s"] for r in rows] == list(result.mu_s.values)
    assert rows[1]["rep"] == 1 and rows[0]["work_block_steps"] == result.runs[0]["work"]["block_steps"]


def test_to_pandas_has_a_row_per_repetition(result):
    pandas = pytest.importorskip("pandas")
    frame = result.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame["mu_s"]) == list(result.mu_s.values)


def test_without_pandas_records_work_and_to_pandas_says_why(result, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # as if it were not installed
    assert len(result.records()) == 3
    with pytest.raises(ImportError, match="python3-pandas"):
        result.to_pandas()


def test_the_package_does_not_import_pandas():

    code = "import sys, springblock; print('pandas' in sys.modules)"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "False"
