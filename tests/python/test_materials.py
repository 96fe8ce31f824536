"""Per-block materials from Python: numpy arrays and lists, segments, and their checks."""
import numpy as np
import pytest

import springblock as sb

BASE = dict(N=30, reps=2, seed=3, duration="3t0")


def test_arrays_of_the_defaults_give_the_uniform_result_bit_for_bit():
    n = BASE["N"]
    arrays = {"mu_s": np.full(n, 1.0), "mu_s_sd": [0.1] * n, "mu_d": np.full(n, 0.5),
              "mu_d_sd": np.full(n, 0.01), "k_s_scale": np.ones(n)}
    for method in ("event", "rk4"):
        uniform = sb.run(sb.Scene(BASE, method=method))
        given = sb.run(sb.Scene(BASE, method=method, materials=arrays))
        assert given.mu_s.mean.hex() == uniform.mu_s.mean.hex()
        assert given.mu_d.mean.hex() == uniform.mu_d.mean.hex()


def test_arrays_are_recorded_with_source_and_hash():
    ramp = np.linspace(0.8, 1.2, BASE["N"])
    m = sb.Scene(BASE, materials={"mu_s": ramp}).to_dict()["materials"]
    assert m["source"] == "python arrays" and m["fields"] == ["mu_s"] and len(m["hash"]) == 16
    other = sb.Scene(BASE, materials={"mu_s": ramp[::-1].copy()}).to_dict()["materials"]
    assert other["hash"] != m["hash"]
    assert sb.Scene(BASE).to_dict()["materials"] == {"source": "uniform", "hash": "cbf29ce484222325", "fields": []}


def test_bool_contact_and_rk4_mechanics():
    n = BASE["N"]
    contact = np.arange(n) % 3 != 2
    mass = np.where(np.arange(n) < n // 2, 1.0, 2.0)
    r = sb.run(sb.Scene(BASE, method="rk4", materials={"contact": contact, "mass_scale": mass}))
    assert r.contact_fraction == pytest.approx(contact.mean())
    assert 0 < r.mu_s.mean < 2


def test_a_file_by_path_or_pathlib(tmp_path):
    f = tmp_path / "m.tsv"
    f.write_text("mu_s\tmu_d\n" + "1.1\t0.5\n" * BASE["N"])
    by_text = sb.Scene(BASE, materials=str(f)).to_dict()["materials"]
    assert by_text == sb.Scene(BASE, materials=f).to_dict()["materials"]
    assert by_text["source"] == str(f) and by_text["fields"] == ["mu_s", "mu_d"]
    with pytest.raises(sb.InputError, match="cannot read materials file"):
        sb.Scene(BASE, materials=tmp_path / "missing.tsv")


def test_segments_as_dicts():
    s = sb.Scene(BASE, segments=[{"field": "mu_s", "from": 0, "to": 14, "value": np.float64(1.2)},
                                 {"field": "mu_d", "from": 15, "to": -1, "start": 0.4, "end": 0.6}])
    m = s.to_dict()["materials"]
    assert m["source"] == "segments" and m["fields"] == ["mu_s", "mu_d"]
    assert m["segments"][1] == {"field": "mu_d", "from": 15, "to": -1, "start": 0.4, "end": 0.6}


@pytest.mark.parametrize("fields, words", [
    ({"materials": {"mu_s": np.ones(29)}}, "mu_s has 29 values; the scene has N = 30 blocks"),
    ({"materials": {"mu_s_sd": np.full(30, -0.1)}}, "python arrays, block 0, column mu_s_sd: value -0.1"),
    ({"materials": {"mu_s": np.full(30, np.nan)}}, "column mu_s: value nan is outside"),
    ({"materials": {"grip": np.ones(30)}}, "unknown field 'grip'"),
    ({"materials": {"mu_s": np.ones((30, 2))}}, "must be a 1-D array"),
    ({"segments": [{"field": "mu_s", "from": 0, "to": 30, "value": 1.0}]}, "segments.0 (mu_s): blocks from = 0 to = 30"),
])
def test_bad_arrays_raise_input_error(fields, words):
    with pytest.raises(sb.InputError, match=None) as e:
        sb.Scene(BASE, **fields)
    assert words in str(e.value)
