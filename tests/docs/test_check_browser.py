#!/usr/bin/python3
"""tools/docs/check_browser.py in a real headless Chromium on tiny pages written here: a clean
page passes and leaves a PNG screenshot; a page with a missing image, a console error, an uncaught
exception, a link to a missing file and a link to a missing anchor fails with each one named, so
the browser check of the report and the documentation can fail.

Usage: PYTHONPATH=<repository root> test_check_browser.py   (CTest: browser_check_selftest)"""
import base64
import os
import subprocess
import sys
import tempfile
import unittest

from tools.docs import check_browser
from tools.docs.cdp import find_chromium

# A 1x1 PNG: an image that renders.
PIXEL = base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==")
GOOD = """<!DOCTYPE html><html><head><title>good</title></head><body>
<h1 id="top">good</h1><table><tr><td>a table</td></tr></table><img src="pixel.png" alt="pixel">
<a href="other.html#there">other</a> <a href="#top">top</a> <a href="https://example.invalid/">external</a>
</body></html>"""
OTHER = '<!DOCTYPE html><html><body><p id="there">there</p></body></html>'
BAD = """<!DOCTYPE html><html><head><title>bad</title></head><body>
<img src="missing.png" alt="missing"> <a href="nowhere.html">nowhere</a> <a href="other.html#nothere">anchor</a>
<script>console.error("deliberate console error"); undefined_function_called();</script>
</body></html>"""


class CheckBrowser(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.chromium = find_chromium()
        if not cls.chromium:
            raise unittest.SkipTest("no chromium")  # reported as a failure below, never a pass
        cls.dir = tempfile.TemporaryDirectory()
        for name, text in (("good.html", GOOD), ("other.html", OTHER), ("bad.html", BAD)):
            with open(os.path.join(cls.dir.name, name), "w") as f:
                f.write(text)
        with open(os.path.join(cls.dir.name, "pixel.png"), "wb") as f:
            f.write(PIXEL)

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def page(self, name):
        return os.path.join(self.dir.name, name)

    def test_a_clean_page_passes_with_a_screenshot(self):
        shot = self.page("good.png")
        faults, facts = check_browser.check(self.page("good.html"), self.chromium, shot, "table")
        self.assertEqual(faults, [])
        self.assertEqual((facts["images"], facts["links"]), (1, 3))
        with open(shot, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")

    def test_every_fault_of_a_broken_page_is_named(self):
        faults, _ = check_browser.check(self.page("bad.html"), self.chromium)
        text = "\n".join(faults)
        for expected in ("image not rendered", "missing.png", "deliberate console error",
                         "undefined_function_called", "nowhere.html: no such file", "no element with id 'nothere'"):
            self.assertIn(expected, text)

    def test_the_command_exits_1_on_faults_in_a_page_or_its_site_and_2_without_a_page(self):
        env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
        run = [sys.executable, "-m", "tools.docs.check_browser"]
        p = subprocess.run(run + [self.page("bad.html")], capture_output=True, text=True, env=env)
        self.assertEqual(p.returncode, 1, p.stderr)
        p = subprocess.run(run + [self.page("good.html"), "--site", self.dir.name], capture_output=True, text=True,
                           env=env)
        self.assertEqual((p.returncode, p.stdout.count("check_browser:")), (1, 3), p.stdout + p.stderr)
        p = subprocess.run(run + [self.page("absent.html")], capture_output=True, text=True, env=env)
        self.assertEqual((p.returncode, "page" in p.stderr), (2, True), p.stderr)


if __name__ == "__main__":
    result = unittest.main(exit=False).result
    # No Chromium is a failure: the browser check it stands for would not run at all.
    sys.exit(0 if result.wasSuccessful() and not result.skipped else 1)
