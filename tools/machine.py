"""Where and when a measurement was taken: cores, UTC time, commit (and whether the tree had local
changes) and the load average, recorded beside every timing the documentation quotes."""
import datetime
import os
import subprocess

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load_average():
    """The 1, 5 and 15 minute load averages: a timing on a shared machine is read beside them."""
    return list(os.getloadavg())


def machine():
    def git(*a):
        return subprocess.run(["git", *a], cwd=REPO, capture_output=True, text=True).stdout.strip()
    return {"cores": os.cpu_count(), "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "commit": git("rev-parse", "--short", "HEAD") or "unknown", "dirty": bool(git("status", "--porcelain"))}
