"""``exactcagd bench``: run the benchmark suite in ``benchmarks/`` (see ``python -m benchmarks``)."""

from __future__ import annotations

from ..errors import NotSupportedError


def main(args) -> int:
    try:
        from benchmarks.__main__ import run
    except ImportError:
        raise NotSupportedError(
            "the benchmarks package is not importable: run from the repository root "
            "or install with 'pip install -e .'"
        ) from None
    return run(args.quick, set(args.only.split(",")) if args.only else None)
