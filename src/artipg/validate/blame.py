"""Which recorded parameters are to blame for a fault, from narrow to wide.

Every part remembers the span of the parameter record that was drawn to build it
(:attr:`artipg.model.part.Part.param_span`, set by ``LinkBuilder.add``). Parameter
names are scoped by dots (``fronts.cell3.door0.thickness``), so a fault can be
blamed on ever wider sets of parameters:

- level 0: the parameters drawn for the parts at fault;
- level k >= 1: every parameter in the scope of those, widened k - 1 times
  (``fronts.cell3.door0.*``, then ``fronts.cell3.*``, then ``fronts.*``), until
  the whole object (except its sub-category) is in play.

Only parameters that an override can change are returned: uniform, integer,
choice and flag draws (``fixed`` values follow from their parents).
"""

from __future__ import annotations

PERTURBABLE = ("uniform", "integer", "choice", "flag")
#: Never perturbed: changing it makes a different kind of object.
FROZEN = ("subcategory",)


def part_params(obj) -> dict[str, list[str]]:
    """Part name -> names of the perturbable parameters drawn to build it."""
    names = list(obj.params)
    out = {}
    for part in obj.parts:
        a, b = getattr(part, "param_span", (0, 0))
        out[part.name] = [n for n in names[a:b] if _perturbable(obj.params[n])]
    return out


def _perturbable(p) -> bool:
    return p.kind in PERTURBABLE and p.name not in FROZEN and not (p.kind == "uniform" and p.hi <= p.lo)


def _scope(name: str) -> str:
    return name.rsplit(".", 1)[0] if "." in name else ""


def blame(obj, part_names, level: int) -> list[str]:
    """Perturbable parameters to blame for faults of ``part_names`` at ``level``.

    Returns a sorted list; empty when nothing is perturbable at that level (the
    caller widens). Parts that drew nothing of their own are blamed, from level 1
    on, through the draws of the other parts of their links.
    """
    per_part = part_params(obj)
    own = sorted({n for p in part_names for n in per_part.get(p, [])})
    if level == 0:
        return own
    if not own:
        links = {int(obj.part_link[i]) for i, p in enumerate(obj.parts) if p.name in set(part_names)}
        own = sorted({n for i, p in enumerate(obj.parts) if int(obj.part_link[i]) in links for n in per_part[p.name]})
    prefixes = set()
    for n in own:
        s = _scope(n)
        for _ in range(level - 1):
            s = _scope(s)
        prefixes.add(s)
    every = [n for n, p in obj.params.items() if _perturbable(p)]
    if "" in prefixes:
        return sorted(every)
    return sorted(n for n in every if any(n.startswith(pre + ".") for pre in prefixes))


def max_level(obj) -> int:
    """Level at which :func:`blame` has widened to every parameter."""
    depth = max((n.count(".") for n in obj.params), default=0)
    return depth + 2
