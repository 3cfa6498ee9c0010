"""``artipg convert``: MJCF, USD and GLB for any object folder with a URDF.

Works on artipg's folders and third-party ones (PartNet-Mobility's): the URDF is
read with ``yourdfpy`` into an :class:`artipg.export.asset.Asset` and written by the
same writers as ``artipg generate``. For third-party URDFs:

- collision meshes that are not convex (a simulator would fill them with their hull)
  become convex pieces: their own hulls where these fit them (:func:`hull_fit`), the
  rest of each link's meshes decomposed together by CoACD; the pieces are written to
  ``collision/<link>_c<k>.obj`` in the folder and reused while the link's meshes are
  unchanged (``collision/cache.json`` keeps a hash of them);
- links that overlap at rest never collide (:func:`rest_overlaps`);
- visual meshes are merged per link into plain OBJ files (:func:`merged_visuals`);
- no ``<inertial>``: mass properties come from the convex collision pieces, solid, at
  the density of the link's material class (:mod:`artipg.materials`);
- no dynamics: joint damping follows artipg's own rule (:mod:`artipg.export.urdf`).

Fixtures are told by ``annotation.json`` or, for PartNet-Mobility, by the category
in ``meta.json``. Files are written under temporary names and renamed into place
only once all are written.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
import re
from pathlib import Path

import numpy as np

from artipg.export.asset import Asset, Geom, asset_from_urdf, geom_arrays, load_robot

#: CoACD settings: a concavity threshold of 0.1 (pieces deviate from the mesh by about
#: a tenth of its size), at most 16 pieces per link, a coarser search than CoACD's
#: defaults (about four times faster on PartNet-Mobility cabinets, still tens of
#: seconds per object: hence the cache).
COACD_OPTIONS = dict(threshold=0.1, max_convex_hull=16, preprocess_resolution=30, resolution=1000,
                     mcts_iterations=50, mcts_nodes=10)

#: A collision mesh is convex when closed and its volume within this fraction of its
#: hull's.
CONVEX_TOL = 0.01


class ConvertError(ValueError):
    """A folder that cannot be converted (no URDF, missing meshes)."""


def find_urdf(folder: Path) -> Path:
    """``mobility.urdf`` of ``folder``, else its only ``*.urdf``."""
    folder = Path(folder)
    if not folder.is_dir():
        raise ConvertError(f"{folder}: not a folder")
    p = folder / "mobility.urdf"
    if p.is_file():
        return p
    found = sorted(folder.glob("*.urdf"))
    if len(found) != 1:
        raise ConvertError(f"{folder}: no URDF" if not found else f"{folder}: several URDFs, none mobility.urdf")
    return found[0]


def folder_fixed_base(folder: Path) -> bool:
    """Whether the object of ``folder`` is a fixture: ``annotation.json`` says so, or
    the category of PartNet-Mobility's ``meta.json`` is one of artipg's fixtures."""
    from artipg.export.annotation import annotated_fixed_base, category_fixed_base

    folder = Path(folder)
    if (folder / "annotation.json").is_file():
        return annotated_fixed_base(folder / "annotation.json")
    try:
        cat = json.loads((folder / "meta.json").read_text())["model_cat"]
    except (OSError, ValueError, KeyError, TypeError):
        return False
    return category_fixed_base(re.sub(r"(?<!^)(?=[A-Z])", "_", str(cat)).lower())


def _labels(folder: Path) -> dict[str, str]:
    """{link: label} from ``semantics.txt`` (``<link> <motion> <label>`` lines)."""
    try:
        lines = (Path(folder) / "semantics.txt").read_text().splitlines()
    except OSError:
        return {}
    return {w[0]: w[2] for w in (ln.split() for ln in lines) if len(w) >= 3}


def _is_convex(V: np.ndarray, F: np.ndarray) -> bool:
    import trimesh

    m = trimesh.Trimesh(V, F, process=True)
    if not m.is_watertight or len(m.vertices) < 4:
        return False
    try:
        hull = m.convex_hull.volume
    except Exception:  # flat or degenerate: not a solid piece
        return False
    return hull > 0 and abs(m.volume) >= (1.0 - CONVEX_TOL) * hull


def _placed(asset: Asset, g: Geom) -> tuple[np.ndarray, np.ndarray]:
    V, F = geom_arrays(asset, g)
    return V @ g.pose[:3, :3].T + g.pose[:3, 3], F


def decompose(V: np.ndarray, F: np.ndarray, seed: int = 0) -> list[tuple[np.ndarray, np.ndarray]]:
    """Convex pieces [(vertices, faces)] of a triangle mesh, by CoACD."""
    try:
        import coacd
    except ImportError:
        raise ConvertError("non-convex collision meshes need CoACD: pip install coacd") from None
    coacd.set_log_level("error")
    mesh = coacd.Mesh(np.asarray(V, dtype=float), np.asarray(F, dtype=np.int64))
    parts = coacd.run_coacd(mesh, seed=seed, **COACD_OPTIONS)
    return [(np.asarray(v, dtype=float), np.asarray(f, dtype=np.int64)) for v, f in parts]


#: A non-convex collision mesh is replaced by its convex hull when no point of the hull
#: lies farther from the mesh than ``HULL_REL`` of the hull's diagonal or ``HULL_OBJ``
#: of the object's (small parts: buttons, knobs); the others go to CoACD.
#: Third-party meshes are mostly soups of nearly convex pieces, one file each, and
#: CoACD takes tens of seconds even on a button.
HULL_REL, HULL_OBJ = 0.05, 0.02

#: Thickness (m) given to flat collision meshes (single-sided panels), whose hull has
#: no volume.
FLAT_THICKNESS = 1e-3


def _diagonal(asset: Asset) -> float:
    """Diagonal (m) of the bounding box of the object's collision geometry at rest."""
    poses = asset.link_poses()
    pts = [np.zeros((1, 3))]
    for lk in asset.links:
        T = poses[lk.name]
        for g in lk.collisions:
            V, _ = _placed(asset, g)
            pts.append(V @ T[:3, :3].T + T[:3, 3])
    P = np.concatenate(pts)
    return float(np.linalg.norm(P.max(axis=0) - P.min(axis=0)))


