#!/usr/bin/python3
"""Markdown tables from bench/out/srd*.tsv (bench_srd) for bench/RESULTS.md.

usage: tools/bench_tables.py bench/out/srd.tsv [L ...]
"""
import csv
import sys


def main():
    path = sys.argv[1]
    sizes = [int(a) for a in sys.argv[2:]]
    with open(path) as f:
        rows = list(csv.DictReader((l for l in f if not l.startswith("#")), delimiter="\t"))
    print("| kernel | L | thr | particles | ns/particle (median) | min..max | Mupd/s | Mupd/s/core "
          "| eff. GB/s | STREAM GB/s | % of bound | model B/particle | alloc B/particle |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if sizes and int(r["L"]) not in sizes:
            continue
        print("| %s | %s | %s | %s | %.2f | %.2f..%.2f | %.1f | %.1f | %.1f | %.1f | %s | %s | %s |" % (
            r["kernel"], r["L"], r["threads"], r["particles"], float(r["ns_per_particle"]),
            float(r["ns_min"]), float(r["ns_max"]), float(r["updates_per_s"]) / 1e6,
            float(r["updates_per_s_per_core"]) / 1e6, float(r["eff_GBps"]), float(r["stream_GBps"]),
            r["pct_of_stream_bound"], r["model_bytes_per_particle"], r["alloc_bytes_per_particle"]))


if __name__ == "__main__":
    main()
