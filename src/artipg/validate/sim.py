"""Simulator checks: the URDF loads in pybullet and MuJoCo and behaves.

For each engine (short simulations, a few hundred milliseconds per object):

- **load**: the URDF loads (MuJoCo through ``MjSpec``, so that a floor, a free joint
  and position servos can be added);
- **rest contacts**: with parent-child contacts turned on (pybullet
  ``URDF_USE_SELF_COLLISION | URDF_USE_SELF_COLLISION_INCLUDE_PARENT`` with
  ``getClosestPoints``; MuJoCo ``mjDSBL_FILTERPARENT``), no two links of the
  collision geometry penetrate deeper than the tolerance at rest: this is where a
  hollow body exported as one convex hull shows up;
- **drive**: with the root fixed, contacts frictionless and gravity off (so that only
  geometry can block a joint, not friction between touching parts or a servo too
  weak to lift a lid), position control drives all movable joints from rest to their
  upper limits and then back to their lower limits (continuous joints have no
  limits: they must turn a quarter turn either way, +-pi/2); each must get within
  ``joint_tol`` of its target. A joint that is still closing in on its target gets
  more time (up to three times ``drive_seconds``); one that stalls is blocked.
  Joints that miss are driven again alone, first with the others held at rest, then
  with the others opened first (a dishwasher rack comes out only past its open door):
  a joint is blocked when it misses both ways;
- **drop**: the object, free on a floor with its joints held rigidly at rest (made
  fixed in a copy of the URDF), settles for ``settle_seconds`` and then moves less
  than ``drift_tol`` in ``drop_seconds`` (largest displacement of the corners of the
  root link's bounding box); the engines' default contact filters apply here.
  Fixtures (``Category.fixed_base``: faucets, switches, doors, windows) are used
  mounted: they are not dropped, and ``info["drop"]`` says ``"fixed base"``.

Engine settings, each fixing a simulator artefact that would otherwise read as a
defect (they never relax a tolerance):

- pybullet pads every convex mesh with a 1 mm collision margin
  (:data:`artipg.validate.sim_pybullet.PYBULLET_MESH_MARGIN`, fixed for URDF links) and turns cylinders into
  padded 32-gon hulls: cylinders are loaded as exact shapes
  (``URDF_USE_IMPLICIT_CYLINDER``) and every mesh as its hull shrunk by the margin
  (:func:`artipg.validate.sim_pybullet.pybullet_urdf`), so that pybullet sees the exported geometry as MuJoCo does
  (pieces thinner than 2 mm keep part of the padding, which the rest-contact
  tolerance adds back, per link);
- pybullet keeps contact points from earlier steps until they drift 2 cm; a lid's edge
  sliding round a hinge barrel leaves stale points behind that jam it
  (:data:`artipg.validate.sim_pybullet.CONTACT_BREAKING`);
- a contact no joint can move along (a knuckle between its cheeks pressed along the
  hinge axis, a knob's back face on its panel, a cap on its neck) has zero effective
  mass: pybullet divides by it (:data:`artipg.validate.sim_pybullet.GLOBAL_CFM` regularises) and MuJoCo makes it
  infinitely stiff when the body cannot translate (:data:`artipg.validate.sim_mujoco.INVWEIGHT_FLOOR`); either
  way round-off turns the unbounded force into torque that flings the part.
"""


from __future__ import annotations

import tempfile
from pathlib import Path

from artipg.validate.report import CheckResult, Issue
from artipg.validate.sim_common import SimOptions, urdf_joints
from artipg.validate.sim_mujoco import run_mujoco
from artipg.validate.sim_pybullet import run_pybullet


def simulate_object(obj, opts: SimOptions = SimOptions(), fixed_base: bool | None = None) -> CheckResult:
    """Export ``obj`` (URDF + meshes) to a temporary folder and simulate it.

    ``fixed_base`` defaults to the registered category's policy
    (:func:`artipg.export.annotation.category_fixed_base`): fixtures are simulated mounted, not dropped.
    """
    from artipg.export.annotation import category_fixed_base
    from artipg.export.urdf import build_urdf, urdf_text

    if fixed_base is None:
        fixed_base = category_fixed_base(obj.category)

    robot, meshes = build_urdf(obj, visuals=False)
    with tempfile.TemporaryDirectory(prefix="artipg-sim-") as d:
        for rel, text in meshes.items():
            p = Path(d) / rel
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_text(text)
        urdf = Path(d) / "mobility.urdf"
        urdf.write_text(urdf_text(robot))
        return simulate_urdf(urdf, opts, fixed_base)


def simulate_urdf(urdf, opts: SimOptions = SimOptions(), fixed_base: bool = False) -> CheckResult:
    """Run the simulator checks on the URDF file ``urdf`` (see module docstring).

    Parameters
    ----------
    urdf : path
    opts : SimOptions
    fixed_base : bool
        The object is a fixture (mounted on a wall, a sink, in a frame): it is not
        dropped on a floor; ``info["drop"]`` says ``"fixed base"`` instead of giving a
        drift.
    """
    urdf = Path(urdf).resolve()
    joints = urdf_joints(urdf)
    issues, info = [], {"fixed_base": bool(fixed_base)}
    for engine in opts.engines:
        run = {"pybullet": run_pybullet, "mujoco": run_mujoco}[engine]
        try:
            eng_issues, eng_info = run(urdf, joints, opts, fixed_base)
        except Exception as e:  # an engine that cannot load the file is a failure, not a crash
            eng_issues, eng_info = [Issue("simulator", "load_failed", 1.0, detail=f"{engine}: {e}".strip()[:300])], {}
        issues += eng_issues
        info[engine] = eng_info
    return CheckResult("simulator", not issues, max([0.0] + [i.amount for i in issues]), issues, info)
