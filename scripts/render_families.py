"""Render one picture per geometry family to docs/images/families/<family>.png:
a few primitives of the family as shaded meshes with UV-coloured sample points.

    python scripts/render_families.py
"""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

from artipg.geometry import extrusion as ex  # noqa: E402
from artipg.geometry import lathe as la  # noqa: E402
from artipg.geometry import outlines, profile  # noqa: E402
from artipg.geometry.rounded_box import rounded_box  # noqa: E402
from artipg.geometry.sweep import sweep  # noqa: E402
from artipg.geometry.transforms import translation  # noqa: E402
from artipg.geometry.tube import arc, line  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "docs" / "images" / "families"
LIGHT = np.array([0.4, -0.5, 0.8]) / np.linalg.norm([0.4, -0.5, 0.8])


def _scene():
    vase = np.array([[0.0, 0.0, 0.0], [0.09, 0.0, -0.25], [0.05, 0.25, 0.0], [0.0, 0.25, 0.0]])
    return {
        "lathe": [la.lathe(vase, pose=translation(-0.3, 0, 0)), la.ring(0.1, 0.08, 0.15, arc=4.5, taper=0.03),
                  la.torus(0.08, 0.025, arc=4.0, pose=translation(0.3, 0, 0.05)),
                  la.sphere(0.09, -0.03, 0.09, arc=5.0, pose=translation(0.0, 0.3, 0.0))],
        "extrusion": [ex.extrusion(outlines.blade(0.3, 0.05), 0.01, pose=translation(-0.15, -0.2, 0)),
                      ex.extrusion(outlines.plier_half(0.18, 0.07, 0.04, 0.012), 0.015, pose=translation(0.0, 0.05, 0)),
                      ex.extrusion([profile.rectangle(0.2, 0.12, 0.02), profile.rectangle(0.12, 0.05)], 0.03,
                                   pose=translation(0.0, 0.3, 0)),
                      ex.extrusion([profile.regular_polygon(0.07, 6)], 0.12, scale=0.5,
                                   pose=translation(0.3, -0.1, 0))],
        "rounded_box": [rounded_box(0.3, 0.2, 0.12, 0.03),
                        rounded_box(0.12, 0.12, 0.12, 0.06, pose=translation(0.3, 0.1, 0)),
                        rounded_box(0.1, 0.25, 0.05, pose=translation(-0.3, 0.0, 0))],
        "sweep": [sweep(0.012, [line(0.1), arc(0.06, 1.6), line(0.12), arc(0.06, 1.6),
                                line(0.1)]),
                  sweep(0.02, [arc(0.12, math.pi)], heading=math.pi / 2, pose=translation(0.3, 0, 0))],
    }


def _draw(ax, prim, rng):
    g, p = prim.geom, np.asarray(prim.params)
    V, F = g.mesh_arrays(p, 48)
    V = V @ prim.pose[:3, :3].T + prim.pose[:3, 3]
    tri = V[F]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)
    shade = 0.35 + 0.6 * np.clip(n @ LIGHT, 0, 1)
    ax.add_collection3d(Poly3DCollection(tri, facecolors=np.c_[shade * 0.75, shade * 0.8, shade * 0.9],
                                         edgecolor="none", alpha=0.9))
    X, N = g.sample_many(p, 600, rng)
    uv = g.uv(p, X, N)
    uv = (uv - uv.min(0)) / np.maximum(np.ptp(uv, axis=0), 1e-12)
    X = X @ prim.pose[:3, :3].T + prim.pose[:3, 3]
    # the UV coordinates as colour (u red, v green) on a sample of surface points
    ax.scatter(*X.T, s=2, c=np.c_[uv, 0.3 * np.ones(len(uv))], depthshade=False)
    return V


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(0)
    for name, prims in _scene().items():
        fig = plt.figure(figsize=(4.0, 3.0), dpi=100)
        ax = fig.add_subplot(projection="3d")
        V = np.concatenate([_draw(ax, q, rng) for q in prims])
        pad = 0.06 * np.ptp(V, axis=0).max()
        lo, hi = V.min(0) - pad, V.max(0) + pad
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect(np.maximum(hi - lo, 1e-3), zoom=1.15)
        ax.view_init(elev=30, azim=-60)
        ax.set_axis_off()
        fig.subplots_adjust(0, 0, 1, 1)
        fig.savefig(OUT / f"{name}.png")
        plt.close(fig)


if __name__ == "__main__":
    main()
