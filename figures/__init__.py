"""One script per figure, run as `python3 -m figures.<name> --data DIR --out DIR` (the `figures`
target does); style, sweep and categories are their shared modules. tools/__init__.py says how
the packages run."""
