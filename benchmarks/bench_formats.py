"""Export time per format and MuJoCo behaviour of MJCF, per category.

For each category, over seeds 0..N-1 (``artipg.generate``; ``--valid`` for validated
and repaired objects), prints

- the median milliseconds per object to write each format from the model: ``urdf``
  (URDF text and mesh files), ``asset`` (reading that URDF back into the neutral
  description the others start from), ``mjcf``, ``usd``, ``glb``, and the whole
  object folder with all four (``export_object(formats=all)``, 2048 points), against
  the folder with the URDF alone;
- loads: objects whose MJCF loads in MuJoCo, whose USD passes USD's own validators
  (UsdPhysics included) and whose GLB loads in trimesh with one node per link;
- MuJoCo: the largest rest drift (mm in 1 s, free-standing objects on a floor;
  fixtures are welded and listed as such) and the joints that reach both limits
  under their position servos, out of all joints.

Usage:

    python benchmarks/bench_formats.py [--categories a b] [--seeds 20] [--workers 2] [--valid]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

import artipg

ALL = ("urdf", "mjcf", "usd", "glb")


def _one(task):
    import mujoco
    import trimesh
    from pxr import Usd, UsdValidation

    from artipg.export.asset import object_asset
    from artipg.export.folder import export_object
    from artipg.export.glb import glb_bytes
    from artipg.export.mjcf import build_mjcf, mjcf_text
    from artipg.export.mjcf_sim import drive_limits, drive_tolerance, rest_drift
    from artipg.export.urdf import build_urdf, urdf_text
    from artipg.export.usd import usd_bytes

    category, seed, valid = task
    if valid:
        from artipg.validate import generate_valid

        obj = generate_valid(category, seed)
    else:
        obj = artipg.generate(category, seed)
    ms = {}
    t = time.perf_counter()
    robot, meshes = build_urdf(obj)
    text = urdf_text(robot)
    ms["urdf"] = time.perf_counter() - t
    t = time.perf_counter()
    asset = object_asset(obj, text, meshes)
    ms["asset"] = time.perf_counter() - t
    t = time.perf_counter()
    mjcf_text(build_mjcf(asset, actuators=True))
    ms["mjcf"] = time.perf_counter() - t
    t = time.perf_counter()
    usd_bytes(asset, actuators=True)
    ms["usd"] = time.perf_counter() - t
    t = time.perf_counter()
    glb_bytes(asset)
    ms["glb"] = time.perf_counter() - t
    with tempfile.TemporaryDirectory(prefix="artipg-bench-") as d:
        t = time.perf_counter()
        export_object(obj, Path(d) / "u")
        ms["folder_urdf"] = time.perf_counter() - t
        t = time.perf_counter()
        f = export_object(obj, Path(d) / "a", formats=ALL, actuators=True)
        ms["folder_all"] = time.perf_counter() - t
        out = {"ms": {k: 1e3 * v for k, v in ms.items()}}
        try:
            mujoco.MjModel.from_xml_path(str(f / "mobility.xml"))
            out["mjcf_ok"] = True
        except Exception:
            out["mjcf_ok"] = False
        ctx = UsdValidation.ValidationContext(UsdValidation.ValidationRegistry().GetOrLoadAllValidators())
        out["usd_ok"] = not ctx.Validate(Usd.Stage.Open(str(f / "mobility.usd")))
        scene = trimesh.load(f / "mobility.glb")
        out["glb_ok"] = {lk.name for lk in obj.links} <= set(scene.graph.nodes)
        out["fixed"] = asset.fixed_base
        out["drift"] = None if asset.fixed_base else rest_drift(f / "mobility.xml")
        tol = drive_tolerance(f / "mobility.xml")
        reached = drive_limits(f / "mobility.xml")
        out["joints"] = len(tol)
        out["reached"] = sum(max(v) <= tol[k] for k, v in reached.items())
        out["missed"] = [k for k, v in reached.items() if max(v) > tol[k]]
    return category, seed, out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--categories", nargs="*", default=None)
    ap.add_argument("--seeds", type=int, default=20)
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--valid", action="store_true", help="validated and repaired objects (slower)")
    args = ap.parse_args()
    cats = args.categories or artipg.categories()
    tasks = [(c, s, args.valid) for c in cats for s in range(args.seeds)]
    _one(tasks[0])  # warm-up: imports and compiled kernels are not export time
    if args.workers > 1:
        with ProcessPoolExecutor(args.workers) as pool:
            results = list(pool.map(_one, tasks))
    else:
        results = [_one(t) for t in tasks]
    keys = ("urdf", "asset", "mjcf", "usd", "glb", "folder_urdf", "folder_all")
    head = f"{'category':18s} " + " ".join(f"{k:>11s}" for k in keys) + "   loads m/u/g   drift mm   joints"
    print(f"median ms per object over {args.seeds} seeds ({'validated' if args.valid else 'unvalidated'} objects)")
    print(head)
    total = {k: [] for k in keys}
    for c in cats:
        rs = [r for cc, _, r in results if cc == c]
        med = {k: float(np.median([r["ms"][k] for r in rs])) for k in keys}
        for k in keys:
            total[k] += [r["ms"][k] for r in rs]
        loads = "/".join(str(sum(r[f"{x}_ok"] for r in rs)) for x in ("mjcf", "usd", "glb"))
        drifts = [r["drift"] for r in rs if r["drift"] is not None]
        drift = "fixture" if not drifts else f"{1e3 * max(drifts):.3g}"
        joints = f"{sum(r['reached'] for r in rs)}/{sum(r['joints'] for r in rs)}"
        print(f"{c:18s} " + " ".join(f"{med[k]:11.1f}" for k in keys) + f"   {loads:>11s}   {drift:>8s}   {joints}")
        for cc, s, r in results:
            if cc == c and (r["missed"] or (r["drift"] or 0) > 2e-3):
                print(f"    seed {s}: missed {r['missed']}, drift {1e3 * (r['drift'] or 0):.3g} mm")
    print(f"{'all':18s} " + " ".join(f"{float(np.median(total[k])):11.1f}" for k in keys))


if __name__ == "__main__":
    main()
