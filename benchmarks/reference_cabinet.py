"""The issue's yardstick: a plain numpy loop that builds a 13-box cabinet and samples
2048 labelled points from it (about 0.5 ms on the machine the target was set on).

It has none of artipg's structure (no rules, parameter record, links, joints, anchors,
regions, grasps or round shapes): five body panels, four doors, four handles, each an
axis-aligned box, and area-uniform points with a box label. ``bench_generate.py`` times
it in the same process as artipg, so that a reader can tell a slow machine (or a slow
moment of a shared one) from slow code: the ratio of artipg's time to this one's moves
far less than either figure.
"""

from __future__ import annotations

import numpy as np

#: The six faces of a unit box as (axis fixed, its sign, the two free axes).
_FACES = [(a, s, [b for b in range(3) if b != a]) for a in range(3) for s in (-1.0, 1.0)]


def cabinet_boxes(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Centres (13, 3) and half extents (13, 3) of a random two-by-two door cabinet, metres,
    and the label (13,) of each box (0 body, 1 door, 2 handle)."""
    w, d, h = rng.uniform((0.6, 0.35, 0.7), (1.2, 0.6, 1.8))
    t = rng.uniform(0.012, 0.025)
    c, e = [], []
    # body: back, two sides, top, bottom
    c += [(0, d / 2 - t / 2, h / 2), (-w / 2 + t / 2, 0, h / 2), (w / 2 - t / 2, 0, h / 2),
          (0, 0, h - t / 2), (0, 0, t / 2)]
    e += [(w / 2, t / 2, h / 2), (t / 2, d / 2, h / 2), (t / 2, d / 2, h / 2),
          (w / 2, d / 2, t / 2), (w / 2, d / 2, t / 2)]
    gap = rng.uniform(0.002, 0.004)
    for i in range(2):
        for k in range(2):
            x = (i - 0.5) * w / 2
            z = t + (k + 0.5) * (h - 2 * t) / 2
            c.append((x, -d / 2 - t / 2, z))
            e.append((w / 4 - gap, t / 2, (h - 2 * t) / 4 - gap))
            hx = x + (0.3 if i == 0 else -0.3) * w / 4
            c.append((hx, -d / 2 - t - 0.015, z))
            e.append((0.006, 0.015, rng.uniform(0.04, 0.09)))
    label = np.array([0] * 5 + [1, 2] * 4)
    return np.array(c), np.array(e), label


def sample_cabinet(centre: np.ndarray, half: np.ndarray, label: np.ndarray, n: int,
                   rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``n`` area-uniform points (n, 3) on the boxes' surfaces, with their outward unit
    normals (n, 3), box index (n,) and box label (n,)."""
    B = len(centre)
    area = np.empty((B, 6))
    for f, (a, _, (b0, b1)) in enumerate(_FACES):
        area[:, f] = 4.0 * half[:, b0] * half[:, b1]
    cum = np.cumsum(area.ravel())
    face = np.searchsorted(cum, rng.random(n) * cum[-1], side="right")
    box, f = np.divmod(face, 6)
    uv = rng.random((n, 2)) * 2.0 - 1.0
    local = np.zeros((n, 3))
    normal = np.zeros((n, 3))
    fa = np.array([_FACES[i][0] for i in range(6)])[f]
    fs = np.array([_FACES[i][1] for i in range(6)])[f]
    free = np.array([_FACES[i][2] for i in range(6)])[f]
    rows = np.arange(n)
    local[rows, fa] = fs
    normal[rows, fa] = fs
    local[rows, free[:, 0]] = uv[:, 0]
    local[rows, free[:, 1]] = uv[:, 1]
    points = centre[box] + local * half[box]
    return points, normal, box, label[box]


def reference_object(seed: int, n: int = 2048):
    """One cabinet and its ``n`` labelled points, from ``seed``."""
    rng = np.random.default_rng(seed)
    centre, half, label = cabinet_boxes(rng)
    return sample_cabinet(centre, half, label, n, rng)
