#!/usr/bin/python3
"""Verdict counts per reproduction target, for the one-line-per-target output of reproduce_all.

After each target finishes, the published numbers and claims whose results are all present are
judged with the checker's own rules (tools/reproduction), and the ones that belong to that
target are counted; at the end, the counts of the written summary.json.
"""
import os

from tools import summary_schema as schema
from tools.reproduction import evaluate


class Counter:
    def __init__(self, results, tables):
        self.results, self.tables = results, tables

    def line(self, target):
        return schema.format_counts(evaluate.target_counts_now(evaluate.Inputs(self.results, self.tables), target))

    def total_line(self):
        return schema.format_counts(schema.load(os.path.join(self.results, "summary.json"))["counts"])
