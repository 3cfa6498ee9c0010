"""artipg: procedural articulated objects with exact annotations (ArtiPG++)."""

from __future__ import annotations

__version__ = "0.2.0"

# Import the registry package *before* defining the function of the same name: the
# import binds the attribute ``artipg.categories`` to the sub-package once, and the
# definition below then replaces it with the public function for good.
from artipg.categories import REGISTRY as _REGISTRY  # noqa: E402


def categories() -> list[str]:
    """Names of all registered categories, sorted."""
    return sorted(_REGISTRY)


def get_category(name: str):
    """The :class:`artipg.rules.Category` registered as ``name``.

    Raises
    ------
    KeyError
        With the list of valid names when ``name`` is unknown.
    """
    try:
        return _REGISTRY[name]
    except KeyError:
        raise KeyError(f"unknown category {name!r}; valid: {', '.join(sorted(_REGISTRY))}") from None


def generate(category: str, seed: int = 0, overrides: dict | None = None, validate: bool = False,
             simulate: bool = False, detail: str | None = None):
    """Generate the object of ``category`` for ``seed``.

    Parameters
    ----------
    category : str
        A name from :func:`categories`.
    seed : int
        Non-negative seed; (category, seed, version) determines the object.
    overrides : dict, optional
        Recorded-parameter name -> value, clamped to the valid range.
    validate : bool
        Check the object (penetration, floating parts, joint sweeps) and repair it
        when a check fails (:func:`artipg.validate.generate_valid`): the object
        ``artipg generate`` writes, with its validation report (checks, repair log)
        in ``obj.report``. Off by default, so a plain call stays a sub-millisecond
        draw with an empty ``obj.report``; an object that passes its checks has the
        same geometry either way, one that fails is only repaired with ``validate``.
    simulate : bool
        With ``validate``, also require the pybullet / MuJoCo checks (the CLI's ``--sim``).
    detail : {"procedural", "off"}, optional
        Geometric detail (``docs/detail.md``): ``"procedural"`` (the default) rounds
        edges, lips and handles and draws door styles as template options; ``"off"``
        gives the sharp structure (sharp boxes, bare rims) with every other parameter
        the same.

    Returns
    -------
    artipg.model.ArticulatedObject
    """
    if int(seed) < 0:
        raise ValueError(f"seed must be >= 0, got {seed}")
    rule = get_category(category)
    if detail is not None:
        rule = rule.with_detail(detail)
    if validate:
        from artipg.validate import generate_valid

        return generate_valid(rule, int(seed), overrides, simulate=simulate)
    if simulate:
        raise ValueError("simulate=True needs validate=True")
    return rule.generate(int(seed), overrides)


__all__ = ["__version__", "categories", "generate", "get_category"]
