"""Merges the tables of a sweep's shards (`flapwright sweep --shard I/N`) into one.

Usage: python3 merge.py SHARD_TABLE... > sweep.csv

Every table must have the same header (the same sweep); the rows are sorted by their
`variant` column, so the output is the table one unsharded sweep writes, byte for byte.
"""
import sys

header, rows = None, []
for path in sys.argv[1:]:
    with open(path, encoding="utf-8", newline="") as f:
        first, *lines = f.read().split("\n")
    if header is None:
        header = first
    elif first != header:
        sys.exit(f"{path}: another sweep's table (its header differs)")
    rows.extend(line for line in lines if line)
if header is None:
    sys.exit("usage: python3 merge.py SHARD_TABLE... > sweep.csv")
rows.sort(key=lambda line: int(line.split(",", 1)[0]))
sys.stdout.write("\n".join([header] + rows) + "\n")
