"""The framework's batched fast paths give the bits of the plain computations they replace."""

from __future__ import annotations

import numpy as np
import pytest

import artipg


def same(a, b) -> bool:
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and np.ascontiguousarray(a).tobytes() == \
        np.ascontiguousarray(b).tobytes()


CATS = artipg.categories()


@pytest.mark.parametrize("category", CATS)
def test_part_bounds_is_the_union_of_the_primitive_bounds(category):
    for seed in range(3):
        for part in artipg.generate(category, seed).parts:
            b = np.array([p.bounds() for p in part.primitives])
            plain = np.stack([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])
            assert same(part.bounds(), plain), part.name
