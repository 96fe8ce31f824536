#!/usr/bin/python3
"""tools/readme_cost.py's run lines on synthetic run records (no simulation, a second): one run is
printed as it is; several runs of one commit are judged on the median one, every total listed;
runs of different commits, tiers or build states are refused; the goals' verdicts follow the
numbers they are given."""
import os
import sys
import unittest

sys.dont_write_bytecode = True
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "tools"))
import readme_cost as rc  # noqa: E402


def record(total, targets, commit="abc1234", tier="paper", units=25):
    return {"commit": commit, "tier": tier, "cores": 2, "dirty": False, "date": "2026-11-24",
            "compiled_units": units, "total_s": total,
            "phases_s": {"configure": 5.0, "build": 100.0, "targets": targets, "figures": 20.0},
            "targets_s": {"tab_pat0": 0.4 * targets, "fig2": 0.3 * targets, "tab_pat2": 0.3 * targets}}


class RunLines(unittest.TestCase):
    def test_one_run_is_printed_as_it_is(self):
        text = "\n".join(rc.run_lines([record(431.0, 294.0)]))
        self.assertIn("whole command 431 s from a fresh clone (25 translation units compiled)", text)
        self.assertIn("targets at most 300 s (met: 294 s)", text)
        self.assertIn("fresh clone at most 420 s (not met: 431 s)", text)

    def test_several_runs_are_judged_on_the_median(self):
        runs = [record(452.0, 310.0), record(405.0, 260.0), record(431.0, 294.0)]
        text = "\n".join(rc.run_lines(runs))
        self.assertIn("3 runs: 405 s, 431 s, 452 s; the median run (431 s) in detail", text)
        self.assertIn("targets at most 300 s (met: the median run's 294 s)", text)
        self.assertIn("fresh clone at most 420 s (not met: the median run's 431 s)", text)
        # The detail lines are the median run's: its targets, not the fastest run's.
        self.assertIn("targets 294 s", text)
        self.assertNotIn("targets 260 s", text)

    def test_an_even_count_takes_the_lower_middle(self):
        text = "\n".join(rc.run_lines([record(400.0, 250.0), record(440.0, 310.0)]))
        self.assertIn("the median run (400 s)", text)

    def test_runs_that_differ_are_refused(self):
        for other in (record(420.0, 280.0, commit="def5678"), record(420.0, 280.0, tier="quick"),
                      record(420.0, 280.0, units=0)):
            with self.assertRaises(SystemExit):
                rc.run_lines([record(431.0, 294.0), other])


if __name__ == "__main__":
    unittest.main()
