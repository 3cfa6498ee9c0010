"""Category rules: a DAG of part slots, traversed in topological order.

A category file declares its sub-categories (weighted) and its slots. Each slot is a
function ``build(ctx)`` that chooses templates, draws parameters through ``ctx.p`` and
attaches parts with ``ctx.builder``; it may read the outputs of the slots it depends
on from ``ctx.out``. Every slot gets its own random stream derived from (seed, slot
name), so adding or removing an optional part never changes the others.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from graphlib import TopologicalSorter
from typing import Any, Callable

from artipg.materials import CLASS_DENSITY
from artipg.model.articulation import ArticulatedObject
from artipg.model.builder import ObjectBuilder
from artipg.rules.detail import DEFAULT_DETAIL, DetailStream, parse_detail
from artipg.rules.params import ParamRecorder
from artipg.rules.streams import stream, stream_key


@dataclass(frozen=True)
class Slot:
    """A part slot: ``build(ctx)`` runs after every slot named in ``after``."""

    name: str
    build: Callable[["SlotContext"], Any]
    after: tuple[str, ...] = ()


@dataclass
class SlotContext:
    """What a slot's build function sees.

    Attributes
    ----------
    p : ParamRecorder
        Recorder scoped to the slot name, on the slot's own stream.
    sub : str
        The object's sub-category.
    out : dict
        Outputs (return values) of the slots built so far.
    builder : ObjectBuilder
        Link / joint assembly.
    templates : dict
        Records template choices (slot -> names); filled by :meth:`choose`.
    """

    p: ParamRecorder
    sub: str
    out: dict
    builder: ObjectBuilder
    templates: dict
    slot: str

    def choose(self, name: str, options, fixed=None):
        """Choose a part template (weighted dict or list) and record the choice."""
        t, chosen = self.p._pick(name, options, fixed)
        self.templates.setdefault(self.slot, []).append(chosen)
        return t

    def choose_detail(self, name: str, options, off):
        """Choose a detail template (weighted dict or list) from the slot's detail
        stream and record it; ``off`` (not recorded) when detail is off."""
        if self.p.detail == "off":
            return off
        t, chosen = self.p._detail_recorder()._pick(name, options)
        self.templates.setdefault(self.slot, []).append(chosen)
        return t


#: (id of a category, detail level) -> (category, its variant at that level)
_VARIANTS: dict = {}


@dataclass(frozen=True)
class Category:
    """A category's generation rule.

    Attributes
    ----------
    name : str
        snake_case category name.
    subcategories : dict
        {name: weight}.
    slots : tuple of Slot
        The part DAG.
    fixed_base : bool
        The object is a fixture, mounted in use (a faucet on a sink, a switch on a
        wall, a door or window in its wall opening): the simulator check holds its
        base fixed instead of dropping it on a floor.
    materials : dict
        {semantic label: material class} for parts of this category whose material
        differs from the default of their label (:data:`artipg.materials.MATERIAL`):
        a kettle body is plastic, not wood. Classes are the keys of
        :data:`artipg.materials.CLASS_DENSITY`.
    mass_range : (float, float)
        Plausible whole-object mass of real objects of the category, kg (generous:
        it catches a wrong material or a solid body that should be hollow, not
        small differences). The tests check every generated object against it.
    detail : str
        Geometric detail level of :meth:`generate` (:mod:`artipg.rules.detail`);
        :meth:`with_detail` gives the same category at another level.
    """

    name: str
    subcategories: dict
    slots: tuple
    fixed_base: bool = False
    materials: dict = field(default_factory=dict)
    mass_range: tuple = (0.0, float("inf"))
    detail: str = DEFAULT_DETAIL
    order: tuple = field(init=False)
    _keys: tuple = field(init=False, repr=False)

    def __post_init__(self):
        unknown = sorted(set(self.materials.values()) - set(CLASS_DENSITY))
        if unknown:
            raise ValueError(f"{self.name}: unknown material classes {unknown}; known: {sorted(CLASS_DENSITY)}")
        lo, hi = self.mass_range
        if not 0.0 <= lo < hi:
            raise ValueError(f"{self.name}: mass_range must satisfy 0 <= low < high, got {self.mass_range}")
        names = {s.name for s in self.slots}
        ts = TopologicalSorter()
        for s in self.slots:
            missing = set(s.after) - names
            if missing:
                raise ValueError(f"{self.name}: slot {s.name} depends on unknown {sorted(missing)}")
            ts.add(s.name, *s.after)
        by_name = {s.name: s for s in self.slots}
        # deterministic topological order: declaration order among ready slots
        ts.prepare()
        order = []
        decl = [s.name for s in self.slots]
        while ts.is_active():
            ready = sorted(ts.get_ready(), key=decl.index)
            for r in ready:
                order.append(by_name[r])
                ts.done(r)
        object.__setattr__(self, "order", tuple(order))
        object.__setattr__(self, "_keys", tuple(stream_key(s.name) for s in order))
        object.__setattr__(self, "detail", parse_detail(self.detail))

    def with_detail(self, detail: str | None) -> "Category":
        """This category at detail level ``detail`` (None: the default); the variant is
        made once and kept, so repeated calls cost a dict look-up."""
        d = parse_detail(detail)
        if d == self.detail:
            return self
        key = (id(self), d)
        hit = _VARIANTS.get(key)
        if hit is None or hit[0] is not self:
            hit = _VARIANTS[key] = (self, replace(self, detail=d))
        return hit[1]

    def generate(self, seed: int, overrides: dict | None = None) -> ArticulatedObject:
        """Build the object for ``seed`` (with optional parameter overrides) at this
        category's detail level (:meth:`with_detail` gives another)."""
        mode = self.detail
        fine = mode != "off"
        record: dict = {}
        templates: dict = {}
        overrides = overrides or {}
        top = ParamRecorder(stream(seed, 0), record, overrides)
        sub = top.choice("subcategory", self.subcategories)
        builder = ObjectBuilder(record)
        out: dict = {}
        for slot, key in zip(self.order, self._keys):
            name = slot.name
            ctx = SlotContext(ParamRecorder(stream(seed, key), record, overrides, name,
                                            DetailStream(mode, seed, key) if fine else None),
                              sub, out, builder, templates, name)
            out[name] = slot.build(ctx)
        obj = builder.build(self.name, sub, seed, record, templates)
        obj.materials = self.materials
        return obj
