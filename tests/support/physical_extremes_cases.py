"""The cases of tests/manual/physical_extremes.sh and tests/cli/physical_refusals.sh:
each physical{} / coarse_graining{} key of scenes/quickstart.cfg,
pl_potential_physical.cfg and hecht_table1.cfg pushed to a tiny and a huge
value, one key per case, written as OUT/CASE.cfg with OUT/cases.tsv
(case, key, value).

    /usr/bin/python3 tests/support/physical_extremes_cases.py SCENES_DIR OUT
"""
import os, re, sys
root, out = sys.argv[1], sys.argv[2]
vals = {
    "physical.radius": ["1e-12", "1e-9", "1e-4", "1e-2"],
    "physical.particle_density": ["1e-6", "1e5"], "physical.solvent_density": ["1e-6", "1e5"],
    "physical.temperature": ["1e-3", "1.0", "1e4"], "physical.viscosity": ["1e-12", "1e3"],
    "physical.gravity": ["1e4"], "physical.hamaker": ["1e-30", "1e-15"],
    "physical.surface_potential": ["1e-6", "1.0", "-1.0"], "physical.kappa": ["1.0", "1e11"],
    "physical.ionic_strength": ["1e-12", "10.0"], "physical.volume_fraction": ["1e-9", "0.74"],
    "physical.box": ["[1e-9, 1e-9, 1e-9]", "[1.0, 1.0, 1.0]", "[1e-3, 1e-3, 1e-3]"],
    "physical.primary_minimum": ["1e-12", "1e-3"], "physical.young_modulus": ["1e-6", "1e13"],
    "physical.hertz_constant": ["1e-30", "1e30"], "physical.permittivity": ["1.0", "1e3"],
    "coarse_graining.hertz_K": ["1e-300", "1e15"], "coarse_graining.reach_energy": ["1e-300", "1e6"],
    "coarse_graining.cell_size": ["1e-3", "100"], "coarse_graining.particles_per_cell": ["1.0001", "1e4"],
    "coarse_graining.mean_free_path": ["1e-6", "10"], "coarse_graining.md_resolution": ["1e6"],
}
def setkey(text, sec, key, val):
    m = re.search(r'(?ms)^%s:\s*\{(.*?)^\};' % sec, text) or re.search(r'(?m)^%s:\s*\{([^\n]*?)\};' % sec, text)
    body = m.group(1)
    pat = re.compile(r'(?m)(^|\s|;|\{)%s\s*=\s*[^;]*;' % re.escape(key))
    nb = pat.sub(lambda g: g.group(1) + "%s = %s;" % (key, val), body, count=1) if pat.search(body) \
        else body + " %s = %s;\n" % (key, val)
    return text[:m.start(1)] + nb + text[m.end(1):]
with open(os.path.join(out, "cases.tsv"), "w") as f:
    for b in ["quickstart", "pl_potential_physical", "hecht_table1"]:
        t = re.sub(r'(?m)#.*$', '', open(os.path.join(root, b + ".cfg")).read())
        for k, vs in vals.items():
            sec, key = k.split(".")
            for v in vs:
                n = "%s__%s_%s" % (b, k.replace(".", "_"), re.sub(r'[^0-9a-zA-Z]+', '', v))
                tt = setkey(t, sec, key, v)
                drop = {"kappa": ["ionic_strength"], "ionic_strength": ["kappa"], "young_modulus": ["hertz_K"],
                        "hertz_constant": ["young_modulus", "hertz_K"]}.get(key, [])
                for d in drop:
                    tt = re.sub(r'(?<![a-z_])%s\s*=\s*[^;]*;' % d, '', tt)
                tt = 'name = "%s";\n' % n + re.sub(r'(?m)^name = .*$', '', tt)
                open(os.path.join(out, n + ".cfg"), "w").write(tt)
                f.write("%s\t%s\t%s\n" % (n, k, v))
