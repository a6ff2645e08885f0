"""The ``exactcagd`` command line.

Subcommands: ``info`` (capabilities), ``verify`` (proof ledger), ``plan`` / ``run``
(scenes), ``refdata`` (exact reference data), ``conformance`` (grade another kernel on
reference data), ``bench`` (benchmarks).  Every
subcommand imports its machinery lazily so ``exactcagd --version`` stays instant.

>>> from exactcagd.cli import main
>>> main(["--version"])  # doctest: +ELLIPSIS
exactcagd ...
0
"""

from __future__ import annotations

import argparse
import importlib
import sys

from . import __version__
from .errors import ExactCAGDError

#: (module, description) of each capability listed by ``exactcagd info``.
CAPABILITIES = [
    ("exactcagd.exact.scalars", "exact rationals (gmpy2.mpq) with an explicit float policy"),
    ("exactcagd.exact.bernstein", "Bernstein arithmetic: de Casteljau, Horner, subdivision, elevation, reduction, products, blossoms"),
    ("exactcagd.exact.algebraic", "real algebraic numbers with isolating intervals (flint)"),
    ("exactcagd.geometry.bezier_curve", "BezierCurve: polynomial and rational, any dimension"),
    ("exactcagd.geometry.bezier_surface", "BezierSurface: tensor-product, polynomial and rational"),
    ("exactcagd.geometry.bspline", "BSplineCurve / BSplineSurface (NURBS): de Boor, Boehm, Bezier extraction"),
    ("exactcagd.composition", "exact composition F(K(t)) of curves with surfaces (Lasser & Bonneau)"),
    ("exactcagd.reparam", "Mobius / quadratic / cubic reparameterization of rational surfaces (Yang et al.)"),
    ("exactcagd.curves_on_surfaces", "G1 parabola / hyperbola / polyline curves on NURBS surfaces (Yang et al.)"),
    ("exactcagd.algebra", "resultants, implicitization, inversion, moving lines, Groebner bases"),
    ("exactcagd.toolbox", "the rest of Sederberg's notes: basics, offsets, blending, splines, interpolation, fitting, surfaces, T-splines, curvature, integrals"),
    ("exactcagd.numeric.evaluation", "float evaluators with certified error bounds"),
    ("exactcagd.numeric.roots", "Bernstein root finding with certified enclosures (exact isolation as reference)"),
    ("exactcagd.numeric.interval", "interval arithmetic and interval Bezier curves"),
    ("exactcagd.numeric.intersection", "curve intersection: subdivision, interval, Bezier clipping, exact"),
    ("exactcagd.scenes", "scene files, lazy planner, runner"),
    ("exactcagd.refdata", "reference data suites for testing other kernels: 12 kinds, hard families, JSON Schemas"),
]


def _available(module: str) -> bool:
    try:
        importlib.import_module(module)
    except ImportError:
        return False
    return True


def cmd_info(args) -> int:
    """Print version, backends and which capabilities are installed."""
    import flint
    import gmpy2
    import mpmath
    import numpy
    import sympy

    print(f"exactcagd {__version__}")
    print(
        f"backends: sympy {sympy.__version__}, python-flint {flint.__version__}, gmpy2 {gmpy2.version()}, "
        f"numpy {numpy.__version__}, mpmath {mpmath.__version__}"
    )
    print("capabilities:")
    for module, text in CAPABILITIES:
        mark = "yes" if _available(module) else "no "
        print(f"  [{mark}] {text}  ({module})")
    return 0


