"""The learned detail bridge (optional, needs torch: the ``learn`` extra).

- :mod:`~artipg.detail.pairs`        (structure, detailed) training pairs from fitted twins;
- :mod:`~artipg.detail.model`        the conditional flow-matching model over per-point offsets;
- :mod:`~artipg.detail.training`     training it;
- :mod:`~artipg.detail.application`  applying it to a labelled cloud, with the drift bounded.

See ``docs/detail_learned.md``.
"""
