#!/usr/bin/env python3
"""Structural limits of the library, checked by CTest (label fast).

The architecture issue asked for an integrator a newcomer can change: no file under
src/springblock/integrate/ over 300 lines, no function in the library or the shells over 80
lines, and no include cycle among the project's headers. These are checked here rather than by
review so that they stay true. Function extents come from Universal Ctags (its `end` field);
when ctags is missing the function check says so and is skipped (exit 77, CTest's skip code)
instead of passing silently.

Two boundaries are checked the same way. No Python file edits the module search path
(sys.path.insert/append/extend/..., an assignment to sys.path or to an item of it,
site.addsitedir): the project's Python is packages run as modules from the repository root
(tools/__init__.py), and a path edit would let a module import a sibling in a way its other
callers cannot. And src/ says why the code is as it is, not its history: an issue number
("issue 16") or a date (2026-11-26) in a C++ comment, or anywhere in src/'s Markdown and CMake
files, belongs in git and paper/choices.md.

Inside integrate/ the folders form layers (src/springblock/README.md): no folder includes one that
includes it, directly or through others (a file at integrate/'s top is a node of its own). And a
class or struct there holds at most MAX_CLASS_MEMBERS data members (static ones not counted): one
that needs more is two.

Usage: python3 -m tools.check_structure SOURCE_DIR [--report]   (--report prints the longest functions)
"""
import ast
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys

MAX_INTEGRATE_FILE_LINES = 300
MAX_FUNCTION_LINES = 80
MAX_CLASS_MEMBERS = 10
# Where the function limit applies: the library and the two command-line shells.
FUNCTION_ROOTS = ["src", "reproduce"]
INCLUDE_RE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
# History in src/: C++ comments, and the Markdown and CMake files (prose and comments throughout).
HISTORY_RE = re.compile(r"\bissues?\s+#?\d+|\b20\d\d-\d\d-\d\d\b", re.I)
CXX_SUFFIXES = (".cpp", ".hpp", ".h", ".cc", ".cxx")
# Methods of a list that change it, called on sys.path.
LIST_EDITS = {"insert", "append", "extend", "remove", "pop", "clear", "__setitem__", "__iadd__"}


def cxx_files(root: pathlib.Path, sub: str):
    return sorted(p for p in (root / sub).rglob("*") if p.suffix in (".cpp", ".hpp"))


def long_files(root):
    bad = []
    for p in cxx_files(root, "src/springblock/integrate"):
        n = len(p.read_text().splitlines())
        if n > MAX_INTEGRATE_FILE_LINES:
            bad.append(f"{p.relative_to(root)}: {n} lines (limit {MAX_INTEGRATE_FILE_LINES})")
    return bad


def function_lengths(root):
    ctags = shutil.which("ctags-universal") or shutil.which("ctags")
    if ctags is None:
        return None
    files = [str(p) for sub in FUNCTION_ROOTS for p in cxx_files(root, sub)]
    out = subprocess.run([ctags, "--c++-kinds=f", "--fields=+ne", "--output-format=json", "-f", "-", *files],
                         capture_output=True, text=True, check=True).stdout
    rows = []
    for line in out.splitlines():
        tag = json.loads(line)
        if "end" in tag:
            rows.append((tag["end"] - tag["line"] + 1, str(pathlib.Path(tag["path"]).relative_to(root)),
                         tag["name"], tag["line"]))
    return sorted(rows, reverse=True)


def include_cycles(root):
    """Cycles in the graph header -> project header it includes (src/ only)."""
    src = root / "src"
    graph = {}
    for p in cxx_files(root, "src"):
        rel = str(p.relative_to(src))
        graph[rel] = [inc for inc in INCLUDE_RE.findall(p.read_text()) if (src / inc).exists()]
    cycles, state = [], {}

    def visit(node, path):
        state[node] = 1
        for nxt in graph.get(node, []):
            if state.get(nxt) == 1:
                cycles.append(" -> ".join(path[path.index(nxt):] + [nxt]))
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = 2

    for node in graph:
        if node not in state:
            visit(node, [node])
    return cycles


def python_files(root):
    """The repository's Python files, without build trees (build*/, as .gitignore has them) and .git."""
    for d, subdirs, files in os.walk(root):
        if pathlib.Path(d) == root:
            subdirs[:] = [s for s in subdirs if s != ".git" and not s.startswith("build")]
        subdirs.sort()
        yield from (pathlib.Path(d) / f for f in sorted(files) if f.endswith(".py"))


