"""Procedural twins of real objects: search our generator for the sub-category, template
choices and parameter values whose object best matches an object folder.

- :mod:`artipg.fit.labels` PartNet-Mobility's category and link names -> ours;
- :mod:`artipg.fit.shape`  what is compared: normalised clouds at a few joint states, links, joints;
- :mod:`artipg.fit.score`  the distance of a candidate to the target (links matched by semantics);
- :mod:`artipg.fit.search` restarts over seeds per sub-category, then sweep + annealing over overrides;
- :mod:`artipg.fit.api`    :func:`fit_object` -> :class:`FitResult`, :func:`write_twin`.
"""

from artipg.fit.api import FitResult, fit_object, write_twin
from artipg.fit.search import FitBudget

__all__ = ["FitBudget", "FitResult", "fit_object", "write_twin"]
