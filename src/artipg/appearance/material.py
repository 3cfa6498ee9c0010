"""The visual material of a part: a physically based (metallic-roughness) description.

A :class:`Material` is what every exporter reads. Colours are sRGB in [0, 1] (as a
person picks them); :meth:`Material.to_pbr` gives the glTF-style values (linear base
colour factor) that MJCF, USD and GLB writers need, so no writer converts colours itself.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def srgb_to_linear(c) -> np.ndarray:
    """Linear-light values of sRGB components ``c`` (any shape, in [0, 1])."""
    c = np.asarray(c, dtype=float)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


@dataclass(frozen=True)
class Material:
    """A physically based visual material.

    Attributes
    ----------
    name : str
        Unique within one object (used for MTL names and texture file names).
    family : str
        The realistic family it was drawn from (``oak``, ``stainless``, ``glossy_plastic`` ...,
        see :data:`artipg.appearance.families.FAMILIES`).
    density_class : str
        The material class of :data:`artipg.materials.CLASS_DENSITY` it dresses.
    color : tuple of 3 floats
        Mean base colour, sRGB in [0, 1].
    metallic, roughness : float
        In [0, 1].
    opacity : float
        1 for opaque; below 1 for glass (alpha of the base colour).
    transmission : float
        Fraction of light transmitted (0 opaque, about 0.9 for clear glass).
    texture : str or None
        Procedural texture kind (``wood``, ``brushed``, ``noise``) or None.
    texture_params : tuple of float
        Parameters of the texture generator (its seed first); see
        :func:`artipg.appearance.textures.texture_image`.
    """

    name: str
    family: str
    density_class: str
    color: tuple
    metallic: float = 0.0
    roughness: float = 0.5
    opacity: float = 1.0
    transmission: float = 0.0
    texture: str | None = None
    texture_params: tuple = ()

    @property
    def texture_file(self) -> str | None:
        """Path of the texture image relative to the object folder (None without texture)."""
        return None if self.texture is None else f"textures/{self.name}.png"

    @property
    def rgba(self) -> tuple:
        """(r, g, b, a) sRGB colour with the opacity as alpha."""
        return (*self.color, self.opacity)

    def to_pbr(self) -> dict:
        """glTF metallic-roughness values of this material, for format writers.

        Returns
        -------
        dict
            ``baseColorFactor`` (4 floats, *linear* RGB and alpha: white when a texture
            carries the colour, since the texture image holds the full sRGB colour),
            ``metallic``, ``roughness``, ``opacity``, ``transmission``, ``texture``
            (path relative to the object folder, or None), ``color_srgb`` (the mean
            sRGB colour, for formats with a single colour such as URDF) and ``name``.
        """
        base = (1.0, 1.0, 1.0) if self.texture else tuple(float(v) for v in srgb_to_linear(self.color))
        return {
            "name": self.name,
            "baseColorFactor": (*base, float(self.opacity)),
            "metallic": float(self.metallic),
            "roughness": float(self.roughness),
            "opacity": float(self.opacity),
            "transmission": float(self.transmission),
            "texture": self.texture_file,
            "color_srgb": tuple(float(v) for v in self.color),
        }

    def mtl_text(self, texture_prefix: str = "../") -> str:
        """Wavefront MTL block of this material; ``texture_prefix`` leads from the MTL
        file's folder to the object folder."""
        r, g, b = self.color
        spec = 0.04 + 0.96 * self.metallic  # F0 of dielectrics against metals
        ns = (1.0 - self.roughness) ** 2 * 1000.0
        lines = [f"newmtl {self.name}", "Ka 0 0 0", f"Kd {r:.4f} {g:.4f} {b:.4f}",
                 f"Ks {spec:.4f} {spec:.4f} {spec:.4f}", f"Ns {ns:.2f}", f"d {self.opacity:.4f}",
                 f"illum {4 if self.opacity < 1 else 2}", f"Pr {self.roughness:.4f}", f"Pm {self.metallic:.4f}"]
        if self.texture:
            lines.append(f"map_Kd {texture_prefix}{self.texture_file}")
        return "\n".join(lines) + "\n"
