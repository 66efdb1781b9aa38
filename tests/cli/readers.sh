#!/usr/bin/env bash
# Issue 15: the files a run writes open in the tools users already have.
#  - colloids.h5 (H5MD 1.1) of a physical scene loads in MDAnalysis (Debian
#    python3-mdanalysis) with its units converted: positions, box and time
#    equal h5py's values times the unit factors; InterRDF runs on it.  A
#    model-unit scene loads with convert_units=False, and InterRDF of an
#    ideal gas of colloids (no pair terms) is 1 at every r beyond contact
#    and equals peloid's own g(r) observer on the same frames within SE.
#  - The trajectory's last frame is the final step; at a guard stop the
#    last good state (the start of the failing step) is the last frame.
#  - fields.h5 is an H5MD time series; ParaView's XDMF reader (pvpython,
#    Debian paraview) opens fields.xdmf and gives h5py's values exactly.  A
#    run whose average took no sample writes no fields file and says so.
#  - colloids.xyz (extended XYZ) reads back in ASE (Debian python3-ase) with
#    the H5MD positions, box, pbc, time and the cluster observer's ids (both
#    files carry them; MDAnalysis loads colloids.h5 with the extra group).
#  - Progress without a terminal: plain log lines, then the end with the
#    files written and their sizes.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
ROOT=$(realpath "$(dirname "$0")/../..")
PY="/usr/bin/python3 -W ignore"
T=$(mktemp -d /tmp/peloid-readers.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }

echo "== file readers (MDAnalysis, ParaView, ASE)"
# quickstart, shortened: 100 steps, a frame every 30 steps (0, 30, 60, 90 and
# the final 100), extended XYZ, fields every 5 steps, a log line every 0.01 s (the run takes ~0.2 s)
sed -e 's/^steps = 2400;/steps = 100;/' -e 's/trajectory_interval = 20;/trajectory_interval = 30;/' \
    -e 's/^output: { thermo_interval = 20; };/output: { thermo_interval = 20; colloids_xyz = true; fields_interval = 5; progress_s = 0.01; };/' \
    "$ROOT/scenes/quickstart.cfg" > q.cfg
"$PELOID" run q.cfg --out q --threads 2 2> q.log; rc=$?
[ $rc -eq 0 ] && ok "quickstart (100 steps) runs" || bad "quickstart run rc=$rc: $(tail -3 q.log)"

$PY - <<'PYEOF' && ok "colloids.h5: H5MD 1.1 layout (h5md, box, edges, units, species, id) and last frame = step 100" || bad "colloids.h5 layout"
import h5py, numpy as np
with h5py.File("q/colloids.h5") as f:
    h = f["h5md"]
    assert tuple(h.attrs["version"]) == (1, 1)
    assert h["author"].attrs["name"] and h["creator"].attrs["name"] and h["creator"].attrs["version"]
    assert h["modules/units"].attrs["system"] == b"SI"
    g = f["particles/colloids"]
    b = g["box"]
    assert b.attrs["dimension"] == 3 and [x.decode() for x in b.attrs["boundary"]] == ["periodic", "periodic", "none"]
    assert b["edges/value"].shape[1:] == (3, 3) and b["edges/value"].attrs["unit"] == "nm"
    assert list(g["position/step"][()]) == [0, 30, 60, 90, 100], g["position/step"][()]
    assert list(b["edges/step"][()]) == [0, 30, 60, 90, 100]
    for el, u in (("position", "nm"), ("velocity", "nm ps-1"), ("angular_velocity", "ps-1")):
        assert g[el + "/value"].attrs["unit"] == u and g[el + "/time"].attrs["unit"] == "ps", el
    assert g["radius"].attrs["unit"] == "nm" and g["mass"].attrs["unit"] == "kg"
    n = g["position/value"].shape[1]
    assert n == 173 and list(g["id"][()]) == list(range(n)) and (g["species"][()] == 0).all()
    a0 = f["parameters"].attrs["a0"]
    assert abs(a0 - 644.8) < 1.0, a0  # nm, the quickstart mapping (a0 = 0.645 um)
    assert abs(np.diag(b["edges/value"][0]) / a0 - [12, 12, 24]).max() < 1e-9
