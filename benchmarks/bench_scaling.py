"""Benchmark: how exactcagd's cost grows -- with degree, with number of patches, with tolerance.

1. Degree: ``compose(S, D)`` for a Bézier surface of degree ``(l, l)`` and a domain curve of
   degree ``N`` (polynomial and rational); the result has degree ``N (l + m) = 2 N l``
   (Lasser & Bonneau, Theorem 1).  Time against the output degree, with the fitted
   exponent ``time ~ degree^k``.
2. Patches: ``compose_spline(S, D)`` for a bicubic NURBS surface with ``k x k`` uniform knot
   spans (``k = 1, 2, 4, ...``) and a fixed cubic domain curve: pieces (patch crossings,
   located exactly) and time.
3. Tolerance: ``approximate(S, D, tol, "parabola")`` (Yang et al. 2012) on the ``4 x 4``
   NURBS surface for ``tol = 1e-1 ...``: segments and time.

Writes ``results/scaling.md`` and ``results/scaling_degree.png``, ``scaling_patches.png``,
``scaling_tolerance.png`` (log-log).

Run: ``python -m benchmarks --only scaling [--quick]``
"""

from __future__ import annotations

import random
from fractions import Fraction as Fr

import numpy as np

from benchmarks._common import loglog_plot, markdown_table, measure, parse_quick, write_result
from exactcagd import BezierCurve, BezierSurface, BSplineSurface
from exactcagd.composition import compose, compose_spline
from exactcagd.curves_on_surfaces import approximate

DOMAIN = [["1/10", "1/5"], ["2/5", "1"], ["7/10", "0"], ["9/10", "4/5"]]


def fitted_exponent(xs, ys) -> float:
    """Least-squares slope of ``log y`` against ``log x``."""
    if len(xs) < 2:
        return float("nan")
    return float(np.polyfit(np.log(xs), np.log(ys), 1)[0])


def _rq(rng) -> Fr:
    return Fr(rng.randint(0, 1000), 1000)


def bezier_instance(l: int, n: int, rational: bool, seed: int = 0):
    rng = random.Random(seed + 97 * l + n)
    net = [[[_rq(rng), _rq(rng), _rq(rng)] for _ in range(l + 1)] for _ in range(l + 1)]
    ws = [[Fr(rng.randint(1, 9), rng.randint(1, 9)) for _ in range(l + 1)] for _ in range(l + 1)] if rational else None
    pts = [[_rq(rng), _rq(rng)] for _ in range(n + 1)]
    wc = [Fr(rng.randint(1, 9), rng.randint(1, 9)) for _ in range(n + 1)] if rational else None
    return BezierSurface(net, ws), BezierCurve(pts, wc)


def nurbs_surface(spans: int, seed: int = 1) -> BSplineSurface:
    """Bicubic NURBS height field over [0, 1]^2 with ``spans x spans`` uniform knot spans."""
    rng = random.Random(seed)
    n = spans + 3
    knots = [Fr(0)] * 4 + [Fr(i, spans) for i in range(1, spans)] + [Fr(1)] * 4
    net = [[[Fr(i, n - 1), Fr(j, n - 1), Fr(rng.randint(-500, 500), 1000)] for j in range(n)] for i in range(n)]
    ws = [[Fr(rng.randint(2, 8), 4) for _ in range(n)] for _ in range(n)]
    return BSplineSurface(net, knots, knots, ws)


def degree_scaling(quick: bool, rows: list, plot: dict) -> str:
    pairs = [(1, 1), (1, 2), (2, 2), (3, 1), (3, 2), (3, 3), (5, 2), (5, 3), (4, 5), (6, 4)]
    if not quick:
        pairs += [(5, 5), (7, 5), (8, 6)]
    notes = []
    for rational in (False, True):
        kind = "rational" if rational else "polynomial"
        xs, ys = [], []
        for l, n in pairs:
            surface, curve = bezier_instance(l, n, rational)
            timing = measure(lambda: compose(surface, curve, shortcut=False), repeat=5 if quick else 7,
                             budget=2 if quick else 10, memory=True)
            degree = 2 * n * l
            rows.append([kind, f"({l}, {l})", n, degree, timing.fmt(), timing.fmt_memory()])
            xs.append(degree)
            ys.append(timing.low)
        plot[f"compose, {kind}"] = sorted(zip(xs, ys))
        big = [(x, y) for x, y in zip(xs, ys) if x >= 12]
        notes.append(f"{kind}: time ~ degree^{fitted_exponent(*zip(*big)):.2f} (fit over output degree >= 12)")
    return "; ".join(notes)


