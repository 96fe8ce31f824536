"""A configured build tree's CMake cache, read by the tools that drive it (reproduce_all.py,
layout_study.py)."""
import os


def cache_value(build, key):
    """The value of a cache entry (e.g. SPRINGBLOCK_TIER) of the build tree `build`."""
    with open(os.path.join(build, "CMakeCache.txt")) as f:
        for line in f:
            if line.startswith(key + ":"):
                return line.split("=", 1)[1].strip()
    raise KeyError(f"{key} not in {build}/CMakeCache.txt: configure first")
