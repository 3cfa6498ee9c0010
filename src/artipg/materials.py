"""Material classes of parts, their densities, and the visual finishes each class allows.

This module is the one place where a part's physical material is decided: its density
(for the inertials of exported links) and, through :data:`FINISHES`, which visual
families of :mod:`artipg.appearance` may dress it, so that what a part looks like and
what it weighs never disagree (a part drawn as glass has the density of glass).

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
    # hollow housings modelled as solids (appliance casings, bottles, faucet bodies,
    # bins): sheet metal, plastic or glass walls averaged over the enclosed volume
    "shell": 600.0,
    "ceramic": 2300.0,   # glazed stoneware and porcelain
    "fabric": 300.0,     # upholstery over foam
}

#: Visual families (:data:`artipg.appearance.families.FAMILIES`) that may dress each
#: class, with the weight of each when the category's appearance scheme names none
#: (weight 0: allowed when the scheme asks for it, never drawn by default).
FINISHES = {
    "wood": {"wood": 0.45, "lacquered_wood": 0.25, "painted_wood": 0.3},
    "plastic": {"matte_plastic": 0.5, "glossy_plastic": 0.3, "neutral_plastic": 0.2, "chrome": 0.0,
                "sanitary_ceramic": 0.0},
    "aluminium": {"brushed_metal": 0.4, "chrome": 0.2, "stainless": 0.2, "black_metal": 0.2, "painted_metal": 0.0},
    "steel": {"stainless": 0.3, "chrome": 0.2, "black_metal": 0.3, "brushed_metal": 0.2, "painted_metal": 0.0},
    "brass": {"chrome": 0.5, "brushed_metal": 0.2, "brass": 0.15, "black_metal": 0.15},
    "glass": {"glass": 1.0, "tinted_glass": 0.0, "display": 0.0},
    "rubber": {"rubber": 1.0},
    "insulated": {"painted_metal": 0.6, "stainless": 0.4},
    "shell": {"painted_metal": 0.5, "stainless": 0.3, "matte_plastic": 0.1, "glossy_plastic": 0.1,
              "neutral_plastic": 0.0, "chrome": 0.0, "brushed_metal": 0.0, "black_metal": 0.0, "brass": 0.0,
              "glass": 0.0, "tinted_glass": 0.0, "ceramic": 0.0, "wood": 0.0, "lacquered_wood": 0.0, "painted_wood": 0.0,
              "sanitary_ceramic": 0.0},
    "ceramic": {"ceramic": 1.0},
    "fabric": {"fabric": 1.0},
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
    "cover": "steel", "blade": "steel",
    "head": "plastic",
    "jaw": "plastic", "segment": "wood",
    "hand": "aluminium", "pendulum": "brass", "bell": "steel", "rotor": "plastic", "guard": "steel",
    "shade": "steel", "bulb": "glass",
    "lock": "brass", "rail": "aluminium",
    "container": "plastic", "portafilter": "steel",
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