def patch_scaling(quick: bool, rows: list, plot: dict) -> str:
    spans_list = (1, 2, 4, 8) if quick else (1, 2, 4, 8, 16, 32)
    domain = BezierCurve(DOMAIN)
    xs, ys = [], []
    for spans in spans_list:
        surface = nurbs_surface(spans)
        holder = {}
        timing = measure(lambda: holder.__setitem__("r", compose_spline(surface, domain)), repeat=3 if quick else 5,
                         budget=5 if quick else 30, memory=True)
        pieces = len(holder["r"].pieces)
        rows.append([f"{spans} x {spans}", spans * spans, pieces, timing.fmt(), f"{timing.median / pieces * 1e3:.2f} ms",
                     timing.fmt_memory()])
        xs.append(pieces)
        ys.append(timing.low)
    plot["compose_spline (bicubic NURBS)"] = list(zip(xs, ys))
    split = [(x, y) for x, y in zip(xs, ys) if x > 1]
    return f"time ~ pieces^{fitted_exponent(*zip(*split)):.2f} (fit over the split cases, pieces > 1)"


def tolerance_scaling(quick: bool, rows: list, plot: dict) -> str:
    tols = ["1e-1", "1e-2", "1e-3", "1e-4", "1e-5"] if quick else ["1e-1", "1e-2", "1e-3", "1e-4", "1e-5", "1e-6"]
    surface = nurbs_surface(4)
    domain = BezierCurve(DOMAIN)
    xs, ys, segs = [], [], []
    for tol in tols:
        holder = {}
        timing = measure(lambda t=tol: holder.__setitem__("r", approximate(surface, domain, t, "parabola")), repeat=1,
                         budget=60)
        r = holder["r"]
        rows.append([tol, len(r), r.degree, f"{float(r.distance_bound):.2e}", timing.fmt()])
        xs.append(float(tol))
        ys.append(timing.median)
        segs.append(len(r))
    plot["approximate parabola: seconds"] = list(zip(xs, ys))
    plot["approximate parabola: segments"] = list(zip(xs, segs))
    return (f"over all tolerances time ~ tol^{fitted_exponent(xs, ys):.2f}, segments ~ tol^{fitted_exponent(xs, segs):.2f}; "
            f"last decade: time ~ tol^{fitted_exponent(xs[-2:], ys[-2:]):.2f}, "
            f"segments ~ tol^{fitted_exponent(xs[-2:], segs[-2:]):.2f} (coarse tolerances are dominated by the "
            "cuts at knot lines, which are needed whatever the tolerance)")


def main(quick: bool | None = None) -> None:
    if quick is None:
        quick = parse_quick(__doc__.splitlines()[0])
    deg_rows, deg_plot = [], {}
    deg_note = degree_scaling(quick, deg_rows, deg_plot)
    print("degree scaling done", flush=True)
    patch_rows, patch_plot = [], {}
    patch_note = patch_scaling(quick, patch_rows, patch_plot)
    print("patch scaling done", flush=True)
    tol_rows, tol_plot = [], {}
    tol_note = tolerance_scaling(quick, tol_rows, tol_plot)
    print("tolerance scaling done", flush=True)
    mem = "peak traced memory"
    body = (
        f"Mode: {'quick' if quick else 'full'}. Times: median (min-max) of repeated runs in one process; the fitted "
        "exponents and the plots use the minimum (least disturbed by other load on the shared cores).\n\n"
        "## 1. Exact composition vs output degree N(l+m)\n\n"
        "Random surfaces of degree (l, l) and domain curves of degree N (coordinates k/1000, weights p/q, 1 <= p, q <= 9), "
        f"`compose(..., shortcut=False)`.  Fitted: {deg_note}.\n\n"
        + markdown_table(["kind", "surface degree", "curve degree N", "output degree N(l+m)", "time", mem], deg_rows)
        + "\n\nPlot: `scaling_degree.png`.\n\n"
        "## 2. compose_spline vs number of patches\n\n"
        "Bicubic NURBS height field with k x k uniform knot spans (weights in [1/2, 2]); domain curve: cubic with control "
        f"points {', '.join('(' + ', '.join(p) + ')' for p in DOMAIN)}.  Fitted: {patch_note}.\n\n"
        + markdown_table(["knot spans", "patches", "pieces crossed", "time", "time per piece", mem], patch_rows)
        + "\n\nPlot: `scaling_patches.png`.\n\n"
        "## 3. approximate (parabola) vs tolerance\n\n"
        f"Same curve on the 4 x 4-span NURBS surface.  Fitted: {tol_note}.\n\n"
        + markdown_table(["tol", "segments", "degree", "certified bound", "time (one run)"], tol_rows)
        + "\n\nPlot: `scaling_tolerance.png`.\n"
    )
    path = write_result("scaling", "Scaling: degree, patches, tolerance", body)
    loglog_plot("scaling_degree.png", deg_plot, "output degree N(l+m)", "seconds", "Exact composition: time vs degree")
    loglog_plot("scaling_patches.png", patch_plot, "pieces (patch crossings)", "seconds", "compose_spline: time vs pieces")
    loglog_plot("scaling_tolerance.png", tol_plot, "tolerance", "seconds / segments", "approximate (parabola) vs tolerance")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
