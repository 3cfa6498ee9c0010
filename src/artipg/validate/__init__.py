"""Physical validation of articulated objects and their repair.

- :func:`check_object`: penetration at rest, floating links / parts, joint sweeps
  (and, with ``simulate=True``, pybullet and MuJoCo checks) on an artipg object;
- :func:`generate_valid`: generate an object and repair it by simulated annealing
  over its recorded parameters (fresh sample from a derived seed as a last resort);
- :func:`validate_folder`: the same checks on an object folder on disk, artipg's
  or PartNet-Mobility style (``mobility.urdf`` + meshes).
"""

from artipg.validate.api import check_object
from artipg.validate.checks import Tolerances
from artipg.validate.repair import RepairBudget, generate_valid, replacement_seed
from artipg.validate.report import CHECKS, CheckResult, Issue, Report

__all__ = ["check_object", "generate_valid", "replacement_seed", "RepairBudget", "Tolerances", "CHECKS",
           "CheckResult", "Issue", "Report"]
