"""Run every benchmark: ``python -m benchmarks [--quick] [--only a,b]`` (or ``exactcagd bench``).

Each ``benchmarks/bench_*.py`` and ``benchmarks/stress_*.py`` module exposes
``main(quick=False)`` (or ``main()`` reading the mode with ``_common.parse_quick``, which
then returns the runner's mode) and writes its own table under ``benchmarks/results/``
(repeated runs: median and min-max; ratios to peers measured in the same run; see
``_common.measure``).  This runner calls them in one process, one after the other, and
writes ``benchmarks/results/RUNS.md`` with what ran, how long it took, the process's
resident-memory high-water mark after it, and what failed.  Peers (``pip install
exactcagd[peers]``) that are absent are skipped with a printed message.
"""

from __future__ import annotations

import argparse
import importlib
import inspect
import pkgutil
import time
import traceback

from . import _common
from ._common import machine, markdown_table, peak_rss

import benchmarks


def discover() -> list[str]:
    names = [m.name for m in pkgutil.iter_modules(benchmarks.__path__)]
    return sorted(n for n in names if n.startswith(("bench_", "stress_")))


def call_main(module, quick: bool) -> None:
    """Call ``module.main`` in the runner's mode, whichever of the two conventions it uses."""
    main = module.main
    _common.RUNNER_QUICK = quick
    try:
        if "quick" in inspect.signature(main).parameters:
            main(quick=quick)
        else:
            main()
    finally:
        _common.RUNNER_QUICK = None


def run(quick: bool, only=None) -> int:
    rows, failures = [], 0
    for name in discover():
        topic = name.split("_", 1)[1]
        if only and topic not in only and name not in only:
            continue
        start = time.perf_counter()
        try:
            call_main(importlib.import_module(f"benchmarks.{name}"), quick)
            status = "ok"
        except Exception:  # noqa: BLE001 - report and go on with the others
            failures += 1
            status = "FAILED: " + traceback.format_exc().strip().splitlines()[-1].replace("|", "/")
        seconds = time.perf_counter() - start
        print(f"{name:<32} {status} ({seconds:.1f} s)", flush=True)
        rows.append([name, "quick" if quick else "full", time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), status,
                     f"{seconds:.1f}", peak_rss()])
    write_runs(rows, quick)
    return 1 if failures else 0


RUNS_HEADERS = ["module", "mode", "finished", "status", "seconds", "peak RSS of the runner so far"]


def write_runs(rows: list, quick: bool) -> None:
    """Update ``RUNS.md`` of the mode's results folder (``results/`` quick, ``results/full/`` full):
    this run's rows replace earlier rows of the same modules."""
    path = (_common.RESULTS if quick else _common.RESULTS / "full") / "RUNS.md"
    keep = {}
    if path.exists():
        for line in path.read_text().splitlines():
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) == len(RUNS_HEADERS) and cells[0].startswith(("bench_", "stress_")):
                keep[cells[0]] = cells
    keep.update({row[0]: row for row in rows})
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(
        f"# Benchmark runs\n\nMachine: {machine()}\n\nLast run: {'quick' if quick else 'full'} mode, "
        f"{len(rows)} module(s).\n\n" + markdown_table(RUNS_HEADERS, [keep[k] for k in sorted(keep)]) + "\n"
    )


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--only", default=None, help="comma-separated topics or module names")
    parser.add_argument("--out", default=None, help="folder for the tables and plots (default: benchmarks/results/)")
    args = parser.parse_args(argv)
    if args.out:
        from exactcagd.outputs import check_output_dir

        _common.set_results_root(check_output_dir(args.out))
    return run(args.quick, set(args.only.split(",")) if args.only else None)


if __name__ == "__main__":
    raise SystemExit(main())
