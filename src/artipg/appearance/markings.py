"""Printed markings: what real objects carry printed on a part (a rule's graduations).

:func:`with_markings` dresses the parts listed in :data:`MARKINGS` with a copy of their
material whose texture is the marking (the material's own colour as the ground), so the
marking travels in every format like any texture. The graduations sit in texture space,
which is metres on the surface (the geometry families' analytic UVs): ticks start at a
part's end and reach in from its edge at their real spacing.
"""

from __future__ import annotations

from dataclasses import replace

#: (category, semantic label) -> texture kind printed on those parts
#: (:mod:`artipg.appearance.textures`). Clock dials carry their hour markers as geometry.
MARKINGS = {("ruler", "segment"): "scale", ("ruler", "arm"): "scale", ("ruler", "blade"): "scale"}
#: Ink on light grounds; light ink on dark ones.
DARK_INK, LIGHT_INK = (0.04, 0.04, 0.05), (0.95, 0.95, 0.92)


def with_markings(obj, mats: dict) -> dict:
    """``mats`` ({part name: Material}) with the parts of ``obj`` listed in
    :data:`MARKINGS` dressed in a marked copy of their material (one copy per material
    and kind, named ``<material>_<kind>``)."""
    out, made = dict(mats), {}
    for part in obj.parts:
        kind = MARKINGS.get((obj.category, part.semantic))
        if kind is None:
            continue
        m = mats[part.name]
        if (m.name, kind) not in made:
            r, g, b = m.color
            ink = DARK_INK if 0.2126 * r + 0.7152 * g + 0.0722 * b > 0.35 else LIGHT_INK
            seed = int(m.texture_params[0]) if m.texture_params else 0
            made[m.name, kind] = replace(m, name=f"{m.name}_{kind}", texture=kind,
                                         texture_params=(seed, r, g, b, *ink))
        out[part.name] = made[m.name, kind]
    return out
