"""Parts: the instances of part templates, with their analytic knowledge."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from artipg.geometry.base import Primitive, corners_bounds_union
from artipg.geometry.transforms import IDENTITY
from artipg.vocabulary import ACTIONABLE_ID, AFFORDANCES, LABEL_ID, label_id


class _Factory:
    """Default of a field that gets a fresh empty container (shown as in dataclasses)."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "<factory>"


_FACTORY = _Factory()
_zeros = np.zeros


# Region and Grasp: frozen dataclasses with hand-written __init__ (init=False) that fill
# the instance dict directly: the generated one calls object.__setattr__ per field (and
# a factory per default), and templates make a dozen of them per object.
@dataclass(frozen=True, init=False)
class Region:
    """An analytic surface region of a part (affordance knowledge).

    A surface point of the part belongs to the region when it lies on a primitive whose
    role is in ``roles`` (any primitive when ``roles`` is empty) and, if ``box`` is
    given, inside that axis-aligned box (2, 3) of the part frame.
    """

    roles: tuple[str, ...] = ()
    box: np.ndarray | None = None

    def __init__(self, roles: tuple[str, ...] = (), box: np.ndarray | None = None):
        d = self.__dict__
        d["roles"] = roles
        d["box"] = box


@dataclass(frozen=True, init=False)
class Grasp:
    """A parallel-jaw grasp in the part frame.

    ``pose`` (4, 4): gripper frame with +z the approach direction (towards the part) and
    +y the jaw-closing axis, origin between the finger tips. ``width`` is the opening in
    metres. ``open_dir`` (3,) is the direction that opens the part, or zeros (a fresh
    array when omitted).
    """

    pose: np.ndarray
    width: float
    open_dir: np.ndarray = field(default_factory=lambda: np.zeros(3))

    def __init__(self, pose: np.ndarray, width: float, open_dir: np.ndarray = _FACTORY):
        d = self.__dict__
        d["pose"] = pose
        d["width"] = width
        d["open_dir"] = _zeros(3) if open_dir is _FACTORY else open_dir


class Deferred:
    """``fn(*args)``, computed on the first call and then kept.

    Knowledge that generation and point sampling never read (grasps) is passed to
    :class:`Part` as a ``Deferred`` and built when first asked for. The arguments are
    kept until then, so they must not be mutated in between (pass numbers, or arrays no
    one changes). Copies of a part share the ``Deferred``, hence the one list it builds.
    """

    __slots__ = ("fn", "args", "value")

    def __init__(self, fn, *args):
        self.fn, self.args, self.value = fn, args, None

    def __call__(self):
        if self.fn is not None:
            self.value = self.fn(*self.args)
            self.fn = self.args = None
        return self.value

    @classmethod
    def one(cls, fn, *args) -> "Deferred":
        """The one-item list ``[fn(*args)]``, deferred (a part with a single grasp)."""
        return cls(_one, fn, args)


_AFFORDANCE_SET = frozenset(AFFORDANCES)


