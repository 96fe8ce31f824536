#!/usr/bin/python3
"""tools/docs/check_site.py on small sites written here (no browser, no Sphinx, a fraction of a
second): a site whose links, anchors, images, stylesheets and scripts all resolve passes; each
kind of fault (a missing page, a missing anchor in another page or in the same one, a missing
image, stylesheet or script, a missing directory index) is reported with its page and line;
external links are not followed."""
import os
import subprocess
import sys
import tempfile
import unittest

from tools.docs.check_site import check_site

PAGES = {
    "index.html": """<html><head><link rel="stylesheet" href="_static/site.css"><script src="_static/site.js"></script></head>
<body><h1 id="top">x</h1><a href="guide/a.html#part">a</a> <a href="#top">top</a> <a href="guide/">dir</a>
<a href="https://example.invalid/x.html">ext</a> <a href="mailto:a@b.c">mail</a> <img src="_images/p.png"></body></html>""",
    "guide/a.html": '<html><body><a name="old"></a><p id="part">p</p><a href="../index.html#top">up</a></body></html>',
    "guide/index.html": "<html><body>guide</body></html>",
    "_static/site.css": "", "_static/site.js": "", "_images/p.png": "",
}


def write(root, pages):
    for rel, text in pages.items():
        path = os.path.join(root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)


class CheckSite(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.root = self.dir.name
        write(self.root, PAGES)

    def tearDown(self):
        self.dir.cleanup()

    def test_a_whole_site_passes(self):
        self.assertEqual(check_site(self.root), [])

    def test_each_fault_is_named_with_its_page_and_line(self):
        write(self.root, {"bad.html": """<html><body>
<a href="gone.html">1</a>
<a href="guide/a.html#nothing">2</a>
<a href="#self">3</a>
<img src="_images/none.png">
<link rel="stylesheet" href="_static/none.css"><script src="_static/none.js"></script>
<a href="_static/">5</a>
</body></html>"""})
        faults = check_site(self.root)
        self.assertTrue(all(f[0] == "bad.html" for f in faults), faults)
        got = {(line, msg.split(":")[0]) for _, line, msg in faults}
        self.assertEqual(got, {(2, "<a> gone.html"), (3, "<a> guide/a.html#nothing"), (4, "<a> #self"),
                               (5, "<img> _images/none.png"), (6, "<link> _static/none.css"),
                               (6, "<script> _static/none.js"), (7, "<a> _static/")})

    def test_the_command_exits_1_on_a_fault_and_2_without_a_site(self):
        env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
        tool = [sys.executable, "-m", "tools.docs.check_site"]
        self.assertEqual(subprocess.run(tool + [self.root], capture_output=True, env=env).returncode, 0)
        os.remove(os.path.join(self.root, "_images", "p.png"))
        p = subprocess.run(tool + [self.root], capture_output=True, text=True, env=env)
        self.assertEqual((p.returncode, "index.html:" in p.stdout), (1, True), p.stdout)
        p = subprocess.run(tool + [os.path.join(self.root, "absent")], capture_output=True, text=True, env=env)
        self.assertEqual(p.returncode, 2, p.stderr)


if __name__ == "__main__":
    unittest.main()
