"""The medians of interleaved rounds, for the peer scripts here (klein.sh, compare.sh).

Each round appends `operation form ns` lines to one file; `read(path)` gives the operations
in the order first seen and the median of each (operation, form) over the rounds.
"""
import collections
import statistics


def read(path):
    t = collections.defaultdict(list)
    for line in open(path):
        op, form, ns = line.split()
        t[(op, form)].append(float(ns))
    ops = list(dict.fromkeys(op for op, _ in t))
    return ops, {k: statistics.median(v) for k, v in t.items()}
