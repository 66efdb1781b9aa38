#!/usr/bin/python3
"""The table and plot of a sweep (peloid sweep, src/app/sweep.c):

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
  OUT/report.md   per point its keys and each observable's value +- SE in its
                  unit; with replicas the pooled mean +- the SE between them,
                  the within-run SE, ratio and flag (tools/sweep_report.py)

A physical study (its points' summary.json has "units_si"): every column of
sweep.tsv is in SI with its unit in the header, the model value beside it
("colloid_D [m^2/s]", "colloid_D_se [m^2/s]", "colloid_D_model [a0^2/t0]",
"colloid_D_model_se [a0^2/t0]"; a dimensionless one once, "rdf_peak [1]"),
cluster sizes as fractions of the colloids ("largest_cluster_fraction [1]":
largest cluster / N, beside "largest_cluster_model [colloids]"), the swept
keys with their units ("physical.kappa [1/m]"); sweep.png in SI with
mathtext units (um as \u00b5m, m^2/s as \u00b5m\u00b2/s).  A model-unit study's
columns are the names alone, as they always were.

Replicas (study key `replicas` = N > 1, points.json "replicas"): the runs
pPPPr0 .. pPPPr{N-1} of a point are pooled (tools/sweep_pool.py): sweep.tsv
has one row per point (id pPPP, the replicas that finished, NAME the mean,
NAME_se the SE from the scatter between replicas, NAME_se_within the mean
within-run SE / sqrt(N), NAME_se_flag ok / high / low when the two disagree
beyond the 95 % interval of their ratio), OUT/sweep_replicas.tsv one row
per run as sweep.tsv has without replicas (plus replica and seed), and
sweep.json "pooled" the pooled rows; sweep.png draws the pooled means with
the SE between replicas (thin bars) and the within-run SE (thick bars), a
flagged point ringed in red.  A study without swept keys (`peloid run SCENE
--replicas N`) draws each replica's value against its number with the
pooled mean and its SE band.
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
import matplotlib.ticker  # noqa: E402

from sweep_pool import pool  # noqa: E402
from system_title import system_title  # noqa: E402
from sweep_report import lines as report_lines  # noqa: E402

# Observables that count colloids: in a physical study given as fractions of N.
CLUSTER_SIZES = ("largest_cluster", "mean_cluster_size")
# SI units as drawn (sweep.png): the factor to the drawn unit and its mathtext.
DRAWN = {"m": (1e6, "\u00b5m"), "1/m": (1e-6, "\u00b5m$^{-1}$"), "m^2": (1e12, "\u00b5m$^2$"),
         "1/m^3": (1e-18, "\u00b5m$^{-3}$"), "m/s": (1e6, "\u00b5m/s"), "m^2/s": (1e12, "\u00b5m$^2$/s"),
         "m^2/s^2": (1e12, "\u00b5m$^2$/s$^2$"), "1/s": (1.0, "s$^{-1}$")}


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
                    row["observables"][name].update({k: o[k] for k in ("value_si", "stderr_si", "unit_si") if k in o})
            if "units_si" in s:  # a physical scene: its colloids, the N of the cluster fractions
                row["units_si"] = True
                row["system"] = {"scene": s.get("scene"), "units_si": s["units_si"]}  # the plot's title
                count = ((s.get("scene") or {}).get("colloids") or {}).get("count")
                row["colloids"] = count if isinstance(count, int) and count > 0 else None
    for k in ("point", "replica", "seed"):
        if k in p:
            row[k] = p[k]
    return row


def scaled(v, n):
    return v / n if isinstance(v, (int, float)) and not isinstance(v, bool) and n else v


def views(name, o, physical, n_colloids):
    """The columns of observable `name` (o: a row's entry): [(column, unit, value, stderr)], unit None for a
    model-unit study (its columns are the names alone); a physical study's SI column first, the model one
    after it (none for a dimensionless one, whose SI value is the model's)."""
    v, e, u = o["value"], o.get("stderr"), o.get("unit") or "1"
    if not physical:
        return [(name, None, v, e)]
    if name in CLUSTER_SIZES and n_colloids:
        return [(name + "_fraction", "1", scaled(v, n_colloids), scaled(e, n_colloids)),
                (name + "_model", "colloids", v, e)]
    usi = o.get("unit_si")
    if usi is None:  # a unit without an SI twin (observables_si.c): its model column alone, named so
        return [(name + "_model", u, v, e)]
    if usi == u:
        return [(name, usi, v, e)]
    return [(name, usi, o.get("value_si"), o.get("stderr_si")), (name + "_model", u, v, e)]


def head(column, unit, suffix=""):
    return f"{column}{suffix} [{unit}]" if unit else column + suffix


def row_views(r, physical):
    return {name: views(name, o, physical, r.get("colloids")) for name, o in r["observables"].items()}


def layout(rows, physical):
    """Each observable any row measured, in order, with its columns [(column, unit)] (from the first row)."""
    out = {}
    for r in rows:
        for name, vs in row_views(r, physical).items():
            out.setdefault(name, [(c, u) for c, u, _, _ in vs])
    return out


def table(rows, keys, physical, units, pooled=False):
    """sweep.tsv's lines: one per row (a run, or with `pooled` a point's pooled replicas)."""
    cols = {}
    for r in rows if pooled else ():
        for name, cs in r["columns"].items():
            cols.setdefault(name, cs)
    cols = cols if pooled else layout(rows, physical)
    kh = [head(k, units.get(k) if physical else None) for k in keys]
    h = ["id", "status", "exit_code", "message"] + kh
    h += ["replicas"] if pooled else [c for c in ("replica", "seed") if rows and c in rows[0]]
    h += ["last_step", head("wall_seconds", "s" if physical else None), "threads"]
    for name, cs in cols.items():
        for i, (c, u) in enumerate(cs):
            h += [head(c, u), head(c, u, "_se")]
            if pooled:
                h += [head(c, u, "_se_within")] + ([name + "_se_flag"] if i == 0 else [])
    lines = ["\t".join(h)]
    for r in rows:
        cells = [r["id"], r["status"], fmt(r["exit_code"]), r["message"].replace("\t", " ")]
        cells += [fmt(r["params"].get(k)) for k in keys]
        cells += [fmt(r.get("replicas_ok"))] if pooled else [fmt(r[c]) for c in ("replica", "seed") if c in r]
        cells += [fmt(r["last_step"]), fmt(r["wall_seconds"]), fmt(r["threads"])]
        got = r["pooled"] if pooled else {n: {c: {"mean": v, "se": e} for c, _, v, e in vs}
                                          for n, vs in row_views(r, physical).items()}
        for name, cs in cols.items():
            for i, (c, _) in enumerate(cs):
                q = got.get(name, {}).get(c)
                cells += [fmt(q["mean"]), fmt(q["se"])] if q else ["", ""]
                if pooled:
                    cells += [fmt(q["se_within"]) if q else ""] + ([q["flag"] if q else ""] if i == 0 else [])
        lines.append("\t".join(cells))
    return lines


def pool_points(rows, physical):
    """One row per point from the rows of its replicas (points.json "point"): status ok when every replica is,
    else the first replica's that is not; each observable's columns pooled over the replicas that finished."""
    by = {}
    for r in rows:
        by.setdefault(r["point"], []).append(r)
    out = []
    for p, rs in sorted(by.items()):
        ok = [r for r in rs if r["status"] == "ok"]
        bad = next((r for r in rs if r["status"] != "ok"), None)
        first = rs[0]
        pr = {"id": first["id"].rpartition("r")[0], "index": p, "params": first["params"],
              "status": bad["status"] if bad else "ok", "exit_code": bad["exit_code"] if bad else 0,
              "message": (f"{bad['id']}: {bad['message']}" if bad else f"{len(ok)}/{len(rs)} replicas ok"),
              "replicas": [r["id"] for r in rs], "replicas_ok": len(ok),
              "last_step": first["last_step"] if all(r["last_step"] == first["last_step"] for r in rs) else None,
              "wall_seconds": math.fsum(r["wall_seconds"] for r in ok) if ok else None,
              "threads": first["threads"], "pooled": {}}
        if bad and bad["status"] != "failed" and ok:
            pr["message"] = f"{len(ok)}/{len(rs)} replicas ok, {bad['id']} {bad['status']}"
        system = next((r["system"] for r in ok if r.get("system")), None)
        if system:
            pr["system"] = system
        vs = [row_views(r, physical) for r in ok]
        pr["columns"] = layout(ok, physical)
        pr["model_unit"] = {n: o["unit"] for r in ok for n, o in r["observables"].items()}
        for name, cols in pr["columns"].items():
            per = [{c: (v, e) for c, _, v, e in v_.get(name, [])} for v_ in vs]
            pr["pooled"][name] = {c: pool([q[c][0] if c in q else None for q in per],
                                          [q[c][1] if c in q else None for q in per]) for c, _ in cols}
        out.append(pr)
    return out


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


def mathtext(unit):
    """A unit as matplotlib draws it: powers as superscripts (m^2 -> m$^2$, 1/m -> m$^{-1}$), um as \u00b5m."""
    unit = re.sub(r"\bum\b", "\u00b5m", unit)
    m = re.fullmatch(r"1/([A-Za-z\u00b5]+)(?:\^(\d+))?", unit)
    if m:
        return f"{m.group(1)}$^{{-{m.group(2) or 1}}}$"
    return re.sub(r"\^(-?\d+)", r"$^{\1}$", unit)


def drawn(rows, physical, pooled):
    """Each row's {observable: (value, SE, axis label, within-run SE, flag)} as sweep.png draws it: a
    model-unit study its values; a physical one its SI column in the drawn units (DRAWN: \u00b5m,
    \u00b5m\u00b2/s, ...); pooled rows their mean with the SE between replicas, the within-run SE of the mean
    and the flag (tools/sweep_pool.py); a run's row its SE as within-run SE and no flag."""
    out = []
    for r in rows:
        d = {}
        if pooled:
            for name, cs in r["columns"].items():
                c, u = cs[0]
                q = r["pooled"][name][c]
                d[name] = (q["mean"], q["se"], u if physical else r["model_unit"].get(name, ""), q["se_within"],
                           q["flag"])
        else:
            for name, vs in row_views(r, physical).items():
                _, u, v, e = vs[0]
                d[name] = (v, e, u if physical else r["observables"][name]["unit"], e, "")
        for name, (v, e, u, w, flag) in list(d.items()):
            if not physical:
                d[name] = (v, e, f"{name} [{u}]" if u and u != "1" else name, w, flag)
                continue
            f, shown = DRAWN.get(u, (1.0, mathtext(u or "1")))
            label = f"{name} / N" if name in CLUSTER_SIZES and u == "1" else name
            d[name] = (scaled(v, 1.0 / f), scaled(e, 1.0 / f), f"{label} [{shown}]" if shown != "1" else label,
                       scaled(w, 1.0 / f), flag)
        out.append(d)
    return out


def _finite0(e):
    return e if isinstance(e, (int, float)) and not isinstance(e, bool) and math.isfinite(e) else 0.0


def title_system(fig, study, rows):
    """A physical study's figure names the system (R, phi, salt, coupling; the swept keys as varied)."""
    src = next((r["system"] for r in rows if r.get("system")), None)
    if src:
        name = dict(src, scene=dict(src.get("scene") or {}, name=study["study"]))
        fig.suptitle(system_title(name, varied=set(study.get("keys") or ())), fontsize=9)


def plot_replicas(study, runs, pooled, path, physical):
    """sweep.png of a study without swept keys (`peloid run SCENE --replicas N`): per observable each
    replica's value with its within-run SE against its replica number, the pooled mean as a line and the
    SE between the replicas as a band around it, the flag in the legend."""
    p = pooled[0]
    per = drawn(runs, physical, False)
    mine = drawn([p], physical, True)[0]
    spec = study.get("plot") or {}
    ys = spec.get("y") or [n for n in p["pooled"]][:6]
    ys = [ys] if isinstance(ys, str) else ys
    fig, axes = plt.subplots(len(ys), 1, figsize=(6, 3.0 * len(ys)), squeeze=False)
    for ax, y in zip(axes[:, 0], ys):
        pts = [(r["replica"], d[y]) for r, d in zip(runs, per) if r["status"] == "ok" and y in d
               and isinstance(d[y][0], (int, float))]
        if not pts or y not in mine or not isinstance(mine[y][0], (int, float)):
            ax.text(0.5, 0.5, f"no finished replica has {y}", ha="center", va="center", transform=ax.transAxes)
            continue
        m, se, label, w, flag = mine[y]
        ax.errorbar([k for k, _ in pts], [d[0] for _, d in pts], yerr=[_finite0(d[1]) for _, d in pts], fmt="o",
                    ms=4, capsize=3, color="C0", label="replica ± its within-run SE")
        ax.axhline(m, color="C1", lw=1.2, label=f"mean ± SE between replicas (flag: {flag or 'n/a'})")
        ax.axhspan(m - _finite0(se), m + _finite0(se), color="C1", alpha=0.25)
        ax.set_xlabel("replica (seed = the scene's seed + replica)")
        ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
        ax.set_ylabel(label)
        ax.legend(fontsize=7)
    axes[0, 0].set_title(f"{study['study']}: {p['replicas_ok']}/{len(runs)} replicas ok; "
                         "flag: within-run SE against the scatter", fontsize=10)
    title_system(fig, study, runs)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot(study, rows, path, units, physical=False, pooled=False):
    spec = study.get("plot") or {}
    keys = study["keys"]
    x = spec.get("x", keys[0])
    series = spec.get("series")
    ys = spec.get("y")
    if ys is None:
        ys = []
        for r in rows:
            ys += [n for n in (r["pooled"] if pooled else r["observables"]) if n not in ys]
        ys = ys[:6]
    elif isinstance(ys, str):
        ys = [ys]
    ok = [(r, d) for r, d in zip(rows, drawn(rows, physical, pooled)) if r["status"] == "ok"
          or (pooled and r.get("replicas_ok"))]
    xunit = units.get(x, "")
    n = max(1, len(ys))
    fig, axes = plt.subplots(n, 1, figsize=(6, 3.2 * n), squeeze=False)
    for ax, y in zip(axes[:, 0], ys):
        groups = {}
        for r, d in ok:
            if y not in d or not isinstance(r["params"].get(x), (int, float)) or not isinstance(d[y][0], (int, float)):
                continue
            groups.setdefault(json.dumps(r["params"].get(series)) if series else "", []).append((r, d))
        for label, rs in sorted(groups.items()):
            rs.sort(key=lambda rd: rd[0]["params"][x])
            xv = [r["params"][x] for r, _ in rs]
            yv = [d[y][0] for _, d in rs]
            ev = [_finite0(d[y][1]) for _, d in rs]
            line = ax.errorbar(xv, yv, yerr=ev, fmt="o-", ms=4, capsize=3,
                               label=f"{series} = {label}" if series else None)
            if pooled:  # the within-run SE of the mean as a thick inner bar; a flagged point ringed in red
                ax.errorbar(xv, yv, yerr=[_finite0(d[y][3]) for _, d in rs], fmt="none", lw=4, alpha=0.35,
                            color=line[0].get_color())
                bad = [(x_, y_) for x_, y_, (_, d) in zip(xv, yv, rs) if d[y][4] in ("high", "low")]
                if bad:
                    ax.plot(*zip(*bad), "o", ms=11, mfc="none", mec="red", mew=1.5)
        ylabel = next((d[y][2] for _, d in ok if y in d), y)
        ax.set_xlabel(f"{x} [{mathtext(xunit) if physical else xunit}]" if xunit else x)
        ax.set_ylabel(ylabel)
        if spec.get("logx"):
            ax.set_xscale("log")
        if spec.get("logy"):
            ax.set_yscale("log")
        if not groups:
            ax.text(0.5, 0.5, f"no finished point has {y}", ha="center", va="center", transform=ax.transAxes)
        elif series:
            ax.legend(fontsize=8)
    failed = sum(r["status"] == "failed" for r in rows)
    bars = "error bars: SE"
    if pooled:
        nrep = study.get("replicas")
        flagged = sum(any(q["flag"] in ("high", "low") for q in r["pooled"].get(y, {}).values()) for r in rows
                      for y in ys)
        bars = (f"{nrep} replicas each\nmean, thin bars: SE between the replicas, thick: within-run SE"
                + (f"\n{flagged} ringed in red: the two SEs disagree" if flagged else ""))
    axes[0, 0].set_title(f"sweep {study['study']}: {len(ok)}/{len(rows)} points ok"
                         + (f", {failed} failed" if failed else "") + ", " + bars, fontsize=10)
    title_system(fig, study, rows)
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
    physical = any(r.get("units_si") for r in rows)
    replicas = study.get("replicas", 1)
    units = key_units()
    pooled = pool_points(rows, physical) if replicas > 1 else None

    def write(name, lines):
        tmp = os.path.join(out, name + ".tmp")
        open(tmp, "w").write("\n".join(lines) + "\n")
        os.replace(tmp, os.path.join(out, name))

    write("sweep.tsv", table(pooled, study["keys"], physical, units, pooled=True) if pooled
          else table(rows, study["keys"], physical, units))
    if pooled:
        write("sweep_replicas.tsv", table(rows, study["keys"], physical, units))
    tmp = os.path.join(out, "sweep.json.tmp")
    doc = {"study": study["study"], "study_file": study["study_file"], "keys": study["keys"], "points": rows}
    if pooled:
        doc["replicas"] = replicas
        doc["pooled"] = pooled
    doc["key_units"] = {k: units[k] for k in study["keys"] if k in units}  # the plot's axis labels
    try:
        doc["plan"] = json.load(open(os.path.join(out, "plan.json")))
    except (OSError, ValueError):
        pass  # a Slurm array (--point, --collect) plans nothing
    json.dump(doc, open(tmp, "w"), indent=1)
    os.replace(tmp, os.path.join(out, "sweep.json"))
    if pooled and not study["keys"]:
        plot_replicas(study, rows, pooled, os.path.join(out, "sweep.png"), physical)
    else:
        plot(study, pooled or rows, os.path.join(out, "sweep.png"), units, physical, bool(pooled))
    write("report.md", report_lines(study, rows, pooled, units, physical, replicas,
                                    lambda r: row_views(r, physical)))
    ok = sum(r["status"] == "ok" for r in rows)
    failed = sum(r["status"] == "failed" for r in rows)
    stopped = sum(r["status"] == "interrupted" for r in rows)
    print(f"peloid sweep {study['study']}: {ok} ok, {failed} failed, {stopped} interrupted, "
          f"{len(rows) - ok - failed - stopped} pending -> "
          f"{out}/sweep.tsv, {'sweep_replicas.tsv, ' if pooled else ''}sweep.json, sweep.png, report.md", file=sys.stderr)


if __name__ == "__main__":
    main()