def hull_fit(V: np.ndarray, F: np.ndarray, tol: float = 0.0) -> tuple[np.ndarray, np.ndarray] | None:
    """The convex hull (vertices, faces) of a mesh when it stands for the mesh within
    :data:`HULL_REL` of its diagonal or ``tol`` (m), else None. A flat mesh gets the hull of its
    vertices moved by half :data:`FLAT_THICKNESS` to either side of its plane."""
    import trimesh

    c = V.mean(axis=0)
    n = np.linalg.svd(V - c, full_matrices=False)[2][-1]
    if np.abs((V - c) @ n).max() < 1e-6:  # flat
        V = np.concatenate([V + 0.5 * FLAT_THICKNESS * n, V - 0.5 * FLAT_THICKNESS * n])
    try:
        hull = trimesh.convex.convex_hull(V)
    except Exception:  # a degenerate mesh (a line, a point): no collision piece
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    pts = np.concatenate([hull.vertices, hull.triangles_center])
    _, dist, _ = trimesh.proximity.closest_point(trimesh.Trimesh(V, F, process=False) if len(F) else hull, pts)
    if dist.max() <= max(HULL_REL * float(np.linalg.norm(hull.extents)), tol):
        return np.asarray(hull.vertices, dtype=float), np.asarray(hull.faces, dtype=np.int64)
    return None


def convex_collisions(asset: Asset, cache_dir: Path) -> dict[str, str]:
    """Replace each link's non-convex collision meshes by convex pieces: their hulls
    where these fit (:func:`hull_fit`), CoACD's pieces of the others, cached in
    ``cache_dir``; returns {relative path: OBJ text} of pieces to write."""
    from artipg.export.meshes import obj_text

    cache_file = cache_dir / "cache.json"
    try:
        cache = json.loads(cache_file.read_text())
    except (OSError, ValueError):
        cache = {}
    new_files: dict[str, str] = {}
    rel_dir = cache_dir.relative_to(asset.folder).as_posix()
    tol = HULL_OBJ * _diagonal(asset)
    for lk in asset.links:
        keep, soup = [], []
        for g in lk.collisions:
            if g.kind != "mesh":
                keep.append(g)
                continue
            V, F = _placed(asset, g)
            (keep.append(g) if _is_convex(V, F) else soup.append((V, F)))
        if not soup:
            continue
        n, verts, faces = 0, [], []
        for V, F in soup:
            verts.append(V)
            faces.append(F + n)
            n += len(V)
        V, F = np.concatenate(verts), np.concatenate(faces)
        settings = (sorted(COACD_OPTIONS.items()), HULL_REL, round(tol, 9), FLAT_THICKNESS)
        key = hashlib.sha256(V.round(9).tobytes() + F.tobytes() + repr(settings).encode()).hexdigest()
        names = cache.get(lk.name, {}).get("pieces", [])
        if cache.get(lk.name, {}).get("key") != key or not all((asset.folder / p).is_file() for p in names):
            names, pieces, rest = [], [], []
            for sv, sf in soup:
                h = hull_fit(sv, sf, tol)
                (rest.append((sv, sf)) if h is None else pieces.append(h) if len(h[1]) else None)
            if rest:
                n, verts, faces = 0, [], []
                for sv, sf in rest:
                    verts.append(sv)
                    faces.append(sf + n)
                    n += len(sv)
                pieces += decompose(np.concatenate(verts), np.concatenate(faces))
            for k, (pv, pf) in enumerate(pieces):
                rel = f"{rel_dir}/{lk.name}_c{k}.obj"
                new_files[rel] = obj_text(pv, pf)
                names.append(rel)
            cache[lk.name] = {"key": key, "pieces": names}
        lk.collisions = keep + [Geom("mesh", np.eye(4), mesh=p) for p in names]
        asset.files.update({p: t for p, t in new_files.items() if p in names})
    if new_files:
        new_files[f"{rel_dir}/cache.json"] = json.dumps(cache, indent=1, sort_keys=True) + "\n"
    return new_files


