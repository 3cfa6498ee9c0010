"""Cooktops for ranges: gas burners under a grate, glass-ceramic and coil hobs.

Frame: origin at the centre of the cooktop plate's underside; the plate spans
``depth`` along x (front at -x) and ``width`` along y, its top surface at
z = thickness. Anchors: ``surface`` (centre of the plate top) and ``top`` (the highest
point: grate or coil tops). ``burners`` is 4, 5 or 6, in two rows (5: 2 x 2 and one in
the middle).
"""

from __future__ import annotations

from artipg.geometry import cuboid, cylinder, rect_ring, ring, torus
from artipg.geometry.transforms import translation
from artipg.model.part import Part, Region


def burner_layout(p, depth: float, width: float, n: int) -> list[tuple[float, float, float]]:
    """(x, y, radius) of ``n`` burners; front and back burners differ in size."""
    cols = 3 if n == 6 else 2
    pitch_y = width / (cols + 0.4)
    r = min(depth / 4, pitch_y / 2) * p.uniform("burner_size", 0.6, 0.8)
    out = []
    for row, x in enumerate((-depth / 4, depth / 4)):
        for c in range(cols):
            y = (c - (cols - 1) / 2) * pitch_y * (1.0 if cols == 3 else 1.3)
            out.append((x, y, r * (1.0 if (row + c) % 2 == 0 else 0.75)))
    if n == 5:
        out.append((0.0, 0.0, 0.75 * r))
    return out


def _plate(p, depth, width):
    t = p.uniform("thickness", 0.008, 0.015)
    return t, cuboid(depth, width, t, translation(0, 0, t / 2), role="plate")


def gas_cooktop(p, depth: float, width: float, burners: int = 4) -> Part:
    """Plate with burner heads (base and cap) under a cast grate (a frame and bars)."""
    t, plate = _plate(p, depth, width)
    gh = p.uniform("grate_height", 0.025, 0.035)
    prims = [plate]
    for x, y, r in burner_layout(p, depth, width, burners):
        prims += [cylinder(0.7 * r, 0.012, translation(x, y, t + 0.006), role="burner"),
                  cylinder(0.5 * r, 0.008, translation(x, y, t + 0.016), role="burner")]
    gw = p.uniform("grate_bar", 0.008, 0.014)
    prims.append(rect_ring(depth - 0.02, width - 0.02, gh, depth - 0.02 - 2 * gw, width - 0.02 - 2 * gw,
                           translation(0, 0, t + gh / 2), role="grate"))
    prims.append(cuboid(gw, width - 0.02, gh, translation(0, 0, t + gh / 2), role="grate"))
    return Part("top", "gas_cooktop", prims, anchors={"surface": (0.0, 0.0, t), "top": (0.0, 0.0, t + gh)},
                regions={"push": Region(("grate",))})


def ceramic_cooktop(p, depth: float, width: float, burners: int = 4) -> Part:
    """Metal frame with a glass-ceramic panel and marked cooking zones."""
    t, plate = _plate(p, depth, width)
    g = p.uniform("glass", 0.004, 0.006)
    inset = p.uniform("frame", 0.005, 0.02)
    prims = [plate, cuboid(depth - 2 * inset, width - 2 * inset, g, translation(0, 0, t + g / 2), role="glass")]
    for x, y, r in burner_layout(p, depth, width, burners):
        prims.append(ring(r, r - 0.004, 0.001, pose=translation(x, y, t + g + 0.0005), role="zone"))
    return Part("top", "ceramic_cooktop", prims, anchors={"surface": (0.0, 0.0, t), "top": (0.0, 0.0, t + g + 0.001)},
                regions={"push": Region(("glass",))})


def coil_cooktop(p, depth: float, width: float, burners: int = 4) -> Part:
    """Plate with drip pans and two concentric heating coils per burner."""
    t, plate = _plate(p, depth, width)
    c = p.uniform("coil", 0.003, 0.005)
    prims = [plate]
    for x, y, r in burner_layout(p, depth, width, burners):
        prims += [cylinder(r, 0.004, translation(x, y, t + 0.002), role="pan"),
                  torus(0.75 * r, c, pose=translation(x, y, t + 0.004 + c), role="coil"),
                  torus(0.4 * r, c, pose=translation(x, y, t + 0.004 + c), role="coil")]
    return Part("top", "coil_cooktop", prims, anchors={"surface": (0.0, 0.0, t), "top": (0.0, 0.0, t + 0.004 + 2 * c)},
                regions={"push": Region(("plate",))})


COOKTOPS = {gas_cooktop: 2.0, ceramic_cooktop: 1.5, coil_cooktop: 1.0}
