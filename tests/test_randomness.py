"""No hidden randomness: a source scan bans global random state in the package."""

from __future__ import annotations

import re
from pathlib import Path

import artipg

SRC = Path(artipg.__file__).parent
BANNED = [
    (re.compile(r"^\s*(import random|from random import)", re.M), "the random module"),
    (re.compile(r"np\.random\.(?!default_rng|Generator|SeedSequence|PCG64)[a-z_]+\("), "numpy's global random functions"),
    (re.compile(r"numpy\.random\.(?!default_rng|Generator|SeedSequence|PCG64)[a-z_]+\("), "numpy's global random functions"),
    (re.compile(r"\buuid\b"), "uuid"),
    (re.compile(r"\btime\.time\(|datetime\.now\("), "wall-clock time"),
]
#: Modules that may read the clock (progress and benchmarks, not generation).
CLOCK_OK = {"commands", "metrics"}


def test_source_has_no_global_randomness():
    problems = []
    for path in SRC.rglob("*.py"):
        text = path.read_text()
        for rx, what in BANNED:
            if what == "wall-clock time" and path.parent.name in CLOCK_OK:
                continue
            for m in rx.finditer(text):
                line = text[: m.start()].count("\n") + 1
                problems.append(f"{path.relative_to(SRC)}:{line} uses {what}")
    assert not problems, "\n".join(problems)


def test_every_category_module_is_registered():
    from artipg.categories import REGISTRY

    modules = {p.stem for p in (SRC / "categories").glob("*.py") if p.stem != "__init__"}
    registered = {rule.__module__ if hasattr(rule, "__module__") else "" for rule in REGISTRY.values()}
    names = set(REGISTRY)
    assert modules == names, f"unregistered: {sorted(modules - names)}; stray: {sorted(names - modules)}"
    assert registered
