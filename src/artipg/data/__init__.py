"""Datasets built from artipg output: the index of an output folder (:mod:`artipg.data.index`)
and the run engine that writes folders in worker processes (:mod:`artipg.data.engine`).

This package also ships ``fid_pointnet.npz`` (the FID encoder of :mod:`artipg.metrics`).
"""
