"""Which material every part of an object wears: the one source of truth.

Parts fall into *groups* by their semantic label (``main`` for the body and everything
that matches it, ``accent`` for handles and controls, ``glass``, ``display``, ``panel``,
``rubber``); a category may move labels between groups. Each group draws one family per
object from the category's scheme, so a cabinet's doors match its carcass, and the
accent family is drawn apart from the main one, so handles contrast. A part then wears
the material of (its group, its density class): the group's family when the class allows
it (:data:`artipg.materials.FINISHES`), else a family drawn from the class's defaults;
its density therefore always agrees with its look.

Every draw comes from a stream of its own, ``SeedSequence(seed, spawn_key=(key of
'appearance', key of the category, key of the group[, key of the class]))``: the same seed gives the same
materials, and adding a part never changes the materials of others.
"""

from __future__ import annotations

import numpy as np

from artipg.appearance.families import draw
from artipg.appearance.markings import with_markings
from artipg.appearance.material import Material
from artipg.materials import FINISHES, material_class
from artipg.rules.streams import stream_key

#: Group of each semantic label; labels not listed are in ``main``.
GROUP = {
    "handle": "accent", "knob": "accent", "button": "accent", "dial": "accent", "switch": "accent",
    "lever": "accent", "hinge": "accent", "cap": "accent", "pump": "accent", "nozzle": "accent",
    "spout": "accent", "glass": "glass", "lens": "glass", "turntable": "glass", "screen": "display",
    "panel": "panel", "keyboard": "panel", "touchpad": "panel", "wheel": "rubber", "pedal": "rubber",
    "hand": "accent", "pendulum": "accent", "bulb": "glass",
}

_FURNITURE = {"main": {"wood": 0.45, "lacquered_wood": 0.25, "painted_wood": 0.3},
              "accent": {"brushed_metal": 0.35, "chrome": 0.15, "black_metal": 0.3, "brass": 0.2}}
_APPLIANCE = {"main": {"painted_metal": 0.55, "stainless": 0.45},
              "accent": {"stainless": 0.3, "chrome": 0.2, "black_metal": 0.3, "brushed_metal": 0.2,
                         "neutral_plastic": 0.2},
              "panel": {"neutral_plastic": 1.0}, "display": {"display": 1.0}}
_OPENING = {"main": {"painted_wood": 0.5, "wood": 0.3, "lacquered_wood": 0.2},
            "accent": {"brushed_metal": 0.3, "chrome": 0.2, "brass": 0.2, "black_metal": 0.3},
            "glass": {"glass": 1.0}}