#: Penetration (m) at rest above which two links of a third-party folder are kept
#: from colliding: convex pieces are fatter than the meshes they stand for, and
#: neighbouring doors would otherwise push each other from the first step.
OVERLAP_TOL = 1e-3


def rest_overlaps(asset: Asset, tol: float = OVERLAP_TOL) -> list[tuple[str, str]]:
    """[(link, link)] pairs whose collision geoms penetrate deeper than ``tol`` at rest
    (parent-child pairs, never colliding, aside), found by MuJoCo on the asset's MJCF."""
    import mujoco

    from artipg.export.mjcf import build_mjcf, mjcf_text

    # root welded to the world: MuJoCo then filters no pair through a free root's weld
    # group (links fixed to the body would not touch a door hinged on it otherwise)
    xml = mjcf_text(build_mjcf(dataclasses.replace(asset, fixed_base=True)))
    files = set(re.findall(r'file="([^"]+)"', xml))
    data = {f: asset.files[f].encode() if f in asset.files else (asset.folder / f).read_bytes() for f in files}
    try:
        m = mujoco.MjSpec.from_string(xml, assets=data).compile()
    except ValueError as e:  # MuJoCo's compiler errors
        raise ConvertError(f"{asset.folder}: MuJoCo cannot compile the model: {str(e).splitlines()[0]}") from None
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    name = lambda g: mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, int(m.geom_bodyid[g]))  # noqa: E731
    pairs = {tuple(sorted((name(c.geom1), name(c.geom2)))) for c in d.contact[:d.ncon] if c.dist < -tol}
    return sorted(p for p in pairs if p[0] != p[1])


def merged_visuals(asset: Asset) -> dict[str, str]:
    """Replace each link's visual meshes by one plain OBJ ``visual/<link>.obj`` (link
    frame; textures dropped, MuJoCo warns on many third-party OBJ files); returns
    {relative path: OBJ text}."""
    from artipg.export.meshes import obj_text

    out = {}
    for lk in asset.links:
        vm = asset.visual_mesh(lk)
        if vm is None:
            continue
        rel = f"visual/{lk.name}.obj"
        out[rel] = asset.files[rel] = obj_text(*vm)
        lk.visuals = [Geom("mesh", np.eye(4), mesh=rel)]
    return out


def _inertials_from_pieces(asset: Asset):
    """``inertials(link)``: mass properties of the solid convex hulls of the link's
    collision geoms (else its visuals) at the density of its label's material."""
    import trimesh

    from artipg.export.meshes import combine_inertials
    from artipg.materials import density

    def inertials(link):
        masses, coms, inertias = [], [], []
        rho = density(link.label)
        for g in link.collisions or link.visuals:
            V, _ = _placed(asset, g)
            try:
                hull = trimesh.convex.convex_hull(V)
            except Exception:  # flat or degenerate pieces carry no volume
                continue
            if not hull.is_volume or hull.volume <= 1e-12:
                continue
            with np.errstate(invalid="ignore", divide="ignore"):
                p = trimesh.triangles.mass_properties(hull.triangles, density=rho)
            if not np.isfinite(p.inertia).all():
                continue
            masses.append(float(p.mass))
            coms.append(np.asarray(p.center_mass))
            inertias.append(np.asarray(p.inertia))
        if not masses:
            return 1e-3, np.zeros(3), np.eye(3) * 1e-6
        return combine_inertials(masses, np.stack(coms), np.stack(inertias))

    return inertials


