"""The Ray engine of ``artipg generate``: the tasks of :mod:`artipg.data.engine`
(:func:`~artipg.data.engine.build_one`, one per (category, seed)) run as Ray tasks on
a cluster, a local one when no address is given.

Every task writes its own folder under the output folder, so on a multi-node cluster
that folder must be on a filesystem every node sees at the same path. The driver
(the process running ``artipg generate``) keeps the progress display and the index
from the outcomes as they arrive, as with the local pool. See ``docs/cluster.md``.
"""

from __future__ import annotations

import logging
import threading
from typing import Iterator, Sequence

from artipg.data.engine import BuildOptions, Outcome, build_one


class EngineError(RuntimeError):
    """The engine cannot run (Ray missing, cluster unreachable); one line for the user."""


def ray_available() -> bool:
    """Whether Ray can be imported."""
    try:
        import ray  # noqa: F401
    except ImportError:
        return False
    return True


def _probe(address: str, timeout: float = 5.0) -> None:
    """Fail fast when nothing listens at a ``[ray://]HOST:PORT`` address (Ray itself
    retries for minutes); ``auto`` and other forms are left to Ray."""
    import socket

    host, sep, port = address.removeprefix("ray://").rpartition(":")
    if not sep or not port.isdigit():
        return
    try:
        socket.create_connection((host, int(port)), timeout=timeout).close()
    except OSError as e:
        raise EngineError(f"cannot connect to the Ray cluster at {address!r}: {e.strerror or e} "
                          "(start one with 'ray start --head', see docs/cluster.md)") from None


def _connect(address: str | None, workers: int):
    """Start a local Ray instance (``workers`` CPUs, loopback only) or join the one at
    ``address``; returns the ``ray`` module and whether this call started Ray."""
    try:
        import ray
    except ImportError:
        raise EngineError("--engine ray needs Ray: pip install 'artipg[ray]'") from None
    if ray.is_initialized():
        return ray, False
    kwargs = dict(include_dashboard=False, log_to_driver=False, logging_level=logging.WARNING,
                  configure_logging=True)
    if address is not None:
        _probe(address)
    try:
        if address is None:
            ray.init(num_cpus=workers, _node_ip_address="127.0.0.1", **kwargs)
        else:
            ray.init(address=address, **kwargs)
    except (ConnectionError, RuntimeError, ValueError) as e:
        first = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
        raise EngineError(f"cannot connect to the Ray cluster at {address!r}: {first}") from None
    return ray, True


def run_tasks_ray(tasks: Sequence[tuple[str, int]], opts: BuildOptions, address: str | None = None,
                  workers: int = 1, stop: threading.Event | None = None) -> Iterator[Outcome]:
    """Run ``tasks`` ((category, seed) pairs) as Ray tasks, yielding outcomes as
    objects finish (completion order).

    Parameters
    ----------
    tasks : sequence of (str, int)
    opts : BuildOptions
        ``opts.out`` must be the same path on every node (a shared filesystem).
    address : str, optional
        A running cluster (``"auto"``, ``"HOST:PORT"``, ``"ray://HOST:PORT"``); None
        starts a local Ray instance with ``workers`` CPUs, shut down at the end.
    workers : int
        CPUs of the local instance; unused with ``address`` (the cluster's CPUs count).
    stop : threading.Event, optional
        Once set, no new object is submitted; objects already submitted (at most
        four per cluster CPU) are finished and yielded, so no folder is left
        half-written. A task killed meanwhile (a second Ctrl-C, a lost node) yields
        nothing: its folder is rebuilt by a re-run.

    Yields
    ------
    Outcome

    Raises
    ------
    EngineError
        Ray is not installed or the cluster cannot be reached.
    """
    stopped = stop.is_set if stop is not None else (lambda: False)
    if not tasks or stopped():
        return
    ray, started = _connect(address, workers)
    try:
        remote = ray.remote(num_cpus=1, max_retries=1)(build_one)
        cpus = max(1, int(ray.cluster_resources().get("CPU", 1)))
        in_flight = 4 * cpus  # enough queued per CPU to hide the scheduling round trip
        todo = iter(tasks)
        running: dict = {}  # object ref -> (category, seed)
        exhausted = False
        while True:
            while not exhausted and not stopped() and len(running) < in_flight:
                task = next(todo, None)
                if task is None:
                    exhausted = True
                else:
                    running[remote.remote(task[0], task[1], opts)] = task
            if not running:
                return
            done, rest = ray.wait(list(running), num_returns=1, timeout=0.25)
            if done and rest:
                more, _ = ray.wait(rest, num_returns=len(rest), timeout=0)
                done += more
            for ref in done:
                category, seed = running.pop(ref)
                try:
                    outcome = ray.get(ref)
                except (ray.exceptions.RayError, KeyboardInterrupt) as e:
                    if stopped():
                        continue  # killed while stopping: a re-run rebuilds it
                    first = (str(e).strip().splitlines() or [type(e).__name__])[0]
                    outcome = Outcome(category, seed, "error", f"{type(e).__name__}: {first}")
                yield outcome
    finally:
        if started:
            ray.shutdown()
