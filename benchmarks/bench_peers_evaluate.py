"""Benchmark: float evaluation of Bézier curves and surfaces, exactcagd against its peers.

Tools (peers from ``pip install exactcagd[peers]``; an absent peer is skipped with a message):

* ``exactcagd.numeric.evaluate`` / ``evaluate_surface`` -- methods ``auto`` (the default), ``decasteljau``,
  ``horner``, ``power``; values only (``bound=False``) and with the certified radius
  (``bound=True``);
* ``bezier`` (``Curve.evaluate_multi``, compiled) -- polynomial curves; rational curves
  through the homogeneous curve ``(wP, w)`` and a division (``bezier`` has no rational
  curves and only *triangular* surfaces, so no tensor-product surface row);
* ``geomdl`` (pure Python; ``evaluate_list`` on a one-span clamped B-spline / NURBS);
* OpenCASCADE through ``cadquery-ocp`` (``Geom_BezierCurve.Value`` and
  ``Geom_BSplineSurface.Value`` in a Python loop: OCP 8.0 exposes no vectorised
  evaluator, so the Python call overhead is part of the figure).

Inputs: control points with coordinates ``k / 2^20`` in [-1, 1] and weights ``k / 2^10``
in [1/2, 2] (exact binary64 numbers, so every tool receives *identical* data), fixed seed.
Error: the largest componentwise ``|float value - exact value|`` over check parameters,
computed exactly in ``mpq`` from exactcagd's exact de Casteljau (``BezierCurve.evaluate`` /
``BezierSurface.evaluate``, all rational arithmetic); the row "correctly rounded" is the
floor any float evaluator can reach (the exact value rounded once).

Writes ``results/peers_evaluate.md`` and ``results/peers_evaluate_work_precision.png``
(seconds per point against max error, log-log).

Run: ``python -m benchmarks --only peers_evaluate [--quick]``
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from benchmarks._common import markdown_table, measure, optional_peer, parse_quick, ratio, results_dir, write_result
from exactcagd import BezierCurve, BezierSurface
from exactcagd.numeric.evaluation import METHODS, evaluate, evaluate_surface

DIM = 3


# ----------------------------------------------------------------------------- inputs
def _coords(rng, shape) -> np.ndarray:
    den = 1 << 20
    return rng.integers(-den, den + 1, shape) / den


def _weights(rng, shape) -> np.ndarray:
    return rng.integers(512, 2049, shape) / 1024


def _exact(a: np.ndarray) -> list:
    return np.vectorize(lambda x: mpq(*float(x).as_integer_ratio()), otypes=[object])(a).tolist()


def make_curve(n: int, rational: bool, rng) -> tuple:
    pts = _coords(rng, (n + 1, DIM))
    w = _weights(rng, n + 1) if rational else None
    return BezierCurve(_exact(pts), None if w is None else _exact(w)), pts, w


def make_surface(l: int, m: int, rational: bool, rng) -> tuple:
    net = _coords(rng, (l + 1, m + 1, DIM))
    w = _weights(rng, (l + 1, m + 1)) if rational else None
    return BezierSurface(_exact(net), None if w is None else _exact(w)), net, w


def max_error(values: np.ndarray, exact: list) -> float:
    """Largest componentwise ``|values - exact|``, computed exactly (``mpq``)."""
    worst = mpq(0)
    for row, ex in zip(values, exact):
        for v, e in zip(row, ex):
            worst = max(worst, abs(mpq(float(v)) - e))
    return float(worst)


def rounded(exact: list) -> np.ndarray:
    return np.array([[float(e) for e in row] for row in exact])


# ----------------------------------------------------------------------------- peers
def bezier_curve(mod, pts, w):
    """``bezier.Curve`` of the (homogeneous, if rational) control points; returns ts -> values."""
    n = len(pts) - 1
    if w is None:
        curve = mod.Curve(np.asfortranarray(pts.T), degree=n)
        return lambda ts: curve.evaluate_multi(ts).T
    hom = np.vstack([(pts * w[:, None]).T, w])
    curve = mod.Curve(np.asfortranarray(hom), degree=n)

    def run(ts):
        h = curve.evaluate_multi(ts)
        return (h[:-1] / h[-1]).T

    return run


def geomdl_curve(mod, pts, w):
    n = len(pts) - 1
    crv = mod.NURBS.Curve() if w is not None else mod.BSpline.Curve()
    crv.degree = n
    if w is None:
        crv.ctrlpts = pts.tolist()
    else:
        crv.ctrlptsw = np.hstack([pts * w[:, None], w[:, None]]).tolist()
    crv.knotvector = [0.0] * (n + 1) + [1.0] * (n + 1)
    return lambda ts: np.array(crv.evaluate_list(ts.tolist()))


def geomdl_surface(mod, net, w):
    l, m = net.shape[0] - 1, net.shape[1] - 1
    srf = mod.NURBS.Surface() if w is not None else mod.BSpline.Surface()
    srf.degree_u, srf.degree_v = l, m
    if w is None:
        flat = net.reshape(-1, DIM).tolist()
        srf.set_ctrlpts(flat, l + 1, m + 1)
    else:
        flat = np.concatenate([net * w[..., None], w[..., None]], axis=2).reshape(-1, DIM + 1).tolist()
        srf.set_ctrlpts(flat, l + 1, m + 1)
    srf.knotvector_u = [0.0] * (l + 1) + [1.0] * (l + 1)
    srf.knotvector_v = [0.0] * (m + 1) + [1.0] * (m + 1)
    return lambda uv: np.array(srf.evaluate_list(uv.tolist()))


def _occ_point_loop(value, params) -> np.ndarray:
    out = np.empty((len(params), DIM))
    for i, p in enumerate(params):
        q = value(*p)
        out[i] = (q.X(), q.Y(), q.Z())
    return out


def occ_curve(pts, w):
    from OCP.OCP import collections as C
    from OCP.OCP.Geom import Geom_BezierCurve
    from OCP.OCP.gp import gp_Pnt

    poles = C.Array1_gp_Pnt(1, len(pts))
    for i, p in enumerate(pts):
        poles.SetValue(i + 1, gp_Pnt(*map(float, p)))
    if w is None:
        curve = Geom_BezierCurve(poles)
    else:
        weights = C.Array1_double(1, len(w))
        for i, x in enumerate(w):
            weights.SetValue(i + 1, float(x))
        curve = Geom_BezierCurve(poles, weights)
    return lambda ts: _occ_point_loop(curve.Value, [(t,) for t in ts.tolist()])


def occ_surface(net, w):
    from OCP.OCP import collections as C
    from OCP.OCP.Geom import Geom_BSplineSurface
    from OCP.OCP.gp import gp_Pnt

    l, m = net.shape[0] - 1, net.shape[1] - 1
    poles = C.Array2_gp_Pnt(1, l + 1, 1, m + 1)
    weights = C.Array2_double(1, l + 1, 1, m + 1)
    for i in range(l + 1):
        for j in range(m + 1):
            poles.SetValue(i + 1, j + 1, gp_Pnt(*map(float, net[i, j])))
            weights.SetValue(i + 1, j + 1, 1.0 if w is None else float(w[i, j]))

    def arr1(kind, values):
        a = getattr(C, kind)(1, len(values))
        for i, x in enumerate(values):
            a.SetValue(i + 1, x)
        return a

    knots = arr1("Array1_double", [0.0, 1.0])
    args = (knots, knots, arr1("Array1_int", [l + 1, l + 1]), arr1("Array1_int", [m + 1, m + 1]), l, m)
    surface = Geom_BSplineSurface(poles, *args) if w is None else Geom_BSplineSurface(poles, weights, *args)
    return lambda uv: _occ_point_loop(surface.Value, uv.tolist())


# ----------------------------------------------------------------------------- driver
class _Table:
    """Rows of one case; ratio column against exactcagd's values-only de Casteljau."""

    def __init__(self, rows: list, plot: dict, label: str):
        self.rows, self.plot, self.label = rows, plot, label
        self.reference = None
        self.best: dict = {}  # tool -> minimum time per point

    def add(self, tool: str, func, npts: int, exact: list, check_values: np.ndarray, opts: dict, plot_key=None):
        timing = measure(func, memory=True, **opts)
        best = timing.low / npts  # the minimum: least disturbed by other jobs on shared cores
        self.best[tool] = best
        if self.reference is None:
            self.reference = best
        per_point = timing.median / npts
        err = max_error(check_values, exact)
        self.rows.append([self.label, tool, f"{npts / timing.median:,.0f}", timing.fmt(), ratio(best, self.reference),
                          f"{err:.2e}", timing.fmt_memory()])
        if plot_key:
            self.plot.setdefault(plot_key, []).append((per_point, err))


