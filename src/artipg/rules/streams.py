"""Independent random streams keyed by (object seed, stream name), from numpy only.

Stream ``key`` of object ``seed`` is a ``numpy.random.Generator`` on a PCG64 seeded by
``SeedSequence(entropy=seed, spawn_key=(key,))``: numpy's own hashing keeps the streams
of one seed independent, and each depends only on (seed, key), never on which other
streams are opened or in what order (so toggling one slot never changes another).
"""

from __future__ import annotations

import zlib

import numpy as np


def stream_key(name: str) -> int:
    """A stable 32-bit key for a stream name (CRC-32 of its UTF-8 bytes)."""
    return zlib.crc32(name.encode())


def stream(seed: int, key: int) -> np.random.Generator:
    """The generator of stream ``key`` (an int >= 0) of object ``seed`` (an int >= 0)."""
    return np.random.Generator(np.random.PCG64(np.random.SeedSequence(entropy=int(seed), spawn_key=(int(key),))))
