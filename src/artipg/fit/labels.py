"""Explicit tables between PartNet-Mobility's names and ours.

- :data:`CATEGORY_OF`: a PartNet-Mobility ``model_cat`` -> our category name;
- :data:`LINK_LABELS`: a PartNet-Mobility ``semantics.txt`` label -> the labels of our
  vocabulary (:data:`artipg.vocabulary.SEMANTIC_LABELS`) a link of ours may carry to be
  matched with it. A link that does not move (static, free, heavy, or held by a fixed
  joint) is a ``"body"`` link on both sides whatever its label says.

Labels of our own vocabulary map to themselves, so artipg folders are read the same way.
"""

from __future__ import annotations

from artipg.vocabulary import SEMANTIC_LABELS

#: Link class of every link that no joint moves (the carcass, frame, base of either side).
BODY = "body"

CATEGORY_OF: dict[str, str] = {
    "Bottle": "bottle", "Box": "box", "Bucket": "bucket", "Chair": "chair", "Dishwasher": "dishwasher",
    "Door": "door", "Eyeglasses": "eyeglasses", "Faucet": "faucet", "Kettle": "kettle",
    "KitchenPot": "kitchen_pot", "Laptop": "laptop", "Microwave": "microwave", "Oven": "oven",
    "Refrigerator": "refrigerator", "Safe": "safe", "Stapler": "stapler",
    "StorageFurniture": "storage_furniture", "Switch": "switch", "Table": "table", "TrashCan": "trash_can",
    "WashingMachine": "washing_machine", "Window": "window",
}

LINK_LABELS: dict[str, frozenset] = {k: frozenset(v) for k, v in {
    "rotation_lid": ("cap", "lid"),
    "lid": ("lid", "cap", "flap"),
    "handle": ("handle", "lever"),
    "rotation_handle": ("handle", "lever"),
    "door": ("door", "flap"),
    "rotation_door": ("door", "flap"),
    "drawer": ("drawer", "tray"),
    "screen": ("screen",),
    "leg": ("temple", "leg"),                 # eyeglasses' hinged legs are our temples
    "switch": ("lever", "handle", "knob"),    # a faucet's handle
    "toggle_button": ("switch", "button"),
    "slider": ("switch", "button", "knob"),
    "button": ("button", "switch"),
    "key": ("button",),
    "knob": ("knob", "dial"),
    "rotation_tray": ("turntable", "tray"),
    "wheel": ("wheel",),
    "caster": ("base", "wheel"),              # our chair's swivelling caster forks
    "seat": ("seat", "base"),                 # our chair's seat rides on the base column
    "translation_window": ("sash", "glass"),
    "rotation_window": ("sash", "glass"),
    "pedal": ("pedal",),
}.items()}


def compatible_labels(label: str) -> frozenset:
    """Our labels a moving link labelled ``label`` may be matched with (empty if none)."""
    if label in LINK_LABELS:
        return LINK_LABELS[label]
    return frozenset((label,)) if label in SEMANTIC_LABELS else frozenset()


def our_category(name: str) -> str:
    """Our category for a PartNet-Mobility ``model_cat`` (or our own name, unchanged)."""
    return CATEGORY_OF.get(name, name)
