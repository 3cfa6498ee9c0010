"""Run one function over many items, each isolated from the others.

Validating thousands of third-party folders must survive any one of them: a mesh
that crashes a C library, a URDF that makes a solver loop, a worker killed for
memory. ``concurrent.futures.ProcessPoolExecutor`` gives up on every pending item
(``BrokenProcessPool``) when one worker dies. Here each worker is a process of its
own with a pipe: the parent hands it one item at a time and waits for the answer
with a deadline. A worker that dies or overruns is killed and replaced; its item
gets a failure result (:func:`failure`) and the run goes on. Workers ignore
Ctrl-C (the parent stops them), and send their stdout and stderr, Python warnings
and library log records to nowhere: C libraries (pybullet) print from native code,
so the file descriptors themselves are redirected.
"""

from __future__ import annotations

import multiprocessing as mp
import os
import signal
import time
from multiprocessing.connection import wait


def failure(item, message: str, seconds: float) -> dict:
    """The result of an item whose worker failed: ``{"item", "ok": False, "error",
    "seconds"}``."""
    return {"item": item, "ok": False, "error": message, "seconds": round(seconds, 3)}


def _quiet() -> None:
    """Silence this process: fds 1 and 2 to /dev/null, warnings and logging off."""
    import logging
    import warnings

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # not the parent's handler
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    os.dup2(null, 2)
    os.close(null)
    warnings.simplefilter("ignore")
    logging.disable(logging.CRITICAL)


def _worker(conn, fn) -> None:
    _quiet()
    while True:
        try:
            item = conn.recv()
        except EOFError:
            return
        if item is None:
            return
        t0 = time.perf_counter()
        try:
            out = fn(item)
        except BaseException as e:  # noqa: BLE001 - any error is this item's failure
            out = failure(item, f"{type(e).__name__}: {e}".splitlines()[0][:300], 0.0)
        out["seconds"] = round(time.perf_counter() - t0, 3)
        conn.send(out)


class _Slot:
    """One worker process and the item it is working on."""

    def __init__(self, ctx, fn):
        self.conn, child = ctx.Pipe()
        self.proc = ctx.Process(target=_worker, args=(child, fn), daemon=True)
        self.proc.start()
        child.close()
        self.index, self.started = None, 0.0

    def give(self, index: int, item) -> None:
        self.index, self.started = index, time.perf_counter()
        self.conn.send(item)

    def stop(self) -> None:
        if self.proc.is_alive():
            self.proc.kill()
        self.proc.join(timeout=5)
        self.conn.close()


def run_isolated(fn, items: list, workers: int = 1, timeout: float = 300.0, on_result=None) -> list:
    """``[fn(item) for item in items]``, each call in a worker process.

    Parameters
    ----------
    fn : callable
        Module-level function of one item returning a dict (it gets a ``"seconds"``
        key: its wall time).
    items : list
        Picklable items.
    workers : int
        Worker processes at a time.
    timeout : float
        Seconds an item may take before its worker is killed.
    on_result : callable, optional
        Called as ``on_result(index, result)`` as each result arrives.

    Returns
    -------
    list
        One result per item, in order: ``fn``'s dict, or :func:`failure` for an item
        whose worker raised, died or timed out. On KeyboardInterrupt the workers are
        stopped and the items not finished get ``failure(item, "interrupted", ...)``;
        the list is then attached to the exception as ``results`` and it is re-raised.
    """
    ctx = mp.get_context("fork" if "fork" in mp.get_all_start_methods() else "spawn")
    results: list = [None] * len(items)
    todo = list(range(len(items)))[::-1]
    slots: list = []

    def done(slot, result):
        results[slot.index] = result
        if on_result is not None:
            on_result(slot.index, result)
        slot.index = None

    try:
        while todo or any(s.index is not None for s in slots):
            while todo and len([s for s in slots if s.index is not None]) < workers:
                slot = next((s for s in slots if s.index is None), None)
                if slot is None:
                    slot = _Slot(ctx, fn)
                    slots.append(slot)
                i = todo.pop()
                slot.give(i, items[i])
            busy = [s for s in slots if s.index is not None]
            now = time.perf_counter()
            left = min(s.started + timeout - now for s in busy)
            ready = wait([s.conn for s in busy] + [s.proc.sentinel for s in busy], timeout=max(left, 0.0))
            now = time.perf_counter()
            for s in busy:
                if s.conn in ready:
                    try:
                        done(s, s.conn.recv())
                        continue
                    except (EOFError, OSError):
                        pass
                if s.conn in ready or s.proc.sentinel in ready:  # died without an answer
                    code = s.proc.exitcode
                    done(s, failure(items[s.index], f"worker died (exit code {code})", now - s.started))
                elif now - s.started >= timeout:
                    done(s, failure(items[s.index], f"timeout after {timeout:g} s", now - s.started))
                else:
                    continue
                s.stop()
                slots.remove(s)
    except KeyboardInterrupt as e:
        for i, r in enumerate(results):
            if r is None:
                results[i] = failure(items[i], "interrupted", 0.0)
        e.results = results
        raise
    finally:
        for s in slots:
            if s.index is None and s.proc.is_alive():
                try:
                    s.conn.send(None)
                except OSError:
                    pass
            s.stop()
    return results
