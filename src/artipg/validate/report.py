"""Validation results: issues, per-check results and the object's report.

Everything here turns into plain JSON (``to_json``) for ``annotation.json`` and the
``artipg validate --json`` report. Values are metres / radians, rounded to 0.1 µm so
that the same object always gives the same bytes.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

#: Order in which checks are run and reported.
CHECKS = ("penetration", "floating", "joint_sweep", "simulator")


def rnd(x, nd: int = 7):
    """Round floats (nested) for stable JSON; numpy scalars become Python numbers."""
    if isinstance(x, dict):
        return {k: rnd(v, nd) for k, v in x.items()}
    if isinstance(x, (list, tuple, np.ndarray)):
        return [rnd(v, nd) for v in x]
    if isinstance(x, (float, np.floating)):
        if not np.isfinite(x):
            return None
        v = round(float(x), nd)
        return 0.0 if v == 0 else v
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.bool_):
        return bool(x)
    return x


@dataclass
class Issue:
    """One fault: what is wrong, where, and by how much.

    Attributes
    ----------
    check : str
        Name of the check that found it (see :data:`CHECKS`).
    kind : str
        ``penetration``, ``floating_link``, ``floating_part``, ``sweep_penetration``,
        ``open_penetration`` or a simulator failure kind.
    amount : float
        Penetration depth or gap in metres (joint error in the joint's unit for
        simulator joint failures); the repair penalty adds these up.
    links, parts : list of str
        The links / parts at fault.
    joint : str or None
        The joint being moved (sweeps, simulator joint checks).
    q : float or None
        The joint value at which the fault is worst.
    point : list of float or None
        Where (object frame, metres), for penetrations.
    detail : str
        A short human-readable explanation.
    params : list of str
        Recorded parameters that built the parts at fault (artipg objects only):
        what repair perturbs first.
    """

    check: str
    kind: str
    amount: float
    links: list = field(default_factory=list)
    parts: list = field(default_factory=list)
    joint: str | None = None
    q: float | None = None
    point: list | None = None
    detail: str = ""
    params: list = field(default_factory=list)

    def to_json(self) -> dict:
        d = {"kind": self.kind, "amount": self.amount, "links": self.links, "parts": self.parts}
        if self.params:
            d["params"] = self.params
        if self.joint is not None:
            d["joint"] = self.joint
        if self.q is not None:
            d["q"] = self.q
        if self.point is not None:
            d["point"] = self.point
        if self.detail:
            d["detail"] = self.detail
        return rnd(d)


@dataclass
class CheckResult:
    """Outcome of one check: ``ok``, the worst measured value and the issues."""

    name: str
    ok: bool
    worst: float = 0.0
    issues: list = field(default_factory=list)
    info: dict = field(default_factory=dict)

    def to_json(self) -> dict:
        d = {"ok": bool(self.ok), "worst": rnd(self.worst), "issues": [i.to_json() for i in self.issues]}
        if self.info:
            d["info"] = rnd(self.info)
        return d


@dataclass
class Report:
    """All check results of one object, plus what repair did (if it ran)."""

    checks: dict = field(default_factory=dict)
    tolerances: dict = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return all(c.ok for c in self.checks.values())

    @property
    def issues(self) -> list:
        return [i for c in self.checks.values() for i in c.issues]

    def penalty(self) -> float:
        """Total of the geometric issues' amounts (metres): the repair objective."""
        return float(sum(i.amount for c in self.checks.values() if c.name != "simulator" for i in c.issues))

    def failed(self) -> list[str]:
        return [n for n in CHECKS if n in self.checks and not self.checks[n].ok]

    def to_json(self) -> dict:
        return {"ok": self.ok, "checks": {n: self.checks[n].to_json() for n in CHECKS if n in self.checks},
                "tolerances": rnd(self.tolerances)}