def bound_names(tree):
    """The names a module binds to sys, to site and to site.addsitedir (`import sys as s`, ...)."""
    names = {"sys": {"sys"}, "site": {"site"}, "addsitedir": set()}
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for a in node.names:
                if a.name in ("sys", "site"):
                    names[a.name].add(a.asname or a.name)
        elif isinstance(node, ast.ImportFrom) and node.module == "site":
            names["addsitedir"] |= {a.asname or a.name for a in node.names if a.name == "addsitedir"}
    return names


def path_edit(node, names):
    """What node does to the module search path, or None."""
    def is_sys_path(n):
        return (isinstance(n, ast.Attribute) and n.attr == "path" and isinstance(n.value, ast.Name)
                and n.value.id in names["sys"])

    if isinstance(node, ast.Call):
        f = node.func
        if isinstance(f, ast.Attribute) and f.attr in LIST_EDITS and is_sys_path(f.value):
            return f"sys.path.{f.attr}"
        if (isinstance(f, ast.Attribute) and f.attr == "addsitedir" and isinstance(f.value, ast.Name)
                and f.value.id in names["site"]) or (isinstance(f, ast.Name) and f.id in names["addsitedir"]):
            return "site.addsitedir"
    elif isinstance(node, (ast.Assign, ast.AugAssign, ast.AnnAssign, ast.Delete)):
        targets = node.targets if isinstance(node, (ast.Assign, ast.Delete)) else [node.target]
        if any(is_sys_path(t) or (isinstance(t, ast.Subscript) and is_sys_path(t.value)) for t in targets):
            return "del sys.path[...]" if isinstance(node, ast.Delete) else "an assignment to sys.path"
    elif isinstance(node, ast.ImportFrom) and node.module == "sys" and any(a.name == "path" for a in node.names):
        return "from sys import path"
    return None


def sys_path_edits(root):
    """file:line of every edit of the module search path: a call of a list method that changes
    sys.path, an assignment or augmented assignment to sys.path or to an item or slice of it, a
    del of one, site.addsitedir, and `from sys import path` (the same list under another name).
    Read from the syntax tree, so a mention in a comment or a string is not an edit."""
    bad = []
    for p in python_files(root):
        rel = str(p.relative_to(root))
        try:
            tree = ast.parse(p.read_text(), rel)
        except SyntaxError as e:
            bad.append((rel, e.lineno or 0, f"cannot parse ({e.msg})"))
            continue
        names = bound_names(tree)
        bad += [(rel, node.lineno, what) for node in ast.walk(tree) if (what := path_edit(node, names))]
    return [f"{rel}:{line}: {what}: import by package name instead (tools/__init__.py)"
            for rel, line, what in sorted(bad)]


def literal_end(text, i):
    """Index just past the string or character literal that starts at text[i] (a quote)."""
    q, j, k = text[i], i + 1, i
    while k > 0 and (text[k - 1].isalnum() or text[k - 1] == "_"):
        k -= 1
    prefix = text[k:i]
    if q == '"' and prefix in ("R", "u8R", "uR", "UR", "LR"):  # raw string: R"delim( ... )delim"
        open_paren = text.find("(", j)
        close = text.find(")" + text[j:open_paren] + '"', open_paren)
        return len(text) if open_paren < 0 or close < 0 else close + open_paren - j + 2
    while j < len(text) and text[j] not in (q, "\n"):
        j += 2 if text[j] == "\\" else 1
    return j + 1


def cxx_comments(text):
    """(line number, text) of every line of every comment in C++ source text. Literals are
    skipped, so a date in a string is not a comment; a quote after a number is a digit separator."""
    out, i, line, n = [], 0, 1, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i) or text.startswith("/*", i):
            end = text.find("\n", i) if c == "/" and text[i + 1] == "/" else text.find("*/", i + 2)
            end = n if end < 0 else end
            for k, part in enumerate(text[i + 2:end].split("\n")):
                out.append((line + k, part))
            line += text.count("\n", i, end)
            i = end
        elif c in "\"'":
            k = i
            while k > 0 and (text[k - 1].isalnum() or text[k - 1] in "_."):
                k -= 1
            if c == "'" and k < i and text[k].isdigit():  # 1'000'000
                i += 1
                continue
            end = literal_end(text, i)
            line += text.count("\n", i, end)
            i = end
        else:
            if c == "\n":
                line += 1
            i += 1
    return out