PYEOF

$PY - <<'PYEOF' && ok "MDAnalysis loads colloids.h5 with units: positions, box, time = h5py x (10 A/nm, ps); InterRDF runs" || bad "MDAnalysis on colloids.h5"
import h5py, numpy as np, MDAnalysis as mda
from MDAnalysis.analysis.rdf import InterRDF
with h5py.File("q/colloids.h5") as f:
    g = f["particles/colloids"]
    pos, t = g["position/value"][()], g["position/time"][()]
    vel, box = g["velocity/value"][()], g["box/edges/value"][()]
u = mda.Universe.empty(pos.shape[1], trajectory=True)
u.load_new("q/colloids.h5", format="H5MD")  # convert_units=True: the units must be readable
tr = u.trajectory
assert len(tr) == len(t) == 5
for k, ts in enumerate(tr):
    # MDAnalysis holds float32: 6e-8 relative
    assert np.abs(ts.positions - 10.0 * pos[k]).max() <= 1e-6 * np.abs(10.0 * pos[k]).max()
    assert np.abs(ts.velocities - 10.0 * vel[k]).max() <= 1e-6 * np.abs(10.0 * vel[k]).max() + 1e-30
    assert np.allclose(ts.dimensions[:3], 10.0 * np.diag(box[k]), rtol=1e-6) and np.allclose(ts.dimensions[3:], 90)
    assert abs(ts.time - t[k]) <= 1e-12 * t[-1]
r = InterRDF(u.atoms, u.atoms, nbins=20, range=(1000.0, 30000.0), exclusion_block=(1, 1)).run()
assert np.isfinite(r.results.rdf).all() and r.results.rdf.max() > 0
print("    quickstart g(r), 0.1..3 um in 20 bins:", np.round(r.results.rdf, 2))
PYEOF

# A user's kinetic temperature: MDAnalysis velocities (A/ps) with the masses
# of colloids.h5 give the scene's 300 K (before: the real masses with the
# model's velocities gave 0.004 K); and MDAnalysis's frame step is the
# trajectory interval, not its "1 ps" fallback.  Bound: over F frames of N
# colloids the mean of 2 KE / (3 N k) has the relative SE sqrt(2 / (3 N F))
# for independent frames (30 SRD steps apart here, ~10 colloid velocity
# relaxation times); 4 SE: a 6e-5 chance of failing by chance.
$PY - <<'PYEOF' && ok "MDAnalysis: kinetic temperature from colloids.h5 = the scene's 300 K; trajectory.dt = the frame interval" || bad "kinetic temperature / dt from colloids.h5"
import h5py, numpy as np, MDAnalysis as mda
with h5py.File("q/colloids.h5") as f:
    g = f["particles/colloids"]
    mass, t = g["mass"][()], g["position/time"][()]
    es = f["parameters"].attrs["energy_scale"]
    assert np.allclose(g["mass"].attrs["real_mass_kg"] * es, mass, rtol=1e-12)
u = mda.Universe.empty(len(mass), trajectory=True)
u.load_new("q/colloids.h5", format="H5MD")
u.add_TopologyAttr("masses", mass / 1.66053906660e-27)  # kg -> u
kB, T = 1.380649e-23, []
for ts in u.trajectory:
    v = ts.velocities * 100.0  # A/ps -> m/s
    T.append((u.atoms.masses * 1.66053906660e-27 * (v * v).sum(1)).sum() / (3 * len(mass) * kB))
T = np.array(T)
se = 300.0 * np.sqrt(2.0 / (3 * len(mass) * len(T)))
dt = u.trajectory.dt
print(f"    T from MDAnalysis: {T.mean():.1f} K (frames {np.round(T, 1)}), 4 SE = {4 * se:.1f} K; dt {dt:.6g} ps, "
      f"frame times {t[1] - t[0]:.6g} ps apart")
assert abs(T.mean() - 300.0) <= 4 * se, T
assert abs(dt - (t[1] - t[0])) <= 1e-9 * dt, (dt, t[:2])
PYEOF

