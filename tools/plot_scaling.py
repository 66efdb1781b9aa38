#!/usr/bin/python3
"""Throughput vs threads for the SRD step against the STREAM-triad bound.

Reads bench/out/srd.tsv and bench/out/stream.tsv (written by bench_srd) and
draws, for the largest box in the file, particle-updates/s of the whole step
(plan and stream-in-scatter pipeline) against threads, next to the bound
STREAM triad GB/s / model bytes per particle of the same run.

usage: tools/plot_scaling.py [bench/out] [out.png]
"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows(path):
    with open(path) as f:
        return list(csv.DictReader((l for l in f if not l.startswith("#")), delimiter="\t"))


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "bench/out"
    png = sys.argv[2] if len(sys.argv) > 2 else "bench/scaling.png"
    srd = rows(d + "/srd.tsv")
    stream = {int(r["threads"]): float(r["GBps_median"]) for r in rows(d + "/stream.tsv")}
    L = max(int(r["L"]) for r in srd)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for kern, label, mark in (("step", "peloid step (plan: stream+bin, sort, collide)", "o-"),
                              ("fused:step", "peloid step (stream-in-scatter)", "s-")):
        pts = sorted((int(r["threads"]), float(r["updates_per_s"]), float(r["ns_min"]),
                      float(r["ns_max"]), float(r["model_bytes_per_particle"]))
                     for r in srd if r["kernel"] == kern and int(r["L"]) == L)
        if not pts:
            continue
        t = [p[0] for p in pts]
        ups = [p[1] for p in pts]
        lo = [u - 1e9 / p[3] for u, p in zip(ups, pts)]
        hi = [1e9 / p[2] - u for u, p in zip(ups, pts)]
        ax.errorbar(t, ups, yerr=[lo, hi], fmt=mark, capsize=3, label=label)
        bound = [stream[k] * 1e9 / pts[0][4] for k in t]
        ax.plot(t, bound, "--", label="STREAM bound, %d B/particle" % pts[0][4])
    ax.set_xlabel("threads")
    ax.set_ylabel("particle updates / s")
    ax.set_title("SRD step, L = %d, 10 per cell (median, min..max)" % L)
    ax.set_xticks(sorted(stream))
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote", png)


if __name__ == "__main__":
    main()
