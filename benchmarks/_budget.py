"""Run a function under a wall-clock budget (SIGALRM; main thread, POSIX): ``(result, seconds)``,
or ``(None, budget)`` when the budget runs out.  Used by the curves-on-surfaces benchmark and
``examples/yang_tables.py`` to keep slow baseline runs from stalling a whole table.

>>> run_with_budget(lambda: 6 * 7, 5.0)[0]
42
"""

from __future__ import annotations

import signal
import time

__all__ = ["run_with_budget"]


class _Stop(Exception):
    pass


def _alarm(signum, frame):  # pragma: no cover - timing dependent
    raise _Stop


def run_with_budget(func, budget: float):
    previous = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, budget)
    start = time.perf_counter()
    try:
        return func(), time.perf_counter() - start
    except _Stop:
        return None, budget
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
