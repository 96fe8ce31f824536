#!/usr/bin/python3
"""tools/sweep_results.py on hand-written files (no simulation): a partial file read while a line
is being written gives the whole lines only; given OUT while only OUT.partial exists it reads
that; scenes come back in scene order whatever order they completed in; a file that is not a
sweep's results is refused."""
import json
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
from tools import sweep_results  # noqa: E402


class ReadPartial(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.out = os.path.join(self.dir.name, "r.jsonl")

    def tearDown(self):
        self.dir.cleanup()

    def write(self, path, text):
        with open(path, "w") as f:
            f.write(text)

    def test_a_line_being_written_is_left_out_and_scenes_are_sorted(self):
        header = {"kind": "sweep", "partial": True, "scenes": 3}
        lines = [header, {"scene": 2, "mu_s": {"mean": 0.5}}, {"scene": 0, "mu_s": {"mean": 0.7}}]
        text = "".join(json.dumps(line) + "\n" for line in lines) + '{"scene": 1, "mu_s": {"me'
        self.write(self.out + ".partial", text)
        got_header, scenes = sweep_results.read(self.out)  # OUT does not exist yet: OUT.partial
        self.assertTrue(got_header["partial"])
        self.assertEqual([s["scene"] for s in scenes], [0, 2])

    def test_the_complete_file_is_read_when_it_exists(self):
        self.write(self.out + ".partial", json.dumps({"kind": "sweep", "partial": True, "scenes": 1}) + "\n")
        self.write(self.out, json.dumps({"kind": "sweep", "scenes": 1}) + "\n" + json.dumps({"scene": 0}) + "\n")
        header, scenes = sweep_results.read(self.out)
        self.assertNotIn("partial", header)
        self.assertEqual(len(scenes), 1)

    def test_another_file_is_refused(self):
        self.write(self.out, json.dumps({"kind": "run"}) + "\n")
        with self.assertRaises(ValueError):
            sweep_results.read(self.out)


if __name__ == "__main__":
    unittest.main()
