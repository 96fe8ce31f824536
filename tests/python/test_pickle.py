"""Scenes and results pickle exactly: an unpickled scene equals the original field for field and
runs bit-identically, in this process or in others (concurrent.futures), where the numbers are
the command line's."""
import concurrent.futures
import math
import multiprocessing
import pickle

import numpy as np
import pytest

import springblock as sb

FIELDS = dict(N=40, reps=3, seed=7, pattern="periodic:2,6", duration="3t0")
ARGS = ["--N", 40, "--reps", 3, "--seed", 7, "--pattern", "periodic:2,6", "--duration", "3t0"]


def copied(x):
    return pickle.loads(pickle.dumps(x))


def same(a, b):
    """Equal, NaN equal to NaN (a repetition's undefined value)."""
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return a == b


def numbers(result):
    """Every number of a result that the seed fixes (not the times)."""
    runs = [{k: v for k, v in run.items() if k not in ("wall_s", "cpu_s")} for run in result.runs]
    for run in runs:
        run["work"] = {k: v for k, v in run["work"].items() if not k.endswith("_s")}
    stats = {name: (getattr(result, name).mean, getattr(result, name).std, getattr(result, name).n)
             for name, _ in sb.observables()}
    return runs, stats


def scenes_to_test():
    """Scenes that exercise every kind of state: each field of the table at its example value, a
    mask given as blocks, per-block arrays and segments, series and stress observation."""
    yield sb.Scene()
    yield sb.Scene(**FIELDS)
    for row in sb.scene_fields():
        if row["key"] in ("materials",):  # a file's path; arrays are tested below
            continue
        yield sb.Scene(**{row["key"]: row["example"]})
    mask = np.zeros(40, dtype=bool)
    mask[::3] = True
    yield sb.Scene(N=40, pattern=mask, reps=2, seed=3)
    yield sb.Scene(N=40, reps=2, materials={"mu_s": np.linspace(0.9, 1.1, 40)},
                   segments=[{"field": "mu_d", "from": 5, "to": 9, "value": 0.4},
                             {"field": "k_s_scale", "from": 0, "to": -1, "start": 1.0, "end": 2.0}])
    yield sb.Scene(N=30, reps=2, stress_times="1ms,2ms", slip_events=True, seed=2**63 - 1)


@pytest.mark.parametrize("scene", list(scenes_to_test()), ids=repr)
def test_an_unpickled_scene_is_the_same_scene(scene):
    back = copied(scene)
    assert back == scene and hash(back) == hash(scene)
    assert back.to_dict() == scene.to_dict()
    assert back is not scene


def test_scenes_that_differ_in_one_field_are_not_equal():
    # The test above could not fail if equality ignored the fields: here one field differs.
    assert sb.Scene(**FIELDS) != sb.Scene(**FIELDS).replace(seed=8)
    assert sb.Scene(**FIELDS) != sb.Scene(**FIELDS).replace(mu_d="0.5,0.02")
    mask = [1, 0] * 20
    other = list(mask)
    other[3] = 1
    assert sb.Scene(N=40, pattern=mask) != sb.Scene(N=40, pattern=other)


def test_an_unpickled_scene_runs_bit_identically():
    for scene in (sb.Scene(**FIELDS), sb.Scene(N=40, reps=2, materials={"mu_s": np.linspace(0.9, 1.1, 40)},
                                              slip_events=True)):
        assert same(numbers(sb.run(copied(scene))), numbers(sb.run(scene)))


def test_a_result_pickles_with_every_number():
    # mu(t) every 0.1 ms: at the default spacing the series is 1.6 million samples and this test
    # took 7.7 s.
    scene = sb.Scene(N=30, reps=3, seed=4, slip_events=True, stress_times="1ms", sample_dt="0.1ms")
    result = sb.run(scene, series=True)
    back = copied(result)
    assert back.scene == result.scene
    assert same(back.runs, result.runs)
    for name, _ in sb.observables():
        a, b = getattr(result, name), getattr(back, name)
        assert same([a.mean, a.std, a.sem, a.n], [b.mean, b.std, b.sem, b.n])
        assert np.array_equal(a.values, b.values, equal_nan=True)
    assert np.array_equal(back.series.mu, result.series.mu) and len(result.series.mu) > 0
    assert same([{k: list(v) if hasattr(v, "tolist") else v for k, v in s.items()} for s in back.stress],
                [{k: list(v) if hasattr(v, "tolist") else v for k, v in s.items()} for s in result.stress])
    assert back.contact_fraction == result.contact_fraction and back.wall_s == result.wall_s
    assert same(back.to_json(), result.to_json())


def test_a_foreign_state_is_refused():
    with pytest.raises(sb.InputError, match="state") as e:
        sb.Scene.__new__(sb.Scene).__setstate__('{"N": 3}')
    assert e.value.field == "state"


def run_in_child(scene):
    """What a worker process returns: the result itself, pickled back."""
    return sb.run(scene)


def in_pool(context, function, items):
    """pool.map in processes started by `context`, stopped (not waited for) if they hang."""
    pool = concurrent.futures.ProcessPoolExecutor(max_workers=2, mp_context=multiprocessing.get_context(context))
    try:
        futures = [pool.submit(function, item) for item in items]
        done, late = concurrent.futures.wait(futures, timeout=120)
        if late:
            for process in list(pool._processes.values()):
                process.kill()
            pytest.fail(f"{len(late)} job(s) of a {context} process pool did not finish in 120 s")
        return [f.result() for f in futures]
    finally:
        pool.shutdown(wait=False, cancel_futures=True)


# spawn: fresh interpreters, which import springblock themselves and receive only the pickles.
# fork (Linux's default): children of this process, which has run scenes on its threads, whose
# idle threads the children do not inherit.
@pytest.mark.parametrize("context", ["spawn", "fork"])
def test_a_process_pool_gives_the_command_lines_numbers(cli, context):
    scenes = [sb.Scene(**FIELDS), sb.Scene(**FIELDS).replace(seed=8)]
    here = [sb.run(s) for s in scenes]  # threads kept idle in this process, before the pool starts
    results = in_pool(context, run_in_child, scenes)
    direct = in_pool(context, sb.run, scenes)  # the package's own function travels too
    for seed, result, other, mine in zip((7, 8), results, direct, here):
        args = [a if a != 7 else seed for a in ARGS]
        expected = cli("run", *args, "--json")
        assert [r["mu_s"] for r in result.runs] == [r["mu_s"] for r in expected["runs"]]
        assert [r["mu_d"] for r in result.runs] == [r["mu_d"] for r in expected["runs"]]
        for name in ("mu_s", "mu_d"):
            assert getattr(result, name).mean == expected[name]["mean"]
            assert getattr(result, name).sem == expected[name]["sem"]
        assert same(numbers(other), numbers(result)) and same(numbers(mine), numbers(result))


def test_a_scene_is_not_equal_to_other_things():
    assert sb.Scene() != 3 and not (sb.Scene() == "smooth")
