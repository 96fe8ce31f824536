"""Exit codes of `--row` and `--claim`. CTest registers 77 as SKIP_RETURN_CODE, so a check that
cannot resolve anything at this tier shows as skipped, never as passed."""
PASS, FAIL, NOT_RESOLVED = 0, 1, 77


def exit_code(verdict, stale, passing, failing):
    """PASS for a verdict in `passing`, FAIL for one in `failing` or a stale known deviation,
    NOT_RESOLVED for not_resolved."""
    if stale or verdict in failing:
        return FAIL
    if verdict in passing:
        return PASS
    if verdict == "not_resolved":
        return NOT_RESOLVED
    raise ValueError(f"verdict {verdict!r} has no exit code")


def row_exit_code(rec):
    return exit_code(rec["verdict"], rec["stale"], ("agree", "disagree_known"), ("disagree_new", "missing"))


def claim_exit_code(rec):
    return exit_code(rec["verdict"], rec["stale"], ("holds", "fails_known"), ("fails_new", "missing"))
