"""Realistic material families and the one function that draws a material from one.

Each family is a small table: the colours real products come in (sRGB, picked from
product photographs and paint charts), ranges of metallic and roughness, opacity and
transmission for glass, and the procedural texture kind. :func:`draw` turns a family
and a random stream into a :class:`Material`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from artipg.appearance.material import Material


@dataclass(frozen=True)
class Family:
    """A family of real materials.

    ``colors`` are sRGB base colours, or (base, grain) pairs for wood; ``jitter`` the
    largest relative change of a drawn colour's brightness; ``texture`` the procedural
    texture kind (None for none) and ``strength`` its contrast.
    """

    colors: tuple
    metallic: tuple = (0.0, 0.0)
    roughness: tuple = (0.5, 0.5)
    opacity: float = 1.0
    transmission: float = 0.0
    texture: str | None = "noise"
    strength: float = 0.04
    jitter: float = 0.04


_WOODS = (  # (base, late-wood grain) of common furniture species
    ((0.72, 0.55, 0.36), (0.52, 0.36, 0.21)),  # white oak
    ((0.43, 0.29, 0.19), (0.27, 0.17, 0.10)),  # walnut
    ((0.86, 0.73, 0.54), (0.74, 0.58, 0.39)),  # maple
    ((0.64, 0.37, 0.23), (0.47, 0.25, 0.14)),  # cherry
    ((0.87, 0.71, 0.47), (0.70, 0.50, 0.27)),  # pine
    ((0.60, 0.42, 0.25), (0.44, 0.29, 0.15)),  # teak
    ((0.89, 0.79, 0.63), (0.77, 0.64, 0.47)),  # birch
    ((0.29, 0.19, 0.13), (0.18, 0.11, 0.07)),  # wenge / dark stained
)
_PAINTS = ((0.93, 0.92, 0.89), (0.96, 0.96, 0.95), (0.55, 0.57, 0.58), (0.31, 0.33, 0.35), (0.06, 0.06, 0.07),
           (0.50, 0.58, 0.50), (0.16, 0.23, 0.36), (0.80, 0.74, 0.64))
_APPLIANCE = ((0.94, 0.94, 0.93), (0.96, 0.96, 0.96), (0.07, 0.07, 0.08), (0.23, 0.24, 0.26),
              (0.60, 0.61, 0.63), (0.88, 0.85, 0.76))
_PLASTIC = ((0.94, 0.94, 0.93), (0.80, 0.80, 0.79), (0.45, 0.46, 0.47), (0.12, 0.12, 0.13), (0.04, 0.04, 0.05),
            (0.86, 0.80, 0.68), (0.10, 0.33, 0.66), (0.78, 0.12, 0.11), (0.19, 0.53, 0.26), (0.95, 0.76, 0.10),
            (0.93, 0.45, 0.10), (0.09, 0.52, 0.55), (0.55, 0.20, 0.50))

#: The families, by name.
FAMILIES: dict[str, Family] = {
    "wood": Family(_WOODS, roughness=(0.55, 0.75), texture="wood", strength=1.0, jitter=0.06),
    "lacquered_wood": Family(_WOODS, roughness=(0.2, 0.35), texture="wood", strength=1.0, jitter=0.06),
    "painted_wood": Family(_PAINTS, roughness=(0.35, 0.6), strength=0.03),
    "painted_metal": Family(_APPLIANCE, metallic=(0.0, 0.1), roughness=(0.25, 0.45), strength=0.02, jitter=0.02),
    "stainless": Family(((0.71, 0.71, 0.70), (0.66, 0.67, 0.67)), metallic=(1.0, 1.0), roughness=(0.28, 0.4),
                        texture="brushed", strength=0.06, jitter=0.03),
    "brushed_metal": Family(((0.80, 0.80, 0.81), (0.75, 0.72, 0.66), (0.55, 0.55, 0.56)), metallic=(1.0, 1.0),
                            roughness=(0.3, 0.45), texture="brushed", strength=0.08, jitter=0.03),
    "chrome": Family(((0.93, 0.93, 0.94),), metallic=(1.0, 1.0), roughness=(0.04, 0.1), texture=None, jitter=0.02),
    "brass": Family(((0.86, 0.69, 0.38), (0.78, 0.58, 0.33)), metallic=(1.0, 1.0), roughness=(0.15, 0.3),
                    texture="brushed", strength=0.08, jitter=0.03),
    "black_metal": Family(((0.05, 0.05, 0.05), (0.10, 0.10, 0.11)), metallic=(0.3, 0.6), roughness=(0.45, 0.65),
                          strength=0.03, jitter=0.02),
    "matte_plastic": Family(_PLASTIC, roughness=(0.6, 0.8), strength=0.04),
    "glossy_plastic": Family(_PLASTIC, roughness=(0.12, 0.3), strength=0.02),
    "neutral_plastic": Family(((0.03, 0.03, 0.04), (0.10, 0.10, 0.11), (0.22, 0.23, 0.24), (0.62, 0.63, 0.64),
                             (0.92, 0.92, 0.91)), roughness=(0.3, 0.6), strength=0.02, jitter=0.02),
    "rubber": Family(((0.04, 0.04, 0.04), (0.12, 0.12, 0.12), (0.20, 0.20, 0.21)), roughness=(0.85, 0.95),
                     strength=0.05),
    "glass": Family(((0.92, 0.95, 0.95),), roughness=(0.0, 0.05), opacity=0.2, transmission=0.9, texture=None,
                    jitter=0.01),
    "tinted_glass": Family(((0.22, 0.42, 0.24), (0.36, 0.21, 0.09), (0.20, 0.30, 0.50), (0.25, 0.25, 0.26)),
                           roughness=(0.0, 0.05), opacity=0.55, transmission=0.6, texture=None, jitter=0.02),
    "display": Family(((0.02, 0.02, 0.03),), roughness=(0.03, 0.08), texture=None, jitter=0.0),
    "ceramic": Family(((0.95, 0.94, 0.90), (0.93, 0.90, 0.82), (0.30, 0.42, 0.60), (0.45, 0.47, 0.48),
                       (0.12, 0.12, 0.13)), roughness=(0.08, 0.2), strength=0.02, jitter=0.03),
    "fabric": Family(((0.45, 0.46, 0.48), (0.18, 0.18, 0.20), (0.16, 0.21, 0.33), (0.72, 0.66, 0.56),
                      (0.35, 0.18, 0.16)), roughness=(0.85, 0.95), strength=0.12, jitter=0.05),
    # sanitary ware (vitreous china, white duroplast seats): white, bone, biscuit, pergamon
    "sanitary_ceramic": Family(((0.96, 0.96, 0.95), (0.95, 0.94, 0.90), (0.93, 0.90, 0.83), (0.90, 0.88, 0.82)),
                               roughness=(0.05, 0.15), strength=0.01, jitter=0.02),
}


def draw(family: str, rng: np.random.Generator, name: str, density_class: str) -> Material:
    """Draw one material of ``family`` from ``rng``.

    Parameters
    ----------
    family : str
        A key of :data:`FAMILIES`.
    rng : numpy.random.Generator
        The stream of this material (see :func:`artipg.appearance.materials_of`).
    name : str
        The material's name (unique within its object).
    density_class : str
        The material class of :mod:`artipg.materials` that the material dresses.
    """
    f = FAMILIES[family]
    k = int(rng.integers(len(f.colors)))
    scale = 1.0 + f.jitter * (2.0 * rng.random() - 1.0)
    colors = np.atleast_2d(np.asarray(f.colors[k], dtype=float))
    colors = np.clip(colors * scale, 0.0, 1.0)
    metallic = float(rng.uniform(*f.metallic))
    roughness = float(rng.uniform(*f.roughness))
    tex_seed = int(rng.integers(2 ** 31))
    params: tuple = ()
    if f.texture == "wood":  # base colour, grain colour, rings per tile, waviness
        params = (tex_seed, *colors[0], *colors[1], float(rng.uniform(6, 14)), float(rng.uniform(0.3, 1.0)))
        color = colors.mean(axis=0) * 0.35 + colors[0] * 0.65
    elif f.texture is not None:
        params = (tex_seed, *colors[0], f.strength)
        color = colors[0]
    else:
        color = colors[0]
    return Material(name=name, family=family, density_class=density_class,
                    color=tuple(round(float(c), 4) for c in color), metallic=round(metallic, 4),
                    roughness=round(roughness, 4), opacity=f.opacity, transmission=f.transmission,
                    texture=f.texture, texture_params=tuple(round(float(p), 6) if isinstance(p, float) else p
                                                            for p in params))
