"""A study's report (tools/sweep_collect.py writes it as OUT/report.md).

Per point the swept keys, then one row per observable column (a physical
study's SI column with its unit, the model column after it): the value
+- its SE.  With replicas (study key `replicas`, or `peloid run SCENE
--replicas N`) the value is the mean over the replicas and the SE the one
from their scatter (tools/sweep_pool.py), beside the within-run SE (what
the runs' own SEs promise for the mean), their ratio and the flag (ok,
high: the replicas scatter more than their SEs say, low: less) with the
interval the ratio falls in 95 % of the time when the within-run SE is
right.  The figure is OUT/sweep.png.
"""
import math


def pm(v, e):
    """'v +- e' with e to two significant digits and v to the same place (plain 'v' without e)."""
    if not isinstance(v, (int, float)) or isinstance(v, bool):
        return "" if v is None else str(v)
    if not isinstance(e, (int, float)) or not math.isfinite(e) or e <= 0:
        return f"{v:.6g}"
    sig = (math.floor(math.log10(abs(v))) - math.floor(math.log10(e)) + 2) if v else 1
    return f"{v:.{min(max(sig, 1), 15)}g} \u00b1 {e:.2g}"


def _num(v, f="{:.3g}"):
    return f.format(v) if isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) else ""


def _params(r, keys, units):
    return ", ".join(f"{k} = {r['params'].get(k)}" + (f" {units[k]}" if units.get(k) else "") for k in keys)


def lines(study, rows, pooled, units, physical, replicas, views):
    """report.md's lines.  rows: each run (sweep_collect.load_point); pooled: each point's pooled row
    (sweep_collect.pool_points) or None; views(row): {observable: [(column, unit, value, SE)]}."""
    keys = study["keys"]
    ok = sum(r["status"] == "ok" for r in rows)
    out = [f"# Study {study['study']}", "",
           f"From `{study['study_file']}`: "
           + (f"{len(pooled)} point(s) x {replicas} replicas (seeds the base scene's + 0 .. {replicas - 1}); "
              if pooled else f"{len(rows)} point(s); ")
           + f"{ok}/{len(rows)} runs finished.  Figure: [sweep.png](sweep.png); table: sweep.tsv"
           + (" (runs: sweep_replicas.tsv)." if pooled else "."), ""]
    if pooled:
        out += ["Each value is the mean over the replicas \u00b1 the SE from their scatter (sd / \u221aN); "
                "*within-run SE* is the mean of the runs' own SEs / \u221aN, what those SEs promise for the mean; "
                "the flag is `high` when the replicas scatter more than their SEs say (the within-run SE is "
                "understated: a correlation longer than its blocks, a drift), `low` when less, and `ok` when "
                "the ratio lies in the interval it falls in 95 % of the time with right SEs "
                "(\u03c7\u00b2 with N \u2212 1 degrees of freedom).", ""]
    for p in pooled or rows:
        title = _params(p, keys, units) if keys else "the base scene"
        out += [f"## {p['id']}: {title}", "", f"status: {p['status']} ({p['message']})", ""]
        if pooled:
            out += ["| observable | unit | mean \u00b1 SE between replicas | within-run SE | ratio | flag (95 % interval) |",
                    "|---|---|---|---|---|---|"]
            for name, cs in p["columns"].items():
                for c, u in cs:
                    q = p["pooled"][name][c]
                    iv = q.get("interval")
                    flag = q["flag"] + (f" ({iv[0]:.2f}\u2013{iv[1]:.2f})" if iv and q["flag"] else "")
                    out.append(f"| {c} | {u or p['model_unit'].get(name, '')} | {pm(q['mean'], q['se'])} | "
                               f"{_num(q['se_within'])} | {_num(q['ratio'], '{:.2f}')} | {flag} |")
        else:
            out += ["| observable | unit | value \u00b1 SE |", "|---|---|---|"]
            for name, vs in views(p).items():
                for c, u, v, e in vs:
                    out.append(f"| {c} | {u or p['observables'][name].get('unit', '')} | {pm(v, e)} |")
        out.append("")
    if physical:
        out += ["SI columns from each run's summary.json (`value_si`, `stderr_si`); cluster sizes as fractions "
                "of the colloids; `_model` columns in the model units beside.", ""]
    return out
