"""Independent random streams keyed by (object seed, slot name), cheap to open.

``np.random.default_rng([seed, key])`` hashes its seed through a ``SeedSequence``,
which costs about 30 µs: a third of a millisecond for an object with ten slots. Here
the seed is hashed once with SplitMix64 into a 128-bit PCG64 state and an odd 128-bit
increment, written straight into a bit generator borrowed from a per-thread pool, and
stream ``key`` (a 32-bit integer) starts ``key * 2**64`` draws further along that
sequence (PCG64 jumps ahead in O(log n); the jump's two constants are computed once per
key and the jumped state written directly): streams never overlap within 2**64 draws,
opening one costs well under 1 µs, and each depends only on (seed, key), never on the
order in which streams are opened.

The pooled generators take the state through a ``ctypes`` view of the PCG64 state
words, which costs a third of numpy's ``state`` setter (a dict, a scratch array and
four big-integer conversions); the view is used only after a round trip through the
setter has shown that it reads and writes exactly what the setter does, and numpy's
setter is used otherwise.
"""

from __future__ import annotations

import threading
import zlib

import numpy as np

_MASK = (1 << 64) - 1
_POOL = threading.local()


def _splitmix64(x: int) -> int:
    """One SplitMix64 output for state ``x`` (Steele, Lea and Flood 2014)."""
    z = (x + 0x9E3779B97F4A7C15) & _MASK
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _MASK
    return z ^ (z >> 31)


def stream_key(name: str) -> int:
    """A stable 32-bit key for a stream name (CRC-32 of its UTF-8 bytes)."""
    return zlib.crc32(name.encode())


def pcg_state(seed: int) -> dict:
    """The PCG64 state (numpy's ``bit_generator.state`` dict) that starts the streams
    of object ``seed`` (a non-negative int below 2**128)."""
    state, inc = _pcg_words(seed)
    return _state_dict(state, inc)


def _pcg_words(seed: int) -> tuple[int, int]:
    """(state, odd increment) of :func:`pcg_state`, as 128-bit ints."""
    hit = _RECENT.get(seed)
    if hit is None:
        w0 = _splitmix64(_splitmix64(seed & _MASK) ^ ((seed >> 64) & _MASK))
        w1 = _splitmix64(w0)
        w2 = _splitmix64(w1)
        w3 = _splitmix64(w2)
        hit = (w0 << 64) | w1, ((w2 << 64) | w3) | 1
        if len(_RECENT) >= 16:
            _RECENT.clear()
        _RECENT[seed] = hit
    return hit


# The words of the last few seeds (about 4 µs of big-integer arithmetic each): an
# object's seed is hashed when it is generated and again when its points are drawn.
_RECENT: dict[int, tuple[int, int]] = {}


def _state_dict(state: int, inc: int) -> dict:
    return {
        "bit_generator": "PCG64",
        "state": {"state": state, "inc": inc},
        "has_uint32": 0,
        "uinteger": 0,
    }


# numpy's PCG64 steps its 128-bit state as state * _MULT + inc (mod 2**128), one step
# per 64-bit draw; n steps compose to state * A(n) + inc * S(n) with A and S
# independent of the state and the increment (pcg_advance_lcg_128, Brown 1994).
_MULT = (2549297995355413924 << 64) | 4865540595714422341
_MASK128 = (1 << 128) - 1
_JUMPS: dict[int, tuple[int, int]] = {}


def _jump(n: int) -> tuple[int, int]:
    """(A(n), S(n)): ``n`` PCG64 steps map state s to ``s * A + inc * S`` mod 2**128."""
    acc_mult, acc_plus, cur_mult, cur_plus = 1, 0, _MULT, 1
    while n:
        if n & 1:
            acc_mult = (acc_mult * cur_mult) & _MASK128
            acc_plus = (acc_plus * cur_mult + cur_plus) & _MASK128
        cur_plus = ((cur_mult + 1) * cur_plus) & _MASK128
        cur_mult = (cur_mult * cur_mult) & _MASK128
        n >>= 1
    return acc_mult, acc_plus


def _stream_jump(key: int) -> tuple[int, int]:
    """:func:`_jump` to the start of stream ``key`` (``key * 2**64`` steps), cached."""
    hit = _JUMPS.get(key)
    if hit is None:
        hit = _jump(key << 64)
        if len(_JUMPS) < 4096:  # stream keys are slot names: a few hundred at most
            _JUMPS[key] = hit
    return hit


def stream_state(seed: int, key: int) -> tuple[int, int]:
    """(state, odd increment), 128-bit ints, of numpy's PCG64 at the start of stream
    ``key`` of object ``seed``: what :meth:`Streams.open` sets."""
    state, inc = _pcg_words(int(seed))
    if key:
        a, b = _stream_jump(key)
        state = (state * a + inc * b) & _MASK128
    return state, inc


#: numpy's PCG64 multiplier (``PCG_DEFAULT_MULTIPLIER_128``).
PCG64_MULTIPLIER = _MULT


