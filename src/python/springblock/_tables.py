"""Results as tables: each row a flat dict (nested entries joined by '_', e.g. mu_s_mean),
convertible to a pandas DataFrame. pandas is imported only when a DataFrame is asked for, so the
package does not need it."""


def flatten(entries, prefix=""):
    """One level of keys for a nested dict: {"mu_s": {"mean": 1}} -> {"mu_s_mean": 1}. Lists stay
    as they are (a column of lists in a table)."""
    row = {}
    for key, value in entries.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            row.update(flatten(value, name + "_"))
        else:
            row[name] = value
    return row


def data_frame(rows):
    """A pandas DataFrame of `rows` (dicts); ImportError saying how to get pandas when it is missing."""
    try:
        import pandas
    except ImportError as e:
        raise ImportError("to_pandas() needs pandas (Debian: apt-get install python3-pandas); "
                          "records() gives the same rows as plain dicts") from e
    return pandas.DataFrame.from_records(rows)


def result_records(self):
    """One flat dict per repetition: its values (NaN-free: None where undefined, as in the results
    JSON), work counters (work_*) and times, from Result.runs."""
    return [flatten(run) for run in self.runs]


def result_to_pandas(self):
    """result.records() as a pandas DataFrame, one row per repetition (needs pandas)."""
    return data_frame(self.records())
