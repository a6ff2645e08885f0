"""Benchmark of the algebra layer (Sederberg's notes, chapters 17-18).

1. Implicitization of random rational planar curves of degree n (3..16; quick 3..8),
   every route exact, same input, same process:

   * ``flint res``   -- Res_t(W x - X, W y - Y) by python-flint (subresultants):
     the fastest plain resultant callable available;
   * ``sympy res``   -- ``sympy.resultant`` of the same pair (skipped once it exceeds
     the time budget);
   * ``Sylvester``   -- Bareiss on the 2n x 2n Sylvester matrix (17.3.5);
   * ``Bezout nxn``  -- Bareiss on the notes' n x n Bezout matrix, power form (17.3.4);
   * ``Bezier l_ij`` -- the same in Bernstein form with the l_ij (17.6);
   * ``ML det``      -- moving lines as the notes do them: zeroing process for the
     mu-basis, then the (n - mu) x (n - mu) Bezout determinant (18.4.6);
   * ``ML flint``    -- the same mu-basis, resultant by python-flint;
   * ``implicitize`` -- the public call (default route + normalization).

   The notes claim the moving-line route is faster than the n x n Bezout
   determinant (18.4.6); the ratio column ``ML det / Bezout`` answers it.
2. Univariate integer resultants (flint vs Bareiss vs sympy).
3. Gröbner engines (17.11): python-flint's naive Buchberger, sympy's Buchberger and
   f5b, and exactcagd's ``auto`` engine, each run in a child process with a timeout.

Run:  python benchmarks/bench_algebra.py [--quick]
Writes benchmarks/results/algebra.md.
"""

from __future__ import annotations

import multiprocessing as mp
import random
import sys
import time
from pathlib import Path

import sympy

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks._common import Timing, markdown_table, measure, parse_quick, write_result  # noqa: E402
from exactcagd import BezierCurve  # noqa: E402
from exactcagd.algebra import implicitize  # noqa: E402
from exactcagd.algebra.implicitize import implicit_bezier, implicit_resultant, reduced_components  # noqa: E402
from exactcagd.algebra.moving_lines import _bernstein_hom, implicit_from_moving_lines, zeroing_process  # noqa: E402


def curve_instance(n: int, seed: int = 0) -> BezierCurve:
    rng = random.Random(1000 * seed + n)
    pts = [[rng.randint(0, 1000), rng.randint(0, 1000)] for _ in range(n + 1)]
    w = [rng.randint(1, 9) for _ in range(n + 1)]
    return BezierCurve(pts, w)


def _ml(X, Y, W, via):
    res = zeroing_process(_bernstein_hom(X, Y, W))
    p, q = res.lines
    return implicit_from_moving_lines(p, q, via)


def _sympy_res(X, Y, W):
    x, y, t = sympy.symbols("x y t")
    P = lambda p: sum(int(c) * t**k for k, c in enumerate(p.coeffs()))  # noqa: E731
    return lambda: sympy.resultant(sympy.expand(P(W) * x - P(X)), sympy.expand(P(W) * y - P(Y)), t)


def bench_implicit(degrees, budget):
    tools = ["flint res", "sympy res", "Sylvester", "Bezout nxn", "Bezier l_ij", "ML det", "ML flint", "implicitize"]
    dropped = set()
    rows = []
    for n in degrees:
        curve = curve_instance(n)
        X, Y, W, _ = reduced_components(curve)
        funcs = {
            "flint res": lambda: implicit_resultant(X, Y, W, "flint"),
            "sympy res": _sympy_res(X, Y, W),
            "Sylvester": lambda: implicit_resultant(X, Y, W, "sylvester"),
            "Bezout nxn": lambda: implicit_resultant(X, Y, W, "bezout"),
            "Bezier l_ij": lambda: implicit_bezier(X, Y, W),
            "ML det": lambda: _ml(X, Y, W, "bezout"),
            "ML flint": lambda: _ml(X, Y, W, "flint"),
            "implicitize": lambda: implicitize(curve),
        }
        times = {}
        for name in tools:
            if name in dropped:
                continue
            t0 = time.perf_counter()
            funcs[name]()  # warm-up and budget probe
            first = time.perf_counter() - t0
            if first > budget:
                times[name] = Timing(first, first, first, 1)
                dropped.add(name)  # larger n would take longer still
                continue
            times[name] = measure(funcs[name], repeat=5 if first < 1 else 2, budget=budget)
        fmt = lambda k: times[k].fmt() if k in times else "(skipped: over budget)"  # noqa: E731
        ratio_ml = times["ML det"].median / times["Bezout nxn"].median if "ML det" in times and "Bezout nxn" in times else float("nan")
        ratio_mlf = times["ML flint"].median / times["flint res"].median if "ML flint" in times and "flint res" in times else float("nan")
        rows.append([n] + [fmt(k) for k in tools] + [f"{ratio_ml:.2f}", f"{ratio_mlf:.2f}"])
        print(n, {k: round(v.median, 4) for k, v in times.items()}, flush=True)
    headers = ["n"] + tools + ["ML det / Bezout nxn", "ML flint / flint res"]
    return markdown_table(headers, rows), rows


def bench_univariate(degrees, budget):
    import flint

    from exactcagd.algebra.resultants import resultant_coeffs

    rows = []
    for d in degrees:
        rng = random.Random(d)
        a = [rng.randint(-99, 99) for _ in range(d)] + [rng.randint(1, 99)]
        b = [rng.randint(-99, 99) for _ in range(d)] + [rng.randint(1, 99)]
        t = sympy.Symbol("t")
        fa, fb = flint.fmpz_poly(a), flint.fmpz_poly(b)
        sa, sb = sum(c * t**k for k, c in enumerate(a)), sum(c * t**k for k, c in enumerate(b))
        cells = [d]
        for f in (lambda: fa.resultant(fb), lambda: resultant_coeffs(a, b, "sylvester"), lambda: resultant_coeffs(a, b, "bezout"), lambda: sympy.resultant(sa, sb, t)):
            cells.append(measure(f, repeat=3, budget=budget).fmt())
        rows.append(cells)
    return markdown_table(["degree", "flint fmpz_poly", "Sylvester (Bareiss)", "Bezout (Bareiss)", "sympy"], rows)


