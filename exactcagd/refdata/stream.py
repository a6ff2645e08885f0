"""Ordered, batched, constant-memory generation of reference records.

Records are computed in *batches* of consecutive indices (one task per batch, never
one per record), on the calling process (``jobs=1``), a local process pool
(``jobs>1``) or a Dask cluster, and yielded strictly in index order.  At most
``2 * workers + 2`` batches (Dask: ``4 * workers + 2``) are in flight, so memory does not grow with the count;
each record is a pure function of its identity (:func:`exactcagd.refdata.kinds.make_record`),
so the bytes never depend on the executor or the batch size.

>>> spec = BatchSpec("roots", "random", seed=0, degrees=(3,), start=0, stop=2)
>>> [line[:26] for line in batch_lines(spec)]
['{"id":"roots/random/0","ki', '{"id":"roots/random/1","ki']
"""

from __future__ import annotations

import importlib.util
import json
import math
import sys
import time
from collections import deque
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass

from ..errors import InputError
from .kinds import make_record, preload

__all__ = ["BatchSpec", "Progress", "RecordExecutor", "batch_lines", "ordered_lines", "plan_batches", "record_line"]

#: Largest batch (records per task).
MAX_BATCH = 64


@dataclass(frozen=True)
class BatchSpec:
    """Records ``start .. stop - 1`` of one ``(kind, family)``."""

    kind: str
    family: str
    seed: int
    degrees: tuple
    start: int
    stop: int

    @property
    def size(self) -> int:
        return self.stop - self.start


def record_line(record: dict) -> str:
    """One record as one compact JSON line (key order fixed by the builders)."""
    return json.dumps(record, separators=(",", ":"), allow_nan=False, ensure_ascii=True)


def batch_lines(spec: BatchSpec) -> list:
    """The JSON lines of one batch (the unit of work sent to a worker)."""
    return [record_line(make_record(spec.kind, spec.family, spec.seed, i, spec.degrees)) for i in range(spec.start, spec.stop)]


def plan_batches(kind: str, family: str, count: int, seed: int, degrees: tuple, workers: int) -> list:
    """Split ``count`` records into batches: about 8 per worker, at most :data:`MAX_BATCH` records each."""
    size = max(1, min(MAX_BATCH, math.ceil(count / (8 * max(1, workers)))))
    return [BatchSpec(kind, family, seed, tuple(degrees), s, min(count, s + size)) for s in range(0, count, size)]


class Progress:
    """A one-line progress bar on stderr: done/total, rate and ETA (throttled to 5 updates/s)."""

    def __init__(self, total: int, label: str, enabled: bool, stream=None):
        self.total, self.label, self.enabled = total, label, enabled
        self.stream = stream or sys.stderr
        self.done = 0
        self.start = time.perf_counter()
        self._last = 0.0

    def update(self, n: int) -> None:
        self.done += n
        if not self.enabled:
            return
        now = time.perf_counter()
        if now - self._last < 0.2 and self.done < self.total:
            return
        self._last = now
        elapsed = max(now - self.start, 1e-9)
        rate = self.done / elapsed
        eta = (self.total - self.done) / rate if rate > 0 else float("inf")
        width = 24
        filled = int(width * self.done / max(1, self.total))
        bar = "#" * filled + "-" * (width - filled)
        self.stream.write(f"\r{self.label} [{bar}] {self.done}/{self.total} {rate:.0f} rec/s ETA {eta:.0f} s ")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled:
            self.stream.write("\n")
            self.stream.flush()


def _windowed(submit, specs, window: int):
    """Submit ``specs`` keeping ``window`` in flight; yield ``(spec, result)`` in order."""
    pending = deque()
    it = iter(specs)
    for spec in it:
        pending.append((spec, submit(spec)))
        if len(pending) >= window:
            break
    while pending:
        spec, future = pending.popleft()
        result = future.result()
        nxt = next(it, None)
        if nxt is not None:
            pending.append((nxt, submit(nxt)))
        yield spec, result


def _dask_client(jobs: int, scheduler):
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise InputError("--dask/--scheduler: Dask is not installed: pip install 'exactcagd[dask]'") from None
    if scheduler:
        client = Client(scheduler)
        cluster = None
    else:
        import logging

        cluster = LocalCluster(n_workers=jobs, threads_per_worker=1, processes=True, dashboard_address=":0", silence_logs=logging.ERROR)
        client = Client(cluster)
    link = client.dashboard_link
    if importlib.util.find_spec("bokeh") is None and cluster is not None:
        link += " (served only when bokeh is installed)"
    print(f"dask dashboard: {link}", file=sys.stderr, flush=True)
    return client, cluster


class RecordExecutor:
    """Where batches run: this process, a local process pool, or a Dask cluster (a context manager).

    One executor serves many calls of :meth:`lines` (a whole suite: one pool, one
    cluster).  ``kinds`` are imported before workers start (forked workers inherit
    them; Dask workers import them once through ``client.run``).

    >>> with RecordExecutor(jobs=1) as ex:
    ...     len(list(ex.lines(plan_batches("roots", "random", 3, 0, (2,), 1))))
    3
    """

    def __init__(self, jobs: int = 1, dask: bool = False, scheduler=None, kinds=()):
        self.jobs, self.dask, self.scheduler, self.kinds = jobs, bool(dask or scheduler), scheduler, tuple(kinds)
        self._pool = self._client = self._cluster = None
        self.workers = 1

    def __enter__(self) -> RecordExecutor:
        if self.dask:
            self._client, self._cluster = _dask_client(self.jobs, self.scheduler)
            self.workers = max(1, len(self._client.scheduler_info().get("workers", {})) or self.jobs)
            if self.kinds:
                self._client.run(preload, sorted(self.kinds))
        elif self.jobs > 1:
            preload(self.kinds)
            self._pool = ProcessPoolExecutor(max_workers=self.jobs)
            self.workers = self.jobs
        return self

    def __exit__(self, *exc) -> None:
        if self._pool is not None:
            self._pool.shutdown(cancel_futures=True)
        if self._client is not None:
            self._client.close()
        if self._cluster is not None:
            self._cluster.close()

    def lines(self, specs, progress: Progress | None = None):
        """Yield the JSON lines of ``specs`` in order (at most a window of batches in flight)."""
        if self._client is not None:
            submit = lambda spec: self._client.submit(batch_lines, spec, pure=False)
            window = 4 * self.workers + 2  # hides the scheduler round trip
        elif self._pool is not None:
            submit = lambda spec: self._pool.submit(batch_lines, spec)
            window = 2 * self.workers + 2
        else:
            submit, window = _Done, 1
        for spec, lines in _windowed(submit, specs, window):
            yield from lines
            if progress:
                progress.update(spec.size)


class _Done:
    """A finished 'future' for in-process runs (computed when submitted)."""

    def __init__(self, spec):
        self._lines = batch_lines(spec)

    def result(self):
        return self._lines


def ordered_lines(specs, jobs: int = 1, dask: bool = False, scheduler=None, progress: Progress | None = None):
    """Yield the JSON lines of all ``specs`` in order, computed where asked.

    Parameters
    ----------
    specs : list of BatchSpec
    jobs : worker processes (local pool or Dask LocalCluster workers); 1 = this process
    dask : run on a Dask LocalCluster with ``jobs`` workers
    scheduler : address of an existing Dask scheduler (implies Dask)
    progress : updated with the number of records of each finished batch
    """
    specs = list(specs)
    with RecordExecutor(jobs, dask, scheduler, kinds={spec.kind for spec in specs}) as executor:
        yield from executor.lines(specs, progress)
