"""Area-uniform surface sampling of a labelled triangle soup (vectorised numpy)."""

from __future__ import annotations

import numpy as np


def sample_surface(vertices: np.ndarray, faces: np.ndarray, n: int, rng: np.random.Generator,
                   face_labels: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Draw ``n`` points uniformly (by area) on a triangle mesh.

    Faces are drawn with probability proportional to their area (one multinomial draw
    via ``rng.choice``), then a point is drawn uniformly inside each chosen triangle with
    the square-root barycentric map, so the density is exactly uniform per unit area.

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions (any unit; the points come out in the same unit and frame).
    faces : (F, 3) int
        Triangle vertex indices.
    n : int
        Number of points.
    rng : numpy.random.Generator
        The only source of randomness.
    face_labels : (F,) int, optional
        A label per face (e.g. link index); each point gets the label of its face.

    Returns
    -------
    points : (n, 3) float64
    labels : (n,) int64
        ``face_labels`` of the faces the points lie on (the face index when None).

    Raises
    ------
    ValueError
        If the mesh has zero total area.
    """
    v = np.asarray(vertices, dtype=np.float64)
    f = np.asarray(faces, dtype=np.int64)
    tri = v[f]                                            # (F, 3, 3)
    e1, e2 = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
    area = 0.5 * np.linalg.norm(np.cross(e1, e2), axis=1)
    total = area.sum()
    if not np.isfinite(total) or total <= 0:
        raise ValueError("cannot sample a surface of zero area")
    face = rng.choice(len(f), size=n, p=area / total)
    r1 = np.sqrt(rng.random(n))
    r2 = rng.random(n)
    # barycentric (a, b, c) = (1 - sqrt(u), sqrt(u) (1 - w), sqrt(u) w) is uniform on the triangle
    a, b, c = 1.0 - r1, r1 * (1.0 - r2), r1 * r2
    pts = a[:, None] * tri[face, 0] + b[:, None] * tri[face, 1] + c[:, None] * tri[face, 2]
    labels = face if face_labels is None else np.asarray(face_labels, dtype=np.int64)[face]
    return pts, labels.astype(np.int64)
