"""artipg: procedural articulated objects with exact annotations (ArtiPG++)."""

from __future__ import annotations

__version__ = "0.1.0"


def categories() -> list[str]:
    """Names of all registered categories, sorted."""
    from artipg.categories import REGISTRY

    return sorted(REGISTRY)


def get_category(name: str):
    """The :class:`artipg.rules.Category` registered as ``name``.

    Raises
    ------
    KeyError
        With the list of valid names when ``name`` is unknown.
    """
    from artipg.categories import REGISTRY

    try:
        return REGISTRY[name]
    except KeyError:
        raise KeyError(f"unknown category {name!r}; valid: {', '.join(sorted(REGISTRY))}") from None


def generate(category: str, seed: int = 0, overrides: dict | None = None):
    """Generate the object of ``category`` for ``seed``.

    Parameters
    ----------
    category : str
        A name from :func:`categories`.
    seed : int
        Non-negative seed; (category, seed, version) determines the object.
    overrides : dict, optional
        Recorded-parameter name -> value, clamped to the valid range.

    Returns
    -------
    artipg.model.ArticulatedObject
    """
    if int(seed) < 0:
        raise ValueError(f"seed must be >= 0, got {seed}")
    return get_category(category).generate(int(seed), overrides)


__all__ = ["__version__", "categories", "generate", "get_category"]
