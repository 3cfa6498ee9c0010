"""More vessel bodies (pots, kettles) and the wall-profile lookup that places handles
and spouts on any vessel body.

Frame (as in :mod:`artipg.templates.bodies`): origin at the centre of the base on
z = 0, axis +z; anchors ``rim`` (0, 0, top), ``rim_edge`` (rim outer radius, 0, top)
and ``base``. Walls are :func:`artipg.geometry.ring` primitives with role ``"wall"``
placed by a translation, so :func:`wall_radius` can read the outer radius at any
height from the part itself.

Kettle bodies are closed at the top except for a filling opening with a short collar;
the collar is their rim (a lid from :mod:`artipg.templates.lids` rests on it).
"""

from __future__ import annotations

from artipg.geometry import frustum, ring
from artipg.geometry.lathe import ring_dims
from artipg.geometry.transforms import translation
from artipg.model.part import Part, Region
from artipg.templates.detail import lip_style, lipped_wall


def wall_radius(part: Part, z: float) -> float:
    """Outer radius (metres) of a vessel's wall at height ``z`` of its frame, read from
    its ``"wall"`` rings (the largest one covering z; 0 where there is none). A ring
    under a rounded lip (its top face left out of the surface,
    :func:`artipg.templates.detail.lipped_wall`) covers the lip's height too."""
    r = 0.0
    for pr in part.primitives:
        dims = ring_dims(pr) if pr.role == "wall" else None
        if dims is None:
            continue
        ro, ri, h, _, tp = dims
        z0 = float(pr.pose[2, 3]) - h / 2  # a float: numpy scalars are slower at the arithmetic
        top = z0 + h + (0.6 * (ro - ri) if pr.params[11] == 0.0 else 0.0)
        if z0 - 1e-9 <= z <= top + 1e-9:
            r = max(r, ro + tp * (z - z0) / h)
    return r


def wall_slope(part: Part, z: float, dz: float = 1e-3) -> float:
    """d(radius)/dz of the wall at ``z`` (negative where the wall leans inwards)."""
    return (wall_radius(part, z + dz) - wall_radius(part, z - dz)) / (2 * dz)


def _anchors(r_rim: float, h: float) -> dict:
    return {"rim": (0.0, 0.0, h), "rim_edge": (r_rim, 0.0, h), "base": (0.0, 0.0, 0.0)}


def _profile_walls(radii, heights, t, bottom, lip="flat"):
    """Bottom disc and tapered wall rings through the profile points (radius, z); the
    top ring ends in a lip of style ``lip`` (:func:`artipg.templates.detail.lipped_wall`)."""
    prims = [frustum(radii[0], radii[0] + (radii[1] - radii[0]) * bottom / heights[1], bottom,
                     translation(0, 0, bottom / 2), role="bottom")]
    last = len(radii) - 2
    for i, ((r0, z0), (r1, z1)) in enumerate(zip(zip(radii, heights), zip(radii[1:], heights[1:]))):
        h = z1 - z0
        prims += lipped_wall(r0, r0 - t, h, z0 + h / 2, lip if i == last else "flat", taper=r1 - r0)
    return prims


def bellied_shell(p, radius: float, height: float, wall: float | None = None, band: float = 0.0) -> Part:
    """Open pot with a rounded belly: the wall flares out from the base and draws in
    again to the rim (Dutch ovens, sauciers, bean pots); ``radius`` is the rim's. The
    top ``band`` (metres) of the wall stays vertical (room for a lid's skirt)."""
    t = p.uniform("wall", 0.002, 0.005, fixed=wall)
    rb = radius * p.uniform("belly", 1.04, 1.15)
    zb = (height - band) * p.uniform("belly_height", 0.3, 0.6)
    r0 = rb * p.uniform("foot", 0.8, 0.95)
    radii, heights = (r0, rb, radius), (0.0, zb, height - band)
    if band > 0:
        radii, heights = radii + (radius,), heights + (height,)
    prims = _profile_walls(radii, heights, t, max(t, p.uniform("bottom", 0.003, 0.008)), lip_style(p))
    return Part("body", "bellied_shell", prims, anchors=_anchors(radius, height), regions={"lift": Region(("wall",))})


def _kettle(name, p, radii, heights, opening, skirt):
    """Walls through the profile, a top plate down to the opening and a collar at least
    ``skirt`` + 1.5 mm tall (so a lid's skirt hanging over it clears the top plate)."""
    t = p.uniform("wall", 0.0015, 0.003)
    prims = _profile_walls(radii, heights, t, max(t, p.uniform("bottom", 0.003, 0.006)))
    H, R = heights[-1], radii[-1]
    tc = p.uniform("collar_wall", 0.002, 0.004)
    hc = max(p.uniform("collar", 0.003, 0.012), skirt + 0.0015 if skirt > 0 else 0.0)
    ro = min(opening, R - 0.008)
    prims.append(ring(R, ro, t, pose=translation(0, 0, H - t / 2), role="top"))
    prims += lipped_wall(ro, ro - tc, hc + 0.0005, H + hc / 2 - 0.00025, lip_style(p), role="rim")
    return Part("body", name, prims, anchors=_anchors(ro, H + hc) | {"shoulder": (R, 0.0, H)},
                regions={"lift": Region(("wall",)), "grasp": Region(("wall",))})


def straight_kettle_body(p, radius: float, height: float, opening: float, skirt: float = 0.0) -> Part:
    """Cylindrical or gently tapered kettle (electric jugs, pour-over kettles); ``radius``
    is at the base, ``opening`` the filling hole's outer radius."""
    top = radius * p.uniform("top_ratio", 0.8, 1.0)
    return _kettle("straight_kettle_body", p, (radius, top), (0.0, height), opening, skirt)


def conical_kettle_body(p, radius: float, height: float, opening: float, skirt: float = 0.0) -> Part:
    """Wide-based cone (classic stovetop kettle), vertical for a short foot."""
    foot = height * p.uniform("foot", 0.1, 0.25)
    top = radius * p.uniform("top_ratio", 0.45, 0.7)
    return _kettle("conical_kettle_body", p, (radius, radius, top), (0.0, foot, height), opening, skirt)


def bellied_kettle_body(p, radius: float, height: float, opening: float, skirt: float = 0.0) -> Part:
    """Round-bellied kettle: flares from the base and draws in to a narrow shoulder."""
    rb = radius * p.uniform("belly", 1.1, 1.25)
    zb = height * p.uniform("belly_height", 0.35, 0.55)
    top = radius * p.uniform("top_ratio", 0.55, 0.8)
    return _kettle("bellied_kettle_body", p, (radius, rb, top), (0.0, zb, height), opening, skirt)


def power_base(p, radius: float) -> Part:
    """Electric kettle's power base: a low disc the jug stands on; anchors ``top`` and
    ``edge`` (the side wall's radius and z at mid-height)."""
    r = radius + p.uniform("overhang", 0.004, 0.015)
    h = p.uniform("height", 0.012, 0.025)
    k = p.uniform("taper", 0.94, 1.0)
    return Part("base", "power_base", [frustum(r, r * k, h, translation(0, 0, h / 2), role="base")],
                anchors={"top": (0.0, 0.0, h), "edge": (r * (1 + k) / 2, 0.0, h / 2)})


KETTLE_BODIES = {straight_kettle_body: 1.0, conical_kettle_body: 1.0, bellied_kettle_body: 1.0}
