"""Shared fixtures: the registered categories and the seeds tests sweep over."""

from __future__ import annotations

import numpy as np
import pytest

import artipg

CATEGORIES = artipg.categories()
#: Seeds every per-category property is checked on (the issue asks for 0..49).
SEEDS = tuple(range(50))


@pytest.fixture(scope="session")
def tmp_out(tmp_path_factory):
    return tmp_path_factory.mktemp("out")


def open_qpos(obj, frac: float = 1.0) -> dict:
    """Every movable joint at ``frac`` of its range (continuous: frac * pi)."""
    q = {}
    for j, (lo, hi) in zip(obj.movable_joints, obj.limits()):
        q[j.name] = lo + frac * (hi - lo) if np.isfinite(hi) else frac * np.pi
    return q
