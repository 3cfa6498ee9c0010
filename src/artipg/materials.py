"""Material classes of parts and their densities, for the inertials of exported links.

A part's material class follows from its semantic label (:data:`MATERIAL`), unless its
category says otherwise (``Category.materials``, carried by every generated object as
``obj.materials``). Densities are bulk densities of the solid primitives; for parts
that are modelled solid but are hollow or layered in reality (a refrigerator wall)
the class stands for the averaged material.
"""

from __future__ import annotations


#: Densities (kg/m^3) of the material classes.
CLASS_DENSITY = {
    "wood": 600.0,       # chipboard / MDF / solid wood furniture panels
    "plastic": 1050.0,   # ABS, polypropylene housings, knobs, caps
    "aluminium": 2700.0,  # handles, frames of small appliances
    "steel": 7850.0,     # hinges, levers, arms, stapler parts
    "brass": 8500.0,     # faucet spouts and levers
    "glass": 2500.0,     # panes, lenses, screens
    "rubber": 1100.0,    # wheels, pedals, pads
    # steel-skinned foam panels (refrigerator walls and doors): two 0.6 mm steel
    # skins, a plastic liner and ~5 cm of polyurethane foam average ~250 kg/m^3
    "insulated": 250.0,
}

#: Material class of each semantic label; labels not listed are :data:`DEFAULT_CLASS`.
#: A category overrides these for its own parts with ``Category.materials``.
MATERIAL = {
    "body": "wood", "base": "wood", "leg": "wood", "door": "wood", "drawer": "wood", "shelf": "wood",
    "top": "wood", "seat": "wood", "backrest": "wood", "armrest": "wood", "frame": "wood", "sash": "wood",
    "flap": "wood", "panel": "plastic",
    "handle": "aluminium", "hinge": "steel", "lever": "brass", "spout": "brass", "nozzle": "brass",
    "arm": "steel", "magazine": "steel",
    "lid": "plastic", "knob": "plastic", "button": "plastic", "dial": "plastic", "switch": "plastic",
    "cap": "plastic", "pump": "plastic", "tray": "plastic", "turntable": "glass", "keyboard": "plastic",
    "touchpad": "plastic", "temple": "plastic",
    "glass": "glass", "lens": "glass", "screen": "glass",
    "wheel": "rubber", "pedal": "rubber",
    "stand": "plastic", "sphere": "plastic", "clip": "steel", "refill": "plastic", "connector": "steel",
    "cover": "steel",
}
DEFAULT_CLASS = "plastic"


def material_class(semantic: str, materials=None) -> str:
    """Material class of a part with semantic label ``semantic``.

    ``materials`` ({semantic: class}, e.g. ``obj.materials``, taken from its
    category) takes precedence over the defaults in :data:`MATERIAL`.
    """
    if materials:
        m = materials.get(semantic)
        if m is not None:
            return m
    return MATERIAL.get(semantic, DEFAULT_CLASS)


def density(semantic: str, materials=None) -> float:
    """Density (kg/m^3) of a part with semantic label ``semantic`` (see
    :func:`material_class`)."""
    return CLASS_DENSITY[material_class(semantic, materials)]
