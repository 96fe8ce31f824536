"""The project's Python tools: the reproduction driver and checker, the generated blocks of the
README and the documentation, the cost model, the structure check, the documentation site and
its browser check (tools/docs/).

tools/, paper/, tables/, figures/ and bench/ are packages rooted at the repository root. A tool
runs as a module from the root, `python3 -m tools.<name>` (CMake, CTest and the Makefile do so,
putting the root on PYTHONPATH), and modules import one another by their package names:
nothing edits sys.path (tools/check_structure.py fails if something does)."""
