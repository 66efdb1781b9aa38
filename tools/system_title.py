"""The system a plot of a run shows, as its title: the scene's name and, for a physical scene (summary.json with
units_si), the colloid radius, volume fraction, salt and coupling.  Used by tools/report.py, tools/plot_sediment.py
and tools/sweep_collect.py (`varied`: the keys a study sweeps, named as varied instead of one point's value)."""


def system_title(summary, varied=()):
    sc = summary.get("scene", {})
    t = str(sc.get("name", ""))
    ph, cg = sc.get("physical"), sc.get("coarse_graining")
    if not (summary.get("units_si") and ph and cg):
        return t
    def given(*keys):
        return any(("physical." + k) in varied for k in keys)
    salt = ("salt varied" if given("ionic_strength", "kappa")
            else f"I = {ph['ionic_strength'] * 1e3:.3g} mM" if ph.get("ionic_strength", 0) > 0
            else f"1/κ = {1e9 / ph['kappa']:.3g} nm" if ph.get("kappa", 0) > 0 else "no salt given")
    radius = "R varied" if given("radius") else f"R = {ph['radius'] * 1e6:.3g} µm"
    phi = "φ varied" if given("volume_fraction") else f"φ = {ph['volume_fraction']:.3g}"
    coupling = "coupling varied" if "coarse_graining.coupling" in varied else f"coupling {cg['coupling']}"
    return f"{t}: {radius}, {phi}, {salt}, {coupling}"
