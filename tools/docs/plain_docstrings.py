"""Sphinx extension: the Python module's docstrings are plain text written for help(), not
reStructuredText, so autodoc must not read `**fields` as the start of bold text or `|mu|` as a
substitution, nor `work_*` as a reference to a target named "work". The inline markup characters
that break such text are escaped; the rest (a `backquoted` name, paragraphs) reads the same in both."""
import re

# * and | start inline markup, and a word ending in _ is a reference; a backslash keeps them literal.
MARKUP = re.compile(r"([*|])")
REFERENCE = re.compile(r"(\w)_(?=\W|$)")


def escape(app, what, name, obj, options, lines):
    if not name.startswith("springblock"):
        return
    for i, line in enumerate(lines):
        lines[i] = REFERENCE.sub(r"\1\\_", MARKUP.sub(r"\\\1", line))


def setup(app):
    app.connect("autodoc-process-docstring", escape)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
