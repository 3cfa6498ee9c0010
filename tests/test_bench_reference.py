"""The benchmark's yardstick (benchmarks/reference_cabinet.py) does what it says: 13
boxes, area-uniform points on their surfaces with outward normals and box labels."""

import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from reference_cabinet import cabinet_boxes, reference_object, sample_cabinet  # noqa: E402


@pytest.mark.parametrize("seed", [0, 1, 7])
def test_points_lie_on_the_boxes_with_outward_normals(seed):
    centre, half, label = cabinet_boxes(np.random.default_rng(seed))
    assert centre.shape == half.shape == (13, 3) and (half > 0).all()
    pts, nrm, box, lab = sample_cabinet(centre, half, label, 4096, np.random.default_rng(seed))
    local = (pts - centre[box]) / half[box]
    assert np.abs(local).max() <= 1 + 1e-12
    # on the face the normal names: the coordinate along it is exactly +-1, its sign the normal's
    np.testing.assert_allclose((local * nrm).sum(axis=1), 1.0)
    np.testing.assert_array_equal(np.abs(nrm).sum(axis=1), 1.0)
    np.testing.assert_array_equal(lab, label[box])


def test_points_per_box_follow_area():
    centre, half, label = cabinet_boxes(np.random.default_rng(3))
    n = 200_000
    _, _, box, _ = sample_cabinet(centre, half, label, n, np.random.default_rng(4))
    area = 8 * (half[:, 0] * half[:, 1] + half[:, 1] * half[:, 2] + half[:, 0] * half[:, 2])
    expected = n * area / area.sum()
    counts = np.bincount(box, minlength=13)
    assert (np.abs(counts - expected) <= 5 * np.sqrt(expected) + 1).all()


def test_reference_is_deterministic():
    a, b = reference_object(5), reference_object(5)
    for x, y in zip(a, b):
        np.testing.assert_array_equal(x, y)
