"""Geometric detail levels: the one place that names them and parses the option.

``"procedural"`` (the default) draws each template's detail options (rounded and
bevelled edges, rounded lips, door styles, ...) with their own recorded parameters;
``"off"`` builds the sharp structure, the objects of artipg 0.2 (sharp boxes, bare
rims). Templates see the level as ``ctx.p.detail`` and draw detail only through
``p.detail_uniform`` / ``p.detail_choice`` / ``p.detail_flag``
(:class:`artipg.rules.params.ParamRecorder`), which read a second stream per slot:
the structure's parameters are the same at every level.
"""

from __future__ import annotations

from artipg.rules.streams import stream

#: The detail levels, default first.
DETAIL_LEVELS = ("procedural", "off")
DEFAULT_DETAIL = DETAIL_LEVELS[0]

#: Offset of a slot's detail stream key from its structure stream key (slot keys are
#: CRC-32 values, below 2**32, so the two never meet).
DETAIL_KEY_OFFSET = 1 << 32


def parse_detail(value) -> str:
    """The detail level named by ``value`` (None: the default).

    Raises
    ------
    ValueError
        One line naming the valid levels.
    """
    if value is None:
        return DEFAULT_DETAIL
    v = str(value).strip().lower()
    if v not in DETAIL_LEVELS:
        raise ValueError(f"detail must be one of {', '.join(DETAIL_LEVELS)}; got {value!r}")
    return v


class DetailStream:
    """The detail stream of one slot of one object, opened on first use (objects whose
    slots draw no detail never pay for the generator)."""

    __slots__ = ("mode", "seed", "key", "_rng")

    def __init__(self, mode: str, seed: int, key: int):
        self.mode = mode
        self.seed = seed
        self.key = key
        self._rng = None

    @property
    def rng(self):
        if self._rng is None:
            self._rng = stream(self.seed, self.key + DETAIL_KEY_OFFSET)
        return self._rng
