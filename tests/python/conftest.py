"""Shared fixtures of the Python module's tests (CTest runs them with the module's build
directory on PYTHONPATH and SPRINGBLOCK_EXE naming the command-line program)."""
import json
import os
import subprocess

import pytest


@pytest.fixture
def cli():
    """Run `springblock ARGS...` and return its stdout as JSON (or the CompletedProcess with
    check=False, for exit codes and messages)."""
    exe = os.environ.get("SPRINGBLOCK_EXE")
    if not exe:
        pytest.skip("SPRINGBLOCK_EXE is not set (CTest sets it)")

    def run(*args, check=True):
        done = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
        if not check:
            return done
        assert done.returncode == 0, done.stderr
        return json.loads(done.stdout)

    return run