def _curve_case(n, rational, rng, peers, sizes, opts, rows, plot):
    curve, pts, w = make_curve(n, rational, rng)
    ts = rng.random(sizes["float"])
    check = ts[: sizes["check"]]
    exact = [curve.evaluate(mpq(*float(t).as_integer_ratio())) for t in check]
    kind = "rational" if rational else "polynomial"
    table = _Table(rows, plot, f"curve deg {n} {kind}")
    evaluate(curve, ts[:4], method="decasteljau", bound=False)  # warm the coefficient cache
    table.add("exactcagd decasteljau", lambda: evaluate(curve, ts, method="decasteljau", bound=False), ts.size, exact,
              evaluate(curve, check, method="decasteljau", bound=False), opts, f"exactcagd decasteljau ({kind} curves)")
    for method in METHODS:
        if method != "decasteljau":
            evaluate(curve, ts[:4], method=method, bound=False)
            table.add(f"exactcagd {method}", lambda m=method: evaluate(curve, ts, method=m, bound=False), ts.size, exact,
                      evaluate(curve, check, method=method, bound=False), opts, f"exactcagd {method} ({kind} curves)")
        table.add(f"exactcagd {method} + certified radius", lambda m=method: evaluate(curve, ts, method=m), ts.size, exact,
                  evaluate(curve, check, method=method)[0], opts)
    if peers["bezier"] is not None:
        run = bezier_curve(peers["bezier"], pts, w)
        name = "bezier evaluate_multi" + (" (homogeneous / w)" if rational else "")
        table.add(name, lambda: run(ts), ts.size, exact, run(check), opts, f"bezier ({kind} curves)")
    if peers["geomdl"] is not None:
        run = geomdl_curve(peers["geomdl"], pts, w)
        few = ts[: sizes["slow"]]
        table.add("geomdl evaluate_list", lambda: run(few), few.size, exact, run(check), opts, f"geomdl ({kind} curves)")
    if peers["occ"] is not None:
        run = occ_curve(pts, w)
        few = ts[: sizes["loop"]]
        table.add("OCC Geom_BezierCurve.Value loop", lambda: run(few), few.size, exact, run(check), opts, f"OCC ({kind} curves)")
    rows.append([table.label, "correctly rounded (floor)", "", "", "", f"{max_error(rounded(exact), exact):.2e}", ""])


