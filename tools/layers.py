"""The layers of src/ and kernels/ against README's "What each layer may touch", read from the built objects.

Every call (or data reference) from an object of one folder to a symbol that an object of another folder defines
is a dependency (nm: the undefined symbols of each .o against the defined ones of all).  The rules, README's:
- kernels/ use nothing of src/;
- src/io/ and src/scene/ use each other and nothing else of src/ or kernels/;
- src/mapping/ reads the scene and the components' theory: no core, observer, app;
- src/core/ knows the components only through the module table (src/core/modules.c), and no mapping or app;
- a component (src/fluid/, src/colloid/, src/coupling/, src/observe/) never uses src/app/;
- src/app/ may use everything; nothing uses it.
What still breaks them is listed in KNOWN with the reason; the check fails on a break not listed and on a listed
one that is gone (the list must say what the code does).

    python3 tools/layers.py [BUILD]        (BUILD: the build folder, default build; exit 1 on a failure)"""
import collections
import glob
import os
import subprocess
import sys

COMPONENTS = ("src/fluid", "src/colloid", "src/coupling", "src/observe")
FOLDERS = ("kernels", "src/io", "src/scene", "src/mapping", "src/core") + COMPONENTS + ("src/app",)

# (from folder, to folder, the symbol): why it still runs that way
KNOWN = {
}


def symbols(build):
    """(defined: symbol -> folder, uses: (folder, object) -> undefined symbols) of the library's objects."""
    defined, uses = {}, collections.defaultdict(set)
    objs = sorted(glob.glob(os.path.join(build, "src", "*", "*.o")) + glob.glob(os.path.join(build, "kernels", "*.o")))
    if not objs:
        raise SystemExit(f"layers: no objects under {build}/src and {build}/kernels; build first (make)")
    for o in objs:
        folder = os.path.relpath(os.path.dirname(o), build)
        dep = o[:-2] + ".d"  # make's dependency file names the source (its first prerequisite)
        if os.path.exists(dep):
            words = open(dep).read().split()
            src = words[1] if len(words) > 1 else ""
            if src and not os.path.exists(src):
                continue  # the object of a source that moved or went: not this tree's
        out = subprocess.run(["nm", o], capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            w = line.split()
            if len(w) == 3 and w[1] in "TDBR":
                defined[w[2]] = folder
            elif len(w) == 2 and w[0] == "U":
                uses[(folder, os.path.basename(o))].add(w[1])
    return defined, uses


def allowed(a, b, obj):
    """Whether folder a may use folder b (README's rules); obj: the using object's name."""
    if a == b or a == "src/app":
        return True
    if b == "src/app":
        return False
    if a == "kernels":
        return False
    if a in ("src/io", "src/scene"):
        return b in ("src/io", "src/scene")
    if a == "src/mapping":
        return b not in ("src/core", "src/observe")
    if a == "src/core":
        return b in ("kernels", "src/io", "src/scene") or (b in COMPONENTS and obj == "modules.o")
    return True  # a component: anything but the app


def breaks(build):
    defined, uses = symbols(build)
    out = collections.defaultdict(set)  # (a, b, symbol) -> objects
    for (a, obj), syms in uses.items():
        for s in syms:
            b = defined.get(s)
            if b and not allowed(a, b, obj):
                out[(a, b, s)].add(obj)
    return out


def main(argv):
    build = argv[1] if len(argv) > 1 else "build"
    found = breaks(build)
    new = sorted(k for k in found if k not in KNOWN)
    gone = sorted(k for k in KNOWN if k not in found)
    for a, b, s in sorted(found):
        tag = "known" if (a, b, s) in KNOWN else "NEW"
        print(f"  {tag:5} {a} -> {b}: {s} ({', '.join(sorted(found[(a, b, s)]))})"
              + (f": {KNOWN[(a, b, s)]}" if tag == "known" else ""))
    for a, b, s in gone:
        print(f"  GONE  {a} -> {b}: {s}: listed in KNOWN but the code no longer does it; remove it from the list")
    pairs = sorted({(a, b) for a, b, _ in found})
    print(f"layers: {len(found)} uses across {len(pairs)} folder pairs break README's rules "
          f"({len(found) - len(new)} known, {len(new)} new, {len(gone)} listed but gone)")
    return 1 if new or gone else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
