"""The documentation site (docs/, built by `make docs`) and its checks: the Sphinx extension that
runs the built command and Python module while the site is built, the site builder, the static
link and image check of the built pages, and the headless-Chromium check of the pages as a
browser shows them."""
