"""The benchmarks' summary (`python3 -m bench.summarize`, run by `make bench`), whose reading of
Google Benchmark JSON tools/readme_cost.py shares; tools/__init__.py says how the packages run."""
