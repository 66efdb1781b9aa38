#!/usr/bin/python3
"""A Markdown table from a benchmark TSV (bench/out/*.tsv); '#' lines, such
as the peer ratios, follow the table as they are.

usage: tools/tsv_table.py FILE.tsv
"""
import sys


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    rows, notes = [], []
    with open(sys.argv[1]) as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("#"):
                notes.append(line[1:].strip())
            elif line:
                rows.append(line.split("\t"))
    if not rows:
        return 1
    print("| " + " | ".join(rows[0]) + " |")
    print("|" + "---|" * len(rows[0]))
    for r in rows[1:]:
        print("| " + " | ".join(r) + " |")
    for n in notes:
        print("\n" + n)
    return 0


if __name__ == "__main__":
    sys.exit(main())