@dataclass(eq=False, init=False)
class Part:
    """One part instance: primitives in its own frame plus knowledge.

    Attributes
    ----------
    semantic : str
        Label from :data:`artipg.vocabulary.SEMANTIC_LABELS`.
    template : str
        Name of the part template that built it.
    primitives : list of Primitive
        Geometry in the part frame (metres).
    anchors : dict
        Named points (3,) in the part frame (attachment points for children).
    regions : dict
        Affordance name -> :class:`Region`.
    canonical : (4, 4) ndarray
        Canonical frame of the part (for part pose and NPCS), in the part frame.
    size : (3,) ndarray or None
        Extents along the canonical axes; derived from the primitives when None.
    grasps : list of Grasp
        Grasp poses defined on the template. The constructor (and assignment) also
        takes a zero-argument callable returning that list, such as a
        :class:`Deferred`: it is called when ``grasps`` is first read.
    actionable : str
        GAPartNet actionable class or ``"none"``.
    name : str
        Instance name, unique in the object (set when added to a link).
    pose : (4, 4) ndarray
        Part frame in its link frame (set when added to a link).
    param_span : (int, int)
        ``(start, stop)`` positions in the object's parameter record of the
        parameters first drawn after the previous part was added and up to this one
        (set when added to a link): the draws that built this part, which is what
        repair perturbs when the part is at fault (see :mod:`artipg.validate.repair`).
    """

    semantic: str
    template: str
    primitives: list[Primitive]
    anchors: dict = field(default_factory=dict)
    regions: dict = field(default_factory=dict)
    canonical: np.ndarray = field(default_factory=lambda: IDENTITY)
    size: np.ndarray | None = None
    grasps: list = field(default_factory=list)
    actionable: str = "none"
    name: str = ""
    pose: np.ndarray = field(default_factory=lambda: IDENTITY)
    param_span: tuple = (0, 0)

    # hand-written (init=False above): the generated one calls a factory per default and
    # then __post_init__; parts are made by the dozen per object
    def __init__(self, semantic: str, template: str, primitives: list[Primitive], anchors: dict = _FACTORY,
                 regions: dict = _FACTORY, canonical: np.ndarray = IDENTITY, size: np.ndarray | None = None,
                 grasps: list = _FACTORY, actionable: str = "none", name: str = "",
                 pose: np.ndarray = IDENTITY, param_span: tuple = (0, 0)):
        if semantic not in LABEL_ID:
            label_id(semantic)  # raises, naming the vocabulary
        if actionable not in ACTIONABLE_ID:
            raise ValueError(f"unknown actionable class {actionable!r}")
        if regions is _FACTORY:
            regions = {}
        else:
            for k in regions:
                if k not in _AFFORDANCE_SET:
                    raise ValueError(f"unknown affordance {k!r}; choose from {AFFORDANCES}")
        self.semantic = semantic
        self.template = template
        self.primitives = primitives
        self.anchors = {} if anchors is _FACTORY else anchors
        self.regions = regions
        self.canonical = canonical
        self.size = size
        if grasps is _FACTORY:
            grasps = []
        elif grasps.__class__ is not list and _pending(grasps):
            grasps = Deferred(grasps)
        self._grasps = grasps
        self.actionable = actionable
        self.name = name
        self.pose = pose
        self.param_span = param_span

    def grasp_source(self):
        """The grasp list, or the :class:`Deferred` that will build it (left unbuilt):
        to give another part the same grasps, or derive them, without building them."""
        return self._grasps

    def bounds(self) -> np.ndarray:
        """Bounding box (2, 3) of the part in its own frame."""
        prims = self.primitives
        B = np.array([p.geom.bounds(p.params) for p in prims])
        return corners_bounds_union(B, np.concatenate([p.pose for p in prims]).reshape(-1, 4, 4))

    def canonical_size(self) -> np.ndarray:
        """Extents (3,) of the part along its canonical axes."""
        if self.size is not None:
            return np.asarray(self.size, dtype=float)
        Ci = np.linalg.inv(self.canonical)
        b = np.stack([p.placed(Ci).bounds() for p in self.primitives])
        return b[:, 1].max(axis=0) - b[:, 0].min(axis=0)

    def anchor(self, name: str) -> np.ndarray:
        """Anchor ``name`` (3,) in the part frame."""
        return np.asarray(self.anchors[name], dtype=float)


def _one(fn, args) -> list:
    return [fn(*args)]


def _pending(grasps) -> bool:
    return grasps.__class__ is not Deferred and callable(grasps)


def _get_grasps(self) -> list:
    g = self._grasps
    if g.__class__ is Deferred:
        g = self._grasps = g()
    return g


def _set_grasps(self, grasps) -> None:
    self._grasps = Deferred(grasps) if _pending(grasps) else grasps


# after the class is made: the dataclass keeps ``grasps`` as a field (fields(), repr,
# dataclasses.replace read it through this property, which builds pending grasps)
Part.grasps = property(_get_grasps, _set_grasps, doc="Grasp poses defined on the template (list of Grasp).")
