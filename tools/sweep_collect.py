#!/usr/bin/python3
"""The table and plot of a sweep (peloid sweep, src/sweep/sweep.c):

    /usr/bin/python3 tools/sweep_collect.py OUT     (or: peloid sweep STUDY --collect)

Reads OUT/points.json (the study's keys, plot and points), each point's
OUT/ID/summary.json and OUT/status/ID.tsv, and writes

  OUT/sweep.tsv   one row per point: id, status (ok / failed / interrupted /
                  pending; interrupted: a signal stopped it at a checkpoint,
                  the next sweep resumes it from there), exit
                  code, message, the swept keys, last_step, wall_seconds,
                  threads (the OpenMP threads its run had), then
                  NAME and NAME_se for every observable any point measured
                  (summary.json "observables": value +- stderr)
  OUT/sweep.json  the same as a list of objects, "key_units" (the swept keys' units, from `peloid keys`:
                  the plot's x axis) and "plan": OUT/plan.json
                  (the jobs x threads the last sweep chose, why, each job's
                  CPU set, the machine), when it exists
  OUT/sweep.png   the study's plot{}: y (one panel per observable) against x,
                  one line per value of `series`, error bars = SE; without
                  plot{}: every observable against the first swept key.
"""
import json
import math
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def fmt(v):
    if v is None:
        return ""
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, (list, dict, bool)):
        return json.dumps(v)
    return str(v)


def load_point(out, p):
    row = {"id": p["id"], "index": p["index"], "params": p["params"], "status": "pending", "exit_code": None,
           "message": "", "last_step": None, "wall_seconds": None, "threads": None, "observables": {}}
    st = os.path.join(out, "status", p["id"] + ".tsv")
    if os.path.exists(st):
        try:
            code, _, msg = open(st).read().rstrip("\n").partition("\t")
            code = int(code)
        except (OSError, ValueError, UnicodeDecodeError) as e:
            sys.exit(f"peloid: error: {st}: {e}; allowed: EXIT_CODE<TAB>MESSAGE as peloid sweep writes it")
        row["exit_code"] = code
        row["message"] = msg
        row["status"] = "ok" if int(code) == 0 else "failed"
    sp = os.path.join(out, p["id"], "summary.json")
    if os.path.exists(sp):
        try:
            s = json.load(open(sp))
        except (OSError, ValueError):
            s = None
        if s and "last_step" in s and s.get("interrupted"):  # a signal ended it early: not finished
            row["status"] = "interrupted"
            row["message"] = row["message"] or "interrupted at step %s" % s["last_step"]
            row["last_step"] = s["last_step"]
        elif row["status"] == "failed":
            pass
        elif s and "last_step" in s:
            row["status"], row["exit_code"] = "ok", 0
            if not row["message"]:
                row["message"] = "ok"
            row["last_step"] = s["last_step"]
            row["wall_seconds"] = s.get("wall_seconds")
            row["threads"] = s.get("threads")
            for name, o in (s.get("observables") or {}).items():
                if isinstance(o, dict) and "value" in o:
                    row["observables"][name] = {"value": o["value"], "stderr": o.get("stderr"),
                                                "unit": o.get("unit", "")}
    return row


def key_units():
    """{"section.key": unit} from `peloid keys` of the binary that ran the sweep ($PELOID_BIN; {} without it)."""
    exe = os.environ.get("PELOID_BIN")
    if not exe:
        return {}
    try:
        text = subprocess.run([exe, "keys"], capture_output=True, text=True, timeout=30).stdout
    except (OSError, subprocess.SubprocessError):
        return {}
    units, sec = {}, ""
    for line in text.splitlines():
        m = re.match(r"#### `([^`]*)`", line)
        if m:
            sec = "" if m.group(1) == "(top level)" else m.group(1) + "."
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= 5 and cells[0].startswith("`") and cells[4] not in ("-", "unit", ""):
            units[sec + cells[0].strip("`")] = cells[4]
    return units


