"""Sphinx configuration of the springblock documentation. Build it with `make docs` (or
`python3 -m tools.docs.build`, which passes the built command and module to the extension that
runs the pages' examples); the site is written to build/docs/html."""
import sys

sys.dont_write_bytecode = True  # conf.py and the extensions leave no __pycache__ in the source tree

project = "springblock"
author = "the springblock authors"
copyright = "the springblock authors"

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "tools.docs.sphinx_run",
    "tools.docs.plain_docstrings",
]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = []
# No math extension: MathJax would load from the network, which the offline browser check refuses.
myst_enable_extensions = ["deflist"]
# Headings become anchors down to ####, so pages can link to a section by its slug.
myst_heading_anchors = 4

# Every cross-reference must resolve (-n), except types from outside the package that the
# module's signatures name (numpy arrays, pybind11's base object, pandas, the standard library):
# the site links no other project's documentation (it is built offline).
nitpicky = True
nitpick_ignore_regex = [("py:class", r"(?!springblock\b).*")]

autodoc_default_options = {"members": True, "undoc-members": True, "show-inheritance": False}
autodoc_docstring_signature = True

html_theme = "alabaster"
html_title = "springblock"
html_show_sourcelink = False
html_copy_source = False
html_theme_options = {"description": "Friction of hierarchical surfaces: a spring-block reproduction",
                      "fixed_sidebar": True, "page_width": "1200px", "sidebar_width": "240px"}