def state_view(bitgen: np.random.PCG64):
    """Writable views ``(words, flags)`` of a PCG64's C state, or None.

    ``words`` (4 uint64: state low, state high, increment low, increment high) and
    ``flags`` (``has_uint32``, ``uinteger``) are memoryviews of the bit generator's
    state memory (found through ``bitgen.ctypes``): assigning all their items is what
    assigning ``bitgen.state`` does. They are returned only when a round trip through
    numpy's ``state`` property confirms that layout (the bit generator is then left in
    an arbitrary state), else None. Keep ``bitgen`` alive as long as the views.
    """
    if type(bitgen) is not np.random.PCG64:
        return None
    try:
        import ctypes

        addr = bitgen.ctypes.state_address  # a pcg64_state: {pcg64_random_t *, int, uint32}
        words = (ctypes.c_uint64 * 4).from_address(ctypes.c_void_p.from_address(addr).value)
        flags = (ctypes.c_uint32 * 2).from_address(addr + ctypes.sizeof(ctypes.c_void_p))
        # memoryviews: item assignment costs less than on the ctypes arrays
        words, flags = memoryview(words).cast("B").cast("Q"), memoryview(flags).cast("B").cast("I")
    except (ImportError, AttributeError, TypeError, ValueError):  # pragma: no cover - no ctypes
        return None
    s, inc = (0x0123456789ABCDEF << 64) | 0xFEDCBA9876543210, (0x0F1E2D3C4B5A6978 << 64) | 0x8796A5B4C3D2E1F1
    probe = _state_dict(s, inc)
    probe["has_uint32"], probe["uinteger"] = 1, 0xDEADBEEF
    bitgen.state = probe
    if list(words) != [s & _MASK, s >> 64, inc & _MASK, inc >> 64] or list(flags) != [1, 0xDEADBEEF]:
        return None
    s, inc = inc - 1, s | 1
    words[0], words[1], words[2], words[3] = s & _MASK, s >> 64, inc & _MASK, inc >> 64
    flags[0] = flags[1] = 0
    return (words, flags) if bitgen.state == _state_dict(s, inc) else None


class Streams:
    """Opens the streams of one object on one borrowed bit generator.

    Only the most recently opened stream may be drawn from: opening another one
    rewinds the shared generator. Use as ``with streams(seed) as s: rng = s.open(key)``.

    Parameters
    ----------
    seed : int
        The object seed (0 <= seed < 2**128).
    bitgen : numpy.random.PCG64
        The bit generator the streams are opened on.
    gen : numpy.random.Generator, optional
        A generator on ``bitgen`` (made here when omitted).
    view : tuple, optional
        :func:`state_view` of ``bitgen``: the state is then written through it.
    scratch : dict, optional
        Kept in :attr:`scratch` (a new dict when omitted).

    Attributes
    ----------
    scratch : dict
        Scratch arrays for the users of these streams (the recorders of
        :meth:`artipg.rules.Category.generate` draw their blocks into them); kept with
        the pooled generator, so they outlive one object.
    """

    __slots__ = ("seed", "_words", "_bitgen", "_gen", "_view", "_inc", "scratch")

    def __init__(self, seed: int, bitgen: np.random.PCG64, gen: np.random.Generator | None = None,
                 view: tuple | None = None, scratch: dict | None = None):
        self.scratch = {} if scratch is None else scratch
        self.seed = int(seed)
        self._words = _pcg_words(self.seed)
        self._bitgen = bitgen
        self._gen = np.random.Generator(bitgen) if gen is None else gen
        self._view = view
        inc = self._words[1]
        self._inc = (inc & _MASK, inc >> 64)

    def open(self, key: int) -> np.random.Generator:
        """The generator positioned at the start of stream ``key`` (0 <= key < 2**32)."""
        state, inc = self._words
        if key:  # what bitgen.advance(key << 64) does, without its call overhead
            a, b = _stream_jump(key)
            state = (state * a + inc * b) & _MASK128
        view = self._view
        if view is None:
            self._bitgen.state = _state_dict(state, inc)
        else:
            # the same four words and zeroed 32-bit cache as the setter writes
            words, flags = view
            words[0] = state & _MASK
            words[1] = state >> 64
            words[2], words[3] = self._inc
            flags[0] = flags[1] = 0
        return self._gen


class streams:
    """Borrow a bit generator from this thread's pool for the streams of ``seed``.

    A context manager: ``with streams(seed) as s`` gives a :class:`Streams`. Nested use
    (an object generated while another is being generated) borrows a second
    generator, so the two never share state.
    """

    __slots__ = ("seed", "_pool", "_lent")

    def __init__(self, seed: int):
        self.seed = seed

    def __enter__(self) -> Streams:
        pool = getattr(_POOL, "free", None)
        if pool is None:
            pool = _POOL.free = []
        self._pool = pool
        # (Generator, its PCG64, state view, scratch arrays), kept together: making the
        # Generator costs as much as a draw, the view much more
        if pool:
            lent = pool.pop()
        else:
            bitgen = np.random.PCG64(0)
            lent = (np.random.Generator(bitgen), bitgen, state_view(bitgen), {})
        self._lent = lent
        try:
            return Streams(self.seed, lent[1], lent[0], lent[2], lent[3])
        except BaseException:
            pool.append(lent)
            raise

    def __exit__(self, *exc) -> None:
        self._pool.append(self._lent)
