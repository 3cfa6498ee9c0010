"""Visual materials and procedural textures of parts (see ``docs/appearance.md``).

- :func:`materials_of`: {part name: :class:`Material`} of an object, the one source of
  truth for what a part looks like (deterministic in the object's seed);
- :meth:`Material.to_pbr`: the glTF metallic-roughness values every format writer uses;
- :func:`texture_png`: the texture image of a material, as PNG bytes.
"""

from artipg.appearance.families import FAMILIES
from artipg.appearance.material import Material
from artipg.appearance.schemes import materials_of
from artipg.appearance.textures import texture_png, texture_image

__all__ = ["FAMILIES", "Material", "materials_of", "texture_png", "texture_image"]
