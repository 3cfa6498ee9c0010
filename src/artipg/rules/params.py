"""The parameter recorder: every random parameter of an object is drawn here.

Each draw records its name, value and the valid range computed *at that moment* from
the parents, so an object's structural parameters can be exported and a repair step
can regenerate it with ``overrides`` (clamped to the then-valid range). The random
number is always drawn, even when overridden, so overriding one parameter never
shifts the stream of the others.

Every draw takes exactly one double from the stream (``Generator.random()``).

Geometric detail (rounded edges, rolled lips, door styles: :mod:`artipg.rules.detail`)
is drawn through ``detail_uniform`` / ``detail_choice`` / ``detail_flag`` from a second
stream of the slot, so switching detail off (``p.detail == "off"``: no detail draws,
the "off" values) leaves every other parameter of the object unchanged.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from artipg.rules.detail import DetailStream


@dataclass(init=False, slots=True)
class Param:
    """A recorded parameter: ``kind`` is uniform, integer, choice, flag or fixed.

    Attributes
    ----------
    name : str
        Full (scoped) name, the key of the record.
    kind : str
        ``uniform``, ``integer``, ``choice``, ``flag`` or ``fixed``.
    value : float, int, str or bool
        The value used (a choice records the option's name).
    lo, hi : float or int or None
        Valid range at draw time (uniform and integer).
    options : tuple
        Option names of a choice, ``(False, True)`` for a flag.
    """

    name: str
    kind: str
    value: Any
    lo: Any
    hi: Any
    options: tuple

    # hand-written: about a third cheaper than the generated __init__ and recorders
    # make one per draw
    def __init__(self, name: str, kind: str, value: Any, lo: Any = None, hi: Any = None,
                 options: tuple = ()):
        self.name = name
        self.kind = kind
        self.value = value
        self.lo = lo
        self.hi = hi
        self.options = options

    def to_json(self) -> dict:
        d = {"kind": self.kind, "value": self.value}
        if self.kind in ("uniform", "integer"):
            d["range"] = [self.lo, self.hi]
        if self.options:
            d["options"] = list(self.options)
        return d


def option_name(opt) -> str:
    """Display name of a choice option: a template's ``__name__`` or ``str``."""
    return getattr(opt, "__name__", None) or str(opt)


def _options(options):
    """(options, weights, names, total weight) of a choice (a dict or a sequence)."""
    if isinstance(options, dict):
        opts, w = list(options), [float(v) for v in options.values()]
    else:
        opts = list(options)
        w = [1.0] * len(opts)
    return opts, w, tuple(option_name(o) for o in opts), sum(w)


_FLAG_OPTIONS = (False, True)


class ParamRecorder:
    """Draws named parameters from one ``Generator`` and records them.

    Parameters
    ----------
    rng : numpy.random.Generator
        The only source of randomness; each draw takes one ``rng.random()`` double.
    record : dict, optional
        Shared name -> :class:`Param` store.
    overrides : dict, optional
        name -> value; clamped to the valid range at draw time.
    prefix : str
        Prepended (with a dot) to every name.
    """

    __slots__ = ("rng", "record", "overrides", "_prefix", "_dot", "_fine")

    def __init__(self, rng: np.random.Generator, record: dict | None = None,
                 overrides: dict | None = None, prefix: str = "", fine: DetailStream | None = None):
        self.rng = rng
        self.record = {} if record is None else record
        self.overrides = overrides or {}
        self._prefix = prefix
        self._dot = f"{prefix}." if prefix else ""  # each key is _dot + name
        self._fine = fine

    def scope(self, name: str) -> "ParamRecorder":
        """A recorder sharing streams and record, whose names are prefixed by ``name``."""
        return ParamRecorder(self.rng, self.record, self.overrides, self._dot + name, self._fine)

    # ------------------------------------------------------------ geometric detail
    @property
    def detail(self) -> str:
        """The object's detail level (:data:`artipg.rules.detail.DETAIL_LEVELS`):
        ``"off"`` gives the sharp structure (no detail draws), ``"procedural"`` the
        template options drawn by the ``detail_*`` methods."""
        return "off" if self._fine is None else self._fine.mode

    def _detail_recorder(self) -> "ParamRecorder":
        return ParamRecorder(self._fine.rng, self.record, self.overrides, self._prefix)

    def detail_uniform(self, name: str, lo: float, hi: float, off: float = 0.0) -> float:
        """A detail size drawn uniformly in [lo, hi] from the detail stream and
        recorded like :meth:`uniform`; ``off`` (not recorded) when detail is off."""
        if self._fine is None:
            return off
        return self._detail_recorder().uniform(name, lo, hi)

    def detail_choice(self, name: str, options, off):
        """A detail option (a weighted dict or a sequence, as :meth:`choice`) from the
        detail stream; ``off`` (not recorded) when detail is off."""
        if self._fine is None:
            return off
        return self._detail_recorder().choice(name, options)

    def detail_flag(self, name: str, p: float) -> bool:
        """True with probability ``p`` from the detail stream; False when detail is off."""
        if self._fine is None:
            return False
        return self._detail_recorder().flag(name, p)

    @property
    def prefix(self) -> str:
        """The scope's name prefix (without the dot); read-only."""
        return self._prefix

    def uniform(self, name: str, lo: float, hi: float, fixed: float | None = None) -> float:
        """Uniform value in [lo, hi]; ``fixed`` (set by a parent) is recorded instead."""
        key = self._dot + name
        if fixed is not None:
            v = float(fixed)
            self.record[key] = Param(key, "fixed", v)
            return v
        lo, hi = float(lo), float(hi)
        if hi < lo:
            raise ValueError(f"parameter {key}: empty range [{lo}, {hi}]")
        v = lo + (hi - lo) * self.rng.random()
        if self.overrides:
            o = self.overrides.get(key)
            if o is not None:
                v = min(hi, max(lo, float(o)))
        self.record[key] = Param(key, "uniform", v, lo, hi, ())
        return v

    def integers(self, name: str, lo: int, hi: int, fixed: int | None = None) -> int:
        """Uniform integer in [lo, hi] (both inclusive)."""
        key = self._dot + name
        if fixed is not None:
            self.record[key] = Param(key, "fixed", int(fixed))
            return int(fixed)
        lo, hi = int(lo), int(hi)
        if hi < lo:
            raise ValueError(f"parameter {key}: empty range [{lo}, {hi}]")
        v = lo + int(self.rng.random() * (hi - lo + 1))
        if self.overrides:
            o = self.overrides.get(key)
            if o is not None:
                v = min(hi, max(lo, int(round(o))))
        self.record[key] = Param(key, "integer", v, lo, hi, ())
        return v

    def choice(self, name: str, options, fixed=None):
        """Weighted choice.

        ``options`` is a dict {option: weight} or a sequence (equal weights). Options
        may be strings or functions (part templates); an override names the option.
        """
        return self._pick(name, options, fixed)[0]

    def _pick(self, name: str, options, fixed=None) -> tuple:
        """:meth:`choice` and the recorded name of the chosen option."""
        key = self._dot + name
        opts, w, names, total = _options(options)
        if fixed is not None:
            self.record[key] = Param(key, "fixed", option_name(fixed))
            return fixed, option_name(fixed)
        u = self.rng.random() * total
        i = 0
        acc = w[0]
        last = len(w) - 1
        while u >= acc and i < last:
            i += 1
            acc += w[i]
        if self.overrides:
            o = self.overrides.get(key)
            if o is not None and option_name(o) in names:
                i = names.index(option_name(o))
        self.record[key] = Param(key, "choice", names[i], None, None, names)
        return opts[i], names[i]

    def flag(self, name: str, p: float, fixed: bool | None = None) -> bool:
        """True with probability ``p``."""
        key = self._dot + name
        if fixed is not None:
            self.record[key] = Param(key, "fixed", bool(fixed))
            return bool(fixed)
        v = self.rng.random() < p
        if self.overrides:
            o = self.overrides.get(key)
            if o is not None:
                v = bool(o)
        v = bool(v)
        self.record[key] = Param(key, "flag", v, None, None, _FLAG_OPTIONS)
        return v