# g(r) of a physical scene also in units of R and in micrometres (the mapping's a0)
$PY - <<'PYEOF' && ok "quickstart g(r): r in a0, R and um consistent with colloids.h5 (a0, radius)" || bad "g(r) units"
import json, h5py, numpy as np
with h5py.File("q/colloids.h5") as f:
    a0_nm, R_nm = f["parameters"].attrs["a0"], f["particles/colloids/radius"][0]
with h5py.File("q/observables.h5") as f:
    g = f["observables/colloid_rdf"]
    r, rR, rum = g["r"][:], g["r_over_R"][:], g["r_um"][:]
    assert g["r_um"].attrs["unit"] in (b"um", "um")
assert np.allclose(rum, r * a0_nm / 1000, rtol=1e-12) and np.allclose(rR, r * a0_nm / R_nm, rtol=1e-9)
e = json.load(open("q/summary.json"))["observables"]["rdf_peak"]
assert abs(e["r_um"] - e["r"] * a0_nm / 1000) < 1e-12 * e["r_um"]
PYEOF

# ideal gas of colloids (no pair terms, no fluid), model units
cat > gas.cfg <<'CFG'
name = "gas";
seed = 5;
steps = 40;
box: { cells = [20, 20, 20]; };
fluid: { density = 0.0; };
srd: { dt = 0.1; };
colloids: { count = 400; radius = 0.5; init = "random"; pairs = ""; substeps = 1; max_overlap = 1.0; trajectory_interval = 10; };
output: { thermo_interval = 10; };
observe: { rdf_interval = 10; rdf_bins = 8; rdf_rmax = 8.0; };
CFG
"$PELOID" run gas.cfg --out gas 2> gas.log || bad "ideal gas run: $(tail -2 gas.log)"
$PY - <<'PYEOF' && ok "model units: MDAnalysis refuses convert_units=True, loads with convert_units=False; ideal-gas InterRDF = 1 +- 0.1 at r = 2..8 a0 and = peloid's g(r) observer within 3 SE" || bad "MDAnalysis model units / ideal-gas g(r) / peloid g(r)"
import h5py, numpy as np, MDAnalysis as mda
from MDAnalysis.analysis.rdf import InterRDF
with h5py.File("gas/colloids.h5") as f:
    g = f["particles/colloids"]
    assert "unit" not in g["position/value"].attrs and g["position/value"].attrs["model_unit"] == "a0"
    assert "units" not in f["h5md"].get("modules", {})
    pos = g["position/value"][()]
u = mda.Universe.empty(400, trajectory=True)
try:
    u.load_new("gas/colloids.h5", format="H5MD")
    raise SystemExit("convert_units=True accepted a file without units")
except ValueError:
    pass
u.load_new("gas/colloids.h5", format="H5MD", convert_units=False)
assert len(u.trajectory) == 5 and u.trajectory[-1].time == 4.0
assert np.abs(u.trajectory[-1].positions - pos[-1]).max() < 1e-5
# 5 frames x ~4e4 pairs within 8 a0: the shell counts have ~2% noise each
# (Poisson, frames correlated), so 0.1 is > 4 sigma
r = InterRDF(u.atoms, u.atoms, nbins=6, range=(2.0, 8.0), exclusion_block=(1, 1)).run()
print("    ideal gas g(r), 2..8 a0:", np.round(r.results.rdf, 3))
assert np.abs(r.results.rdf - 1.0).max() < 0.1
# the same 5 frames through peloid's own g(r) observer (observables.h5):
# InterRDF over [0, 8) in 8 bins agrees bin by bin within 3 SE of peloid's
# (InterRDF normalises by N^2 where peloid uses N (N - 1): 0.25 %, far
# inside the SE)
with h5py.File("gas/observables.h5") as f:
    gp, se = f["observables/colloid_rdf/value"][0], f["observables/colloid_rdf/value_se"][0]
    assert int(f["observables/colloid_rdf/samples"][()]) == 5
