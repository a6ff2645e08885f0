"""Shared helpers for benchmarks: timing with repeats, peak memory, machine facts, tables.

Timings are medians of repeated runs with min-max; ratios compare tools measured in
the same process run.  Results go to ``benchmarks/results/``.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time
import tracemalloc
from dataclasses import dataclass
from pathlib import Path

RESULTS = Path(__file__).resolve().parent / "results"


@dataclass
class Timing:
    median: float
    low: float
    high: float
    runs: int
    peak_bytes: int | None = None

    def fmt(self) -> str:
        return f"{_fmt_seconds(self.median)} ({_fmt_seconds(self.low)}-{_fmt_seconds(self.high)})"


def _fmt_seconds(s: float) -> str:
    if s < 1e-3:
        return f"{s * 1e6:.1f} us"
    if s < 1:
        return f"{s * 1e3:.2f} ms"
    return f"{s:.2f} s"


def measure(func, *, repeat: int = 5, min_time: float = 0.0, budget: float = 20.0, memory: bool = False) -> Timing:
    """Run ``func()`` ``repeat`` times (fewer if the time ``budget`` runs out); median and range.

    With ``memory=True`` one extra run measures the peak traced allocation (tracemalloc).
    """
    times = []
    start = time.perf_counter()
    for _ in range(max(repeat, 1)):
        t0 = time.perf_counter()
        func()
        times.append(time.perf_counter() - t0)
        if time.perf_counter() - start > budget:
            break
    peak = None
    if memory:
        tracemalloc.start()
        func()
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
    return Timing(statistics.median(times), min(times), max(times), len(times), peak)


def machine() -> str:
    """One line describing the machine (for every results file)."""
    cpu = platform.processor() or platform.machine()
    return f"{platform.node()} | {platform.system()} {platform.release()} | {cpu} | {os.cpu_count()} cores | Python {platform.python_version()}"


def markdown_table(headers: list[str], rows: list[list]) -> str:
    lines = ["| " + " | ".join(headers) + " |", "|" + "---|" * len(headers)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def write_result(topic: str, title: str, body: str) -> Path:
    """Write ``results/<topic>.md`` with a title, the machine line and the body."""
    RESULTS.mkdir(parents=True, exist_ok=True)
    path = RESULTS / f"{topic}.md"
    stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    path.write_text(f"# {title}\n\nRun {stamp} on: {machine()}\n\n{body}\n")
    return path


def parse_quick(description: str) -> bool:
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--quick", action="store_true", help="smaller sizes (minutes, not hours)")
    return parser.parse_args().quick
