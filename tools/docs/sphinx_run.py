"""Sphinx extension: the documentation's examples are run while the site is built, so every output
it shows is the output of the code it documents, never pasted.

Directives (MyST: ```` ```{sb-command} ````):

  sb-command   each content line is a shell command, run in the page's work directory with the
               built `springblock` first on PATH; shown as `$ command` and its output.
               :returncode: the exit code expected (default 0); any other stops the build.
               :stderr:     show the standard error too (always shown when :returncode: is not 0).
               :tail: N     show only the last N lines of each output.
               :image: FILE a picture the commands wrote, shown after them (:alt: its text).
  sb-file      writes its content to the work directory as :name: and shows it with that caption.
  sb-python    runs its content with /usr/bin/python3 (the built module importable) and shows
               the code and what it printed; :image: FILE shows a picture the code wrote.
  sb-help      `springblock [SUBCOMMAND] --help`, shown as printed.
  sb-cli-reference
               one section per subcommand listed by `springblock --help`, each its --help: a new
               subcommand appears without editing the page.

Configuration (conf.py or -D): springblock_exe (the built command), springblock_python_dir (the
directory holding the built module), springblock_work (scratch space for the commands, emptied
at each build; one subdirectory per page, which also holds `examples/`, a link to the
repository's examples)."""
import os
import re
import shlex
import shutil
import subprocess

from docutils import nodes
from docutils.parsers.rst import Directive, directives
from sphinx.errors import ExtensionError

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TIMEOUT_S = 600
# A subcommand line of CLI11's help: two spaces, a lower-case name, spaces, its description.
SUBCOMMAND_RE = re.compile(r"^  ([a-z][a-z0-9-]*)\s{2,}\S")


def _config(env):
    c = env.config
    for key in ("springblock_exe", "springblock_python_dir", "springblock_work"):
        if not getattr(c, key):
            raise ExtensionError(f"sphinx_run: the configuration value {key} is not set (tools/docs/build.py sets it)")
    return c


def work_dir(env):
    """The current page's scratch directory, made on first use with its links to the command,
    the interpreter and the examples."""
    c = _config(env)
    d = os.path.join(os.path.abspath(c.springblock_work), env.docname.replace("/", "_"))
    if not os.path.isdir(d):
        os.makedirs(os.path.join(d, ".bin"))
        os.symlink(os.path.abspath(c.springblock_exe), os.path.join(d, ".bin", "springblock"))
        # The project's interpreter (Debian's, with numpy and matplotlib), whatever python3 PATH finds.
        os.symlink("/usr/bin/python3", os.path.join(d, ".bin", "python3"))
        os.symlink(os.path.join(REPO, "examples"), os.path.join(d, "examples"))
    return d


def run_env(env, d):
    c = _config(env)
    e = dict(os.environ)
    e["PATH"] = os.path.join(d, ".bin") + os.pathsep + e.get("PATH", "")
    e["PYTHONPATH"] = os.pathsep.join([os.path.abspath(c.springblock_python_dir), REPO])
    e["PYTHONDONTWRITEBYTECODE"] = "1"
    e["MPLBACKEND"] = "Agg"
    return e