m = InterRDF(u.atoms, u.atoms, nbins=8, range=(0.0, 8.0), exclusion_block=(1, 1)).run().results.rdf
k = slice(2, 8)
z = np.abs(m[k] - gp[k]) / se[k]
print("    InterRDF", np.round(m[k], 4), "peloid", np.round(gp[k], 4), "+-", np.round(se[k], 4))
assert np.all(se[k] > 0) and np.all(z < 3), z
PYEOF

# guard stop: colloids of an ideal gas at low temperature overlap by more
# than colloids.max_overlap = 0.1 during collision step 17
sed -e 's/max_overlap = 1.0;/temperature = 0.001;/' -e 's/trajectory_interval = 10/trajectory_interval = 5/' \
    -e 's/steps = 40;/steps = 400;/' gas.cfg > guard.cfg
"$PELOID" run guard.cfg --out guard 2> guard.log; rc=$?
$PY - <<'PYEOF' && [ $rc -eq 3 ] && ok "guard stop: exit 3; the last frame is the last good state (step 17, before the failing step)" || bad "guard stop (rc=$rc): $(grep error guard.log)"
import h5py, numpy as np
with h5py.File("guard/colloids.h5") as f:
    g = f["particles/colloids"]
    st, pos = g["position/step"][()], g["position/value"][()]
assert list(st) == [0, 5, 10, 15, 17], st
d = pos[-1][:, None, :] - pos[-1][None, :, :]
d -= 20.0 * np.rint(d / 20.0)
r = np.sqrt((d * d).sum(-1))[np.triu_indices(400, 1)]
assert (1.0 - r.min()) / 1.0 <= 0.1, r.min()  # within colloids.max_overlap
PYEOF

$PY - <<'PYEOF' && ok "fields.h5: H5MD time series value[t][z][y][x], step/time arrays, grid origin and spacing; value_si (um-3, um s-1), time_si (s), grid in um" || bad "fields.h5 layout"
import h5py, numpy as np
with h5py.File("q/fields.h5") as f:
    a0, t0 = f["observables"].attrs["a0_m"], f["observables"].attrs["t0_s"]
    for name, unit, fac in (("fluid_density", "um-3", (a0 * 1e6) ** -3), ("fluid_velocity", "um s-1", a0 * 1e6 / t0)):
        g = f["observables/" + name]
        assert g["value_si"].attrs["unit"] == unit and g["time_si"].attrs["unit"] == "s"
        assert np.allclose(g["value_si"][()], g["value"][()] * fac, rtol=1e-12, atol=0)
        assert abs(g["time_si"][0] - g["time"][0] * t0) <= 1e-12 * g["time_si"][0]
        assert np.allclose(g.attrs["spacing_si"], [a0 * 1e6] * 3, rtol=1e-12) and list(g.attrs["origin_si"]) == [0, 0, 0]
    assert tuple(f["h5md"].attrs["version"]) == (1, 1)
    for name, shape in (("fluid_density", (1, 24, 12, 12)), ("fluid_velocity", (1, 24, 12, 12, 3))):
        g = f["observables/" + name]
        assert g["value"].shape == shape and g["step"].shape == (1,) and g["time"].shape == (1,)
        assert g["step"][0] == 100 and abs(g["time"][0] - 25.0) < 1e-12
        assert list(g.attrs["origin"]) == [0, 0, 0] and list(g.attrs["spacing"]) == [1, 1, 1]
    assert abs(f["observables/fluid_density/value"][()].mean() - 10.0) < 1e-9
    assert f["observables/samples"][()] == 20
PYEOF

if command -v pvpython > /dev/null; then
  cat > pv.py <<'PYEOF'