#: Per category: ``groups`` (label -> group overrides), ``families`` (group -> {family:
#: weight}) and ``sub`` (sub-category -> group -> {family: weight}, over ``families``).
SCHEMES: dict[str, dict] = {
    "storage_furniture": {"families": _FURNITURE},
    "box": {"families": _FURNITURE},
    "table": {"families": _FURNITURE},
    "chair": {"families": {**_FURNITURE, "main": {"wood": 0.5, "lacquered_wood": 0.3, "painted_wood": 0.2}},
              "sub": {"office": {"main": {"neutral_plastic": 1.0, "painted_wood": 0.0}}}},
    "door": {"families": _OPENING},
    "window": {"families": _OPENING},
    "refrigerator": {"families": _APPLIANCE, "groups": {"shelf": "glass", "tray": "panel"}},
    "dishwasher": {"families": _APPLIANCE, "groups": {"tray": "panel"}},
    "oven": {"families": _APPLIANCE, "groups": {"tray": "panel"}},
    "microwave": {"families": _APPLIANCE, "groups": {"tray": "panel"}},
    "washing_machine": {"families": {**_APPLIANCE, "main": {"painted_metal": 0.8, "stainless": 0.2}},
                        "groups": {"tray": "panel"}},
    "safe": {"families": {**_APPLIANCE, "main": {"painted_metal": 1.0}}, "groups": {"tray": "panel"}},
    "trash_can": {"families": {"main": {"stainless": 0.45, "matte_plastic": 0.3, "painted_metal": 0.25},
                               "accent": {"black_metal": 0.5, "matte_plastic": 0.3, "chrome": 0.2}},
                  "sub": {"bin_cabinet": {"main": _FURNITURE["main"]}}},
    "bucket": {"families": {"main": {"matte_plastic": 0.6, "glossy_plastic": 0.4},
                            "accent": {"brushed_metal": 0.5, "black_metal": 0.3, "stainless": 0.2}}},
    "bottle": {"families": {"main": {"glossy_plastic": 0.5, "matte_plastic": 0.5},
                            "accent": {"matte_plastic": 0.5, "glossy_plastic": 0.3, "neutral_plastic": 0.2}},
               "sub": {"wine_bottle": {"main": {"tinted_glass": 1.0}},
                       "water_bottle": {"main": {"stainless": 0.4, "tinted_glass": 0.3, "glossy_plastic": 0.3}}}},
    "eyeglasses": {"groups": {"temple": "main"},
                   "families": {"main": {"glossy_plastic": 0.4, "neutral_plastic": 0.6}, "glass": {"glass": 1.0}},
                   "sub": {"sunglasses": {"glass": {"tinted_glass": 1.0}}}},
    "faucet": {"groups": {"spout": "main", "lever": "main", "nozzle": "main"},
               "families": {"main": {"chrome": 0.6, "brushed_metal": 0.2, "black_metal": 0.2}}},
    "kettle": {"groups": {"spout": "main", "lid": "main"},
               "families": {"main": {"glossy_plastic": 0.5, "matte_plastic": 0.3, "neutral_plastic": 0.2},
                            "accent": {"black_metal": 0.5, "neutral_plastic": 0.3, "brushed_metal": 0.2}}},
    "kitchen_pot": {"families": {"main": {"stainless": 0.5, "brushed_metal": 0.3, "black_metal": 0.2},
                                 "accent": {"black_metal": 0.6, "stainless": 0.4}, "glass": {"glass": 1.0}}},
    "laptop": {"groups": {"screen": "panel"}, "families": {"main": {"brushed_metal": 0.5, "black_metal": 0.3, "painted_metal": 0.2},
                            "panel": {"neutral_plastic": 1.0}, "accent": {"neutral_plastic": 1.0},
                            "display": {"display": 1.0}}},
    "stapler": {"groups": {"arm": "main", "magazine": "accent", "hinge": "accent"},
                "families": {"main": {"painted_metal": 0.4, "black_metal": 0.3, "neutral_plastic": 0.3},
                             "accent": {"chrome": 0.6, "brushed_metal": 0.4}}},
    "switch": {"families": {"main": {"neutral_plastic": 1.0}, "accent": {"neutral_plastic": 1.0}}},
    "dispenser": {"groups": {"lid": "main"},
                  "families": {"main": {"glossy_plastic": 0.5, "matte_plastic": 0.3, "neutral_plastic": 0.2},
                               "accent": {"neutral_plastic": 0.5, "matte_plastic": 0.3, "glossy_plastic": 0.1,
                                          "chrome": 0.1},
                               "glass": {"glass": 1.0}}},
    "shampoo": {"groups": {"lid": "accent"},
                "families": {"main": {"glossy_plastic": 0.6, "matte_plastic": 0.4},
                             "accent": {"glossy_plastic": 0.4, "matte_plastic": 0.3, "neutral_plastic": 0.3}}},
    "shaver": {"groups": {"head": "accent"},
               "families": {"main": {"neutral_plastic": 0.5, "matte_plastic": 0.3, "glossy_plastic": 0.2},
                            "accent": {"neutral_plastic": 0.6, "chrome": 0.4}}},
    "lighter": {"families": {"main": {"glossy_plastic": 0.5, "matte_plastic": 0.3, "neutral_plastic": 0.2}},
                "sub": {"flip_top": {"main": {"chrome": 0.4, "brushed_metal": 0.35, "black_metal": 0.25}}}},
    "clock": {"groups": {"dial": "panel", "bell": "accent"},
              "families": {"main": {"glossy_plastic": 0.35, "matte_plastic": 0.25, "brushed_metal": 0.2,
                                    "black_metal": 0.2},
                           "accent": {"black_metal": 0.5, "brass": 0.3, "chrome": 0.2},
                           "panel": {"neutral_plastic": 1.0}, "glass": {"glass": 1.0}},
              "sub": {"mantel_clock": {"main": {"wood": 0.5, "lacquered_wood": 0.5},
                                       "accent": {"brass": 0.7, "black_metal": 0.3}}}},
    "fan": {"groups": {"rotor": "accent", "blade": "accent"},
            "families": {"main": {"matte_plastic": 0.45, "glossy_plastic": 0.35, "painted_metal": 0.2},
                         "accent": {"neutral_plastic": 0.5, "glossy_plastic": 0.3, "chrome": 0.2}}},
    "lamp": {"groups": {"shade": "shade", "bulb": "glass"},
             "families": {"main": {"black_metal": 0.3, "brushed_metal": 0.25, "brass": 0.2, "painted_metal": 0.25},
                          "shade": {"neutral_plastic": 0.4, "matte_plastic": 0.4, "glossy_plastic": 0.2},
                          "accent": {"black_metal": 0.5, "chrome": 0.3, "neutral_plastic": 0.2},
                          "glass": {"glass": 1.0}},
             "sub": {"table_lamp": {"main": {"ceramic": 0.5, "glossy_plastic": 0.2, "brass": 0.3}}}},
    "door_handle": {"groups": {"handle": "main", "knob": "main"},
                    "families": {"main": {"brushed_metal": 0.35, "chrome": 0.25, "stainless": 0.2, "black_metal": 0.2}}},
    "folding_rack": {"families": {"main": {"painted_metal": 0.4, "stainless": 0.3, "brushed_metal": 0.3}}},
    "toilet": {"families": {"main": {"sanitary_ceramic": 1.0},
                            "accent": {"chrome": 0.6, "brushed_metal": 0.2, "black_metal": 0.1, "neutral_plastic": 0.1},
                            "panel": {"chrome": 0.4, "neutral_plastic": 0.6}}},
    "coffee_machine": {"groups": {"portafilter": "accent"},
                       "families": {"main": {"glossy_plastic": 0.2, "neutral_plastic": 0.3, "stainless": 0.4,
                                             "painted_metal": 0.1},
                                    "accent": {"chrome": 0.4, "black_metal": 0.3, "neutral_plastic": 0.3},
                                    "panel": {"neutral_plastic": 1.0}, "glass": {"glass": 1.0}}},
    "printer": {"families": {"main": {"painted_metal": 1.0}, "accent": {"neutral_plastic": 1.0},
                             "panel": {"neutral_plastic": 1.0}, "display": {"display": 1.0}}},
    "camera": {"groups": {"lens": "main"},
               "families": {"main": {"matte_plastic": 0.5, "black_metal": 0.3, "neutral_plastic": 0.2},
                            "accent": {"black_metal": 0.4, "matte_plastic": 0.3, "chrome": 0.3}, "glass": {"glass": 1.0}},
               "sub": {"instant": {"main": {"glossy_plastic": 0.6, "neutral_plastic": 0.4}}}},
    "mouse": {"groups": {"button": "main"}, "families": {"main": {"matte_plastic": 0.5, "glossy_plastic": 0.3, "neutral_plastic": 0.2},
                           "accent": {"matte_plastic": 0.6, "glossy_plastic": 0.4}}},
    "phone": {"groups": {"lid": "main", "hinge": "main"},
              "families": {"main": {"matte_plastic": 0.4, "glossy_plastic": 0.4, "neutral_plastic": 0.2},
                           "accent": {"matte_plastic": 0.5, "neutral_plastic": 0.5}, "display": {"display": 1.0}}},
    "cart": {"families": {"main": {"chrome": 0.4, "painted_metal": 0.3, "stainless": 0.3},
                          "accent": {"black_metal": 0.5, "painted_metal": 0.5}}},
}