def run(env, argv_or_line, *, shell, expect=0, where=""):
    d = work_dir(env)
    try:
        p = subprocess.run(argv_or_line, shell=shell, executable="/bin/bash" if shell else None, cwd=d,
                           env=run_env(env, d), capture_output=True, text=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        raise ExtensionError(f"{where}: `{argv_or_line}` ran longer than {TIMEOUT_S} s")
    if p.returncode != expect:
        raise ExtensionError(f"{where}: `{argv_or_line}` exited {p.returncode}, expected {expect}\n"
                             f"stdout:\n{p.stdout}\nstderr:\n{p.stderr}")
    return p


def literal(text, language):
    node = nodes.literal_block(text, text)
    node["language"] = language
    return node


def tail(text, n):
    lines = text.rstrip("\n").splitlines()
    return "\n".join(lines[-n:] if n else lines)


class Command(Directive):
    has_content = True
    option_spec = {"returncode": directives.nonnegative_int, "stderr": directives.flag,
                   "tail": directives.nonnegative_int, "image": directives.unchanged_required,
                   "alt": directives.unchanged}

    def run(self):
        env = self.state.document.settings.env
        expect = self.options.get("returncode", 0)
        shown = []
        for line in (ln for ln in self.content if ln.strip()):
            p = run(env, line, shell=True, expect=expect, where=f"{env.docname}:{self.lineno}")
            out = p.stdout
            if "stderr" in self.options or expect != 0:
                out += p.stderr
            shown.append(f"$ {line}\n{tail(out, self.options.get('tail', 0))}".rstrip("\n"))
        return [literal("\n".join(shown), "console")] + image_nodes(env, self.options, self.lineno)


class File(Directive):
    has_content = True
    option_spec = {"name": directives.unchanged_required}

    def run(self):
        env = self.state.document.settings.env
        name = self.options.get("name")
        if not name or os.path.isabs(name) or ".." in name.split("/"):
            raise self.error("sb-file needs :name:, a path inside the page's work directory")
        text = "\n".join(self.content) + "\n"
        path = os.path.join(work_dir(env), name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
        container = nodes.container("", literal_caption(name), literal(text.rstrip("\n"), "text"),
                                    classes=["literal-block-wrapper"], literal_block=True)
        return [container]


def literal_caption(name):
    return nodes.caption(name, "", nodes.literal(name, name))


class Python(Directive):
    has_content = True
    option_spec = {"image": directives.unchanged_required, "alt": directives.unchanged}

    def run(self):
        env = self.state.document.settings.env
        code = "\n".join(self.content) + "\n"
        p = run(env, ["/usr/bin/python3", "-c", code], shell=False, where=f"{env.docname}:{self.lineno}")
        out = [literal(code.rstrip("\n"), "python")]
        if p.stdout.strip():
            out.append(literal(p.stdout.rstrip("\n"), "text"))
        return out + image_nodes(env, self.options, self.lineno)


def image_nodes(env, options, lineno):
    """The picture options["image"] names in the page's work directory, as an image node whose
    path is relative to the page (Sphinx copies it into the site like any other image)."""
    if "image" not in options:
        return []
    img = os.path.join(work_dir(env), options["image"])
    if not os.path.isfile(img):
        raise ExtensionError(f"{env.docname}:{lineno}: the example wrote no {options['image']}")
    page_dir = os.path.dirname(env.doc2path(env.docname))
    return [nodes.image(uri=os.path.relpath(img, page_dir), alt=options.get("alt", ""))]


def help_text(env, sub, where):
    argv = ["springblock"] + ([sub] if sub else []) + ["--help"]
    return run(env, " ".join(shlex.quote(a) for a in argv), shell=True, where=where).stdout


class Help(Directive):
    optional_arguments = 1

    def run(self):
        env = self.state.document.settings.env
        sub = self.arguments[0] if self.arguments else ""
        text = help_text(env, sub, f"{env.docname}:{self.lineno}")
        return [literal(text.rstrip("\n"), "text")]


def subcommands(main_help):
    """The subcommands a CLI11 help lists under its SUBCOMMANDS heading, in order."""
    names, inside = [], False
    for line in main_help.splitlines():
        if line.strip().upper().startswith("SUBCOMMANDS"):
            inside = True
        elif inside:
            m = SUBCOMMAND_RE.match(line)
            if m:
                names.append(m.group(1))
            elif line.strip() and not line.startswith(" "):
                inside = False
    return names


class CliReference(Directive):
    def run(self):
        env = self.state.document.settings.env
        where = f"{env.docname}:{self.lineno}"
        names = subcommands(help_text(env, "", where))
        if not names:
            raise ExtensionError(f"{where}: `springblock --help` listed no subcommands")
        out = []
        for name in names:
            section = nodes.section(ids=[f"springblock-{name}"], names=[f"springblock {name}"])
            title = f"springblock {name}"
            section += nodes.title(title, "", nodes.literal(title, title))
            section += literal(help_text(env, name, where).rstrip("\n"), "text")
            self.state.document.note_implicit_target(section, section)
            out.append(section)
        return out


def fresh_work(app):
    work = app.config.springblock_work
    if work:
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)


def setup(app):
    app.add_config_value("springblock_exe", "", "env")
    app.add_config_value("springblock_python_dir", "", "env")
    app.add_config_value("springblock_work", "", "env")
    app.add_directive("sb-command", Command)
    app.add_directive("sb-file", File)
    app.add_directive("sb-python", Python)
    app.add_directive("sb-help", Help)
    app.add_directive("sb-cli-reference", CliReference)
    app.connect("builder-inited", fresh_work)
    return {"version": "1", "parallel_read_safe": False, "parallel_write_safe": True}
