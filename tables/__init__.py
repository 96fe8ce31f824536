"""The published tables' data and their rendering (`python3 -m tables.render_tables`, also
imported by the report); tools/__init__.py says how the packages run."""
