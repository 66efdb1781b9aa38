#!/usr/bin/env bash
# Observers through bin/peloid (src/observe/observe_module.c), checked against
# analytic results:
#  - free Brownian colloids (no pair terms): D from the MSD observer equals
#    the Stokes-Einstein kT / (6 pi eta R) within 3 SE (SE over the 64
#    independent colloids; the 3-SE bound fails by chance 0.3 % of the time);
#    g(r) of these uncorrelated centres is 1 once the non-overlapping start
#    has relaxed (rdf_start = 10 t0).  eta = 0.02 makes D = 2.65 a0^2/t0, so
#    the pair counts in a shell of radius r < 8 decorrelate within r^2 / D
#    < 25 t0 and the 590 samples (every 1 t0) give the blocking a plateau:
#    at least 90 % of the bins within
#    3 SE of 1 (expected 99.7 %) and chi^2 per bin below 1.5; S(q) likewise
#    (wave vectors of the box up to 4 / a0, 40 bins);
#  - clusters on a lattice of spacing 4 a0 (R = 1, gap 2): bond gap 2.5 puts
#    all 64 in one cluster at the start, bond gap 1 none (64 clusters of 1);
#  - the observables (observables.h5 and summary.json values) are bitwise the
#    same at 1 and 2 threads;
#  - summary.json carries value, stderr, se_vs_time at 1/8, 1/4, 1/2, 1 of the
#    run; observables.h5 carries unit attributes;
#  - velocity distributions against Maxwell-Boltzmann;
#  - the settling velocity and phi(z) of sedimenting Brownian colloids;
#  - analysis windows (observe.average_from) on a drifting series;
#  - the stopping rule stops at the first check where the target is met;
#  - peloid report writes report.md with the plots of what the run measured.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
TOOLS=$(realpath "$(dirname "$0")/../../tools")
T=$(mktemp -d /tmp/peloid-observe.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== observer tests"

cat > free.cfg <<'CFG'
name = "free";
seed = 11;
steps = 6000;
box: { cells = [16, 16, 16]; };
fluid: { density = 0.0; };
srd: { dt = 0.1; };
colloids: { count = 64; radius = 1.0; mass_density = 1.0; temperature = 1.0; init = "random";
  pairs = ""; integrator = "brownian"; bd_viscosity = 0.02; substeps = 1; max_overlap = 1.0; };
observe: { rdf_interval = 10; rdf_start = 100; rdf_bins = 40; msd_interval = 1; sq_interval = 10; sq_start = 100;
  sq_qmax = 4.0; sq_bins = 40; };
CFG
for th in 1 2; do
  "$PELOID" run free.cfg --threads $th --out free$th 2> /dev/null || bad "free BD run ($th threads)"
done
if out=$($PY - <<'PY'
import json, math, h5py, numpy as np
s = json.load(open("free1/summary.json"))["observables"]
D, se = s["colloid_D"]["value"], s["colloid_D"]["stderr"]
D0 = 1.0 / (6 * math.pi * 0.02 * 1.0)
assert abs(D - D0) < 3 * se, f"D = {D:.5f} +- {se:.5f}, Stokes-Einstein {D0:.5f}"
assert [p["run_fraction"] for p in s["colloid_D"]["se_vs_time"]] == [0.125, 0.25, 0.5, 1.0]
with h5py.File("free1/observables.h5") as f:
    g = f["observables/colloid_rdf/value"][0]; e = f["observables/colloid_rdf/value_se"][0]
    r = f["observables/colloid_rdf/r"][:]
    assert f["observables/colloid_rdf/r"].attrs["unit"] in (b"a0", "a0")
    assert f["observables/colloid_msd/value"].attrs["unit"] in (b"a0^2", "a0^2")
m = (e > 0) & (r > 1.0)
z = (g[m] - 1) / e[m]
inside, chi2 = np.mean(np.abs(z) < 3), np.mean(z**2)
assert inside >= 0.9 and chi2 < 1.5, f"g(r) of an ideal gas: {inside:.2f} within 3 SE, chi2/bin {chi2:.2f}"
with h5py.File("free1/observables.h5") as f:
    S, Se, nv = (f["observables/colloid_sq/" + k][()] for k in ("value", "value_se", "vectors"))
mq = nv > 0
zq = (S[0][mq] - 1) / Se[0][mq]
inq, chq = np.mean(np.abs(zq) < 3), np.mean(zq**2)
assert inq >= 0.9 and chq < 1.5, f"S(q) of an ideal gas: {inq:.2f} within 3 SE, chi2/bin {chq:.2f}"
print(f"D = {D:.5f} +- {se:.5f} vs kT/(6 pi eta R) = {D0:.5f}; g(r) = 1: {inside:.2f} of {m.sum()} bins "
      f"within 3 SE, chi2/bin {chi2:.2f}; S(q) = 1: {inq:.2f} of {mq.sum()} bins, chi2/bin {chq:.2f}")
PY
); then ok "free Brownian colloids: $out"; else bad "free Brownian colloids: $out"; fi
if $PY - <<'PY'
import json, h5py, numpy as np
a, b = (json.load(open(f"free{t}/summary.json"))["observables"] for t in (1, 2))
for k in ("colloid_D", "rdf_peak"): # everything but the wall times
    assert (a[k]["value"], a[k]["stderr"]) == (b[k]["value"], b[k]["stderr"]), k
    assert [(p["value"], p["stderr"]) for p in a[k]["se_vs_time"]] == \
        [(p["value"], p["stderr"]) for p in b[k]["se_vs_time"]], k
with h5py.File("free1/observables.h5") as f, h5py.File("free2/observables.h5") as g:
    for name in ("observables/colloid_rdf/value", "observables/colloid_msd/value", "observables/colloid_sq/value"):
        assert np.array_equal(f[name][:], g[name][:]), name
PY
then ok "observables bitwise the same at 1 and 2 threads"; else bad "observables differ between 1 and 2 threads"; fi

for gap in 2.5 1.0; do
cat > lat$gap.cfg <<CFG
name = "lat";
seed = 3;
steps = 20;
box: { cells = [16, 16, 16]; };
fluid: { density = 0.0; };
srd: { dt = 0.01; };
colloids: { count = 64; radius = 1.0; init = "lattice"; pairs = ""; integrator = "brownian"; substeps = 1;
  max_overlap = 1.0; };
observe: { clusters_interval = 1; clusters_gap = $gap; };
CFG
"$PELOID" run lat$gap.cfg --out lat$gap 2> /dev/null || bad "lattice run gap $gap"
done
if out=$($PY - <<'PY'
import h5py
with h5py.File("lat2.5/observables.h5") as f:
    n, big = f["observables/cluster_number/value"][0], f["observables/largest_cluster/value"][0]
    assert (n, big) == (1, 64), f"gap 2.5: {n} clusters, largest {big}"
with h5py.File("lat1.0/observables.h5") as f:
    n, big = f["observables/cluster_number/value"][0], f["observables/largest_cluster/value"][0]
    hist = f["observables/cluster_size_distribution/value"][:]
    assert (n, big) == (64, 1) and hist[1] == 64 * len(f["observables/cluster_number/step"]), f"gap 1: {n}, {big}"
print("gap 2.5: 1 cluster of 64; gap 1: 64 single colloids")
PY
); then ok "clusters on a lattice: $out"; else bad "clusters on a lattice: $out"; fi
# Energy bonds (observe.clusters_bond = "energy") on a constructed
# configuration of 13 colloids (R = 2 a0, DLVO of Hecht Fig. 1 + Hertz) at
# step 0: pairs at surface gaps 0 (the parabolic primary minimum, U = -6 kT
# by construction), 0.2414 a0 (the secondary minimum, three pairs: a chain of
# three and a pair across the periodic x face), 0.0475 a0 (the barrier,
# +11.9 kT), 0.5 a0 (-1.36 kT) and 1 a0 (-0.36 kT).  The expected bonds and
# their kinds come from an independent evaluation of Hecht Eqs. 1-2
# (tools/dlvo_reference.py, SI units) and the barrier gap found there: every
# pair energy is at least 0.35 kT from -E_c, far beyond the 0.001 kT cut-off
# shift, so the counts must be exact (E_c = 2: 1 primary + 3 secondary bonds,
# 9 clusters; E_c = 1: the 0.5 a0 pair joins, 4 secondary, 8 clusters).
cat > eb_pos.txt <<'POS'
5 5 5
9 5 5
5 25 5
9.2414 25 5
5 29.2414 5
0.5 15 35
36.2586 15 35
25 5 25
30 5 25
25 25 25
29.0475 25 25
25 15 5
29.5 15 5
POS
for ec in 2.0 1.0; do
cat > eb$ec.cfg <<CFG
name = "eb";
seed = 3;
steps = 0;
box: { cells = [40, 40, 40]; };
fluid: { density = 0.0; };
srd: { dt = 0.001; };
colloids: { count = 13; radius = 2.0; temperature = 0.0; init = "file"; init_file = "eb_pos.txt";
  pairs = "dlvo, hertz"; substeps = 4; trajectory_interval = 1; };
dlvo: { psi0 = 20.0; kappa = 1.4e8; hamaker = 4.76e-20; length_unit = 1.25e-7; primary_depth = 6.0; };
hertz: { K = 1000.0; };
output: { colloids_xyz = true; };
observe: { clusters_interval = 1; clusters_bond = "energy"; clusters_energy = $ec; };
CFG
"$PELOID" run eb$ec.cfg --out eb$ec 2> /dev/null || bad "energy-bond run E_c = $ec"
done
if out=$(PYTHONPATH="$TOOLS" $PY - <<'PY'
import h5py, itertools, numpy as np
from dlvo_reference import v_kt, dv_kt
from scipy.optimize import brentq
a0, R, L = 1.25e-7, 2.0, 40.0
d = 2 * R * a0
x = np.loadtxt("eb_pos.txt")
hb = brentq(lambda h: dv_kt(d + h * a0, d, 0.020, 1.4e8), 0.01, 0.2)  # the barrier gap, a0
def energy(h):  # kT; gaps inside the parabolic primary minimum (h < 0.0312 a0): its depth 6 at h0 = 0
    return -6.0 if h < 0.01 else v_kt(d + h * a0, d, 0.020, 1.4e8)
for ec in (2.0, 1.0):
    prim = sec = 0
    parent = list(range(len(x)))
    def root(i):
        while parent[i] != i: i = parent[i]
        return i
    for i, j in itertools.combinations(range(len(x)), 2):
        dx = x[j] - x[i]; dx -= L * np.rint(dx / L)
        h = np.linalg.norm(dx) - 2 * R
        if h > 7.0: continue
        u = energy(h)
        assert abs(u + ec) > 0.3, (i, j, u)
        if u < -ec:
            prim, sec = prim + (h < hb), sec + (h >= hb)
            a, b = root(i), root(j); parent[max(a, b)] = min(a, b)
    ids = [root(i) for i in range(len(x))]
    with h5py.File(f"eb{ec}/observables.h5") as f:
        got = tuple(int(f[f"observables/{k}/value"][0]) for k in
                    ("cluster_bonds_primary", "cluster_bonds_secondary", "cluster_number"))
    assert got == (prim, sec, len(set(ids))), (ec, got, (prim, sec, len(set(ids))))
    with h5py.File(f"eb{ec}/colloids.h5") as f:
        cid = f["particles/colloids/cluster_id/value"][0]
    assert list(cid) == ids, (list(cid), ids)
    xyz = open(f"eb{ec}/colloids.xyz").read().split("\n")
    assert "cluster_id:I:1" in xyz[1] and [int(l.split()[-1]) for l in xyz[2:2 + len(x)]] == ids
    print(f"E_c = {ec}: {prim} primary + {sec} secondary bonds, {len(set(ids))} clusters;", end=" ")
print(f"barrier at gap {hb:.4f} a0; cluster ids in colloids.h5 and colloids.xyz")
PY
); then ok "energy bonds on a constructed configuration: $out"; else bad "energy bonds: $out"; fi

# g(r) per size class (observe.rdf_size_classes).  (a) A rock-salt lattice
# read from a file: 64 sites 4 a0 apart in a box of 16, radius 1.0 and 1.2 on
# the two sublattices, so the two radius classes are the sublattices exactly:
# the pair counts g_ab n_a n_b P_b (P_b the ideal-gas fraction of the bin)
# give 192 unlike pairs at r = 4 and none closer, 192 like pairs of each
# class at 4 sqrt 2 and none closer (to 1e-9: the counts are integers).
# (b) Free Brownian colloids with polydispersity 0.25 in 3 classes: each of
# the 6 partials is 1 within 3 SE in >= 85 % of the bins beyond contact
# (expected 99.7 %; fewer samples and pairs per partial than the total g(r)
# above, so a looser bound) with chi^2 per bin < 2.
$PY - <<'PY'
with open("rs_pos.txt", "w") as f:
    for i in range(4):
        for j in range(4):
            for k in range(4):
                f.write(f"{4 * i + 2} {4 * j + 2} {4 * k + 2} {1.0 if (i + j + k) % 2 == 0 else 1.2}\n")
PY
cat > rs.cfg <<'CFG'
name = "rs";
seed = 3;
steps = 0;
box: { cells = [16, 16, 16]; };
fluid: { density = 0.0; };
srd: { dt = 0.01; };
colloids: { count = 64; radius = 1.0; init = "file"; init_file = "rs_pos.txt"; pairs = ""; integrator = "brownian";
  substeps = 1; max_overlap = 1.0; };
observe: { rdf_interval = 1; rdf_bins = 64; rdf_rmax = 8.0; rdf_size_classes = 2; };
CFG
sed -e 's/^name = "free";/name = "poly";/' -e 's/^steps = 6000;/steps = 4000;/' \
    -e 's/max_overlap = 1.0; };/max_overlap = 1.0; polydispersity = 0.25; };/' \
    -e 's/rdf_interval = 10; rdf_start = 100; rdf_bins = 40; msd_interval = 1;/rdf_interval = 10; rdf_start = 100; rdf_bins = 40; rdf_size_classes = 3;/' free.cfg > poly.cfg
"$PELOID" run rs.cfg --out rs 2> /dev/null || bad "rock-salt run"
"$PELOID" run poly.cfg --out poly 2> /dev/null || bad "polydisperse run"
if out=$($PY - <<'PY'
import json, math, h5py, numpy as np
with h5py.File("rs/observables.h5") as f:
    g = f["observables/colloid_rdf_classes"]
    r, val, pairs = g["r"][:], g["value"][0], g["pairs"][:]
    cnt, crad = g["class_count"][:], g["class_radius"][:]
    assert list(cnt) == [32, 32] and np.allclose(crad, [[1.0, 1.0], [1.2, 1.2]]), (cnt, crad)
    assert np.allclose(g["r_over_R"][:], r / 1.0) and "r_um" not in g
dr = 8.0 / 64
pb = 4 * math.pi / 3 * ((r + dr / 2) ** 3 - (r - dr / 2) ** 3) / 16 ** 3
for p, (a, b) in enumerate(pairs):
    npairs = 32 * 32 if a != b else 32 * 31 / 2
    n = val[p] * npairs * pb
    assert np.abs(n - np.rint(n)).max() < 1e-9, (a, b)
    first = np.nonzero(np.rint(n))[0][0]
    want = 4.0 if a != b else 4 * math.sqrt(2)
    assert r[first] - dr / 2 <= want < r[first] + dr / 2 and np.rint(n[first]) == 192, (a, b, r[first], n[first])
s = json.load(open("poly/summary.json"))["observables"]
assert len(s["rdf_peak_classes"]) == 6
with h5py.File("poly/observables.h5") as f:
    g = f["observables/colloid_rdf_classes"]
    r, val, se, crad = g["r"][:], g["value"][0], g["value_se"][0], g["class_radius"][:]
worst = (1.0, 0.0)
for p in range(6):
    m = (se[p] > 0) & (r > 2 * crad[-1][1])
    z = (val[p][m] - 1) / se[p][m]
    inside, chi2 = np.mean(np.abs(z) < 3), np.mean(z ** 2)
    assert inside >= 0.85 and chi2 < 2.0, (p, inside, chi2)
    worst = (min(worst[0], inside), max(worst[1], chi2))
print(f"rock salt: 192 unlike pairs at 4 a0, 192 like pairs per class at 4 sqrt 2 a0; polydisperse gas: "
      f"6 partials, worst {worst[0]:.2f} of bins within 3 SE, chi2/bin <= {worst[1]:.2f}")
PY
); then ok "g(r) per size class: $out"; else bad "g(r) per size class: $out"; fi

# C_FF (observe.cff_interval; potential coupling only): 8 pinned colloids
# (sigma_cf = 2 a0, epsilon_cf = 2.5 kT) 12 a0 apart in SRD fluid (n_f = 5).
# The Green-Kubo friction integrated to the first zero of C_FF is the
# short-time (random-force) part of the friction, which PL App. B and Eq. 40
# give as the Enskog friction xi_E = (8/3) sqrt(2 pi kT m_f) n_f sigma_cf^2
# = 133.7 m_f/t0 for a fixed colloid; Eq. 40 is for hard spheres and the WCA
# wall is soft (an effective sigma a few % off moves xi_E twice as much), and
# the integral's end at the first zero is a choice, so the bound is generous:
# 0.8 < xi / xi_E < 1.4 (measured 1.125 +- 0.026), SE below 5 %.  Bitwise the
# same at 1 and 2 threads.
cat > cff.cfg <<'CFG'
name = "cff";
seed = 7;
steps = 1000;
box: { cells = [24, 24, 24]; };
fluid: { density = 5.0; temperature = 1.0; };
srd: { dt = 0.1; rule = "random_axis"; alpha = 90.0; };
thermostat: { type = "rescale"; temperature = 1.0; };
colloids: { count = 8; radius = 2.0; mass_density = 5.0; temperature = 1.0; init = "lattice"; pairs = "";
  substeps = 4; };
coupling: { method = "potential"; sigma_cf = 2.0; epsilon_cf = 2.5; pinned = true; };
observe: { cff_interval = 1; };
CFG
for th in 1 2; do "$PELOID" run cff.cfg --threads $th --out cff$th 2> /dev/null || bad "C_FF run ($th threads)"; done
if out=$($PY - <<'PY'
import json, math, h5py, numpy as np
a, b = (json.load(open(f"cff{t}/summary.json"))["observables"]["colloid_friction_green_kubo"] for t in (1, 2))
assert (a["value"], a["stderr"]) == (b["value"], b["stderr"])
with h5py.File("cff1/observables.h5") as f, h5py.File("cff2/observables.h5") as g:
    c, lag = f["observables/colloid_cff/value"][:, 3], f["observables/colloid_cff/lag"][:]
    assert np.array_equal(c, g["observables/colloid_cff/value"][:, 3])
xiE = 8 / 3 * math.sqrt(2 * math.pi) * 5 * 2.0 ** 2
q = a["value"] / xiE
assert 0.8 < q < 1.4 and a["stderr"] < 0.05 * a["value"], (a, xiE)
assert c[0] == a["force_variance"] and 0 < a["integrated_to_t0"] < 1.0
print(f"xi = {a['value']:.1f} +- {a['stderr']:.1f} m_f/t0 (to t = {a['integrated_to_t0']:.2f} t0) = {q:.3f} xi_E; "
      f"C_FF(0.1 t0)/C_FF(0) = {c[1] / c[0]:.3f}; 1 and 2 threads bitwise")
PY
); then ok "C_FF of pinned colloids: $out"; else bad "C_FF: $out"; fi

# Velocity distributions (Hecht Fig. 2): a fluid started from the uniform
# (square-well) distribution is rejected at step 0 (p < 1e-6 with 25600
# components), and sampled from step 100 on (relaxed within a few collision
# times) it is Maxwell-Boltzmann (p > 1e-3; chance of a false failure
# 0.1 %), as are the coupling II colloids' velocities.
cat > vd.cfg <<'CFG'
name = "vd";
seed = 5;
steps = 200;
box: { cells = [8, 8, 8]; };
fluid: { density = 5.0; init_velocity = "uniform"; };
srd: { dt = 0.5; };
colloids: { count = 8; radius = 1.5; mass_density = 5.0; init = "lattice"; pairs = "hertz"; substeps = 20; };
coupling: { method = "hecht2"; };
observe: { vdist_interval = VDI; };
CFG
sed 's/VDI/1000000/' vd.cfg > vd0.cfg; sed -e 's/VDI/20; vdist_start = 100/' -e 's/^steps = 200;/steps = 400;/' vd.cfg > vd1.cfg
"$PELOID" run vd0.cfg --steps 0 --out vd0 2> /dev/null; "$PELOID" run vd1.cfg --out vd1 2> /dev/null
if out=$($PY - <<'PY'
import json, h5py
p0 = json.load(open("vd0/summary.json"))["observables"]["fluid_velocity_chi2"]["p_value"]
o = json.load(open("vd1/summary.json"))["observables"]
p1 = o["fluid_velocity_chi2"]["p_value"]; pc = o["colloid_velocity_chi2"]["p_value"]
assert p0 < 1e-6 and p1 > 1e-3 and pc > 1e-3, (p0, p1, pc)
with h5py.File("vd1/observables.h5") as f:
    assert f["observables/fluid_velocity_distribution/value"].shape == (4, 62)
print(f"uniform start p = {p0:.2g}; after relaxation fluid p = {p1:.3f}, colloids p = {pc:.3f}")
PY
); then ok "velocity distributions: $out"; else bad "velocity distributions: $out"; fi

# Sedimentation of free Brownian colloids in a periodic box under gravity
# g = -0.02: the settling velocity from the mean height is M g / (6 pi eta R)
# within 3 SE (blocking over 400 samples); phi(z) of every sample sums to
# the colloids' volume fraction N (4/3) pi R^3 / V (exact slices: 1e-12).
cat > sed.cfg <<'CFG'
name = "sed";
seed = 5;
steps = 4000;
box: { cells = [16, 16, 16]; };
fluid: { density = 0.0; };
srd: { dt = 0.1; };
colloids: { count = 64; radius = 1.0; mass_density = 1.0; init = "random"; pairs = ""; integrator = "brownian";
  bd_viscosity = 0.02; substeps = 1; max_overlap = 1.0; gravity = [0.0, 0.0, -0.02]; };
observe: { sediment_interval = 10; };
CFG
"$PELOID" run sed.cfg --out sed 2> /dev/null || bad "sedimentation run"
if out=$($PY - <<'PY'
import json, math, h5py, numpy as np
e = json.load(open("sed/summary.json"))["observables"]["settling_velocity"]
M = 4 / 3 * math.pi
v0 = M * 0.02 / (6 * math.pi * 0.02)  # positive down (gravity along -z)
assert e["positive"] == "down", e
assert abs(e["value"] - v0) < 3 * e["stderr"], (e["value"], e["stderr"], v0)
with h5py.File("sed/observables.h5") as f:
    phi = f["observables/colloid_phi_z/value"][:]
phi_tot = 64 * M / 16**3
assert np.max(np.abs(phi.mean(axis=1) - phi_tot)) < 1e-12 * phi_tot, np.max(np.abs(phi.mean(axis=1) - phi_tot))
print(f"v = {e['value']:.4f} +- {e['stderr']:.4f} vs M g / (6 pi eta R) = {v0:.4f}; phi(z) sums to {phi_tot:.5f}")
PY
); then ok "sedimentation: $out"; else bad "sedimentation: $out"; fi

# Analysis windows (observe.average_from, src/observe/window.c) on a
# drifting series: the quickstart's settling velocity falls from the
# initial settling to ~0 once the layer has formed.  "50%" averages the
# samples from the run's middle on; "auto" from Chodera's detected start;
# "start" the whole run.  Each summary value equals the mean of the
# observables.h5 series from the stated start on (computed here with numpy,
# 1e-12 relative: the blocking's Welford mean rounds differently), the start
# is stated (average_from_step, average_from_time in s, window_source) in
# summary.json and as attributes of the series, the whole-run mean lies
# outside the late window's mean +- 3 SE (the drift is what the window
# removes), and a detected start lies after the first samples.
for w in "half 50%" "auto auto" "whole start"; do
  set -- $w
  sed "s/sediment_interval = 20;/sediment_interval = 20; average_from = \"$2\";/" \
    "$(dirname "$TOOLS")/scenes/quickstart.cfg" > win_$1.cfg
  "$PELOID" run win_$1.cfg --threads 2 --out win_$1 2> /dev/null || bad "window run $1"
done
if out=$($PY - <<'PY'
import json, h5py, numpy as np
res = {}
for name, src in (("half", "user"), ("auto", "detected"), ("whole", "whole run")):
    e = json.load(open(f"win_{name}/summary.json"))["observables"]["settling_velocity"]
    with h5py.File(f"win_{name}/observables.h5") as f:
        g = f["observables/settling_velocity"]
        step, v = g["step"][:], g["value"][:]
        st, tm = g.attrs["average_from_step_time"]
        assert g.attrs["window_source"].decode() == src, g.attrs["window_source"]
    assert e["window_source"] == src, (name, e["window_source"])
    assert e["average_from_step"] == st and e["average_from_time_unit"] == "s", (e["average_from_step"], st)
    keep = step >= e["average_from_step"]
    assert e["samples"] == keep.sum() and step[keep][0] == e["average_from_step"], (e["samples"], keep.sum())
    assert abs(e["average_from_time"] - tm) <= 1e-12 * abs(tm), (e["average_from_time"], tm)
    m = v[keep].mean()
    assert abs(e["value"] - m) <= 1e-12 * abs(m), (name, e["value"], m)
    res[name] = (e, v.mean(), step)
e, whole, step = res["half"]
assert e["average_from_step"] == step[step >= 1200][0], e["average_from_step"]
assert abs(whole - e["value"]) > 3 * e["stderr"], (whole, e["value"], e["stderr"])
assert res["whole"][0]["average_from_step"] == step[0]
assert res["auto"][0]["average_from_step"] > step[0]
a = res["auto"][0]
print(f"whole run {whole:.5f}; from 50% (step {e['average_from_step']}) {e['value']:.5f} +- {e['stderr']:.5f}; "
      f"detected from step {a['average_from_step']} ({a['average_from_time']:.2f} s, N_eff {a['window_n_eff']:.1f}) "
      f"{a['value']:.5f} +- {a['stderr']:.5f} a0/t0")
PY
); then ok "analysis windows: $out"; else bad "analysis windows: $out"; fi

# The stopping rule: stop at the first check (every 50 steps) where the
# number of clusters (free colloids, bond gap 1) has a relative SE <= 1 %;
# the same step at 1 and 2 threads; runs without the rule to that step and
# to one check before show the SE on either side of the target (the
# blocking average at a step does not depend on the planned run length).
sed -e 's/^name = "free";/name = "stop";/' -e 's/rdf_interval = 10; rdf_start = 100; rdf_bins = 40; msd_interval = 1;/clusters_interval = 2; clusters_gap = 1.0;/' free.cfg > nostop.cfg
{ cat nostop.cfg; echo 'stop: { observable = "cluster_number"; rel_error = 0.01; check_interval = 50; };'; } > stop.cfg
"$PELOID" run stop.cfg --threads 1 --out stop1 2> /dev/null && "$PELOID" run stop.cfg --threads 2 --out stop2 2> /dev/null
S=$($PY -c 'import json; print(json.load(open("stop1/summary.json"))["stop"]["step"])' 2> /dev/null || echo 0)
S2=$($PY -c 'import json; print(json.load(open("stop2/summary.json"))["stop"]["step"])' 2> /dev/null || echo -1)
if [ "$S" -gt 50 ] && [ "$S" -lt 6000 ] && [ "$S" = "$S2" ] &&
   "$PELOID" run nostop.cfg --steps "$S" --out at 2> /dev/null &&
   "$PELOID" run nostop.cfg --steps $((S - 50)) --out before 2> /dev/null &&
   out=$($PY - <<'PY'
import json
rel = lambda d: (lambda e: e["stderr"] / abs(e["value"]))(json.load(open(d + "/summary.json"))["observables"]["cluster_number"])
a, b = rel("at"), rel("before")
assert a <= 0.01 < b, (a, b)
print(f"relative SE {b:.4f} one check before, {a:.4f} at the stop")
PY
)
then ok "stop rule: stopped at step $S (1 and 2 threads), $out"
else bad "stop rule: stop step $S / $S2 ${out:-}"; fi

# Observers continue across checkpoint/restart (README "Observables":
# restart): 2N steps == N + restart + N, bitwise, for every observables.h5
# dataset and every summary.json observable value and stderr (wall times
# aside), with the correlators (MSD every 10 steps, VACF every 5) growing a
# level at the restart (pl_mtau_grow):
#  - quickstart (g(r), MSD, VACF, clusters, sedimentation, velocity
#    distributions; walls, DLVO, coupling II), 160 vs 80 + 80 steps, with
#    the detected averaging windows and (qsw) average_from = "50%" of the
#    combined run;
#  - free Brownian colloids, polydisperse: g(r) per size class and S(q);
#  - the stress observer: Green-Kubo (pure fluid, periodic) and Couette;
#  - a restart with another observe section, and one from a checkpoint
#    without observer state (written before peloid saved it), start the
#    observers afresh and say so (one log line, summary observables.resumed
#    false with the reason), as does one with --restart-changed (another
#    srd.grid_shift); a wrong-sized observer item is PL_ERR_INPUT
#    naming the file and the item.
cat > rcmp.py <<'PY'
import json, sys, h5py, numpy as np
a, b = sys.argv[1], sys.argv[2]
def walk(f):
    out = {}
    f.visititems(lambda n, o: out.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
    return out
with h5py.File(a + "/observables.h5") as f, h5py.File(b + "/observables.h5") as g:
    A, B = walk(f), walk(g)
assert A.keys() == B.keys(), sorted(set(A) ^ set(B))
bad = [k for k in A if not np.array_equal(A[k], B[k])]
assert not bad, bad
CLOCK = {"wall_s", "wall_s_for_target", "resumed", "reason"}
def strip(x):
    if isinstance(x, dict): return {k: strip(v) for k, v in x.items() if k not in CLOCK}
    if isinstance(x, list): return [strip(v) for v in x]
    return x
ja, jb = (json.load(open(d + "/summary.json"))["observables"] for d in (a, b))
assert jb.get("resumed") is True, jb.get("resumed")
sa, sb = strip(ja), strip(jb)
diff = [k for k in sa if sa[k] != sb.get(k)]
assert not diff and sa.keys() == sb.keys(), diff
n = sum(len(e["se_vs_time"]) for e in sa.values() if isinstance(e, dict) and "se_vs_time" in e)
print(f"{len(A)} datasets, {len(sa) - 2} summary observables ({n} se_vs_time points), first_step {sb['first_step']}")
PY
sed -e 's/sediment_interval = 20;/sediment_interval = 20; vacf_interval = 5; vdist_interval = 40;/' \
  "$(dirname "$TOOLS")/scenes/quickstart.cfg" > qsr.cfg
sed -e 's/^name = "free";/name = "freer";/' -e 's/mass_density = 1.0;/mass_density = 1.0; polydispersity = 0.2;/' \
  -e 's/rdf_bins = 40;/rdf_bins = 40; rdf_size_classes = 2;/' free.cfg > freer.cfg
cat > gkr.cfg <<'CFG'
seed = 17;
box: { cells = [8, 8, 8]; };
fluid: { density = 10; };
srd: { dt = 0.5; alpha = 130; };
observe: { stress_interval = 20; };
CFG
cat > cour.cfg <<'CFG'
seed = 18;
box: { cells = [6, 6, 8]; walls_z = "noslip"; wall_velocity_bottom = [-0.2, 0.0, 0.0];
  wall_velocity_top = [0.2, 0.0, 0.0]; };
fluid: { density = 10; };
srd: { dt = 0.5; alpha = 130; grid_shift = true; };
thermostat: { type = "heyes"; temperature = 1.0; };
observe: { stress_interval = 20; };
CFG
sed -e 's/sediment_interval = 20;/sediment_interval = 20; average_from = "50%";/' qsr.cfg > qsw.cfg
for c in "qsr 80" "qsw 80" "freer 200" "gkr 200" "cour 200"; do
  set -- $c
  if "$PELOID" run $1.cfg --steps $(($2 * 2)) --threads 2 --out $1.full 2> /dev/null &&
     "$PELOID" run $1.cfg --steps $2 --threads 2 --out $1.half 2> /dev/null &&
     "$PELOID" run $1.cfg --steps $2 --threads 2 --restart $1.half/checkpoint.h5 --out $1.res 2> $1.err &&
     out=$($PY rcmp.py $1.full $1.res 2>&1) && cmp -s $1.full/checkpoint.h5 $1.res/checkpoint.h5
  then ok "restart $1: $(($2 * 2)) steps == $2 + restart + $2, bitwise (checkpoint too): $out"
  else bad "restart $1: ${out:-run failed} $(tail -1 $1.err 2> /dev/null)"; fi
done
sed -e 's/rdf_interval = 20;/rdf_interval = 40;/' qsr.cfg > qsr2.cfg
cp qsr.half/checkpoint.h5 old.h5
$PY -c 'import h5py; f = h5py.File("old.h5", "r+"); del f["observe"]' 2> /dev/null
for c in "qsr2 qsr.half/checkpoint.h5 observe.rdf_interval" "qsr old.h5 no.observer.state"; do
  set -- $c
  if "$PELOID" run $1.cfg --steps 80 --restart $2 --out $1.fresh.$(basename $2 .h5) 2> fresh.err &&
     grep -q "observers start afresh" fresh.err && grep -q "${3/no.observer.state/no observer state}" fresh.err &&
     out=$($PY - $1.fresh.$(basename $2 .h5) <<'PY'
import json, sys
o = json.load(open(sys.argv[1] + "/summary.json"))["observables"]
assert o["resumed"] is False and o["first_step"] == 80 and "afresh" in o["reason"], o
print(o["reason"])
PY
)
  then ok "restart afresh ($2): $out"
  else bad "restart afresh ($2): $(cat fresh.err | tail -2)"; fi
done
# (grid_shift = false is another calibration, another t0; the model gravity,
# which keeps the Peclet number, is derived without t0 and keeps every bit:
# naming srd.grid_shift alone is enough)
sed -e 's/grid_shift = true;/grid_shift = false;/' qsr.cfg > qsr3.cfg
if "$PELOID" run qsr3.cfg --steps 80 --restart qsr.half/checkpoint.h5 --restart-changed srd.grid_shift \
     --out qsr3.fresh 2> fresh.err &&
   grep -q "restart-changed srd.grid_shift: the physics changed, the observers start afresh" fresh.err &&
   $PY -c 'import json, sys; o = json.load(open("qsr3.fresh/summary.json"))["observables"]; sys.exit(not (o["resumed"] is False and o["first_step"] == 80))'
then ok "restart afresh after --restart-changed srd.grid_shift: $(grep -o 'the physics.*' fresh.err)"
else bad "restart afresh after --restart-changed: $(tail -2 fresh.err)"; fi
cp qsr.half/checkpoint.h5 bad.h5
$PY -c '
import h5py, numpy as np
f = h5py.File("bad.h5", "r+"); c = f["observe/msd_counters"][:]; s = f["observe/msd_counters"].attrs["fnv1a64"]
del f["observe/msd_counters"]; d = f["observe"].create_dataset("msd_counters", data=c[:-1]); d.attrs["fnv1a64"] = s' 2> /dev/null
"$PELOID" run qsr.cfg --steps 80 --restart bad.h5 --out qsr.bad 2> bad.err; rc=$?
if [ $rc -eq 2 ] && grep -q "bad.h5" bad.err && grep -q "/observe/msd_counters" bad.err && [ ! -e qsr.bad ]
then ok "wrong-sized observer item refused: $(grep -o 'dataset.*' bad.err | head -1)"
else bad "wrong-sized observer item: rc $rc $(cat bad.err)"; fi

if "$PELOID" report free1 > /dev/null && [ -s free1/report.md ] && [ -s free1/rdf.png ] && [ -s free1/msd.png ] &&
   grep -q "Error against run time" free1/report.md && "$PELOID" report lat2.5 > /dev/null && [ -s lat2.5/clusters.png ] &&
   [ -s free1/sq.png ] && "$PELOID" report poly > /dev/null && [ -s poly/rdf_classes.png ] &&
   "$PELOID" report cff1 > /dev/null && [ -s cff1/cff.png ] && "$PELOID" report eb2.0 > /dev/null && [ -s eb2.0/bonds.png ]
then ok "peloid report: report.md with g(r), g_ab(r), S(q), MSD, C_FF, cluster and bond plots and the error table"
else bad "peloid report"; fi
# unreadable inputs of peloid report (issue 37): one line naming the file,
# exit non-zero, no Python traceback
rep_bad() { # NAME DIR FILE: peloid report DIR must fail on FILE
  "$PELOID" report "$2" > /dev/null 2> "$1.err"; local rc=$?
  if [ $rc -ne 0 ] && [ "$(wc -l < "$1.err")" -eq 1 ] && grep -q "^peloid report: .*$3: " "$1.err" &&
     ! grep -q Traceback "$1.err"
  then ok "peloid report on $1: $(cat "$1.err")"
  else bad "peloid report on $1: rc $rc $(head -c 600 "$1.err")"; fi
}
mkdir -p rep_h5 rep_json rep_nods
cp free1/summary.json free1/thermo.tsv rep_h5/ && head -c 3000 free1/observables.h5 > rep_h5/observables.h5
rep_bad truncated_h5 rep_h5 rep_h5/observables.h5
cp free1/observables.h5 free1/thermo.tsv rep_json/ && printf '{' > rep_json/summary.json
rep_bad bad_json rep_json rep_json/summary.json
rep_bad missing_summary rep_missing rep_missing/summary.json
cp free1/summary.json free1/observables.h5 rep_nods/
$PY -c 'import h5py; f = h5py.File("rep_nods/observables.h5", "r+"); del f["observables/colloid_rdf/value"]' 2> /dev/null
rep_bad missing_dataset rep_nods rep_nods/observables.h5
mkdir -p sed_h5 && cp free1/summary.json sed_h5/ && head -c 3000 free1/observables.h5 > sed_h5/colloids.h5
$PY "$TOOLS/plot_sediment.py" sed_h5 > /dev/null 2> sed_h5.err; rc=$?
if [ $rc -ne 0 ] && [ "$(wc -l < sed_h5.err)" -eq 1 ] && grep -q "^plot_sediment: sed_h5/colloids.h5: " sed_h5.err
then ok "plot_sediment.py on a truncated colloids.h5: $(cat sed_h5.err)"
else bad "plot_sediment.py on a truncated colloids.h5: rc $rc $(head -c 600 sed_h5.err)"; fi
# sedimentation without gravity (issue 45): no Stokes velocity to divide by;
# the run wrote 'over_stokes' = -inf and failed at its end before
sed 's/gravity *= *9.81;/gravity = 0.0;/' "$TOOLS/../scenes/quickstart.cfg" > g0.cfg
"$PELOID" run g0.cfg --out g0 --steps 400 > /dev/null 2> g0.err; rc=$?
if [ $rc -eq 0 ] && $PY - <<'PYEOF'
import json, h5py
e = json.load(open("g0/summary.json"))["observables"]["initial_settling_velocity"]
assert e["stokes"] == 0.0 and "over_stokes" not in e and "no gravity" in e["note"], e
h5py.File("g0/observables.h5", "r").close()
PYEOF
then ok "sedimentation with physical.gravity = 0: no over_stokes, a note, observables.h5 written"
else bad "gravity 0: rc $rc $(grep -m1 'error:' g0.err)"; fi
# a run too short, with too few colloids, to resolve a settling velocity
# (issue 45): the audit says so; the quickstart itself resolves it
sed -e 's/^steps *= *[0-9]*;/steps = 120;/' -e 's/volume_fraction = 0.05;/volume_fraction = 0.0005;/' \
  "$TOOLS/../scenes/quickstart.cfg" > unres.cfg
if "$PELOID" params unres.cfg 2>&1 | grep -q "SETTLING_UNRESOLVED: the run's settling Peclet number" \
   && ! "$PELOID" params "$TOOLS/../scenes/quickstart.cfg" 2>&1 | grep -q SETTLING_UNRESOLVED
then ok "SETTLING_UNRESOLVED for 2 colloids over 120 steps, not for the quickstart"
else bad "SETTLING_UNRESOLVED: $("$PELOID" params unres.cfg 2>&1 | grep -m1 -i 'settl\|error')"; fi
echo "observers.sh: $pass passed, $fail failed"
[ $fail -eq 0 ]
