"""Shared helpers for benchmarks: timing with repeats, peak memory, machine facts, tables.

Timings are medians of repeated runs with min-max; ratios compare tools measured in
the same process run.  Results go to ``benchmarks/results/``.
"""

from __future__ import annotations

import argparse
import importlib
import os
import platform
import statistics
import time
import tracemalloc
from dataclasses import dataclass
from pathlib import Path

#: Root of every table and plot: the checkout's ``benchmarks/results/`` (never the installed
#: package: ``benchmarks/`` is not shipped), or ``--out`` through :func:`set_results_root`.
RESULTS = Path(__file__).resolve().parent / "results"


def set_results_root(path) -> Path:
    """Send the tables and plots of this process under ``path`` (``exactcagd bench --out``).

    Quick runs write ``path/<topic>.md``, full runs ``path/full/<topic>.md``, as under the
    default ``benchmarks/results/``.
    """
    global RESULTS
    RESULTS = Path(path).resolve()
    return RESULTS

#: Set by the runner (``python -m benchmarks``): modules whose ``main()`` reads the mode
#: with :func:`parse_quick` get the runner's mode instead of parsing ``sys.argv``.
RUNNER_QUICK: bool | None = None
#: The mode :func:`parse_quick` read from the command line (a module run on its own).
_PARSED_QUICK: bool | None = None


def is_quick() -> bool:
    """The mode of the benchmark running now: the runner's, else the command line's, else full."""
    if RUNNER_QUICK is not None:
        return RUNNER_QUICK
    return bool(_PARSED_QUICK)


def results_dir(quick: bool | None = None) -> Path:
    """Where a run's tables and plots go: ``results/`` for quick runs, ``results/full/`` for full runs.

    The one-command quick run (``python -m benchmarks --quick``) regenerates every file in
    ``results/`` together; full runs take hours and keep their own folder, so neither mode
    ever replaces the other's tables.
    """
    path = RESULTS if (is_quick() if quick is None else quick) else RESULTS / "full"
    path.mkdir(parents=True, exist_ok=True)
    return path


@dataclass
class Timing:
    median: float
    low: float
    high: float
    runs: int
    peak_bytes: int | None = None

    def fmt(self) -> str:
        return f"{_fmt_seconds(self.median)} ({_fmt_seconds(self.low)}-{_fmt_seconds(self.high)})"

    def fmt_memory(self) -> str:
        return fmt_bytes(self.peak_bytes)


def fmt_bytes(n: int | None) -> str:
    if n is None:
        return "-"
    for unit, size in (("GB", 1 << 30), ("MB", 1 << 20), ("kB", 1 << 10)):
        if n >= size:
            return f"{n / size:.1f} {unit}"
    return f"{n} B"


def ratio(slow: Timing | float, fast: Timing | float) -> str:
    """``slow / fast`` as ``"3.2x"``: medians of two Timings measured in the same run, or plain seconds."""
    a = slow.median if isinstance(slow, Timing) else slow
    b = fast.median if isinstance(fast, Timing) else fast
    if not b:
        return "-"
    r = a / b
    return f"{r:.3g}x" if r < 100 else f"{r:,.0f}x"


def optional_peer(module: str, what: str):
    """Import an optional peer package; ``None`` (with a printed SKIP message) when absent.

    Peers come with the ``peers`` extra: ``pip install exactcagd[peers]``.
    """
    try:
        return importlib.import_module(module)
    except Exception as exc:  # ImportError, or a broken binary wheel
        print(f"SKIP {what}: peer module {module!r} not importable ({type(exc).__name__}: {exc}); "
              "install with `pip install exactcagd[peers]`")
        return None


def peak_rss() -> str:
    """High-water mark of this process's resident memory (``resource.getrusage``)."""
    try:
        import resource
    except ImportError:  # not on POSIX
        return "-"
    return fmt_bytes(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024)


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
    """Write ``<topic>.md`` under :func:`results_dir` with a title, the machine line and the body."""
    path = results_dir() / f"{topic}.md"
    stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    path.write_text(f"# {title}\n\nRun {stamp} on: {machine()}\n\n{body}\n")
    return path


def parse_quick(description: str) -> bool:
    """The runner's mode, or ``--quick`` from the command line (remembered for :func:`results_dir`)."""
    global _PARSED_QUICK
    if RUNNER_QUICK is not None:
        return RUNNER_QUICK
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--quick", action="store_true", help="smaller sizes (minutes, not hours)")
    _PARSED_QUICK = parser.parse_args().quick
    return _PARSED_QUICK


def loglog_plot(filename: str, series: dict, xlabel: str, ylabel: str, title: str, *, lines: bool = True,
                floor: float = 1e-18, floor_meaning: str = "error 0") -> Path:
    """Log-log plot of ``{label: [(x, y), ...]}`` into :func:`results_dir` (values <= 0 drawn at
    ``floor``, with a dotted line labelled ``floor_meaning``)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 5))
    for label, points in series.items():
        if not points:
            continue
        xs = [x for x, _ in points]
        ys = [max(y, floor) for _, y in points]
        ax.plot(xs, ys, marker="o", linestyle="-" if lines else "none", label=label, markersize=4)
    if any(y <= floor for points in series.values() for _, y in points):  # say what the floor means
        ax.axhline(floor, color="0.5", ls=":", lw=1, label=f"{floor_meaning} (drawn at {floor:g})")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    path = results_dir() / filename
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
