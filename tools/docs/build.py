#!/usr/bin/python3
"""Build the documentation site (docs/) into OUT/html with Sphinx, warnings as errors and
nitpicky, then check that every internal link, anchor and image of the built pages resolves
(tools/docs/check_site.py). The examples in the pages run the built command and module
(tools/docs/sphinx_run.py) in OUT/work.

The site is built into OUT/html.new and renamed to OUT/html only when the build and the check
pass: OUT/html is always a whole, checked site (or absent). Nothing is written into the source
tree (no bytecode, no copied sources).

Usage: python3 -m tools.docs.build --exe build/src/springblock --python-dir build/python --out build/docs
Exit 0 built and checked, 1 a Sphinx warning or a broken link, 2 bad arguments.
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

from tools.docs.check_site import check_site

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PYTHON = "/usr/bin/python3"


def sphinx(args, html):
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1",
               PYTHONPATH=os.pathsep.join([REPO, os.path.abspath(args.python_dir)]))
    cmd = [PYTHON, "-m", "sphinx", "-b", "html", "-W", "--keep-going", "-n", "-E", "-q",
           "-d", os.path.join(args.out, "doctrees"),
           "-D", f"springblock_exe={os.path.abspath(args.exe)}",
           "-D", f"springblock_python_dir={os.path.abspath(args.python_dir)}",
           "-D", f"springblock_work={os.path.abspath(os.path.join(args.out, 'work'))}",
           os.path.join(REPO, "docs"), html]
    return subprocess.run(cmd, env=env).returncode


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--exe", required=True, help="the built springblock command")
    ap.add_argument("--python-dir", required=True, help="the directory holding the built module")
    ap.add_argument("--out", required=True, help="output directory (html/, doctrees/, work/ under it)")
    a = ap.parse_args(argv)
    for field, path, ok in (("exe", a.exe, os.path.isfile(a.exe) and os.access(a.exe, os.X_OK)),
                            ("python-dir", a.python_dir, os.path.isdir(a.python_dir))):
        if not ok:
            print(f"docs: invalid --{field}: {path} is not {'an executable file' if field == 'exe' else 'a directory'}",
                  file=sys.stderr)
            return 2
    t0 = time.monotonic()
    os.makedirs(a.out, exist_ok=True)
    new, final = os.path.join(a.out, "html.new"), os.path.join(a.out, "html")
    shutil.rmtree(new, ignore_errors=True)
    if sphinx(a, new) != 0:
        print("docs: Sphinx reported warnings or errors (above); the site was not updated", file=sys.stderr)
        return 1
    faults = check_site(new)
    for rel, line, msg in faults:
        print(f"docs: {rel}:{line}: {msg}", file=sys.stderr)
    if faults:
        print(f"docs: {len(faults)} broken link(s) or missing image(s); the site was not updated", file=sys.stderr)
        return 1
    shutil.rmtree(final, ignore_errors=True)
    os.replace(new, final)
    print(f"docs: {os.path.join(final, 'index.html')} built and checked in {time.monotonic() - t0:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