import sys, numpy as np
from paraview.simple import XDMFReader, servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy
r = XDMFReader(FileNames=[sys.argv[1]])
r.UpdatePipeline()
d = servermanager.Fetch(r)
b = d.GetBlock(0) if d.IsA("vtkMultiBlockDataSet") else d
assert b.GetClassName() == "vtkImageData", b.GetClassName()
h = float(sys.argv[2])  # a physical scene: the grid in um
assert b.GetDimensions() == (13, 13, 25) and np.allclose(b.GetSpacing(), (h, h, h), rtol=1e-12), (b.GetDimensions(), b.GetSpacing())
cd = b.GetCellData()
np.save("pv_rho.npy", vtk_to_numpy(cd.GetArray("fluid_density")))
np.save("pv_vel.npy", vtk_to_numpy(cd.GetArray("fluid_velocity")))
print("    ParaView:", b.GetClassName(), b.GetDimensions(), "times", list(r.TimestepValues))
PYEOF
  h=$($PY -c 'import h5py; print(repr(h5py.File("q/fields.h5")["observables/fluid_density"].attrs["spacing_si"][0]))')
  timeout 300 pvpython --force-offscreen-rendering pv.py q/fields.xdmf "$h" > pv.log 2>&1
  $PY - <<'PYEOF' && ok "ParaView (pvpython XDMFReader) opens fields.xdmf of a physical scene: image data in um, cell values = h5py's value_si (um-3, um/s) exactly" || bad "ParaView on fields.xdmf: $(tail -3 pv.log)"
import h5py, numpy as np
with h5py.File("q/fields.h5") as f:
    R = f["observables/fluid_density/value_si"][0]
    V = f["observables/fluid_velocity/value_si"][0]
assert np.array_equal(np.load("pv_rho.npy"), R.ravel())
assert np.array_equal(np.load("pv_vel.npy"), V.reshape(-1, 3))
PYEOF
  grep "ParaView:" pv.log
else
  echo "  skipped: ParaView XDMF check (no pvpython; Debian package paraview)"
fi

"$PELOID" run q.cfg --out nofields --steps 0 2> nofields.log; rc=$?
[ $rc -eq 0 ] && [ ! -e nofields/fields.h5 ] && [ ! -e nofields/fields.xdmf ] && grep -q "no field sample was taken" nofields.log \
  && grep -q '"field_samples": 0' nofields/summary.json \
  && ok "a run without a field sample writes no fields file, says so and reports field_samples = 0: $(grep 'no field' nofields.log | cut -c1-100)" \
  || bad "no-sample run (rc=$rc): $(cat nofields.log)"

$PY - <<'PYEOF' && ok "ASE reads colloids.xyz: 5 frames, positions, radius, velocities, cell, pbc, time, cluster ids = colloids.h5" || bad "ASE on colloids.xyz"
import ase.io, h5py, numpy as np
fr = ase.io.read("q/colloids.xyz", index=":", format="extxyz")
with h5py.File("q/colloids.h5") as f:
    g = f["particles/colloids"]
    pos, vel, t = g["position/value"][()], g["velocity/value"][()], g["position/time"][()]
    box, rad, st = g["box/edges/value"][()], g["radius"][()], g["position/step"][()]
assert len(fr) == len(st) == 5
for k, a in enumerate(fr):
    assert len(a) == 173 and list(a.pbc) == [True, True, False]
    assert np.abs(a.positions - pos[k]).max() <= 1e-9 * np.abs(pos[k]).max()  # 10 digits
    assert np.abs(a.arrays["vel"] - vel[k]).max() <= 1e-9 * np.abs(vel[k]).max() + 1e-300
    assert np.allclose(a.arrays["radius"], rad, rtol=1e-9)
    assert np.allclose(a.cell.array, box[k], rtol=1e-9)
    assert a.info["step"] == st[k] and abs(a.info["Time"] - t[k]) <= 1e-12 * t[-1]
# the cluster observer's ids (quickstart: clusters_interval = 20) with every frame, in both files
with h5py.File("q/colloids.h5") as f:
    c = f["particles/colloids/cluster_id"]
    assert list(c["step"][()]) == list(st) and c["value"].shape == (5, 173)
    cid = c["value"][()]
for k, a in enumerate(fr):
    assert list(a.arrays["cluster_id"]) == list(cid[k])
    assert all(0 <= i <= j and cid[k][i] == i for j, i in enumerate(cid[k]))  # canonical: the smallest member
PYEOF

