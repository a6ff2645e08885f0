"""Curve intersection (issue 15): the exact route's scaling over degree 3..30 against the
float routes and bezier's ``Curve.intersect``; the interval method's ratio to subdivision
on the hard fixture pairs.

Pairs: two random integer Bézier curves of degree n (coordinates in [-100, 100], seeded),
the same pair for every route.  Every route must return the same number of
intersections (the exact route is the reference; bezier's float answer is counted too).
Goals (issue 15): exact route < 1 s at degree 10 and < 10 s at degree 20 on one core;
interval method <= 3x subdivision on every fixture.

Run: ``python -m benchmarks.bench_intersection [--quick]`` (quick: degrees 3-30 in 8 steps).
"""

from __future__ import annotations

import random
import time

from exactcagd import BezierCurve, limits
from exactcagd.numeric.intersection import intersect

from ._common import loglog_plot, markdown_table, optional_peer, parse_quick, write_result

ROUTES = ("exact", "clipping", "subdivision", "interval")


def random_pair(n: int, seed: int = 0):
    rng = random.Random(1000 * n + seed)
    return tuple(BezierCurve([[rng.randint(-100, 100), rng.randint(-100, 100)] for _ in range(n + 1)]) for _ in range(2))


def fixtures() -> dict:
    """The hard pairs of tests/test_intersection_fixtures.py (tangencies, contacts, rational, shared)."""
    return {
        "tangent order 2": (BezierCurve([[0, 0], [1, 2], [2, 0]]), BezierCurve([[0, 1], [2, 1]])),
        "tangent order 3": (BezierCurve([["-1/2", "1/4"], [0, "-1/4"], ["1/2", "1/4"]]),
                            BezierCurve([["-1/4", "1/4"], ["-1/4", "-1/4"], ["3/4", "1/4"]])),
        "end point contact": (BezierCurve([[0, 0], [1, 1]]), BezierCurve([[1, 1], [2, 0], [3, 3]])),
        "rational crossing": (BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2]), BezierCurve([[0, 0], [1, 1]])),
        "rational tangent": (BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2]), BezierCurve([["-1/5", "7/5"], ["7/5", "1/5"]])),
        "shared arc": (BezierCurve([[0, 0], ["1/2", 0], [1, 1]]), BezierCurve([["1/2", "1/4"], [1, "3/4"], ["3/2", "9/4"]])),
        "shared, end point only": (BezierCurve([[0, 0], ["1/2", 0], [1, 1]]), BezierCurve([[1, 1], ["3/2", 2], [2, 4]])),
        "weights 1e8": (BezierCurve([[0, 0], [1, 2], [2, 0]], weights=[1, 10**8, 1]), BezierCurve([[0, "1/2"], [2, "1/2"]])),
    }


def _bezier_count(bezier, a, b) -> int:
    import numpy as np

    def conv(c):
        pts = np.asfortranarray(np.array([[float(x) for x in p] for p in c.points_array()]).T)
        return bezier.Curve(pts, degree=c.degree)

    return conv(a).intersect(conv(b)).shape[1]


def _time(func):
    t0 = time.perf_counter()
    value = func()
    return time.perf_counter() - t0, value


def scaling(degrees, bezier) -> tuple[list, dict]:
    rows, series = [], {r: [] for r in ROUTES + (("bezier (float)",) if bezier else ())}
    for n in degrees:
        a, b = random_pair(n)
        times, counts = {}, {}
        with limits.raised(max_implicit_degree=max(n, 24)):
            for route in ROUTES:
                seconds, res = _time(lambda: intersect(a, b, method=route))
                times[route], counts[route] = seconds, len(res)
                series[route].append((n, seconds))
        if bezier:
            try:
                seconds, count = _time(lambda: _bezier_count(bezier, a, b))
                series["bezier (float)"].append((n, seconds))
            except ValueError as exc:  # "failed to converge to approximately linear subdivisions"
                seconds, count = float("nan"), f"failed: {str(exc)[:40]}"
            times["bezier"], counts["bezier"] = seconds, count
        agree = all(c == counts["exact"] for k, c in counts.items() if k != "bezier")
        rows.append([n, n * n, counts["exact"], "yes" if agree else f"NO {counts}"]
                    + [f"{times[r]:.3f}" for r in ROUTES] + ([f"{times['bezier']:.4f} ({counts['bezier']})"] if bezier else []))
        print(f"degree {n}: " + ", ".join(f"{k} {v:.3f} s" for k, v in times.items()) + f" counts {counts}", flush=True)
    return rows, series


def fixture_ratios() -> list:
    rows = []
    for name, (a, b) in fixtures().items():
        t = {}
        for route in ("subdivision", "interval", "clipping", "exact"):
            best = min(_time(lambda: intersect(a, b, method=route))[0] for _ in range(3))
            t[route] = best
        rows.append([name] + [f"{t[r] * 1e3:.1f}" for r in ("subdivision", "interval", "clipping", "exact")]
                    + [f"{t['interval'] / t['subdivision']:.2f}"])
    return rows


def main(quick: bool | None = None) -> None:
    if quick is None:
        quick = parse_quick(__doc__.splitlines()[0])
    bezier = optional_peer("bezier", "bezier's Curve.intersect")
    degrees = [3, 5, 8, 10, 15, 20, 25, 30] if quick else [3, 5, 8, 10, 12, 15, 18, 20, 22, 25, 28, 30]
    rows, series = scaling(degrees, bezier)
    plot = loglog_plot("intersection_scaling.png", series, "degree n of both curves", "seconds",
                       "Curve intersection: exact route vs float routes vs bezier")
    headers = ["degree", "resultant degree", "intersections", "routes agree"] + [f"{r} (s)" for r in ROUTES]
    headers += ["bezier (s, count)"] if bezier else []
    fx = fixture_ratios()
    exact_at = {row[0]: float(row[4]) for row in rows}
    worst = max(fx, key=lambda r: float(r[-1]))
    goals = [
        f"exact route, degree 10: {exact_at.get(10, float('nan')):.2f} s (goal < 1 s)",
        f"exact route, degree 20: {exact_at.get(20, float('nan')):.2f} s (goal < 10 s)",
        f"interval / subdivision on the fixtures: at most {worst[-1]} ({worst[0]}; goal <= 3)",
    ]
    body = "\n\n".join([
        "## Goals (issue 15)",
        "\n".join(f"- {g}" for g in goals),
        "## Scaling (random integer pairs, one process, 2 cores shared with other work)",
        markdown_table(headers, rows),
        f"Plot: `{plot.name}`.  Float routes run with the default work bound and exact fallback; "
        "bezier is a float peer without certification (its count may differ on tangencies).",
        "## Hard fixtures: milliseconds (best of 3) and interval / subdivision",
        markdown_table(["pair", "subdivision", "interval", "clipping", "exact", "interval / subdivision"], fx),
    ])
    path = write_result("bench_intersection", "Curve intersection: exact scaling and fixture ratios", body)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
