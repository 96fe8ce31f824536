"""The report generator (`python3 -m paper.build_report`, run by the `report` target); a package
so that it imports tables/ and tools/ by name (tools/__init__.py says how the packages run)."""
