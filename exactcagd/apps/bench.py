"""``exactcagd bench``: run the benchmark suite in a repository checkout's ``benchmarks/``.

``benchmarks/`` is not part of the installed package (its tables describe the repository,
and it imports the peers and the example scripts), so the command looks for a checkout:
the current directory or one of its parents, else the source tree of an editable install.
Tables and plots go to that checkout's ``benchmarks/results/`` or to ``--out``; never into
the installed package.

>>> from pathlib import Path
>>> is_checkout(Path("/"))
False
"""

from __future__ import annotations

import sys
from pathlib import Path

from ..errors import NotSupportedError

NEEDS_CHECKOUT = (
    "exactcagd bench needs a repository checkout: the benchmarks/ folder is not installed with "
    "the package. Clone the exactcagd repository and run 'exactcagd bench' (or "
    "'python -m benchmarks') from its root; results go to benchmarks/results/ or --out."
)


def is_checkout(root: Path) -> bool:
    """Whether ``root`` is an exactcagd repository checkout with its benchmarks."""
    return (root / "benchmarks" / "__main__.py").is_file() and (root / "exactcagd" / "__init__.py").is_file()


def find_checkout(start: Path | None = None) -> Path | None:
    """The checkout holding ``benchmarks/``: ``start`` (default: the current directory) or a
    parent of it, else the source tree this package was imported from (editable install)."""
    start = (start or Path.cwd()).resolve()
    import exactcagd

    for root in (start, *start.parents, Path(exactcagd.__file__).resolve().parents[1]):
        if is_checkout(root):
            return root
    return None


def main(args) -> int:
    root = find_checkout()
    if root is None:
        raise NotSupportedError(NEEDS_CHECKOUT)
    out = getattr(args, "out", None)
    if out:
        from ..outputs import check_output_dir

        out = check_output_dir(out)  # before any benchmark runs
    if str(root) not in sys.path:
        sys.path.insert(0, str(root))
    import benchmarks

    if Path(benchmarks.__file__).resolve().parent != root / "benchmarks":
        raise NotSupportedError(
            f"a different 'benchmarks' package is importable ({benchmarks.__file__}); " + NEEDS_CHECKOUT
        )
    from benchmarks import _common
    from benchmarks.__main__ import run

    if out:
        _common.set_results_root(out)
    return run(args.quick, set(args.only.split(",")) if args.only else None)
