"""Exact annotations at any joint state (see ``docs/annotations.md``).

Modules, one job each:

- :mod:`~artipg.annotate.points`: area-uniform labelled surface sampling (semantic,
  instance, link, primitive);
- :mod:`~artipg.annotate.knowledge`: per-object lookup tables of the templates'
  region, pose and class knowledge (cached);
- :mod:`~artipg.annotate.labels`: per-point actionable class, affordance masks, part
  and object NPCS; part poses (:func:`~artipg.annotate.labels.part_frames`);
- :mod:`~artipg.annotate.grasps`: grasp poses in the object frame, gripper collision
  check, opening directions;
- :mod:`~artipg.annotate.sdf`: signed distance to the object from primitive SDFs;
- :mod:`~artipg.annotate.mesh` and :mod:`~artipg.annotate.views`: labelled ray-cast
  views, depth, back-projected partial clouds;
- :mod:`~artipg.annotate.align`: label transfer to off-surface points;
- :mod:`~artipg.annotate.arrays`: all of it as the arrays of ``points.npz`` /
  ``views.npz``.
"""