def history_in_src(root):
    """file:line of every issue number or date in src/'s C++ comments, Markdown and CMake files."""
    bad = []
    for p in sorted((root / "src").rglob("*")):
        rel = p.relative_to(root).as_posix()
        if not p.is_file():
            continue
        if p.suffix in CXX_SUFFIXES:
            lines = cxx_comments(p.read_text())
        elif p.suffix in (".md", ".cmake") or p.name == "CMakeLists.txt":
            lines = list(enumerate(p.read_text().splitlines(), 1))
        else:
            continue
        for n, text in lines:
            for m in HISTORY_RE.finditer(text):
                bad.append(f"{rel}:{n}: '{m.group(0)}' is history: say why the code is as it is "
                           "(git and paper/choices.md keep the history)")
    return bad


def integrate_folder_cycles(root):
    """Cycles in the graph folder -> folder it includes from, among integrate/'s folders."""
    prefix = "springblock/integrate/"

    def node(rel):  # a path under src/: its folder below integrate/, or the top-level file itself
        parts = rel[len(prefix):].split("/")
        return parts[0] + "/" if len(parts) > 1 else parts[0]

    graph = {}
    for p in cxx_files(root, "src/springblock/integrate"):
        a = node(p.relative_to(root / "src").as_posix())
        for inc in INCLUDE_RE.findall(p.read_text()):
            if inc.startswith(prefix) and node(inc) != a:
                graph.setdefault(a, set()).add(node(inc))
    cycles, state = [], {}

    def visit(n, path):
        state[n] = 1
        for m in sorted(graph.get(n, ())):
            if state.get(m) == 1:
                cycles.append(" -> ".join(path[path.index(m):] + [m]))
            elif m not in state:
                visit(m, path + [m])
        state[n] = 2

    for n in sorted(graph):
        if n not in state:
            visit(n, [n])
    return cycles


def class_members(root):
    """Non-static data members per class or struct defined under integrate/ (None without ctags)."""
    ctags = shutil.which("ctags-universal") or shutil.which("ctags")
    if ctags is None:
        return None
    files = [str(p) for p in cxx_files(root, "src/springblock/integrate")]
    out = subprocess.run([ctags, "--c++-kinds=m", "--fields=+s", "--fields-c++=+{properties}", "--output-format=json",
                          "-f", "-", *files], capture_output=True, text=True, check=True).stdout
    counts = {}
    for line in out.splitlines():
        tag = json.loads(line)
        if tag.get("kind") == "member" and "static" not in tag.get("properties", "") and "scope" in tag:
            counts[tag["scope"]] = counts.get(tag["scope"], 0) + 1
    return counts


def fat_classes(counts):
    return [f"{k}: {n} data members (limit {MAX_CLASS_MEMBERS}): split it"
            for k, n in sorted(counts.items()) if n > MAX_CLASS_MEMBERS]


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    failures = long_files(root)
    failures += [f"include cycle: {c}" for c in include_cycles(root)]
    failures += [f"integrate/ folder cycle: {c}" for c in integrate_folder_cycles(root)]
    failures += sys_path_edits(root)
    failures += history_in_src(root)
    rows = function_lengths(root)
    members = class_members(root)
    if members is not None:
        failures += fat_classes(members)
        if "--report" in sys.argv:
            for k in sorted(members, key=lambda k: -members[k])[:5]:
                print(f"{members[k]:4d}  {k} (data members)")
    if rows is not None:
        failures += [f"{path}:{line} {name}: {n} lines (limit {MAX_FUNCTION_LINES})"
                     for n, path, name, line in rows if n > MAX_FUNCTION_LINES]
        if "--report" in sys.argv:
            for n, path, name, line in rows[:15]:
                print(f"{n:4d}  {path}:{line} {name}")
    for f in failures:
        print("structure:", f)
    if failures:
        return 1
    if rows is None:
        print("structure: ctags not found, function lengths not checked (install universal-ctags)")
        return 77
    print("structure: integrate/ files <= %d lines, functions <= %d lines, no include cycle, no folder cycle in "
          "integrate/, its classes <= %d data members, no sys.path edit, no issue number or date in src/'s comments"
          % (MAX_INTEGRATE_FILE_LINES, MAX_FUNCTION_LINES, MAX_CLASS_MEMBERS))
    return 0


if __name__ == "__main__":
    sys.exit(main())
