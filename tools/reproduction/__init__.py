"""The reproduction checker, split by job (tools/check_reproduction.py is its command line).

  stats      quantiles, the detection and equivalence rules, the resolution of a tier
  inputs     published tables, known deviations, the targets' JSON documents
  rows       one verdict per published number
  exit_codes what `--row` and `--claim` return
  lines      ok / fail / unresolved comparison lines and the verdict of a claim
  claims     one small function per figure claim, registered with the targets it reads
  evaluate   everything together: the summary document (schema: tools/summary_schema.py)
"""
