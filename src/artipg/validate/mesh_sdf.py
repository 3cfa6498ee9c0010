"""Fast signed distances to third-party triangle meshes (PartNet-Mobility parts).

trimesh's exact ``signed_distance`` (an R-tree of candidate faces, a ray test per
point for the sign) costs seconds per real object part and dominated ``artipg
validate`` on real objects (about 8 s per object, a minute for a box of 116
parts). Here each mesh is prepared once:

- its faces are subdivided until no edge is longer than ``1/16`` of the part's
  bounding-box diagonal (:func:`trimesh.remesh.subdivide_to_size`), so that face
  centroids are spread evenly over the surface;
- a k-d tree of the face centroids gives each query point its ``K`` nearest faces;
  the distance is the exact distance to the nearest of those
  (:func:`trimesh.triangles.closest_point`). Missing the true nearest face
  overestimates the distance by at most the circumradius of a face, and only when
  more than ``K`` faces crowd closer centroids (it does not happen on subdivided
  meshes with ``K = 8`` in practice);
- the sign is that of the offset from the closest point along the face normal
  (inside: negative); where several candidate faces tie (an edge or a corner), the
  face with the largest absolute offset decides, which is right at convex edges.
  That only means "inside" for closed, outward-oriented meshes; on an open mesh (a
  single panel, a bucket without a lid: most PartNet-Mobility parts) a point that
  the normal calls inside is confirmed by its generalised winding number (the solid
  angle the mesh subtends, over 4 pi; more than 1/2 in absolute value: inside), so
  the back of a panel or the space above a cup is outside, and penetration depths
  into open parts are measured only where the part encloses the point. Points
  within ``sign_floor`` of an open part count as outside (the winding number
  costs a pass over all faces per point): set it to the penetration tolerance,
  below which the sign changes no verdict.
"""

from __future__ import annotations

import numba
import numpy as np

from artipg.validate.shapes import Pieces

#: Candidate faces per query point.
K_NEAREST = 8
#: Faces are subdivided until every edge is at most this fraction of the part's
#: bounding-box diagonal.
EDGE_FRACTION = 1.0 / 16.0
#: Distances within this (relative to the part's diagonal) count as ties for the sign.
_TIE = 1e-9


class MeshSDF:
    """Signed distance to one triangle mesh (see module docstring).

    Parameters
    ----------
    vertices : (V, 3) float64
    faces : (F, 3) int64
    sign_floor : float
        Distance (mesh units) below which points near an open mesh count as outside.
    """

    def __init__(self, vertices: np.ndarray, faces: np.ndarray, sign_floor: float = 0.0):
        import trimesh
        from scipy.spatial import cKDTree

        v = np.asarray(vertices, dtype=float)
        f = np.asarray(faces, dtype=np.int64)
        diag = float(np.linalg.norm(v.max(axis=0) - v.min(axis=0))) if len(v) else 0.0
        self.scale = max(diag, 1e-12)
        self.sign_floor = float(sign_floor)
        if len(f):
            v, f = trimesh.remesh.subdivide_to_size(v, f, max_edge=EDGE_FRACTION * self.scale, max_iter=8)
        tri = v[f]
        n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        norm = np.linalg.norm(n, axis=1)
        keep = norm > 1e-14 * self.scale ** 2  # degenerate faces have no normal
        self.triangles = tri[keep]
        self.normals = n[keep] / norm[keep, None]
        self.tree = cKDTree(self.triangles.mean(axis=1)) if len(self.triangles) else None
        self.closed = bool(trimesh.Trimesh(vertices, faces, process=True).is_watertight) if len(f) else False
        self._raw = np.asarray(vertices, dtype=float)[np.asarray(faces, dtype=np.int64)] if len(f) else None

    def __call__(self, x: np.ndarray) -> np.ndarray:
        """Signed distance (n,) of points ``x`` (n, 3), mesh frame, negative inside."""
        import trimesh

        x = np.asarray(x, dtype=float).reshape(-1, 3)
        if self.tree is None or not len(x):
            return np.full(len(x), np.inf)
        k = min(K_NEAREST, len(self.triangles))
        _, cand = self.tree.query(x, k=k)
        cand = cand.reshape(len(x), k)
        X = np.repeat(x, k, axis=0)
        c = trimesh.triangles.closest_point(self.triangles[cand.ravel()], X).reshape(len(x), k, 3)
        off = x[:, None, :] - c
        dist = np.sqrt((off * off).sum(axis=2))
        along = (off * self.normals[cand]).sum(axis=2)
        dmin = dist.min(axis=1)
        tie = dist <= dmin[:, None] + _TIE * self.scale
        pick = np.where(tie, np.abs(along), -1.0).argmax(axis=1)
        inside = along[np.arange(len(x)), pick] < 0.0
        if not self.closed:
            # nearer than the floor the sign changes nothing that a tolerance would see
            inside &= dmin > self.sign_floor
            idx = inside.nonzero()[0]
            inside[idx] = np.abs(winding_number(self._raw, np.ascontiguousarray(x[idx]))) > 0.5
        return np.where(inside, -dmin, dmin)