# SI beside the model units (src/io/observables_si.c): the shortened quickstart
# (g(r), MSD, clusters, sedimentation) and a physical fluid with the stress
# observer; every /observables dataset in a model unit has a twin X_si in an
# SI unit with X_si = X * to_si, to_si following from a0, t0, m_f of
# /parameters (= summary.json units_si); every summary entry with a unit has
# unit_si and value_si/stderr_si, and, where its unit holds t0, the share of
# the calibration's relative error (stderr_mapping_si) and the combined
# stderr_total_si; a model scene keeps its model units only.
sed -e 's/^steps = 1000;/steps = 40;/' "$ROOT/scenes/pl_colloid_1um.cfg" > pls.cfg
echo 'observe: { stress_interval = 5; };' >> pls.cfg
"$PELOID" run pls.cfg --out pls --threads 2 2> pls.log || bad "physical stress run: $(tail -1 pls.log)"
cat > ms.cfg <<'CFG'
name = "model_stress";
seed = 3;
steps = 40;
box: { cells = [8, 8, 8]; };
observe: { stress_interval = 5; };
CFG
"$PELOID" run ms.cfg --out ms --threads 2 2> ms.log || bad "model stress run: $(tail -1 ms.log)"
$PY - <<'PYEOF' && ok "observables.h5 + summary.json of physical scenes: SI twins (m, s, m^2, m/s, Pa, Pa s) = model x factor from a0, t0, m_f; model scene unchanged" || bad "SI observables"
import h5py, json, math, numpy as np
SI = {"m", "1/m", "m^2", "1/m^3", "s", "1/s", "m/s", "m^2/s", "m^2/s^2", "Pa", "Pa s", "kg/s", "N^2", "J", "kg"}
DIMLESS = {"1", "R", "1/R", "um"}
def s(x): return x.decode() if isinstance(x, bytes) else x
def factor(unit, a0, t0, mf):
    return eval(unit.replace("^", "**").replace(" ", "*"), {"a0": a0, "t0": t0, "m_f": mf, "kT": mf * a0**2 / t0**2})
seen = set()
nmapped = [0]
for d in ("q", "pls"):
    js = json.load(open(d + "/summary.json"))
    u = js["units_si"]
    with h5py.File(d + "/observables.h5") as f:
        p = f["parameters"].attrs
        a0, t0, mf = p["a0_m"], p["t0_s"], p["m_f_kg"]
        assert math.isclose(a0, u["a0_m"], rel_tol=1e-12) and math.isclose(t0, u["t0_s"], rel_tol=1e-12)
        assert math.isclose(p["kT_J"], mf * a0**2 / t0**2, rel_tol=1e-12)
        ds = {}
        f["observables"].visititems(lambda n, o: ds.__setitem__(n, o) if isinstance(o, h5py.Dataset) else None)
        n = 0
        for name, o in ds.items():
            if name.endswith("_si") or "unit" not in o.attrs: continue
            unit = s(o.attrs["unit"])
            if unit in DIMLESS: continue
            t = ds.get(name + "_si")
            assert t is not None, f"{d}: {name} [{unit}] has no SI twin"
            assert s(t.attrs["unit"]) in SI and s(t.attrs["model_unit"]) == unit, (name, t.attrs["unit"])
            fac = factor(unit, a0, t0, mf)
            assert math.isclose(t.attrs["to_si"], fac, rel_tol=1e-12), (name, t.attrs["to_si"], fac)
            x, y = o[()], t[()]
            assert y.shape == x.shape and (abs(y - x * fac) <= 1e-12 * abs(x * fac)).all(), name
            seen.add(s(t.attrs["unit"])); n += 1
        assert n >= 4, (d, n)
    def walk(e):
        if isinstance(e, list):
            for v in e: walk(v)
        if not isinstance(e, dict): return
        if "unit" in e and "value" in e:
            fac = 1.0 if e["unit"] in DIMLESS else factor(e["unit"], a0, t0, mf)
            assert e["unit_si"] in SI | {"1"}, e["unit"]
            for k in ("value", "stderr"):
                assert math.isclose(e[k + "_si"], e[k] * fac, rel_tol=1e-12, abs_tol=1e-300), (k, e)
            # t0 rests on the calibrated colloid D: an SI value in t0^p carries |p| x its relative error
            # (summary.json calibration.relative_error), beside the run's SE and combined in quadrature
            pt = 0 if e["unit"] in DIMLESS else round(math.log2(factor(e["unit"], a0, 2 * t0, mf) / fac))
            rel = js.get("calibration", {}).get("relative_error") or 0.0
            if pt and rel > 0 and "stderr" in e:
                mapped = abs(pt) * rel * abs(e["value_si"])
                assert math.isclose(e["stderr_mapping_si"], mapped, rel_tol=1e-9, abs_tol=1e-300), (e, mapped)
                assert math.isclose(e["stderr_total_si"], math.hypot(e["stderr_si"], mapped), rel_tol=1e-9), e
                nmapped[0] += 1
            else:
                assert "stderr_mapping_si" not in e and "stderr_total_si" not in e, e
        for k, v in e.items():  # times in t0 and lengths in a0 beside in s and m
            for mu, su, fac in (("_t0", "_s", t0), ("_a0", "_m", a0)):
                if k.endswith(mu) and isinstance(v, (float, list)):
                    assert np.allclose(e[k[:-3] + su], np.array(v) * fac, rtol=1e-12, atol=0), k
        for v in e.values(): walk(v)
    walk(js["observables"])
