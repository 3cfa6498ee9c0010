"""Independent random streams keyed by (object seed, slot name), cheap to open.

``np.random.default_rng([seed, key])`` hashes its seed through a ``SeedSequence``,
which costs about 30 µs: a third of a millisecond for an object with ten slots. Here
the seed is hashed once with SplitMix64 into a 128-bit PCG64 state and an odd 128-bit
increment, written straight into a bit generator borrowed from a per-thread pool, and
stream ``key`` (a 32-bit integer) starts ``key * 2**64`` draws further along that
sequence (PCG64 jumps ahead in O(log n); the jump's two constants are computed once per
key and the jumped state written directly): streams never overlap within 2**64 draws,
opening one costs about 2 µs, and each depends only on (seed, key), never on the order
in which streams are opened.
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
    w0 = _splitmix64(_splitmix64(seed & _MASK) ^ ((seed >> 64) & _MASK))
    w1 = _splitmix64(w0)
    w2 = _splitmix64(w1)
    w3 = _splitmix64(w2)
    return (w0 << 64) | w1, ((w2 << 64) | w3) | 1


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


class Streams:
    """Opens the streams of one object on one borrowed bit generator.

    Only the most recently opened stream may be drawn from: opening another one
    rewinds the shared generator. Use as ``with streams(seed) as s: rng = s.open(key)``.
    """

    def __init__(self, seed: int, bitgen: np.random.PCG64, gen: np.random.Generator | None = None):
        self.seed = int(seed)
        self._words = _pcg_words(self.seed)
        self._bitgen = bitgen
        self._gen = np.random.Generator(bitgen) if gen is None else gen

    def open(self, key: int) -> np.random.Generator:
        """The generator positioned at the start of stream ``key`` (0 <= key < 2**32)."""
        state, inc = self._words
        if key:  # what bitgen.advance(key << 64) does, without its call overhead
            a, b = _stream_jump(key)
            state = (state * a + inc * b) & _MASK128
        self._bitgen.state = _state_dict(state, inc)
        return self._gen


class streams:
    """Borrow a bit generator from this thread's pool for the streams of ``seed``.

    A context manager: ``with streams(seed) as s`` gives a :class:`Streams`. Nested use
    (an object generated while another is being generated) borrows a second
    generator, so the two never share state.
    """

    __slots__ = ("seed", "_pool", "_gen")

    def __init__(self, seed: int):
        self.seed = seed

    def __enter__(self) -> Streams:
        pool = getattr(_POOL, "free", None)
        if pool is None:
            pool = _POOL.free = []
        self._pool = pool
        # a Generator on a PCG64, kept together: making the Generator costs as much as a draw
        self._gen = pool.pop() if pool else np.random.Generator(np.random.PCG64(0))
        try:
            return Streams(self.seed, self._gen.bit_generator, self._gen)
        except BaseException:
            pool.append(self._gen)
            raise

    def __exit__(self, *exc) -> None:
        self._pool.append(self._gen)
