"""The one shared vocabulary of semantic part labels and actionable-part classes.

Every part of every category takes its ``semantic`` label from :data:`SEMANTIC_LABELS`;
the integer label of a point is the label's index here, so ids mean the same thing in
every object and every category. Add new labels at the end only (ids are stable).
"""

from __future__ import annotations

SEMANTIC_LABELS: tuple[str, ...] = (
    "body",        # main static shell / housing / frame of an object
    "base",        # a stand, plinth or foot the body rests on
    "leg",
    "door",
    "drawer",
    "handle",      # fixed or movable grip: bar, arch, knob-pull, bail, lever-handle
    "lid",
    "knob",        # rotary control
    "button",      # push control
    "spout",
    "lever",       # faucet lever, toggle, rocker
    "shelf",
    "turntable",
    "tray",        # rack / tray / basket that slides
    "screen",
    "keyboard",
    "seat",
    "backrest",
    "armrest",
    "wheel",
    "pedal",
    "cap",
    "pump",
    "glass",       # window pane / glass panel
    "frame",       # door / window frame, eyeglass frame front
    "temple",      # eyeglass arm
    "dial",
    "switch",
    "magazine",    # stapler magazine
    "arm",         # stapler top arm, generic rotating arm
    "hinge",
    "panel",       # control panel, decorative panel
    "top",         # table top, stove top
    "flap",
    "sash",        # window sash
    "nozzle",
    "lens",        # eyeglass lens
    "touchpad",    # laptop touchpad
    "stand",       # display neck / column / height carriage, globe stand
    "sphere",      # globe ball
    "clip",        # pen pocket clip
    "refill",      # pen refill point, glue stick column
    "connector",   # USB plug, its sliding carriage
    "cover",       # swivel cover of a flash drive
    "blade",       # scissor, plier, knife blade or jaw
    "head",        # shaver head, razor cartridge, rotary head holder
    "jaw",         # a spring clip's leg (bag clip, plastic clothes peg)
    "segment",     # a folding rule's segment
    "hand",        # clock hand
    "pendulum",    # clock pendulum
    "bell",        # alarm-clock bell
    "rotor",       # fan rotor hub (its blades are "blade")
    "guard",       # fan guard / grille
    "shade",       # lamp shade or reflector head
    "bulb",        # lamp bulb
    "lock",        # lock cylinder, keyhole escutcheon
    "rail",        # drying-rack rail, rung or bar
    "container",   # removable vessel of an appliance: coffee carafe, water tank
    "portafilter",  # espresso machine's filter holder with its handle
)

LABEL_ID: dict[str, int] = {name: i for i, name in enumerate(SEMANTIC_LABELS)}

#: GAPartNet actionable-part classes (plus "none" for parts that are not one).
ACTIONABLE_CLASSES: tuple[str, ...] = (
    "none",
    "line_fixed_handle",
    "round_fixed_handle",
    "slider_button",
    "hinge_door",
    "slider_drawer",
    "slider_lid",
    "hinge_lid",
    "hinge_knob",
    "hinge_handle",
)

ACTIONABLE_ID: dict[str, int] = {name: i for i, name in enumerate(ACTIONABLE_CLASSES)}

#: Affordance kinds that part templates may define as analytic regions.
AFFORDANCES: tuple[str, ...] = ("grasp", "pull", "push", "lift", "rotate", "press")


def label_id(name: str) -> int:
    """Integer id of semantic label ``name``; raises ``KeyError`` naming the vocabulary."""
    try:
        return LABEL_ID[name]
    except KeyError:
        raise KeyError(f"unknown semantic label {name!r}; add it to artipg.vocabulary") from None