def plot(study, rows, path, units):
    spec = study.get("plot") or {}
    keys = study["keys"]
    x = spec.get("x", keys[0])
    series = spec.get("series")
    ys = spec.get("y")
    if ys is None:
        ys = []
        for r in rows:
            ys += [n for n in r["observables"] if n not in ys]
        ys = ys[:6]
    elif isinstance(ys, str):
        ys = [ys]
    ok = [r for r in rows if r["status"] == "ok"]
    xunit = units.get(x, "")
    n = max(1, len(ys))
    fig, axes = plt.subplots(n, 1, figsize=(6, 3.2 * n), squeeze=False)
    for ax, y in zip(axes[:, 0], ys):
        groups = {}
        for r in ok:
            if y not in r["observables"] or not isinstance(r["params"].get(x), (int, float)):
                continue
            groups.setdefault(json.dumps(r["params"].get(series)) if series else "", []).append(r)
        for label, rs in sorted(groups.items()):
            rs.sort(key=lambda r: r["params"][x])
            xv = [r["params"][x] for r in rs]
            yv = [r["observables"][y]["value"] for r in rs]
            ev = [r["observables"][y]["stderr"] or 0.0 for r in rs]
            ev = [e if e is not None and math.isfinite(e) else 0.0 for e in ev]
            ax.errorbar(xv, yv, yerr=ev, fmt="o-", ms=4, capsize=3,
                        label=f"{series} = {label}" if series else None)
        unit = next((r["observables"][y]["unit"] for r in ok if y in r["observables"]), "")
        ax.set_xlabel(f"{x} [{xunit}]" if xunit else x)
        ax.set_ylabel(f"{y} [{unit}]" if unit and unit != "1" else y)
        if spec.get("logx"):
            ax.set_xscale("log")
        if spec.get("logy"):
            ax.set_yscale("log")
        if not groups:
            ax.text(0.5, 0.5, f"no finished point has {y}", ha="center", va="center", transform=ax.transAxes)
        elif series:
            ax.legend(fontsize=8)
    failed = sum(r["status"] == "failed" for r in rows)
    axes[0, 0].set_title(f"sweep {study['study']}: {len(ok)}/{len(rows)} points ok"
                         + (f", {failed} failed" if failed else "") + ", error bars: SE", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: sweep_collect.py OUT")
    out = sys.argv[1]
    try:
        study = json.load(open(os.path.join(out, "points.json")))
    except OSError as e:
        sys.exit(f"peloid: error: {out}/points.json: {e.strerror}; allowed: the output of peloid sweep")
    except ValueError as e:
        sys.exit(f"peloid: error: {out}/points.json: not JSON ({e}); allowed: the output of peloid sweep")
    ok_keys = isinstance(study, dict) and all(k in study for k in ("study", "study_file", "keys", "points"))
    if not ok_keys or not all(isinstance(p, dict) and all(k in p for k in ("id", "index", "params"))
                              for p in study["points"]):
        sys.exit(f"peloid: error: {out}/points.json: not a study (needs study, study_file, keys and points "
                 "with id, index, params); allowed: the output of peloid sweep")
    rows = [load_point(out, p) for p in study["points"]]
    names = []
    for r in rows:
        names += [n for n in r["observables"] if n not in names]
    head = ["id", "status", "exit_code", "message"] + study["keys"] + ["last_step", "wall_seconds", "threads"]
    for n in names:
        head += [n, n + "_se"]
    lines = ["\t".join(head)]
    for r in rows:
        cells = [r["id"], r["status"], fmt(r["exit_code"]), r["message"].replace("\t", " ")]
        cells += [fmt(r["params"].get(k)) for k in study["keys"]]
        cells += [fmt(r["last_step"]), fmt(r["wall_seconds"]), fmt(r["threads"])]
        for n in names:
            o = r["observables"].get(n)
            cells += [fmt(o["value"]), fmt(o["stderr"])] if o else ["", ""]
        lines.append("\t".join(cells))
    tmp = os.path.join(out, "sweep.tsv.tmp")
    open(tmp, "w").write("\n".join(lines) + "\n")
    os.replace(tmp, os.path.join(out, "sweep.tsv"))
    tmp = os.path.join(out, "sweep.json.tmp")
    doc = {"study": study["study"], "study_file": study["study_file"], "keys": study["keys"], "points": rows}
    units = key_units()
    doc["key_units"] = {k: units[k] for k in study["keys"] if k in units}  # the plot's axis labels
    try:
        doc["plan"] = json.load(open(os.path.join(out, "plan.json")))
    except (OSError, ValueError):
        pass  # a Slurm array (--point, --collect) plans nothing
    json.dump(doc, open(tmp, "w"), indent=1)
    os.replace(tmp, os.path.join(out, "sweep.json"))
    plot(study, rows, os.path.join(out, "sweep.png"), units)
    ok = sum(r["status"] == "ok" for r in rows)
    failed = sum(r["status"] == "failed" for r in rows)
    stopped = sum(r["status"] == "interrupted" for r in rows)
    print(f"peloid sweep {study['study']}: {ok} ok, {failed} failed, {stopped} interrupted, "
          f"{len(rows) - ok - failed - stopped} pending -> "
          f"{out}/sweep.tsv, sweep.json, sweep.png", file=sys.stderr)


main()