@numba.njit(cache=True)
def winding_number(triangles: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Generalised winding number (n,) of points ``x`` (n, 3) with respect to the
    triangles (F, 3, 3): the signed solid angle they subtend over 4 pi (Van Oosterom
    and Strackee's formula); 1 inside a closed outward mesh, 0 outside."""
    n, F = x.shape[0], triangles.shape[0]
    out = np.empty(n)
    for i in range(n):
        total = 0.0
        for f in range(F):
            ax = triangles[f, 0, 0] - x[i, 0]
            ay = triangles[f, 0, 1] - x[i, 1]
            az = triangles[f, 0, 2] - x[i, 2]
            bx = triangles[f, 1, 0] - x[i, 0]
            by = triangles[f, 1, 1] - x[i, 1]
            bz = triangles[f, 1, 2] - x[i, 2]
            cx = triangles[f, 2, 0] - x[i, 0]
            cy = triangles[f, 2, 1] - x[i, 1]
            cz = triangles[f, 2, 2] - x[i, 2]
            la = np.sqrt(ax * ax + ay * ay + az * az)
            lb = np.sqrt(bx * bx + by * by + bz * bz)
            lc = np.sqrt(cx * cx + cy * cy + cz * cz)
            det = ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx)
            den = la * lb * lc + (ax * bx + ay * by + az * bz) * lc + (bx * cx + by * cy + bz * cz) * la \
                + (cx * ax + cy * ay + cz * az) * lb
            total += 2.0 * np.arctan2(det, den)
        out[i] = total / (4.0 * np.pi)
    return out


class MeshPieces(Pieces):
    """:class:`Pieces` whose mesh pieces use :class:`MeshSDF` instead of trimesh's
    ray-tested signed distance (primitive pieces are unchanged); ``sign_floor``
    (keyword, object units) as in :class:`MeshSDF`."""

    def __init__(self, *args, sign_floor: float = 0.0, **kwargs):
        super().__init__(*args, **kwargs)
        self.sign_floor = float(sign_floor)
        self._mesh_sdf = {}

    def mesh_sdf(self, piece: int) -> MeshSDF:
        """The prepared :class:`MeshSDF` of mesh piece ``piece`` (built on first use)."""
        f = self._mesh_sdf.get(piece)
        if f is None:
            m = self.meshes[piece]
            f = self._mesh_sdf[piece] = MeshSDF(m.vertices, m.faces, self.sign_floor)
        return f

    def _sdf_pieces(self, g, k: int, r: np.ndarray, x: np.ndarray) -> np.ndarray:
        if g is not None:
            return super()._sdf_pieces(g, k, r, x)
        out = np.empty(len(r))
        order = np.argsort(r, kind="stable")
        cuts = np.diff(r[order]).nonzero()[0] + 1
        for chunk in np.split(order, cuts):
            out[chunk] = self.mesh_sdf(int(r[chunk[0]]))(x[chunk])
        return out