def _rng(seed: int, *keys: str) -> np.random.Generator:
    """The appearance stream of object ``seed`` for ``keys`` (category first)."""
    ss = np.random.SeedSequence(int(seed), spawn_key=(stream_key("appearance"), *map(stream_key, keys)))
    return np.random.Generator(np.random.PCG64(ss))


def _pick(weights: dict, rng: np.random.Generator, exclude: str | None = None) -> str:
    """A key of ``weights`` drawn by weight (``exclude`` left out while others remain)."""
    names = sorted(k for k, w in weights.items() if w > 0 and k != exclude) or sorted(
        k for k, w in weights.items() if w > 0)
    w = np.array([weights[k] for k in names], dtype=float)
    return names[int(rng.choice(len(names), p=w / w.sum()))]


def group_of(category: str, semantic: str) -> str:
    """The appearance group of label ``semantic`` in ``category``."""
    return SCHEMES.get(category, {}).get("groups", {}).get(semantic, GROUP.get(semantic, "main"))


def group_families(category: str, subcategory: str) -> dict[str, dict]:
    """{group: {family: weight}} of a category's scheme, with its sub-category's changes."""
    scheme = SCHEMES.get(category, {})
    return {**scheme.get("families", {}), **scheme.get("sub", {}).get(subcategory, {})}


def materials_of(obj) -> dict[str, Material]:
    """The visual material of every part of ``obj``: {part name: Material}.

    The one source of truth for what a part looks like (exporters, renderers and the
    viewer all read it); deterministic in ``obj.seed``. Parts of one (group, density
    class) share one :class:`Material` object.
    """
    fams = group_families(obj.category, obj.subcategory)
    chosen: dict[str, str | None] = {}
    out: dict[str, Material] = {}
    made: dict[tuple, Material] = {}
    for group in sorted({group_of(obj.category, p.semantic) for p in obj.parts}, key=lambda g: g != "main"):
        weights = fams.get(group)
        exclude = chosen.get("main") if group == "accent" else None
        chosen[group] = _pick(weights, _rng(obj.seed, obj.category, group), exclude) if weights else None
    for part in obj.parts:
        group = group_of(obj.category, part.semantic)
        cls = material_class(part.semantic, obj.materials)
        key = (group, cls)
        mat = made.get(key)
        if mat is None:
            rng = _rng(obj.seed, obj.category, group, cls)
            allowed = FINISHES[cls]
            family = chosen[group]
            if family not in allowed:
                fit = {f: w for f, w in (fams.get(group) or {}).items() if f in allowed and w > 0}
                family = _pick(fit or allowed, rng, chosen.get("main") if group == "accent" else None)
            mat = made[key] = draw(family, rng, f"{group}_{cls}", cls)
        out[part.name] = mat
    return with_markings(obj, out)
