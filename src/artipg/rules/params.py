"""The parameter recorder: every random parameter of an object is drawn here.

Each draw records its name, value and the valid range computed *at that moment* from
the parents, so an object's structural parameters can be exported and a repair step
can regenerate it with ``overrides`` (clamped to the then-valid range). The random
number is always drawn, even when overridden, so overriding one parameter never
shifts the stream of the others.

Every draw takes exactly one double from the stream (``Generator.random()``). A
recorder made with ``read_ahead=True`` takes those doubles in blocks
(``Generator.random(k)`` yields the same values as ``k`` scalar calls), which is what
:meth:`artipg.rules.Category.generate` does for its per-slot streams; reading
:attr:`ParamRecorder.rng` rewinds the generator over the doubles read ahead, so the
generator it returns is exactly where the draws so far left it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np


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


_OPTION_CACHE: dict[int, tuple] = {}


def _options(options):
    """(options, weights, names, total weight) of a choice, cached per options object."""
    hit = _OPTION_CACHE.get(id(options))
    if hit is not None and hit[0] is options:
        return hit[1]
    if isinstance(options, dict):
        opts, w = list(options), [float(v) for v in options.values()]
    else:
        opts = list(options)
        w = [1.0] * len(opts)
    out = (opts, w, tuple(option_name(o) for o in opts), sum(w))
    if len(_OPTION_CACHE) < 4096:  # keyed by id: keep the object alive with its entry
        _OPTION_CACHE[id(options)] = (options, out)
    return out


#: Bit generators whose ``advance`` counts one step per double, so doubles read ahead
#: can be given back by advancing the period minus their number.
_PCG_PERIOD = 1 << 128
_REWINDABLE = {np.random.PCG64: _PCG_PERIOD, np.random.PCG64DXSM: _PCG_PERIOD}
_FIRST_BLOCK = 32  # a slot's stream gives 15 draws on median, 0 to 70+ (one in seven takes more than 32)
_MAX_BLOCK = 256


class _Draws:
    """The uniform doubles of one generator, optionally read ahead in blocks.

    ``buf`` holds the doubles read ahead but not used yet, last to be used first; it is
    shared (the same list object) by every recorder of the stream. ``scratch`` maps a
    block size to an array the block is drawn into (filled in as needed; it may be
    shared with other draws on the same thread, as a block is copied out at once).
    """

    __slots__ = ("gen", "buf", "block", "period", "scratch")

    def __init__(self, gen: np.random.Generator, read_ahead: bool):
        self.gen = gen
        self.buf: list[float] = []
        bitgen = getattr(gen, "bit_generator", None)
        self.period = _REWINDABLE.get(type(bitgen)) if read_ahead else None
        self.block = _FIRST_BLOCK if self.period else 1
        self.scratch = {}

    def refill(self) -> float:
        """The next double when ``buf`` is empty; reads the next block into ``buf``."""
        n = self.block
        if n == 1:
            return self.gen.random()
        out = self.scratch.get(n)
        if out is None:
            out = self.scratch[n] = np.empty(n)
        # drawing into a kept array saves random()'s allocation: the same doubles
        block = self.gen.random(out=out).tolist()
        block.reverse()
        buf = self.buf
        buf += block
        if n < _MAX_BLOCK:
            self.block = 2 * n
        return buf.pop()

    def sync(self) -> np.random.Generator:
        """The generator, rewound over the doubles read ahead (which are dropped)."""
        n = len(self.buf)
        if n:
            bitgen = self.gen.bit_generator
            state = bitgen.state
            bitgen.advance(self.period - n)  # also clears the cached 32-bit half: restore it
            if state["has_uint32"]:
                rewound = bitgen.state
                rewound["has_uint32"], rewound["uinteger"] = state["has_uint32"], state["uinteger"]
                bitgen.state = rewound
            self.buf.clear()
        return self.gen


_new = object.__new__


def _param(name: str, kind: str, value, lo, hi, options: tuple) -> Param:
    """``Param(name, kind, value, lo, hi, options)`` without the class call and its
    ``__init__`` (a recorder makes one per draw, 50-100 per object)."""
    p = _new(Param)
    p.name = name
    p.kind = kind
    p.value = value
    p.lo = lo
    p.hi = hi
    p.options = options
    return p
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
    read_ahead : bool
        Take the doubles from ``rng`` in blocks (same values, fewer calls). The
        generator then runs ahead of the draws until :attr:`rng` is read, so use it
        only when the recorder (and its scopes) is the generator's only user. Applies
        to PCG64 and PCG64DXSM generators; others are read one double at a time.
    """

    __slots__ = ("_draws", "_buf", "record", "overrides", "_prefix", "_dot")

    def __init__(self, rng: np.random.Generator, record: dict | None = None,
                 overrides: dict | None = None, prefix: str = "", *, read_ahead: bool = False):
        self._draws = _Draws(rng, read_ahead)
        self._buf = self._draws.buf
        self.record = {} if record is None else record
        self.overrides = overrides or {}
        self._prefix = prefix
        self._dot = f"{prefix}." if prefix else ""  # each key is _dot + name

    @classmethod
    def _on_stream(cls, gen: np.random.Generator, record: dict, overrides: dict, prefix: str,
                   scratch: dict) -> "ParamRecorder":
        """``ParamRecorder(gen, record, overrides, prefix, read_ahead=True)`` for a
        Generator on a PCG64 (a slot's stream), without the generic checks, drawing its
        blocks into the arrays of ``scratch`` (block size -> array, filled in as needed;
        the slots of an object share it)."""
        draws = _new(_Draws)
        draws.gen = gen
        draws.buf = buf = []
        draws.period = _PCG_PERIOD
        draws.block = _FIRST_BLOCK
        draws.scratch = scratch
        s = _new(cls)
        s._draws = draws
        s._buf = buf
        s.record = record
        s.overrides = overrides
        s._prefix = prefix
        s._dot = f"{prefix}." if prefix else ""
        return s

    @property
    def rng(self) -> np.random.Generator:
        """The generator, positioned right after the doubles drawn so far."""
        return self._draws.sync()

    @rng.setter
    def rng(self, gen: np.random.Generator) -> None:
        self._draws = _Draws(gen, False)
        self._buf = self._draws.buf

    def scope(self, name: str) -> "ParamRecorder":
        """A recorder sharing stream and record, whose names are prefixed by ``name``."""
        s = _new(ParamRecorder)
        s._draws = self._draws
        s._buf = self._buf
        s.record = self.record
        s.overrides = self.overrides
        s._prefix = key = self._dot + name
        s._dot = key + "."
        return s

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
        buf = self._buf
        v = lo + (hi - lo) * (buf.pop() if buf else self._draws.refill())
        if self.overrides:
            o = self.overrides.get(key)
            if o is not None:
                v = min(hi, max(lo, float(o)))
        self.record[key] = _param(key, "uniform", v, lo, hi, ())
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
        buf = self._buf
        v = lo + int((buf.pop() if buf else self._draws.refill()) * (hi - lo + 1))
        if self.overrides:
            o = self.overrides.get(key)
            if o is not None:
                v = min(hi, max(lo, int(round(o))))
        self.record[key] = _param(key, "integer", v, lo, hi, ())
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
        buf = self._buf
        u = (buf.pop() if buf else self._draws.refill()) * total
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
        self.record[key] = _param(key, "choice", names[i], None, None, names)
        return opts[i], names[i]

    def flag(self, name: str, p: float, fixed: bool | None = None) -> bool:
        """True with probability ``p``."""
        key = self._dot + name
        if fixed is not None:
            self.record[key] = Param(key, "fixed", bool(fixed))
            return bool(fixed)
        buf = self._buf
        v = (buf.pop() if buf else self._draws.refill()) < p
        if self.overrides:
            o = self.overrides.get(key)
            if o is not None:
                v = bool(o)
        v = bool(v)
        self.record[key] = _param(key, "flag", v, None, None, _FLAG_OPTIONS)
        return v
