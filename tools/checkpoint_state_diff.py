#!/usr/bin/python3
"""Compare the simulation state of two peloid checkpoints bit for bit.

    tools/checkpoint_state_diff.py A/checkpoint.h5 B/checkpoint.h5

Every dataset (and every file or group attribute except the embedded scene,
`scene_keys`, and its `scene_fingerprint`) must hold the same bytes.  Used to
show that a change which adds scene keys (and so changes the checkpoint's
embedded scene and its file hash) leaves the trajectory bitwise the same.
Exit 0 when equal, 1 with the first differences listed otherwise."""
import sys

import h5py
import numpy as np

SCENE_ATTRS = {"scene_keys", "scene_fingerprint"}


def items(path):
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                out["dataset " + name] = np.asarray(obj[()]).tobytes()
            for k, v in obj.attrs.items():
                out["attr %s@%s" % (name, k)] = np.asarray(v).tobytes()
        for k, v in f.attrs.items():
            if k not in SCENE_ATTRS:
                out["attr /@" + k] = np.asarray(v).tobytes()
        f.visititems(visit)
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = items(sys.argv[1]), items(sys.argv[2])
    bad = sorted(k for k in a.keys() | b.keys() if a.get(k) != b.get(k))
    for k in bad[:10]:
        print("differs: " + k)
    print("%d items compared, %d differ" % (len(a.keys() | b.keys()), len(bad)))
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
