"""PNG plots of structure statistics (matplotlib, headless)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from artipg.metrics.structure import JOINT_BINS, joint_histogram


def _pyplot():
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    return plt


def plot_joint_histograms(structures: dict, path: str | Path, title: str = "") -> Path:
    """Grouped bar chart of the joint-count frequencies (0..9, 10+) of one or more sets,
    as in the paper's Fig. 4.

    Parameters
    ----------
    structures : dict
        {set label: sequence of :class:`~artipg.metrics.structure.ObjectStructure`}.
    path : str or Path
        PNG file to write (parent folders are created).
    title : str

    Returns
    -------
    Path
    """
    plt = _pyplot()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(7, 3.6), dpi=110)
    x = np.arange(len(JOINT_BINS))
    width = 0.8 / max(1, len(structures))
    for k, (label, objs) in enumerate(structures.items()):
        h = joint_histogram([o.n_joints for o in objs])
        ax.bar(x + (k - (len(structures) - 1) / 2) * width, 100 * h, width, label=f"{label} (n={len(objs)})")
    ax.set_xticks(x, JOINT_BINS)
    ax.set_xlabel("movable joints per object")
    ax.set_ylabel("objects (%)")
    ax.set_title(title or "joint counts")
    ax.legend(frameon=False)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path


def plot_sizes(structures: dict, path: str | Path, title: str = "") -> Path:
    """Histograms of bounding-box depth (x), width (y), height (z) and diagonal at the
    rest pose, one panel each, sets overlaid.

    Parameters
    ----------
    structures : dict
        {set label: sequence of ObjectStructure}.
    path : str or Path
        PNG file to write.
    title : str

    Returns
    -------
    Path
    """
    plt = _pyplot()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig, axes = plt.subplots(1, 4, figsize=(12, 3.2), dpi=110)
    data = {label: np.array([o.extents for o in objs], dtype=float).reshape(-1, 3) for label, objs in structures.items()}
    names = ("depth x (m)", "width y (m)", "height z (m)", "diagonal (m)")
    for i, ax in enumerate(axes):
        cols = {lb: (e[:, i] if i < 3 else np.linalg.norm(e, axis=1)) for lb, e in data.items()}
        allv = np.concatenate([v for v in cols.values() if len(v)] or [np.zeros(1)])
        bins = np.linspace(allv.min(), allv.max() + 1e-9, 21)
        for lb, v in cols.items():
            ax.hist(v, bins=bins, alpha=0.55, label=lb)
        ax.set_xlabel(names[i])
    axes[0].set_ylabel("objects")
    axes[0].legend(frameon=False, fontsize=8)
    fig.suptitle(title or "sizes at rest pose")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path
