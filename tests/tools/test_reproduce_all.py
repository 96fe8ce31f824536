#!/usr/bin/python3
"""tools/reproduce_all.py runs the reproduction targets itself from <build>/reproduce/commands.json
(no simulation here, a second): a target runs when its output is missing or older than an input,
as make would; a target whose input another target has just rewritten runs again; each target's
output goes to its own log; a launcher (--mpirun) starts each target; a failing target stops the
run with its log's tail."""
import contextlib
import io
import json
import os
import sys
import tempfile
import time
import unittest

sys.dont_write_bytecode = True
from tools import reproduce_all as ra  # noqa: E402


def touch(path, t):
    with open(path, "a"):
        pass
    os.utime(path, (t, t))


class UpToDate(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.out = os.path.join(self.dir.name, "out.json")
        self.dep = os.path.join(self.dir.name, "program")
        self.cmd = {"output": self.out, "depends": [self.dep]}

    def tearDown(self):
        self.dir.cleanup()

    def test_make_rule(self):
        # (output's mtime, input's mtime, None: missing) -> up to date
        cases = {"missing output runs": (None, 1000, False), "newer input runs": (1000, 1001, False),
                 "missing input runs": (1000, None, False), "older input does not": (1000, 999, True),
                 "input as old as the output does not": (1000, 1000, True)}
        for name, (out, dep, expected) in cases.items():
            with self.subTest(name):
                for path, t in ((self.out, out), (self.dep, dep)):
                    if os.path.exists(path):
                        os.remove(path)
                    if t is not None:
                        touch(path, t)
                self.assertEqual(ra.up_to_date(self.cmd), expected)


class RunTargets(unittest.TestCase):
    """Two targets, b reading a's output, each a shell command that counts its runs."""

    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.build = self.dir.name
        self.rdir = os.path.join(self.build, "reproduce")
        self.logs = os.path.join(self.build, "logs")
        os.makedirs(self.rdir), os.makedirs(self.logs)
        with open(os.path.join(self.rdir, "targets.txt"), "w") as f:
            f.write("a\nb\n")
        self.program = os.path.join(self.build, "program")
        touch(self.program, time.time() - 100)
        self.write_commands(fail=None)

    def tearDown(self):
        self.dir.cleanup()

    def out(self, n):
        return os.path.join(self.rdir, f"{n}.json")

    def write_commands(self, fail):
        cmds = {}
        for n, deps in (("a", [self.program]), ("b", [self.program, self.out("a")])):
            script = (f"echo '[{n}] 50.0% done'; echo ran >> {n}.runs; echo ${{SB_LAUNCHED:-no}} >> launched; "
                      + ("echo broken >&2; exit 3" if n == fail else f"echo '{{}}' > {self.out(n)}"))
            cmds[n] = {"program": "/bin/sh", "args": ["-c", script], "output": self.out(n), "depends": deps}
        with open(os.path.join(self.rdir, "commands.json"), "w") as f:
            json.dump(cmds, f)

    def runs(self, n):
        path = os.path.join(self.rdir, f"{n}.runs")  # the commands run in <build>/reproduce
        return len(open(path).readlines()) if os.path.exists(path) else 0

    def run_targets(self):
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed), contextlib.redirect_stderr(io.StringIO()):
            rc = ra.run_targets(self.build, "paper", self.logs, "targets.txt", lambda n: "")
        return rc, printed.getvalue()

    def test_runs_what_is_stale_and_only_that(self):
        rc, _ = self.run_targets()
        self.assertEqual(rc, 0)
        self.assertEqual((self.runs("a"), self.runs("b")), (1, 1))
        self.assertIn("[a] 50.0% done", open(os.path.join(self.logs, "a.log")).read())
        with open(os.path.join(self.rdir, "timings.json")) as f:
            timings = json.load(f)
        self.assertLessEqual({"a", "b"}, set(timings["paper"]))
        rc, printed = self.run_targets()
        self.assertEqual((self.runs("a"), self.runs("b")), (1, 1))
        self.assertEqual(printed.count("up to date"), 2)

    def test_a_rewritten_input_reruns_its_reader(self):
        self.run_targets()
        os.utime(self.out("a"), (time.time() - 50,) * 2)  # a's output older than its program
        touch(self.program, time.time() - 10)
        os.utime(self.out("b"), (time.time() - 20,) * 2)
        self.run_targets()
        self.assertEqual((self.runs("a"), self.runs("b")), (2, 2))

    def test_a_launcher_starts_each_target(self):
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed), contextlib.redirect_stderr(io.StringIO()):
            rc = ra.run_targets(self.build, "paper", self.logs, "targets.txt", lambda n: "",
                                ["/usr/bin/env", "SB_LAUNCHED=yes"])
        self.assertEqual(rc, 0)
        for n in ("a", "b"):
            self.assertEqual(self.runs(n), 1)
        self.assertEqual(open(os.path.join(self.rdir, "launched")).read().split(), ["yes", "yes"])

    def test_a_failure_stops_the_run(self):
        self.write_commands(fail="a")
        rc, _ = self.run_targets()
        self.assertNotEqual(rc, 0)
        self.assertEqual(self.runs("b"), 0)
        self.assertFalse(os.path.exists(self.out("a")))
        self.assertIn("broken", open(os.path.join(self.logs, "a.log")).read())


if __name__ == "__main__":
    unittest.main(verbosity=2)
