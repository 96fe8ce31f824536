"""1-D spring-block friction model (Costagliola, Bosia & Pugno, PRE 2016).

``Scene(**fields)`` configures a simulation with the command line's field names, defaults and
units; ``run(scene)`` runs its repetitions and returns a ``Result``; ``sweep(file_or_dict)`` runs a
whole sweep as ``springblock sweep`` does; ``design(...)`` answers the query ``springblock design``
answers; ``theory`` holds the closed forms. Scenes and results pickle exactly, so they travel to
other processes (``multiprocessing``, ``concurrent.futures``); every result has ``records()``
(plain dicts) and ``to_pandas()`` (a DataFrame, when pandas is installed).
"""
from springblock import _core
from springblock._core import (InputError, Result, Scene, Series, Statistic, __version__, observables,
                               pattern_text, scene_fields, theory)
from springblock._studies import DesignResult, SweepResult, design, sweep
from springblock._tables import result_records, result_to_pandas


def run(scene, series=False):
    """Run the scene's repetitions (in parallel over its ``threads``) and return a Result.

    The same scene and seed give the numbers ``springblock run`` gives (with series=True, those of
    ``springblock run --series FILE``); series=True keeps mu(t) of repetition 0 (Result.series).
    The GIL is released while it runs, and Ctrl-C stops it cleanly. A plain Python function, so
    it pickles by name: ``pool.map(springblock.run, scenes)`` works in a process pool.
    """
    return _core.run(scene, series)


def run_many(scenes, series=False):
    """Run several scenes in one pool of threads (every scene-repetition is one job); each result
    is what run() gives that scene."""
    return _core.run_many(scenes, series)


Result.records = result_records
Result.to_pandas = result_to_pandas
# Documented (and pickled) as the package's own, where users find them.
for _public in (DesignResult, SweepResult, design, sweep):
    _public.__module__ = __name__
del _public

__all__ = ["DesignResult", "InputError", "Result", "Scene", "Series", "Statistic", "SweepResult", "__version__",
           "design", "observables", "pattern_text", "run", "run_many", "scene_fields", "sweep", "theory"]
