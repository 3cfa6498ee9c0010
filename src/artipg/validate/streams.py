"""Uniform sample streams served from a shared cache.

Every object's surface samples come from the streams ``np.random.default_rng([seed,
key])`` of one fixed seed (:data:`artipg.validate.api.SAMPLE_STREAM`) and a small
key (a geometry template's index in the object): the same few streams for every
object. :class:`UniformStream` hands out their doubles from a cache instead of
seeding a generator per object and template (about 30 µs each) and drawing again.

``UniformStream(seed, key).random(size)`` returns exactly what the generator's
``random(size)`` calls would return in the same order: ``Generator.random`` fills
its output in C order with one 64-bit draw per double, so consecutive calls read
consecutive stretches of one sequence.
"""

from __future__ import annotations

import threading
from collections import OrderedDict

import numpy as np

#: Doubles kept per stream at most (8 bytes each: 2 MiB, so at most 64 MiB for all
#: streams); draws beyond come from a generator advanced to their position. Objects
#: of the registered categories use at most about 75 000 per stream.
_CAP = 1 << 18
#: Streams kept (least recently used ones are dropped beyond).
_STREAMS = 32

_lock = threading.Lock()
_cache: OrderedDict = OrderedDict()  # (seed, key) -> [generator, read-only buffer]


def _buffer(seed: int, key: int, n: int) -> np.ndarray:
    """The first ``min(n, _CAP)`` doubles (at least) of stream ``(seed, key)``, read-only."""
    with _lock:
        entry = _cache.get((seed, key))
        if entry is None:
            entry = [np.random.default_rng([seed, key]), np.zeros(0)]
            _cache[(seed, key)] = entry
            while len(_cache) > _STREAMS:
                _cache.popitem(last=False)
        else:
            _cache.move_to_end((seed, key))
        gen, buf = entry
        if len(buf) < min(n, _CAP):
            grow = min(max(n, 2 * len(buf), 4096), _CAP) - len(buf)
            buf = np.concatenate([buf, gen.random(grow)])
            buf.setflags(write=False)
            entry[1] = buf
        return buf


class UniformStream:
    """Stands in for ``np.random.default_rng([seed, key])`` where only ``random`` is
    called: the same doubles in the same order, read from the shared cache.

    Parameters
    ----------
    seed, key : int
        The stream's seed words.

    Arrays handed out are read-only views of the cache (callers must not write
    into them).
    """

    def __init__(self, seed: int, key: int):
        self.seed = int(seed)
        self.key = int(key)
        self.pos = 0  # doubles consumed so far
        self._buf = _buffer(self.seed, self.key, 0)

    def random(self, size=None):
        """Uniform doubles in [0, 1) of shape ``size`` (int or tuple), like
        :meth:`numpy.random.Generator.random`."""
        if size is None:
            return float(self.random(1)[0])
        shape = (size,) if isinstance(size, (int, np.integer)) else tuple(size)
        n = 1
        for s in shape:
            n *= int(s)
        start, end = self.pos, self.pos + n
        self.pos = end
        if end <= _CAP:
            if end > len(self._buf):
                self._buf = _buffer(self.seed, self.key, end)
            return self._buf[start:end].reshape(shape)
        gen = np.random.default_rng([self.seed, self.key])  # far beyond the cache: rare
        gen.bit_generator.advance(start)
        return gen.random(shape)
