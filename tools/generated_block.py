"""Generated text in hand-written files, and files written whole or not at all: shared by the
tools that write the generated blocks of the README and the documentation (readme_results.py;
readme_cost.py, cost_model.py, sweep_cost.py, design_cost.py and first_slip_cost.py, into
docs/cost.md)."""
import argparse
import json
import os
import sys
import tempfile


def replace_block(text, begin, end, new_block):
    """text with everything from the marker begin to the marker end (both included) replaced by
    new_block, which carries the markers itself. ValueError when the markers are missing or out
    of order, so a page without them is never rewritten."""
    i, j = text.find(begin), text.find(end)
    if i < 0 or j < i:
        raise ValueError(f"markers not found: {begin!r} ... {end!r}")
    return text[:i] + new_block + text[j + len(end):]


def write_atomic(path, text):
    """Write text to path through a temporary file in the same directory and a rename: a reader
    sees the old file or the new one, never a part."""
    d = os.path.dirname(os.path.abspath(path))
    os.makedirs(d, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=d, prefix="." + os.path.basename(path))
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.chmod(tmp, 0o644)  # mkstemp makes it private; these files are meant to be shared
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def block_actions(parser, page):
    """The --page, --write and --print options of a tool that writes one generated block."""
    parser.add_argument("--page", default=page)
    act = parser.add_mutually_exclusive_group(required=True)
    act.add_argument("--write", action="store_true")
    act.add_argument("--print", action="store_true")


def put_block(args, begin, end, text, tool):
    """Print the block (--print) or replace it in args.page, written whole (--write). Returns 0."""
    if args.print:
        print(text)
        return 0
    with open(args.page) as f:
        page = f.read()
    write_atomic(args.page, replace_block(page, begin, end, text))
    print(f"{tool}: wrote the block into {args.page}", file=sys.stderr)
    return 0


def main_from_file(argv, tool, doc, source, page, begin, end, make_block, errors=()):
    """The command of a tool that writes one block from one benchmark's JSON: --from (default
    source), --page/--write/--print; exit 2 with the reason, the page untouched, when the file
    cannot be read or make_block finds it wanting (ValueError, KeyError, TypeError, or errors)."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("--from", dest="source", default=source)
    block_actions(ap, page)
    a = ap.parse_args(argv)
    try:
        with open(a.source) as f:
            text = make_block(json.load(f))
    except (OSError, ValueError, KeyError, TypeError, *errors) as e:
        print(f"{tool}: cannot read {a.source} ({type(e).__name__}: {e})", file=sys.stderr)
        return 2
    return put_block(a, begin, end, text, tool)
