"""Benchmark: curves on surfaces (Yang et al. 2012) -- parabola / hyperbola / polyline against the
exact composition, and the exact quadratic field against sympy's algebraic field.

For a bicubic relief (``samples.analytic_surface``, face) and the closed 8-point cubic NURBS
domain curve, over a range of tolerances eps_D (angle tolerance 1 deg for the baselines):
wall time of ``approximate`` per method, segments, degree, and the *achieved* error = the
certified Hausdorff bound to the exact image (``distance_bound``); the exact composition
``compose_spline`` (zero error, degree 18) is timed once.

Writes ``benchmarks/results/curves_on_surfaces.md``, a work-precision plot
``curves_on_surfaces_work_precision.png`` (time vs achieved error, log-log, one line per
method, the exact composition as a marker at its time) and ``curves_on_surfaces_scaling.png``
(segments and time vs eps_D).  ``--quick`` (parabola at three tolerances, hyperbola at two,
polyline at one) runs in about a minute; single runs longer than the budget are recorded as
stopped.

Run: ``python -m benchmarks.bench_curves_on_surfaces [--quick]``
"""

from __future__ import annotations

import random
import time

from gmpy2 import mpq

from benchmarks._budget import run_with_budget as _timed
from benchmarks._common import markdown_table, measure, parse_quick, results_dir, write_result
from exactcagd.curves_on_surfaces import approximate
from exactcagd.curves_on_surfaces.samples import analytic_surface, closed_domain_curve
from exactcagd.exact.quadratic import QuadraticNumber

METHODS = ("parabola", "hyperbola", "polyline")


def bench_methods(quick: bool) -> tuple[str, dict]:
    size = 17
    S, D = analytic_surface(size, size, "face"), closed_domain_curve(8)
    tols = ["1e-1", "1e-2", "1e-3"] if quick else ["1e-1", "1e-2", "1e-3", "1e-4", "1e-5"]
    budget = 40.0 if quick else 150.0
    skip = {("hyperbola", "1e-2"), ("polyline", "1e-1"), ("polyline", "1e-2")} if quick else set()
    from exactcagd.composition import compose_spline

    exact, t_exact = _timed(lambda: compose_spline(S, D), budget)
    rows = [[f"face {size}x{size}", "exact composition", "-", len(exact.pieces), max(p.curve.degree for p in exact.pieces), "0", f"{t_exact:.2f}"]]
    data = {"exact": t_exact, "runs": {m: [] for m in METHODS}}
    for tol in tols:
        for method in METHODS:
            if (method, tol) in skip:
                continue
            r, seconds = _timed(lambda: approximate(S, D, tol, method, angle_tol=1), budget)
            if r is None:
                rows.append([f"face {size}x{size}", method, tol, "-", "-", "-", f"> {budget:.0f} (stopped)"])
                continue
            err = float(r.distance_bound)
            data["runs"][method].append((float(tol), seconds, err, len(r)))
            rows.append([f"face {size}x{size}", method, tol, len(r), r.degree, f"{err:.2e}", f"{seconds:.2f}"])
            print(f"{method:9s} eps={tol} segments={len(r)} bound={err:.2e} {seconds:.1f}s", flush=True)
    table = markdown_table(["model", "method", "eps_D", "segments", "degree", "achieved (certified) error", "time (s)"], rows)
    return table, data


def plots(data: dict) -> list[str]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    markers = {"parabola": "o-", "hyperbola": "s-", "polyline": "^-"}
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for method, runs in data["runs"].items():
        if runs:
            ax.loglog([x[2] for x in runs], [x[1] for x in runs], markers[method], label=method)
    ax.axhline(data["exact"], color="k", ls=":", label="exact composition (error 0)")
    ax.set_xlabel("achieved error: certified Hausdorff bound to S(D(t))")
    ax.set_ylabel("time (s)")
    ax.set_title("curves on surfaces: work vs precision")
    ax.legend(fontsize=8)
    fig.tight_layout()
    wp = results_dir() / "curves_on_surfaces_work_precision.png"
    fig.savefig(wp, dpi=100)
    plt.close(fig)

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    for method, runs in data["runs"].items():
        if runs:
            a1.loglog([x[0] for x in runs], [x[3] for x in runs], markers[method], label=method)
            a2.loglog([x[0] for x in runs], [x[1] for x in runs], markers[method], label=method)
    a1.set_xlabel("eps_D")
    a1.set_ylabel("segments")
    a2.set_xlabel("eps_D")
    a2.set_ylabel("time (s)")
    a1.invert_xaxis()
    a2.invert_xaxis()
    a1.legend(fontsize=8)
    fig.suptitle("scaling with the tolerance (angle tolerance 1 deg for the baselines)")
    fig.tight_layout()
    sc = results_dir() / "curves_on_surfaces_scaling.png"
    fig.savefig(sc, dpi=100)
    plt.close(fig)
    return [wp.name, sc.name]


def bench_field(quick: bool) -> str:
    """Multiply-add chains in Q(sqrt(D)): exactcagd QuadraticNumber vs sympy ANP elements."""
    import sympy
    from sympy import QQ

    rng = random.Random(1)
    D = 1000003
    n = 200 if quick else 1000
    data = [(mpq(rng.randint(-10**12, 10**12), rng.randint(1, 10**9)), mpq(rng.randint(-10**12, 10**12), rng.randint(1, 10**9))) for _ in range(n)]
    mine = [QuadraticNumber(a, b, D) for a, b in data]
    K = QQ.algebraic_field(sympy.sqrt(D))
    theirs = [K.from_sympy(sympy.Rational(int(a.numerator), int(a.denominator)) + sympy.Rational(int(b.numerator), int(b.denominator)) * sympy.sqrt(D)) for a, b in data]

    def chain_div(xs):
        acc = xs[0]
        for x in xs[1:50]:
            acc = (acc + x) / (x + 3)
        return acc

    t_mine = measure(lambda: [a * b + a for a, b in zip(mine[:-1], mine[1:])], repeat=5)
    t_sym = measure(lambda: [a * b + a for a, b in zip(theirs[:-1], theirs[1:])], repeat=3)
    t_mine_div = measure(lambda: chain_div(mine), repeat=5)
    t_sym_div = measure(lambda: chain_div(theirs), repeat=3)
    rows = [
        [f"{n - 1} products a*b + a", t_mine.fmt(), t_sym.fmt(), f"{t_sym.median / t_mine.median:.1f}x"],
        ["49 steps (acc + x)/(x + 3)", t_mine_div.fmt(), t_sym_div.fmt(), f"{t_sym_div.median / t_mine_div.median:.1f}x"],
    ]
    return markdown_table(["workload (D = 1000003)", "QuadraticNumber", "sympy ANP", "speed-up"], rows)


def main(quick: bool = False) -> None:
    start = time.perf_counter()
    table, data = bench_methods(quick)
    pictures = plots(data)
    body = (
        ("quick mode: parabola at 3 tolerances, hyperbola at 2, polyline at 1\n\n" if quick else "")
        + "## Methods (eps_T = 1 deg for the baselines; closed 8-point cubic NURBS domain curve)\n\n"
        + table
        + "\n\nPlots: " + ", ".join(f"`{p}`" for p in pictures)
        + "\n\n## Exact quadratic field\n\n" + bench_field(quick)
        + f"\n\nTotal benchmark time {time.perf_counter() - start:.1f} s.\n"
    )
    path = write_result("curves_on_surfaces", "Curves on surfaces: parabola / hyperbola / polyline / exact", body)
    print(path.read_text())


if __name__ == "__main__":
    main(parse_quick(__doc__.splitlines()[0]))