assert {"s", "m", "m^2", "m/s", "Pa", "Pa s"} <= seen, seen
assert nmapped[0] >= 2, nmapped  # the quickstart's D and settling velocity at least
q = json.load(open("q/summary.json"))["observables"]
assert q["settling_velocity"]["unit_si"] == "m/s" and len(q["colloid_D"]["fit_window_s"]) == 2
with h5py.File("ms/observables.h5") as f:
    assert "parameters" not in f
    names = []
    f["observables"].visit(names.append)
    assert names and not [n for n in names if n.endswith("_si")], names
    assert s(f["observables/fluid_stress/value"].attrs["unit"]) == "kT/a0^3"
assert "unit_si" not in json.dumps(json.load(open("ms/summary.json"))["observables"])
PYEOF
"$PELOID" report q > /dev/null && "$PELOID" report pls > /dev/null && "$PELOID" report ms > /dev/null && \
  grep -q "^| settling_velocity | .* a0/t0 = .* m/s ± .* (calibration of t0) = ± .* m/s combined |" q/report.md && \
  grep -q "^| colloid_D | .* a0^2/t0 = .* m^2/s ± .* (calibration of t0) = ± .* m^2/s combined |" q/report.md && \
  grep -q "^eta = .* Pa s " pls/report.md && grep -q "^pressure .* Pa " pls/report.md && \
  grep -q "^eta = .* m_f/(a0 t0) " ms/report.md && ! grep -q "Pa" ms/report.md \
  && ok "peloid report: a physical scene's values in SI beside the model ones, with t0's calibration error and the combined SE (plots in um, s, um/s, K, Pa), a model scene's in model units" \
  || bad "report in SI: $(grep -h "settling\|colloid_D\|^eta\|^pressure" q/report.md pls/report.md ms/report.md)"

# progress without a terminal (stderr is a file here)
n=$(grep -c "^peloid: step [0-9]*/100 .*t = .* t0 (.* s)  ETA .*Mupdates/s .*MD steps/s" q.log)
grep -q "^peloid: done: steps 0..100 in .*Mupdates/s, .*MD steps/s; simulated time 25 t0 = " q.log && \
  grep -qE "^peloid:   .*/q/colloids.xyz  [0-9.]+ kB" q.log && grep -qE "^peloid:   .*/q/fields.xdmf  [0-9.]+ (B|kB)" q.log && [ "$n" -ge 1 ] \
  && ok "progress in a log: $n plain lines, then the end with wall time, rates and the files written with sizes" \
  || bad "progress log: $(cat q.log)"
grep -q $'\r' q.log && bad "carriage returns in a non-terminal log" || ok "no carriage returns in the log"
n=$(grep -c "MD steps/s" gas.log)
grep -q "Mupdates" gas.log && bad "colloid-only run reports fluid updates: $(cat gas.log)" || ok "colloid-only run: MD steps/s, no Mupdates/s ($n lines)"

echo "readers.sh: $pass passed, $fail failed"
[ $fail -eq 0 ]
