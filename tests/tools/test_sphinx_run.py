#!/usr/bin/python3
"""tools/docs/sphinx_run.py's reading of the command's help (no Sphinx, no simulation): the
command-line reference lists exactly the subcommands CLI11's help lists, in its order, and a help
without subcommands gives none (the directive then stops the build rather than show an empty
reference)."""
import unittest

from tools.docs.sphinx_run import subcommands, tail

HELP = """springblock: 1-D spring-block friction model.
Usage: springblock [OPTIONS] SUBCOMMAND

Options:
  -h,--help                   Print this help message and exit

Subcommands:
  run                         run one scene as an ensemble of repetitions
  pattern                     print a surface's contact mask
  design                      inverse design: search a pattern family for the surface that gives
                              a target mu_s
  sweep                       run every scene of a sweep file

Footer text that is not a subcommand:
  notasub                     (outside the list)
"""


class Subcommands(unittest.TestCase):
    def test_lists_the_subcommands_in_order(self):
        self.assertEqual(subcommands(HELP), ["run", "pattern", "design", "sweep"])

    def test_no_subcommands_heading_gives_none(self):
        self.assertEqual(subcommands("Usage: x [OPTIONS]\n\nOptions:\n  -h,--help   help\n"), [])

    def test_tail_keeps_the_last_lines(self):
        self.assertEqual(tail("a\nb\nc\n", 2), "b\nc")
        self.assertEqual(tail("a\nb\n", 0), "a\nb")


if __name__ == "__main__":
    unittest.main()