def check_folder(folder: Path):
    """The ``yourdfpy`` robot of the folder's URDF after checking that the URDF exists,
    parses, and that every mesh it names exists; raises :class:`ConvertError`."""
    from artipg.export.asset import relative_mesh_path

    folder = Path(folder).resolve()
    urdf = find_urdf(folder)
    try:
        robot = load_robot(urdf)
    except Exception as e:  # yourdfpy and lxml raise many kinds on malformed files
        raise ConvertError(f"{urdf}: cannot read the URDF ({str(e).strip() or type(e).__name__})") from None
    if not robot.links:
        raise ConvertError(f"{urdf}: no links")
    for lk in robot.links:
        for el in [*lk.visuals, *lk.collisions]:
            if el.geometry is not None and el.geometry.mesh is not None:
                rel = relative_mesh_path(el.geometry.mesh.filename)
                if not (folder / rel).is_file():
                    raise ConvertError(f"{urdf}: mesh {rel} of link {lk.name} is missing")
    return robot


def folder_asset(folder: Path, decompose_meshes: bool = True) -> tuple[Asset, dict[str, str]]:
    """The :class:`Asset` of an object folder and {relative path: text} of merged
    visual meshes and collision pieces to write (none when cached or convex already)."""
    folder = Path(folder).resolve()
    robot = check_folder(folder)
    try:
        asset = asset_from_urdf(robot, folder=folder, fixed_base=folder_fixed_base(folder),
                                labels=_labels(folder), name=robot.name)
    except ValueError as e:
        raise ConvertError(f"{folder}: {e}") from None
    pieces: dict[str, str] = {}
    if not (folder / "annotation.json").is_file():
        pieces.update(merged_visuals(asset))
    if decompose_meshes:
        pieces.update(convex_collisions(asset, folder / "collision"))
    if not (folder / "annotation.json").is_file():
        asset.excludes = rest_overlaps(asset)
    missing = {lk.name for lk in robot.links if lk.inertial is None or lk.inertial.mass is None}
    if missing:  # from the convex pieces, then the joint dynamics that follow from them
        estimate = _inertials_from_pieces(asset)
        from artipg.export.asset import ARMATURE_MIN, ARMATURE_RATIO, FRICTION_SPEED, effective_inertia
        from artipg.export.urdf import joint_damping

        for lk in asset.links:
            if lk.name in missing:
                lk.mass, lk.com, lk.inertia = estimate(lk)
        for j in asset.joints:  # dynamics follow the new inertials
            if j.type == "fixed":
                continue
            c = asset.link(j.child)
            j.effective = effective_inertia(j.type, j.axis, c.mass, c.com, c.inertia)
            j.damping = joint_damping(j.type, j.axis, c.mass, c.com, c.inertia)
            j.friction = FRICTION_SPEED * j.damping
            j.armature = max(ARMATURE_RATIO * j.effective, ARMATURE_MIN)
    return asset, pieces


def write_atomic(folder: Path, files: dict[str, bytes]) -> list[Path]:
    """Write ``files`` {relative path: bytes} into ``folder``: all under temporary
    names first, then each renamed into place (nothing half-written on failure)."""
    tmp = []
    try:
        for rel, data in files.items():
            dst = folder / rel
            dst.parent.mkdir(parents=True, exist_ok=True)
            t = dst.with_name(f".tmp-{dst.name}-{os.getpid()}")
            t.write_bytes(data)
            tmp.append((t, dst))
    except BaseException:
        for t, _ in tmp:
            t.unlink(missing_ok=True)
        raise
    for t, dst in tmp:
        os.replace(t, dst)
    return [dst for _, dst in tmp]


def convert_folder(folder, formats=("mjcf",), actuators: bool = False) -> list[Path]:
    """Write ``formats`` (of mjcf, usd, glb) of the object folder ``folder`` beside its
    URDF; returns the paths written. Raises :class:`ConvertError` on bad input."""
    from artipg.export.formats import format_files

    folder = Path(folder).resolve()
    asset, pieces = folder_asset(folder)
    files = {k: v.encode() for k, v in pieces.items()}
    files.update(format_files(asset, formats, actuators))
    return write_atomic(folder, files)