def _lazy(module: str, func: str):
    def run(args):
        return getattr(importlib.import_module(module), func)(args)

    return run


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="exactcagd", description="Exact computer algebra for CAGD.")
    parser.add_argument("--version", action="version", version=f"exactcagd {__version__}")
    sub = parser.add_subparsers(dest="command")

    info = sub.add_parser("info", help="list capabilities and backends")
    info.set_defaults(func=cmd_info)

    verify = sub.add_parser("verify", help="run the proof ledger of the source documents")
    verify.add_argument("--doc", choices=["lasser", "yang", "sederberg"], help="only this document")
    verify.add_argument("--json", action="store_true", help="print the ledger as JSON on stdout")
    verify.add_argument("--fast", action="store_true", help="skip the claims marked slow")
    verify.add_argument("--jobs", type=int, default=2, help="parallel processes (default 2)")
    verify.add_argument("--trace", metavar="KEY", help="print the derivation trace of one claim (substring of its key, or its label as printed by verify)")
    verify.add_argument("--trace-format", choices=("text", "markdown", "latex"), default="text", help="--trace output: plain text (default), or a Markdown / LaTeX block for lecture notes")
    verify.add_argument("--html", metavar="DIR", default=None, help="also render the ledger as browsable HTML pages in DIR")
    verify.add_argument("--out", default=None, help="directory for LEDGER.md and ledger.json (default: the current directory; --doc/--fast runs write LEDGER-<doc>[-fast].md, never the full ledger)")
    verify.set_defaults(func=_lazy("exactcagd.apps.verify", "main"))

    for name, helptext in (("plan", "show what a scene will compute and what is skipped"), ("run", "compute a scene")):
        p = sub.add_parser(name, help=helptext)
        p.add_argument("scene", help="scene file (.toml or .json)")
        p.add_argument("--out", default="out", help="output directory (default: out)")
        p.add_argument("--no-cache", action="store_true", help="ignore cached results")
        p.set_defaults(func=_lazy("exactcagd.scenes.runner", f"cmd_{name}"))

    ref = sub.add_parser("refdata", help="generate exact reference data (JSON Lines suites for testing other kernels)")
    ref.add_argument("kind", help="a record kind (curve_eval, surface_eval, bspline_eval, knot_insertion, bezier_extraction, degree_elevation, subdivision, compose, implicitize, inversion, intersect, roots) or 'suite' for the standard suite")
    ref.add_argument("--count", type=int, default=None, help="records per family (default 10; suite: the standard counts)")
    ref.add_argument("--seed", type=int, default=0, help="random seed: the same seed gives byte-identical output (default 0)")
    ref.add_argument("--degree", default=None, help="degree spec, e.g. 3 or 2,1,2 (N,l,m for compose; default per kind)")
    ref.add_argument("--family", default=None, help="random (default), a hard family of the kind, or all")
    ref.add_argument("--format", default="jsonl", help="jsonl (default) or bezier (the bezier package's functional-test fixtures; --out is a folder)")
    ref.add_argument("--out", default=None, help="output file (default stdout); a folder for 'suite' and --format bezier")
    ref.add_argument("--jobs", type=int, default=2, help="worker processes, or Dask workers with --dask (default 2)")
    ref.add_argument("--scheduler", default=None, help="address of an existing Dask scheduler")
    ref.add_argument("--dask", action="store_true", help="run on a Dask LocalCluster with --jobs workers (dashboard address printed)")
    ref.add_argument("--progress", action="store_true", default=None, help="progress bar on stderr even when it is not a terminal")
    ref.set_defaults(func=_lazy("exactcagd.refdata.suite", "cmd_refdata"))

    conf = sub.add_parser("conformance", help="run another kernel (bezier, geomdl, occ) on a reference suite and grade it")
    conf.add_argument("--kernel", required=True, help="bezier, geomdl, occ, or package.module:Class (your own adapter)")
    conf.add_argument("--suite", required=True, help="suite folder written by 'exactcagd refdata suite --out DIR'")
    conf.add_argument("--out", required=True, help="folder for report.md, report.json and errors.png (replaced)")
    conf.add_argument("--kinds", default=None, help="comma-separated kinds (default: every kind the kernel supports)")
    conf.add_argument("--limit", type=int, default=None, help="only the first N records of each kind")
    conf.add_argument("--quiet", action="store_true", help="no progress on stderr")
    conf.set_defaults(func=_lazy("exactcagd.refdata.conformance", "cmd_conformance"))

    bench = sub.add_parser("bench", help="run the benchmarks")
    bench.add_argument("--quick", action="store_true", help="smaller sizes, minutes not hours (results in benchmarks/results/; full runs in results/full/)")
    bench.add_argument("--only", default=None, help="comma-separated benchmark topics")
    bench.add_argument("--out", default=None, help="folder for tables and plots (default: the checkout's benchmarks/results/)")
    bench.set_defaults(func=_lazy("exactcagd.apps.bench", "main"))
    return parser


def main(argv=None) -> int:
    """Entry point of the ``exactcagd`` command."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --version / --help / usage errors
        return int(exc.code or 0)
    if not getattr(args, "func", None):
        parser.print_help()
        return 0
    try:
        return int(args.func(args) or 0)
    except ExactCAGDError as exc:
        print(f"exactcagd: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
