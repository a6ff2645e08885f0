"""Run every benchmark: ``python -m benchmarks [--quick] [--only a,b]`` (or ``exactcagd bench``).

Each ``benchmarks/bench_*.py`` and ``benchmarks/stress_*.py`` module exposes
``main(quick=False)`` and writes its own table under ``benchmarks/results/``; this
runner calls them in one process, one after the other, and writes
``benchmarks/results/RUNS.md`` with what ran, how long it took and what failed.
"""

from __future__ import annotations

import argparse
import importlib
import pkgutil
import time
import traceback

from ._common import RESULTS, machine, markdown_table

import benchmarks


def discover() -> list[str]:
    names = [m.name for m in pkgutil.iter_modules(benchmarks.__path__)]
    return sorted(n for n in names if n.startswith(("bench_", "stress_")))


def run(quick: bool, only=None) -> int:
    rows, failures = [], 0
    for name in discover():
        topic = name.split("_", 1)[1]
        if only and topic not in only and name not in only:
            continue
        start = time.perf_counter()
        try:
            importlib.import_module(f"benchmarks.{name}").main(quick=quick)
            status = "ok"
        except Exception:  # noqa: BLE001 - report and go on with the others
            failures += 1
            status = "FAILED: " + traceback.format_exc().strip().splitlines()[-1]
        seconds = time.perf_counter() - start
        print(f"{name:<32} {status} ({seconds:.1f} s)", flush=True)
        rows.append([name, status, f"{seconds:.1f}"])
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "RUNS.md").write_text(
        f"# Benchmark runs ({'quick' if quick else 'full'})\n\nMachine: {machine()}\n\n"
        + markdown_table(["module", "status", "seconds"], rows)
        + "\n"
    )
    return 1 if failures else 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--only", default=None, help="comma-separated topics or module names")
    args = parser.parse_args(argv)
    return run(args.quick, set(args.only.split(",")) if args.only else None)


if __name__ == "__main__":
    raise SystemExit(main())
