"""Benchmark: curves on surfaces (Yang et al. 2012) -- parabola / hyperbola / polyline, the exact
composition, and the exact quadratic field against sympy's algebraic field.

Usage::

    python -m benchmarks.bench_curves_on_surfaces [--quick]

Writes ``benchmarks/results/curves_on_surfaces.md``.
"""

from __future__ import annotations

import random

from gmpy2 import mpq

from benchmarks._common import markdown_table, measure, parse_quick, write_result
from exactcagd.curves_on_surfaces import approximate
from exactcagd.curves_on_surfaces.samples import analytic_surface, closed_domain_curve
from exactcagd.exact.quadratic import QuadraticNumber


def bench_methods(quick: bool) -> str:
    cases = [("face 17x17", analytic_surface(17, 17, "face"), closed_domain_curve(8))]
    if not quick:
        cases.append(("venus 145x55", analytic_surface(145, 55, "venus"), closed_domain_curve(12)))
    tols = ["1e-2"] if quick else ["1e-2", "1e-4"]
    rows = []
    for name, S, D in cases:
        try:
            from exactcagd.composition import compose_spline

            holder = {}
            timing = measure(lambda: holder.__setitem__("r", compose_spline(S, D)), repeat=1 if quick else 3, budget=120)
            rows.append([name, "exact composition", "-", len(holder["r"].pieces), max(p.curve.degree for p in holder["r"].pieces), "0", timing.fmt()])
        except ImportError:
            rows.append([name, "exact composition", "-", "n/a", "n/a", "-", "composition package missing"])
        for tol in tols:
            for method in ("parabola", "hyperbola", "polyline"):
                if quick and method == "polyline":
                    continue
                holder = {}
                timing = measure(lambda: holder.__setitem__("r", approximate(S, D, tol, method, angle_tol=1)), repeat=1, budget=600)
                r = holder["r"]
                rows.append([name, method, tol, len(r), r.degree, f"{float(r.distance_bound):.2e}", timing.fmt()])
    return markdown_table(["model", "method", "eps_D", "segments", "degree", "certified bound", "time"], rows)


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


def main() -> None:
    quick = parse_quick(__doc__.splitlines()[0])
    body = "## Methods (eps_T = 1 deg for the baselines)\n\n" + bench_methods(quick)
    body += "\n\n## Exact quadratic field\n\n" + bench_field(quick) + "\n"
    path = write_result("curves_on_surfaces", "Curves on surfaces: parabola / hyperbola / polyline / exact", body)
    print(path.read_text())


if __name__ == "__main__":
    main()