# ------------------------------------------------------------------ Gröbner engines
def _gb_problems():
    x, y, z, w, v, s, t = sympy.symbols("x y z w v s t")
    c4 = [x + y + z + w, x * y + y * z + z * w + w * x, x * y * z + y * z * w + z * w * x + w * x * y, x * y * z * w - 1]
    k3 = [x + 2 * y + 2 * z + 2 * w - 1, x**2 + 2 * y**2 + 2 * z**2 + 2 * w**2 - x, 2 * x * y + 2 * y * z + 2 * z * w - y, y**2 + 2 * x * z + 2 * y * w - z]
    k4 = [
        x + 2 * y + 2 * z + 2 * w + 2 * v - 1,
        x**2 + 2 * y**2 + 2 * z**2 + 2 * w**2 + 2 * v**2 - x,
        2 * x * y + 2 * y * z + 2 * z * w + 2 * w * v - y,
        y**2 + 2 * x * z + 2 * y * w + 2 * z * v - z,
        2 * y * z + 2 * x * w + 2 * y * v - w,
    ]
    X, Y, W = 2 * t**3 - 18 * t**2 + 18 * t + 4, 39 * t**3 - 69 * t**2 + 33 * t + 1, -3 * t**2 + 3 * t + 1
    impl = [W * x - X, W * y - Y, W * s - 1]
    return {
        "cyclic-4": (c4, [x, y, z, w]),
        "katsura-3": (k3, [x, y, z, w]),
        "katsura-4": (k4, [x, y, z, w, v]),
        "implicitize 17.5 cubic (elim s, t)": (impl, [s, t, x, y]),
    }


def _gb_child(name, order, engine, queue):
    from exactcagd.algebra.groebner import groebner_basis

    polys, gens = _gb_problems()[name]
    times = []
    for _ in range(3):
        t0 = time.perf_counter()
        G = groebner_basis(polys, gens, order, engine)
        times.append(time.perf_counter() - t0)
        if times[-1] > 2:
            break
    queue.put((min(times), len(G)))


def bench_groebner(timeout):
    ctx = mp.get_context("fork")
    engines = ["flint", "buchberger", "f5b", "auto"]
    rows = []
    for name in _gb_problems():
        orders = ["lex"] if name.startswith("implicitize") else ["grevlex", "lex"]
        for order in orders:
            cells = [name, order]
            for engine in engines:
                q = ctx.Queue()
                p = ctx.Process(target=_gb_child, args=(name, order, engine, q))
                p.start()
                p.join(timeout)
                if p.is_alive():
                    p.terminate()
                    p.join()
                    cells.append(f"> {timeout:.0f} s (killed)")
                else:
                    try:
                        sec, size = q.get(timeout=1)
                        cells.append(f"{sec * 1e3:.1f} ms ({size})" if sec < 1 else f"{sec:.2f} s ({size})")
                    except Exception:  # noqa: BLE001
                        cells.append("error")
            rows.append(cells)
            print(cells, flush=True)
    return markdown_table(["ideal", "order"] + [f"{e}" for e in engines], rows)


def main():
    quick = parse_quick(__doc__.splitlines()[0])
    degrees = list(range(3, 9)) if quick else list(range(3, 17))
    budget = 15.0 if quick else 60.0
    table, rows = bench_implicit(degrees, budget)
    uni = bench_univariate([10, 20, 40] if quick else [10, 20, 40, 80], budget)
    gb = bench_groebner(20 if quick else 120)
    ml_faster = [r[0] for r in rows if r[-2] != "nan" and float(r[-2]) < 1]
    ml_slower = [r[0] for r in rows if r[-2] != "nan" and float(r[-2]) >= 1]
    verdict = (
        f"Moving lines vs the n x n Bezout determinant (same Bareiss elimination): faster for n in {ml_faster}, "
        f"not faster for n in {ml_slower}.  "
        "The (n - mu) x (n - mu) matrix is smaller, but the mu-basis coefficients are about n/2 times "
        "longer than the control points (a few hundred bits at n = 16 for 10-bit input), so in exact arithmetic "
        "the smaller determinant does not pay off at high degree; python-flint's subresultant resultant of the "
        "original pair (Res_t(W x - X, W y - Y)) is the fastest route throughout and is implicitize()'s default."
    )
    body = "\n\n".join(
        [
            "## Implicitization of random rational curves (coordinates 0..1000, weights 1..9)",
            "Median (min-max) of repeated runs; routes that exceeded the per-call budget are not run for larger n.",
            table,
            "**Verdict on notes 18.4.6.** " + verdict,
            "## Univariate integer resultants (coefficients -99..99)",
            uni,
            "## Gröbner bases (17.11): engines, minimum of up to 3 runs (basis size)",
            "`flint` = python-flint `fmpz_mpoly_vec.buchberger_naive` + `autoreduction` without limits; "
            "`auto` = exactcagd's choice (flint with size limits, then flint grevlex + FGLM for zero-dimensional lex, "
            "then sympy f5b).",
            gb,
        ]
    )
    path = write_result("algebra", "Algebra layer: resultants, implicitization, Gröbner bases", body)
    print("wrote", path)


if __name__ == "__main__":
    main()
