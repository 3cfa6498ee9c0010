"""Validate one artipg object: geometric checks, optionally the simulators."""

from __future__ import annotations

import numpy as np

from artipg.validate.blame import part_params
from artipg.validate.checks import Tolerances, run_checks
from artipg.validate.kinematics import Kinematics
from artipg.validate.report import Report
from artipg.validate.shapes import Pieces, stream_seed

#: Seed of the surface-sample stream, the same for every object: a check's result
#: depends on the geometry only, not on the seed an object carries.
SAMPLE_STREAM = 0x5A3B1E
#: The sample-stream seed that ``np.random.default_rng(SAMPLE_STREAM)`` gives
#: :class:`Pieces` (drawn once, here).
_SAMPLE_SEED = stream_seed(np.random.default_rng(SAMPLE_STREAM))


def check_object(obj, tol: Tolerances = Tolerances(), simulate: bool = False, sim_options=None,
                 fixed_base: bool | None = None) -> Report:
    """Run the validation checks on an :class:`artipg.model.ArticulatedObject`.

    Parameters
    ----------
    obj : ArticulatedObject
    tol : Tolerances
        Geometric thresholds (metres).
    simulate : bool
        Also export the object to a temporary folder and run the simulator checks
        (pybullet and MuJoCo; see :mod:`artipg.validate.sim`).
    sim_options : artipg.validate.sim.SimOptions, optional
    fixed_base : bool, optional
        Simulate the object mounted (its root fixed) instead of dropping it on a floor;
        by default its category's ``fixed_base`` policy (fixtures: faucets, switches,
        doors, windows).

    Returns
    -------
    Report
        ``penetration``, ``floating`` and ``joint_sweep`` results (and ``simulator``),
        each issue naming the links, parts and recorded parameters at fault.
    """
    checks = run_checks(Kinematics.of(obj), Pieces.of(obj, _SAMPLE_SEED), tol)
    if any(c.issues for c in checks.values()):
        blame = part_params(obj)
        for c in checks.values():
            for issue in c.issues:
                issue.params = sorted({n for p in issue.parts for n in blame.get(p, [])})
    report = Report(checks, tol.to_json())
    if simulate:
        from artipg.validate.sim import SimOptions, simulate_object

        report.checks["simulator"] = simulate_object(obj, sim_options or SimOptions(), fixed_base)
    return report
