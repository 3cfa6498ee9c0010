"""The local engine of ``artipg generate``: one task per (category, seed), run in
this process or in a pool of worker processes, stoppable between objects.

A task checks an existing folder against its file list
(:func:`artipg.io.manifest.check_folder`) and keeps it when complete; otherwise it
generates the object exactly as :func:`artipg.generate` does (validated and repaired
unless told not to) and writes the folder atomically. It returns an
:class:`Outcome` carrying the folder's index row, so the parent process alone
writes the index.
"""

from __future__ import annotations

import json
import os
import signal
import threading
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, Sequence

from artipg.data.index import index_row
from artipg.io.manifest import ANNOTATION_NAME, check_folder


@dataclass(frozen=True)
class BuildOptions:
    """What every task of a run writes.

    Attributes
    ----------
    out : str
        Output folder; objects go to ``out/<category>/<seed>/``.
    n_points : int
        Labelled points in ``points.npz`` (0: no file).
    views : int
        Partial views in ``views.npz`` (0: no file).
    validate, simulate : bool
        As :func:`artipg.generate` (``simulate`` only counts with ``validate``).
    overwrite : bool
        Rewrite complete folders too.
    hashes : bool
        Check hashes, not only sizes, of existing folders.
    formats : tuple of str, optional
        Simulator files beside the URDF (default
        :data:`artipg.export.formats.DEFAULT_FORMATS`).
    actuators : bool
        Position servos per joint in MJCF and USD.
    rgb : str, optional
        ``"studio"`` or ``"random"``: colour images of the views in ``views_rgb.npz``.
    detail : str
        Geometric detail level (:mod:`artipg.rules.detail`), as :func:`artipg.generate`, or
        ``"learned"``: the sharp structure (level ``"off"``), whose ``points.npz`` holds the
        detailed cloud of the model at ``detail_model`` (docs/detail_learned.md).
    detail_model : str, optional
        Path of the detail model.
    """

    out: str
    n_points: int = 2048
    views: int = 0
    validate: bool = True
    simulate: bool = False
    overwrite: bool = False
    hashes: bool = True
    formats: tuple | None = None
    actuators: bool = False
    rgb: str | None = None
    detail: str = "procedural"
    detail_model: str | None = None


@dataclass
class Outcome:
    """Result of one task.

    Attributes
    ----------
    category : str
    seed : int
    status : {"new", "kept", "rebuilt", "rewritten", "error"}
        ``rebuilt``: an incomplete or damaged folder was replaced; ``rewritten``: a
        complete one, under ``overwrite``.
    reason : str
        ``rebuilt``: the old folder's state ("incomplete" or "damaged");
        ``error``: the exception, one line.
    row : dict or None
        The folder's index row (:func:`artipg.data.index.index_row`), None on error.
    """

    category: str
    seed: int
    status: str
    reason: str = ""
    row: dict | None = None

    @property
    def written(self) -> bool:
        return self.status in ("new", "rebuilt", "rewritten")


def build_one(category: str, seed: int, opts: BuildOptions) -> Outcome:
    """Keep, or (re)build and write, the folder of one object; never raises for a
    failure of this object (an ``error`` outcome instead)."""
    import artipg
    from artipg.export.folder import export_object

    rel = f"{category}/{seed}"
    dest = Path(opts.out) / category / str(seed)
    status, reason = "new", ""
    if os.path.lexists(dest):
        if opts.overwrite:
            status = "rewritten"
        else:
            check = check_folder(dest, hashes=opts.hashes)
            if check.ok:
                return Outcome(category, seed, "kept", row=index_row(check.annotation, rel))
            status, reason = "rebuilt", check.status
    try:
        learned = opts.detail == "learned"  # the bridge was trained on sharp structures
        obj = artipg.generate(category, seed, validate=opts.validate, simulate=opts.validate and opts.simulate,
                              detail="off" if learned else opts.detail)
        model = None
        if learned:
            from artipg.detail.application import generation_model

            model = generation_model(opts.detail_model)
        export_object(obj, dest, n_points=opts.n_points, overwrite=True, views=opts.views, formats=opts.formats,
                      actuators=opts.actuators, rgb=opts.rgb, detail_model=model)
        annotation = json.loads((dest / ANNOTATION_NAME).read_bytes())
    except Exception as e:  # noqa: BLE001 - one object's failure must not stop a run of thousands
        return Outcome(category, seed, "error", f"{type(e).__name__}: {e}")
    return Outcome(category, seed, status, reason, index_row(annotation, rel))


def _build_task(task: tuple[str, int, BuildOptions]) -> Outcome:
    return build_one(*task)


def _ignore_sigint() -> None:
    # Ctrl-C in a terminal reaches the whole process group: workers finish their
    # object and the parent decides when to stop
    signal.signal(signal.SIGINT, signal.SIG_IGN)


ENGINES = ("local", "ray")


def run_tasks(tasks: Sequence[tuple[str, int]], opts: BuildOptions, workers: int = 1,
              stop: threading.Event | None = None, engine: str = "local",
              address: str | None = None) -> Iterator[Outcome]:
    """Run ``tasks`` ((category, seed) pairs), yielding outcomes as objects finish.

    Parameters
    ----------
    tasks : sequence of (str, int)
    opts : BuildOptions
    workers : int
        1 runs in this process; more use a process pool with a few tasks in flight
        per worker (outcomes then come in completion order), started once this
        process has built the first object.
    stop : threading.Event, optional
        Once set, no new object is started; objects already started are finished
        and yielded, so no folder is left half-written.
    engine : {"local", "ray"}
        ``"ray"`` runs the same tasks on a Ray cluster
        (:func:`artipg.data.ray_engine.run_tasks_ray`; ``workers`` then sizes a local
        Ray instance, started when ``address`` is None).
    address : str, optional
        Ray cluster address (``engine="ray"`` only).

    Yields
    ------
    Outcome
    """
    if engine == "ray":
        from artipg.data.ray_engine import run_tasks_ray

        yield from run_tasks_ray(tasks, opts, address=address, workers=workers, stop=stop)
        return
    if engine != "local":
        raise ValueError(f"unknown engine {engine!r}; valid engines: {', '.join(ENGINES)}")
    stopped = stop.is_set if stop is not None else (lambda: False)
    if workers <= 1:
        for category, seed in tasks:
            if stopped():
                return
            yield build_one(category, seed, opts)
        return
    todo = iter(tasks)
    # the first object is built here: the workers, forked afterwards, inherit the
    # loaded modules and compiled kernels instead of each loading them (1-3 s apiece)
    first = next(todo, None)
    if first is None or stopped():
        return
    yield build_one(first[0], first[1], opts)
    in_flight = 2 * workers
    running: set = set()
    pool = ProcessPoolExecutor(max_workers=workers, initializer=_ignore_sigint)
    try:
        exhausted = False
        while True:
            while not exhausted and not stopped() and len(running) < in_flight:
                task = next(todo, None)
                if task is None:
                    exhausted = True
                else:
                    running.add(pool.submit(_build_task, (task[0], task[1], opts)))
            if stopped():
                for f in running:
                    f.cancel()  # only those no worker has taken yet
            if not running:
                return
            done, running = wait(running, timeout=0.25, return_when=FIRST_COMPLETED)
            for f in done:
                if not f.cancelled():
                    yield f.result()
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
