"""Meshes, bounding boxes and convex collision sectors of solids of revolution about the
local z axis over ``0 <= θ <= arc`` (from +x towards +y): the helpers of the lathe and
swept-tube families (:mod:`artipg.geometry.lathe`, :mod:`artipg.geometry.sweep`)."""

from __future__ import annotations

import functools
import math

import numpy as np

from artipg.geometry.base import TWO_PI, CollisionPiece, convex_hull
from artipg.geometry.transforms import rot_z

FULL = TWO_PI
_QUARTERS = np.array([0.5 * np.pi, np.pi, 1.5 * np.pi])


def revolve_arrays(profile, arc: float = FULL, sections: int = 32, cap_start: bool = True,
                   cap_end: bool = True, closed_profile: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and faces of a (ρ, z) profile revolved about z from θ = 0 to θ = ``arc``.

    Parameters
    ----------
    profile : (P, 2) array_like
        Profile vertices (ρ >= 0, z) in counter-clockwise order in the (ρ, z) plane.
        Vertices on the axis (ρ = 0) are shared by all sections.
    arc : float
        Swept angle in radians; a full turn gives a closed surface of revolution.
    sections : int
        Segments for a full turn (scaled down for partial arcs, at least 2).
    cap_start, cap_end : bool
        Close a partial arc with the (convex) profile polygon at θ = 0 / θ = arc.
    closed_profile : bool
        Connect the last profile vertex back to the first.

    Returns
    -------
    vertices : (V, 3) float64
    faces : (F, 3) int64
        Outward-oriented triangles without degenerate faces or unused vertices
        (watertight for closed profiles and full or capped arcs).
    """
    prof = np.asarray(profile, dtype=float)
    full = arc >= TWO_PI - 1e-9
    n_sec = max(2, int(math.ceil(sections * arc / TWO_PI)))
    n_th = n_sec if full else n_sec + 1
    cos_th, sin_th, th = _section_angles(float(arc), n_sec, n_th)
    P = len(prof)
    rho, z = prof[:, 0], prof[:, 1]
    V = np.empty((n_th, P, 3))
    V[..., 0] = rho[None, :] * cos_th
    V[..., 1] = rho[None, :] * sin_th
    V[..., 2] = z[None, :]
    verts = V.reshape(-1, 3)
    caps, ccw = (False, False), False
    if not full:
        caps = (bool(cap_start), bool(cap_end))
        # a counter-clockwise profile makes the fan (centre, v_k, v_k+1) face -θ at θ = 0
        ccw = float(np.sum(prof[:, 0] * np.roll(prof[:, 1], -1) - np.roll(prof[:, 0], -1) * prof[:, 1])) > 0
        centroid = prof.mean(axis=0)
        extra = [[centroid[0] * math.cos(t), centroid[0] * math.sin(t), centroid[1]]
                 for on, t in zip(caps, (th[0], th[n_th - 1])) if on]
        verts = np.concatenate([verts, np.array(extra).reshape(-1, 3)])
    used, F = _revolve_topology(P, tuple((rho <= 0.0).tolist()), n_sec, n_th, bool(closed_profile), caps, ccw)
    return verts[used], F.copy()


@functools.lru_cache(maxsize=64)
def _section_angles(arc: float, n_sec: int, n_th: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cosines (n_th, 1), sines (n_th, 1) and angles (n_th,) of the sections of
    :func:`revolve_arrays` (read-only: they are shared)."""
    th = np.linspace(0.0, arc, n_sec + 1)[:n_th]
    out = np.cos(th)[:, None], np.sin(th)[:, None], th
    for a in out:
        a.flags.writeable = False
    return out


@functools.lru_cache(maxsize=256)
def _revolve_topology(P: int, on_axis: tuple, n_sec: int, n_th: int, closed_profile: bool,
                      caps: tuple[bool, bool], ccw: bool) -> tuple[np.ndarray, np.ndarray]:
    """Which vertices (U,) of :func:`revolve_arrays`'s grid (``n_th`` sections of ``P``
    profile vertices, then one centre per cap) are used, and the faces (F, 3) indexing
    them: they depend only on the counts, the on-axis vertices and the caps, so a
    template's meshes share them (read-only)."""
    idx = np.arange(n_th * P).reshape(n_th, P)
    axis = np.array(on_axis, dtype=bool)
    # every section's copy of an on-axis profile vertex is replaced by the first one
    idx[:, axis] = idx[0, axis]
    n_edges = P if closed_profile else P - 1
    i = np.arange(n_edges)
    i1 = (i + 1) % P
    j = np.arange(n_sec)
    j1 = (j + 1) % n_th
    a, b = idx[j][:, i].ravel(), idx[j][:, i1].ravel()
    c, d = idx[j1][:, i1].ravel(), idx[j1][:, i].ravel()
    faces = [np.stack([a, c, b], 1), np.stack([a, d, c], 1)]
    cidx = n_th * P
    for on, jj, start in ((caps[0], 0, True), (caps[1], n_th - 1, False)):
        if not on:
            continue
        ring = idx[jj]
        tri = np.stack([np.full(P, cidx), ring, np.roll(ring, -1)], 1)
        faces.append(tri if start == ccw else tri[:, ::-1])
        cidx += 1
    F = np.concatenate(faces)
    F = F[(F[:, 0] != F[:, 1]) & (F[:, 1] != F[:, 2]) & (F[:, 0] != F[:, 2])]
    used, F = np.unique(F, return_inverse=True)
    F = F.reshape(-1, 3).astype(np.int64)
    used.flags.writeable = False
    F.flags.writeable = False
    return used, F


def _turn_boxes(r, z0, z1):
    """Boxes (M, 2, 3) of full turns of radius ``r`` over z0..z1: a square footprint."""
    out = np.empty((len(r), 2, 3))
    out[:, 1, 0] = r
    out[:, 1, 1] = r
    np.negative(out[:, 1, 0:2], out=out[:, 0, 0:2])
    out[:, 0, 2] = z0
    out[:, 1, 2] = z1
    return out


def arc_bounds(r_lo, r_hi, arc, z0, z1):
    """Bounding boxes (M, 2, 3) of annular sectors r_lo..r_hi, 0..arc (M,), extruded
    over z0..z1."""
    if arc.min() >= FULL - 1e-9:  # full turns (the common case)
        return _turn_boxes(r_hi, z0, z1)
    M = len(arc)
    out = np.empty((M, 2, 3))
    out[:, 0, 2] = z0
    out[:, 1, 2] = z1
    arc = np.minimum(arc, FULL)
    # candidate angles 0, arc and the quarter turns inside the arc
    cand = np.empty((M, 5))
    cand[:, 0] = 0.0
    cand[:, 1] = arc
    cand[:, 2:] = _QUARTERS
    cs = np.empty((2, M, 5))  # their cosines and sines
    np.cos(cand, out=cs[0])
    np.sin(cand, out=cs[1])
    # x and y of the candidates at both radii, (2, M, 10): 5 angles at r_lo, 5 at r_hi
    v = np.empty((2, M, 10))
    np.multiply(cs, r_lo[:, None], out=v[:, :, :5])
    np.multiply(cs, r_hi[:, None], out=v[:, :, 5:])
    ok = np.ones((M, 10), dtype=bool)
    ok[:, 2:5] = _QUARTERS < arc[:, None]
    ok[:, 5:] = ok[:, :5]
    out[:, 0, 0:2] = np.where(ok, v, np.inf).min(2).T
    out[:, 1, 0:2] = np.where(ok, v, -np.inf).max(2).T
    return out


#: Largest gap (metres) between a curved surface and the flat faces of the convex
#: sectors that replace it in collision geometry: sets how many sectors a ring or torus
#: is cut into (8 to 48 per turn), so a bottle collar needs far fewer pieces than a
#: bucket wall (every piece costs simulators time).
SECTOR_SAGITTA = 5e-4


def sector_hulls(profile: np.ndarray, arc: float, r_concave: float) -> list[CollisionPiece]:
    """Convex hulls of equal sectors of ``profile`` (ρ, z) revolved over ``arc`` radians,
    as few as keep each hull within :data:`SECTOR_SAGITTA` of the concave side at
    radius ``r_concave``. All pieces share one hull (the same vertex and face arrays)
    placed by their ``pose``, a turn about z, so exporters can write it once."""
    arc = min(float(arc), FULL)
    r = max(float(r_concave), 1e-6)
    step = 2.0 * math.acos(max(-1.0, 1.0 - SECTOR_SAGITTA / r))
    n_turn = int(np.clip(math.ceil(FULL / step), 8, 48))
    n = max(1, int(math.ceil(arc / (FULL / n_turn) - 1e-9)))
    a = arc / n
    V, F = convex_hull(revolve_arrays(profile, arc=a, sections=max(2, int(math.ceil(FULL / a))))[0])
    return [CollisionPiece("mesh", pose=rot_z(i * a), vertices=V, faces=F) for i in range(n)]
