"""One benchmarked command run to its end, with the operating system's own account of it."""
import os
import subprocess


def run_child(cmd, capture=False):
    """(its stdout if capture else None, its resource usage from wait4, its exit code)."""
    child = subprocess.Popen(cmd, stdout=subprocess.PIPE if capture else subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL if capture else None, text=True)
    out = child.stdout.read() if capture else None
    _, status, usage = os.wait4(child.pid, 0)
    return out, usage, os.waitstatus_to_exitcode(status)
