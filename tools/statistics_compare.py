"""Shared parts of the statistical comparisons of two peloid builds
(tools/compare_md_statistics.py, tools/compare_coupling_statistics.py): the
command line and the seed loop, running a scene with a binary, the colloids'
g(r) and diffusion coefficient from colloids.h5, and the table of
differences in units of the combined SE."""
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

import h5md_colloids


def run(binary, scene_text, tag, seed, tmp, threads):
    """Runs scene_text (seed set) with binary in tmp/TAG_SEED; returns that directory."""
    cfg = os.path.join(tmp, "s%d.cfg" % seed)
    with open(cfg, "w") as f:
        f.write(scene_text)
    out = os.path.join(tmp, "%s_%d" % (tag, seed))
    subprocess.run([binary, "run", cfg, "--out", out, "--force", "--threads", str(threads)], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return out


def colloid_structure(out, n, edges):
    """g(r) of the n colloids over the second half of the frames (minimum
    image, bins `edges`) with the bins' shell volumes, and D from the MSD
    slope over the second half of the lags (unwrapped positions)."""
    c = h5md_colloids.load(os.path.join(out, "colloids.h5"))
    pos, img, t, L = c["pos"], c["img"], c["t"], c["edges"]
    hist = np.zeros(len(edges) - 1)
    frames = range(len(t) // 2, len(t))
    for k in frames:
        d = pos[k][:, None, :] - pos[k][None, :, :]
        d -= L * np.rint(d / L)
        r = np.sqrt((d * d).sum(-1))[np.triu_indices(n, 1)]
        hist += np.histogram(r, edges)[0]
    shell = 4.0 / 3.0 * math.pi * (edges[1:] ** 3 - edges[:-1] ** 3)
    gr = hist / (len(frames) * n * (n - 1) / 2 / np.prod(L) * shell)
    xu = pos + img * L
    lags = np.arange(1, len(t) // 2)
    msd = np.array([np.mean(np.sum((xu[l:] - xu[:-l]) ** 2, axis=-1)) for l in lags])
    sel = lags >= len(lags) // 2
    D = np.polyfit(lags[sel] * (t[1] - t[0]), msd[sel], 1)[0] / 6.0
    return gr, shell, np.prod(L), D


def interleaved(seeds, variants, observables, threads, each=None):
    """Runs every variant (tag, binary, scene_text(seed)) seed by seed, the
    variants in turn for each seed (interleaved, so that a slow spell of the
    machine falls on all of them); observables(out) gives a dict per run,
    each(tag, seed, values) sees it at once (None: nothing).  Returns
    {tag: [values per seed]}."""
    rows = {tag: [] for tag, _, _ in variants}
    with tempfile.TemporaryDirectory() as tmp:
        for s in seeds:
            for tag, binary, text in variants:
                out = run(binary, text(s), tag, s, tmp, threads)
                rows[tag].append(observables(out))
                if each:
                    each(tag, s, rows[tag][-1])
    return rows


def table(rows, quantities, not_physics=()):
    """Prints old and new (mean +- SE over seeds) and z = their difference
    over the combined SE per quantity; returns the largest |z| of the
    quantities not in not_physics."""
    print("| quantity | old (mean +- SE) | new (mean +- SE) | z |")
    print("|---|---|---|---|")
    worst = 0.0
    for q in quantities:
        a = np.array([r[q] for r in rows["old"]])
        b = np.array([r[q] for r in rows["new"]])
        sa, sb = a.std(ddof=1) / math.sqrt(len(a)), b.std(ddof=1) / math.sqrt(len(b))
        z = (b.mean() - a.mean()) / math.hypot(sa, sb) if sa + sb > 0 else 0.0
        if q not in not_physics:
            worst = max(worst, abs(z))
        print("| %s | %.5g +- %.2g | %.5g +- %.2g | %+.2f |" % (q, a.mean(), sa, b.mean(), sb, z))
    print("# largest |z| (physics rows) = %.2f" % worst)
    return worst


def main(doc, scene, threads, observables, title, quantities, not_physics=(), seeds=4, steps=4000):
    """usage: OLD_PELOID NEW_PELOID [SEEDS] [STEPS] (doc printed otherwise).
    Runs scene (a format string with {seed} and {steps}) with both binaries,
    seed by seed, interleaved; observables(out, steps) gives a dict per run;
    prints title % (seeds, steps) and the table of quantities.  Exit code."""
    if len(sys.argv) < 3:
        print(doc)
        return 2
    seed_range = range(1, 1 + (int(sys.argv[3]) if len(sys.argv) > 3 else seeds))
    steps = int(sys.argv[4]) if len(sys.argv) > 4 else steps
    text = lambda s: scene.format(seed=s, steps=steps)  # noqa: E731
    rows = interleaved(seed_range, [("old", sys.argv[1], text), ("new", sys.argv[2], text)],
                       lambda out: observables(out, steps), threads)
    print(title % (len(seed_range), steps))
    table(rows, quantities, not_physics)
    return 0