def _surface_case(l, rational, rng, peers, sizes, opts, rows, plot):
    surface, net, w = make_surface(l, l, rational, rng)
    uv = rng.random((sizes["float"], 2))
    check = uv[: sizes["check_surface"]]
    exact = [surface.evaluate(*(mpq(*float(x).as_integer_ratio()) for x in p)) for p in check]
    kind = "rational" if rational else "polynomial"
    table = _Table(rows, plot, f"surface {l}x{l} {kind}")
    u, v = uv[:, 0].copy(), uv[:, 1].copy()
    cu, cv = check[:, 0].copy(), check[:, 1].copy()
    evaluate_surface(surface, u[:4], v[:4], bound=False)
    table.add("exactcagd decasteljau", lambda: evaluate_surface(surface, u, v, bound=False), u.size, exact,
              evaluate_surface(surface, cu, cv, bound=False), opts, f"exactcagd decasteljau ({kind} surfaces)")
    for method in METHODS:
        if method != "decasteljau":
            evaluate_surface(surface, u[:4], v[:4], method=method, bound=False)
            table.add(f"exactcagd {method}", lambda m=method: evaluate_surface(surface, u, v, method=m, bound=False), u.size,
                      exact, evaluate_surface(surface, cu, cv, method=method, bound=False), opts,
                      f"exactcagd {method} ({kind} surfaces)")
        table.add(f"exactcagd {method} + certified radius", lambda m=method: evaluate_surface(surface, u, v, method=m), u.size,
                  exact, evaluate_surface(surface, cu, cv, method=method)[0], opts)
    if peers["geomdl"] is not None:
        run = geomdl_surface(peers["geomdl"], net, w)
        few = uv[: sizes["slow"] // 4]
        table.add("geomdl evaluate_list", lambda: run(few), len(few), exact, run(check), opts, f"geomdl ({kind} surfaces)")
    if peers["occ"] is not None:
        run = occ_surface(net, w)
        few = uv[: sizes["loop"]]
        table.add("OCC Geom_BSplineSurface.Value loop", lambda: run(few), len(few), exact, run(check), opts,
                  f"OCC ({kind} surfaces)")
    rows.append([table.label, "correctly rounded (floor)", "", "", "", f"{max_error(rounded(exact), exact):.2e}", ""])


def goal_sweep(bezier, degrees, npts: int, rounds: int, rng) -> list:
    """Issue 18's goal at every degree: ``evaluate(curve, ts)`` (default, certified radius)
    against bezier's ``evaluate_multi``, minimum times per point, the two measured in
    alternation (``rounds`` times) so that both see the same load of the shared machine."""
    ts = rng.random(npts)
    rows = []
    for rational in (False, True):
        for n in degrees:
            curve, pts, w = make_curve(n, rational, rng)
            peer = bezier_curve(bezier, pts, w)
            tools = {"default + radius": lambda: evaluate(curve, ts), "values only": lambda: evaluate(curve, ts, bound=False),
                     "bezier": lambda: peer(ts)}
            best = dict.fromkeys(tools, float("inf"))
            for func in tools.values():
                func()  # coefficient cache, compiled kernel
            for _ in range(rounds):
                for name, func in tools.items():
                    best[name] = min(best[name], measure(func, repeat=5, budget=0.2).low / npts)
            goal = best["default + radius"] / best["bezier"]
            rows.append([f"curve deg {n} {'rational' if rational else 'polynomial'}", f"{best['default + radius'] * 1e9:.1f} ns",
                         f"{best['values only'] * 1e9:.1f} ns", f"{best['bezier'] * 1e9:.1f} ns", f"{goal:.2f}x",
                         "yes" if goal <= 1.5 else "no"])
    return rows


_FIRST_CALL = """
import time
t0 = time.perf_counter()
import numpy as np
from exactcagd import BezierCurve
from exactcagd.numeric import evaluate
t1 = time.perf_counter()
ts = np.linspace(0.0, 1.0, 5000)
evaluate(BezierCurve([[0, 0, 0], [1, 2, 3], [2, 0, 1], [3, 3, 3]], weights=[1, 2, 3, 1]), ts)
t2 = time.perf_counter()
evaluate(BezierCurve([[0, 0, 0], [1, 2, 3], [2, 0, 1], [3, 3, 3]]), ts)
t3 = time.perf_counter()
print(t1 - t0, t2 - t1, t3 - t2)
"""


def first_call_cost() -> list:
    """Seconds of a fresh interpreter's import and first ``evaluate`` calls (5000 parameters:
    the compiled kernel), with an empty numba cache (compilation) and with the cache it wrote."""
    import os
    import subprocess
    import sys
    import tempfile

    rows = []
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        for label in ("empty numba cache (compiles the kernel)", "numba cache written by the run above"):
            out = subprocess.run([sys.executable, "-c", _FIRST_CALL], env=env, capture_output=True, text=True, check=True)
            imported, first, second = map(float, out.stdout.split())
            rows.append([label, f"{imported:.2f} s", f"{first:.2f} s", f"{second * 1e3:.2f} ms"])
    return rows


def _kernel_available() -> bool:
    from exactcagd.numeric import _horner_kernel

    return _horner_kernel.AVAILABLE


def load_peers() -> dict:
    geomdl = optional_peer("geomdl", "geomdl rows")
    if geomdl is not None:
        import geomdl.BSpline  # noqa: F401  (submodules used as attributes)
        import geomdl.NURBS  # noqa: F401
    return {
        "bezier": optional_peer("bezier", "bezier rows"),
        "geomdl": geomdl,
        "occ": optional_peer("OCP.OCP.Geom", "OpenCASCADE rows (cadquery-ocp)"),
    }


def main(quick: bool | None = None) -> None:
    if quick is None:
        quick = parse_quick(__doc__.splitlines()[0])
    peers = load_peers()
    sizes = ({"float": 20_000, "check": 100, "check_surface": 40, "slow": 400, "loop": 4000} if quick else
             {"float": 200_000, "check": 500, "check_surface": 200, "slow": 4000, "loop": 40_000})
    opts = {"repeat": 5, "budget": 1.0} if quick else {"repeat": 9, "budget": 15.0}
    curve_degrees = (3, 10, 20) if quick else (3, 5, 10, 15, 20)
    surface_degrees = (3, 7) if quick else (3, 5, 7)
    rng = np.random.default_rng(20261122)
    rows, plot = [], {}
    goals = goal_sweep(peers["bezier"], range(3, 21), sizes["float"], 4 if quick else 8, rng) if peers["bezier"] else []
    print("goal sweep done", flush=True)
    first_call = first_call_cost() if _kernel_available() else []
    for rational in (False, True):
        for n in curve_degrees:
            _curve_case(n, rational, rng, peers, sizes, opts, rows, plot)
        print(f"curves ({'rational' if rational else 'polynomial'}) done", flush=True)
    surf_rows = []
    for rational in (False, True):
        for l in surface_degrees:
            _surface_case(l, rational, rng, peers, sizes, opts, surf_rows, plot)
        print(f"surfaces ({'rational' if rational else 'polynomial'}) done", flush=True)
    headers = ["case", "tool", "points/s (median)", "time per call: median (min-max)", "min time/point vs exactcagd decasteljau",
               "max abs error", "peak traced memory"]
    skipped = [k for k, v in peers.items() if v is None]
    body = (
        f"Mode: {'quick' if quick else 'full'}. 3-D control points; {sizes['float']:,} random parameters per call for "
        f"exactcagd and bezier, {sizes['slow']:,} (curves) / {sizes['slow'] // 4:,} (surfaces) for geomdl (pure Python), "
        f"{sizes['loop']:,} for the OCC Python loop; points/s = points / median time. Timings: median (min-max) of up to "
        f"{opts['repeat']} runs in the same process; the ratio column is the minimum time per point divided by "
        "exactcagd's values-only de Casteljau minimum time per point in the same case (> 1: slower than exactcagd; minima "
        "because the machine's cores are shared and medians of short calls vary by up to 5x between runs). Max abs error: exact "
        f"(mpq) comparison against exactcagd's exact rational evaluation at {sizes['check']} (curves) / "
        f"{sizes['check_surface']} (surfaces) parameters. Peak memory: tracemalloc peak of one extra run "
        "(allocations inside OCC's C++ are not traced).\n\n"
        + (f"Skipped peers (not installed): {', '.join(skipped)}.\n\n" if skipped else "")
        + "## Goal (issue 18): the default path with its certified radius within 1.5x of bezier\n\n"
        "Default = `evaluate(curve, ts)`: method `auto` (Bernstein-Horner on t in [0, 1], compiled with numba when "
        f"installed: {'yes' if _kernel_available() else 'no'}), certified radius included, refusing t outside [0, 1]; "
        f"every degree 3-20, {sizes['float']:,} random parameters, 3-D; minimum time per point of 5-call measurements "
        "taken in alternation with bezier's (rational: bezier on the homogeneous curve, then a numpy division); "
        "ratio = default + radius / bezier.\n\n"
        + markdown_table(["case", "exactcagd default + radius", "exactcagd values only", "bezier evaluate_multi", "ratio",
                          "goal <= 1.5x met"], goals)
        + ("\n\nFirst calls in a fresh interpreter (numba compiles the kernel lazily, at the first call with >= 4096 "
           "parameters, and caches it on disk): import of exactcagd, a first rational `evaluate` with radius, then a "
           "polynomial one (5,000 parameters each).\n\n"
           + markdown_table(["numba cache", "import", "first call", "second call (other curve)"], first_call)
           if first_call else "")
        + "\n\n## Curves\n\n" + markdown_table(headers, rows)
        + "\n\n## Tensor-product surfaces\n\n`bezier` has only triangular patches: no row.\n\n"
        + markdown_table(headers, surf_rows)
        + "\n\nWork-precision plot: `peers_evaluate_work_precision.png` (seconds per point vs max error; one "
        "marker per degree, degree grows with the time).\n"
    )
    path = write_result("peers_evaluate", "Float evaluation: exactcagd vs bezier, geomdl, OpenCASCADE", body)
    plot_work_precision(plot)
    print(f"wrote {path}")


def plot_work_precision(plot: dict) -> None:
    """Two log-log panels (curves, surfaces); colour = tool, solid = polynomial, dashed = rational."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=True)
    tools = sorted({key.split(" (")[0] for key in plot})
    colors = {tool: f"C{i}" for i, tool in enumerate(tools)}
    for key, points in plot.items():
        tool, kind = key.split(" (")
        ax = axes[0] if "curves" in kind else axes[1]
        xs, ys = zip(*points)
        ax.plot(xs, [max(y, 1e-17) for y in ys], marker="o", markersize=4, color=colors[tool],
                linestyle="-" if kind.startswith("polynomial") else "--",
                label=f"{tool}, {kind.split()[0]}")
    for ax, title in zip(axes, ("curves (degree grows along each line)", "tensor-product surfaces")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("seconds per point")
        ax.set_title(title)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=6, ncol=2)
    axes[0].set_ylabel("max |error| vs exact value")
    fig.suptitle("Bezier evaluation: work vs precision (solid: polynomial, dashed: rational)")
    fig.tight_layout()
    fig.savefig(results_dir() / "peers_evaluate_work_precision.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
