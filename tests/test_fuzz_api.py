"""Fuzz property test of the public API (issue 14, part 6).

Property: every call of a public entry point with malformed or extreme arguments (bools,
bytes, None, NaN, inf, 10^5000, negative/zero/huge counts, wrong nesting, sympy symbols
and irrationals, strings, mismatched weights, huge degrees) either returns or raises an
:class:`exactcagd.errors.ExactCAGDError`, within a time bound.  A generic Python
exception, a ``MemoryError`` under a 3 GiB address-space cap, or a call running past
``CALL_SECONDS`` is a failure.

Each call runs in a forked worker process (``conn.poll`` timeout; a hung worker is
killed and replaced), so a hang in C code (flint, gmpy2) is caught as well as one in
Python.  Valid objects (curves, surfaces, B-splines) are named by :class:`Ref` and built
in the worker; malformed arguments are sent as they are.

The default run is bounded (derandomized, 6 examples per entry point, 20-40 s on the
shared 2-core machine); ``-m slow`` runs 150 random examples per entry point (``FUZZ_EXAMPLES``
overrides; ~8400 calls in about a minute).  Set ``FUZZ_REPORT=path`` to append the tally
(calls, results, package errors by class, generic exceptions, hangs) as JSON.
"""

from __future__ import annotations

import json
import math
import multiprocessing
import os
import resource
import traceback
from dataclasses import dataclass
from fractions import Fraction

import pytest
import sympy
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

CALL_SECONDS = 30  # a call running longer is a hang
MEMORY_BYTES = 3 << 30


# ---------------------------------------------------------------- valid objects, built in the worker
@dataclass(frozen=True)
class Ref:
    """A valid object of the catalogue, by name (built in the worker)."""

    name: str


def _catalogue() -> dict:
    from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface

    return {
        "line": BezierCurve([[0, 0], [1, 1]]),
        "parabola": BezierCurve([[0, 0], [1, 2], [2, 0]]),
        "cubic": BezierCurve([[0, 0], [1, 3], [2, -3], [3, 0]]),
        "arc": BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2]),
        "space_curve": BezierCurve([[0, 0, 0], [1, 2, 3], [2, 0, 1]]),
        "domain_line": BezierCurve([["1/4", "1/4"], ["3/4", "3/4"]]),
        "domain_quad": BezierCurve([["1/10", "1/10"], ["1/2", "9/10"], ["9/10", "1/5"]]),
        "domain_iso": BezierCurve([["1/2", 0], ["1/2", 1]]),
        "saddle": BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]),
        "biquad": BezierSurface([[[i, j, (i * j) % 3] for j in range(3)] for i in range(3)]),
        "rational_surface": BezierSurface(
            [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], weights=[[1, 2], [3, 1]]
        ),
        "bspline": BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], knots=[0, 0, 0, 1, 2, 2, 2]),
        "nurbs": BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], knots=[0, 0, 0, 1, 2, 2, 2], weights=[1, 2, 1, 3]),
        "bspline_surface": BSplineSurface(
            [[[i, j, (i + j) % 2] for j in range(3)] for i in range(4)],
            knots_u=[0, 0, 0, 1, 2, 2, 2],
            knots_v=[0, 0, 1, 2, 2],
        ),
    }


_OBJECTS: dict = {}


def _resolve(value):
    if isinstance(value, Ref):
        if not _OBJECTS:
            _OBJECTS.update(_catalogue())
        return _OBJECTS[value.name]
    return value


# ---------------------------------------------------------------- malformed values
BAD = [
    True, False, b"1", bytearray(b"x"), None, math.nan, math.inf, -math.inf, 10**5000, -(10**5000),
    Fraction(1, 10**5000), "abc", "", "1e100000000", "1/0", "nan", sympy.Symbol("x"), sympy.pi, sympy.oo,
    sympy.sqrt(2), [], [[]], [[1, 2], [3]], [[[1]]], {}, 1j, -1, 0, 10**6, 2.5, object,
]
BAD_COUNTS = [-1, -(10**5000), True, False, 2.0, 10**6, 10**9, 10**5000, None, "2", b"2", math.nan, sympy.Integer(10**6)]

scalar = st.one_of(st.sampled_from([0, 1, 2, -3, "1/3", Fraction(2, 7), 0.5, "0.25"]), st.sampled_from(BAD))
param = st.one_of(st.sampled_from([0, 1, "1/3", "1/2", Fraction(3, 4), 0.25]), st.sampled_from([2, -1, "7/3"]), st.sampled_from(BAD))
count = st.one_of(st.integers(0, 3), st.sampled_from(BAD_COUNTS))
tol = st.one_of(st.sampled_from([1e-6, "1/100", Fraction(1, 1000), 0.01]), st.sampled_from(BAD))
flag = st.one_of(st.booleans(), st.sampled_from([None, "yes", 0, 1, b"1"]))


def _points(dimension: int = 2):
    good = st.lists(st.lists(st.sampled_from([0, 1, -2, "1/3", 3]), min_size=dimension, max_size=dimension), min_size=2, max_size=4)
    huge = st.sampled_from([[[10**5000, 0], [1, 1]], [[0, 0]] * 100_001, [[0, 0]] * 1500, [[0] * 10**5, [1] * 10**5]])
    ragged = st.sampled_from([[[0, 0], [1]], [0, 1, 2], [[[0, 0]], [[1, 1]]], [["a", 0], [1, 1]], [[None, 0], [1, 1]], "0,0;1,1", [[True, 0], [1, 1]]])
    return st.one_of(good, huge, ragged, st.sampled_from(BAD))


def _net():
    good = st.sampled_from([[[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], [[[0, 0], [1, 0]], [[0, 1], [1, 1]]]])
    huge = st.sampled_from([[[[0, 0, 0]] * 1500] * 2, [[[0, 0, 0]] * 400] * 400, [[[10**5000, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]])
    ragged = st.sampled_from([[[[0, 0, 0], [0, 1]], [[1, 0, 0], [1, 1, 1]]], [[0, 0, 0]], [[[0, 0, 0]], [[1, 1, 1], [2, 2, 2]]]])
    return st.one_of(good, huge, ragged, st.sampled_from(BAD))


def _weights(n: int = 3):
    return st.one_of(
        st.none(),
        st.lists(st.sampled_from([1, 2, "1/2", 0, -1, True, math.nan, 10**5000, sympy.pi]), min_size=n, max_size=n),
        st.sampled_from([[1], [1] * (n + 1), [[1, 1]] * n, "111", b"111"]),
        st.sampled_from(BAD),
    )


def ref(*names):
    return st.sampled_from([Ref(n) for n in names])


planar = ref("line", "parabola", "cubic", "arc")
curve_obj = ref("line", "parabola", "cubic", "arc", "space_curve", "domain_quad", "bspline", "nurbs")  # for method calls
any_curve = st.one_of(curve_obj, st.sampled_from(BAD))
surface_obj = ref("saddle", "biquad", "rational_surface", "bspline_surface")
domain = st.one_of(ref("domain_line", "domain_quad", "domain_iso", "parabola", "space_curve", "bspline"), st.sampled_from(BAD))
surface = st.one_of(surface_obj, st.sampled_from(BAD))
plane_curve = st.one_of(planar, ref("space_curve", "bspline"), st.sampled_from(BAD))
def method(*good):
    return st.one_of(st.sampled_from(good), st.sampled_from(["nope", None, 3, True, b"fast"]))
coefficients = st.one_of(
    st.lists(st.sampled_from([-1, 0, 1, "1/3", 2]), min_size=1, max_size=5),
    st.sampled_from([[], [0, 0, 0], [1] * 1500, [10**5000, -1, 1], [[1, 2], [3, 4]], [1, None], [1, "abc"], "123"]),
    st.sampled_from(BAD),
)


# ---------------------------------------------------------------- the entry points
def _call(obj, name, *args, **kwargs):
    return getattr(obj, name)(*args, **kwargs)


def _entries() -> dict:
    """name -> (function run in the worker, strategy of (args, kwargs))."""
    def args(*a, **k):
        return st.tuples(st.tuples(*a), st.fixed_dictionaries(k))

    E = {}

    # constructors
    E["BezierCurve"] = (lambda p, w: __import__("exactcagd").BezierCurve(p, w), args(_points(), _weights()))
    E["BezierSurface"] = (lambda p, w: __import__("exactcagd").BezierSurface(p, w), args(_net(), _weights(2)))

    def bspline_curve(p, knots, w, degree):
        from exactcagd import BSplineCurve

        return BSplineCurve(p, knots, w, degree)

    knots = st.one_of(
        st.sampled_from([[0, 0, 0, 1, 2, 2, 2], [0, 0, 1, 1], [0, 0, 0, 0, 1, 1, 1, 1], [2, 1, 0], [0, 0, "x", 1], [0] * 10**5, list(range(1500))]),
        st.sampled_from(BAD),
    )
    E["BSplineCurve"] = (bspline_curve, args(_points(), knots, _weights(4), st.one_of(st.none(), count)))

    def bspline_surface(net, ku, kv, w):
        from exactcagd import BSplineSurface

        return BSplineSurface(net, ku, kv, w)

    E["BSplineSurface"] = (bspline_surface, args(_net(), knots, knots, _weights(2)))
    E["BezierCurve.from_dict"] = (
        lambda d: __import__("exactcagd").BezierCurve.from_dict(d),
        args(st.one_of(st.fixed_dictionaries({"control_points": _points(), "weights": _weights()}), st.sampled_from(BAD))),
    )

    # methods of curves and surfaces
    E["evaluate"] = (lambda c, t: c.evaluate(t), args(curve_obj, param))
    E["evaluate_horner"] = (lambda c, t, x: c.evaluate_horner(t, extrapolate=x), args(planar, param, flag))
    E["subdivide"] = (lambda c, t: c.subdivide(t), args(planar, param))
    E["elevate"] = (lambda c, r: c.elevate(r), args(planar, count))
    E["reparametrize"] = (lambda c, a, b: c.reparametrize(a, b), args(planar, scalar, scalar))
    E["blossom"] = (lambda c, ps: c.blossom(ps), args(planar, st.one_of(st.lists(param, max_size=4), st.sampled_from(BAD))))
    E["derivative/reduce"] = (lambda c, which: _call(c, which), args(planar, st.sampled_from(["derivative", "reduce", "true_degree", "reversed", "to_float"])))
    E["surface.evaluate"] = (lambda s, u, v: s.evaluate(u, v), args(surface_obj, param, param))
    E["surface.elevate"] = (lambda s, ru, rv: s.elevate(ru, rv), args(ref("saddle", "biquad", "rational_surface"), count, count))
    E["surface.subdivide"] = (lambda s, u: s.subdivide_u(u), args(ref("saddle", "biquad", "rational_surface"), param))
    E["surface.reparametrize"] = (lambda s, a, b: s.reparametrize(a, b), args(ref("saddle", "biquad"), st.one_of(st.tuples(scalar, scalar), st.sampled_from(BAD)), st.one_of(st.tuples(scalar, scalar), st.sampled_from(BAD))))
    E["bspline.insert_knot"] = (lambda c, t, k: c.insert_knot(t, k), args(ref("bspline", "nurbs"), param, count))
    E["bspline_surface.insert_knot_u"] = (lambda s, t, k: s.insert_knot_u(t, k), args(ref("bspline_surface"), param, count))

    # composition, reparametrization
    def compose(s, c, m, reduce):
        from exactcagd import compose as f

        return f(s, c, m, reduce=reduce)

    E["compose"] = (compose, args(surface, domain, method("fast", "lasser"), flag))

    def compose_spline(s, c):
        from exactcagd.composition import compose_spline as f

        return f(s, c)

    E["compose_spline"] = (compose_spline, args(surface, domain))

    def ffd(lattice, shape):
        from exactcagd.composition import ffd as f

        return f(lattice, shape)

    E["ffd"] = (ffd, args(surface, domain))

    def approximate_cubic(s, c, t, segments):
        from exactcagd.composition import approximate_cubic as f

        return f(s, c, t, max_segments=segments)

    E["approximate_cubic"] = (approximate_cubic, args(ref("saddle"), ref("domain_line", "domain_quad"), tol, st.one_of(st.just(8), st.sampled_from(BAD_COUNTS))))

    def mobius(s, a, b):
        from exactcagd.reparam import mobius as f

        return f(s, a, b)

    E["reparam.mobius"] = (mobius, args(surface, scalar, scalar))

    # curves on surfaces
    def approximate(s, c, t, m, snap_bits, max_segments):
        from exactcagd.curves_on_surfaces import approximate as f

        return f(s, c, t, m, snap_bits=snap_bits, max_segments=max_segments)

    E["approximate"] = (
        approximate,
        args(
            st.one_of(ref("saddle", "biquad"), st.sampled_from(BAD)),
            st.one_of(ref("domain_line", "domain_quad"), st.sampled_from(BAD)),
            tol,
            method("parabola", "hyperbola", "polyline", "fit"),
            st.one_of(st.just(64), st.none(), st.sampled_from(BAD_COUNTS), st.sampled_from([-5, 0, 24])),
            st.one_of(st.just(1000), st.sampled_from(BAD_COUNTS)),
        ),
    )

    # algebra
    def implicitize(c, m):
        from exactcagd.algebra import implicitize as f

        return f(c, m)

    E["implicitize"] = (implicitize, args(plane_curve, method("resultant", "bezier", "moving_lines")))
    E["inversion"] = (lambda c: __import__("exactcagd.algebra", fromlist=["x"]).inversion(c), args(plane_curve))

    def resultant(f, g, var, m):
        from exactcagd.algebra import resultant as r

        return r(f, g, var, m)

    x, y = sympy.symbols("x y")
    poly = st.one_of(st.sampled_from([x**2 - 1, x * y - 1, x - y, x**3 + y, x ** (10**5), x**400 * y**400 - 1]), st.sampled_from(BAD))
    E["resultant"] = (resultant, args(poly, poly, st.one_of(st.sampled_from([x, y]), st.sampled_from(BAD)), method("flint", "sympy", "sylvester", "bezout")))

    def groebner(polys, gens):
        from exactcagd.algebra import groebner as g

        return g(polys, gens)

    E["groebner"] = (groebner, args(st.one_of(st.lists(poly, min_size=1, max_size=2), st.sampled_from(BAD)), st.one_of(st.just([x, y]), st.sampled_from(BAD))))

    def algebra_intersect(a, b):
        from exactcagd.algebra import intersect as f

        return f(a, b)

    E["algebra.intersect"] = (algebra_intersect, args(plane_curve, plane_curve))

    # numeric
    def bernstein_roots(c, m, t):
        from exactcagd.numeric import bernstein_roots as f

        return f(c, m, t)

    E["bernstein_roots"] = (bernstein_roots, args(coefficients, method("isolate", "marching", "exact"), tol))

    def numeric_intersect(a, b, m, t):
        from exactcagd.numeric import intersect as f

        return f(a, b, m, t)

    E["numeric.intersect"] = (numeric_intersect, args(plane_curve, plane_curve, method("subdivision", "interval", "clipping", "exact"), tol))

    def numeric_evaluate(c, ts, m):
        from exactcagd.numeric import evaluate as f

        return f(c, ts, m)

    E["numeric.evaluate"] = (numeric_evaluate, args(any_curve, st.one_of(st.lists(param, max_size=3), st.sampled_from(BAD)), method("auto", "horner", "de_casteljau")))

    def line_roots(c, line):
        from exactcagd.numeric import line_roots as f

        return f(c, line)

    E["line_roots"] = (line_roots, args(plane_curve, st.one_of(st.tuples(scalar, scalar, scalar), st.sampled_from(BAD))))

    # toolbox: functions that take counts and degrees
    def toolbox(module, name, *a):
        import importlib

        return getattr(importlib.import_module(f"exactcagd.toolbox.{module}"), name)(*a)

    E["toolbox.bernstein_basis"] = (lambda n: toolbox("blending", "bernstein_basis", n), args(count))
    E["toolbox.d2_coefficients"] = (lambda n: toolbox("integrals", "d2_coefficients", n), args(count))
    E["toolbox.max_bernstein"] = (lambda n, m: toolbox("integrals", "max_bernstein", n, m), args(count, count))
    E["toolbox.hybrid_curve"] = (lambda c, n: toolbox("integrals", "hybrid_curve", c, n), args(planar, count))
    E["toolbox.derivatives_at"] = (lambda c, t, k: toolbox("bezier_extras", "derivatives_at", c, t, k), args(planar, param, count))
    E["toolbox.rasterize"] = (lambda c, n: toolbox("forward_diff", "rasterize", c, n), args(planar, st.one_of(st.none(), count)))
    E["toolbox.extend"] = (lambda v, n: toolbox("forward_diff", "extend", v, n), args(coefficients, count))
    E["toolbox.forward_difference"] = (
        lambda p, n: toolbox("forward_diff", "forward_difference", p, 0, "1/10", n),
        args(coefficients, count),
    )
    E["toolbox.area_under"] = (lambda c: toolbox("integrals", "area_under", c), args(any_curve))
    E["toolbox.curve_curvature"] = (lambda c, t: toolbox("curvature", "curve_curvature", c, t), args(any_curve, param))
    E["toolbox.periodic_bspline"] = (lambda p, d: toolbox("bspline_extras", "periodic_bspline", p, d), args(_points(), count))
    E["toolbox.gram_matrix"] = (lambda k, d: toolbox("fitting", "gram_matrix", k, d), args(knots, count))

    # more of the algebra, reparametrization and numeric API
    def algebra(name, *a, **k):
        import exactcagd.algebra as alg

        return getattr(alg, name)(*a, **k)

    point = st.one_of(st.tuples(scalar, scalar), st.sampled_from(BAD))
    E["sylvester_matrix"] = (lambda a, b: algebra("sylvester_matrix", a, b), args(coefficients, coefficients))
    E["bezout_matrix"] = (lambda a, b: algebra("bezout_matrix", a, b), args(coefficients, coefficients))
    E["discriminant"] = (lambda f, v: algebra("discriminant", f, v), args(poly, st.one_of(st.sampled_from([x, y]), st.sampled_from(BAD))))
    E["euclid_steps"] = (lambda f, g: algebra("euclid_steps", f, g), args(poly, poly))
    E["singular_points"] = (lambda f: algebra("singular_points", f), args(poly))
    E["genus"] = (lambda f: algebra("genus", f), args(poly))
    E["conic_through_points"] = (lambda ps: algebra("conic_through_points", ps), args(st.one_of(st.lists(point, min_size=0, max_size=6), st.sampled_from(BAD))))
    E["circle_through_points"] = (lambda a, b, c: algebra("circle_through_points", a, b, c), args(point, point, point))
    E["mu_basis"] = (lambda c: algebra("mu_basis", c), args(plane_curve))
    E["double_points"] = (lambda c: algebra("double_points", c), args(plane_curve))
    E["implicit_equation"] = (lambda c, s: algebra("implicit_equation", c, strict=s), args(plane_curve, flag))
    E["intersection_polynomial"] = (lambda a, b: algebra("intersection_polynomial", a, b), args(plane_curve, plane_curve))
    E["implicitize_surface"] = (
        lambda s, m: algebra("implicitize_surface", __import__("exactcagd.algebra", fromlist=["x"]).SurfaceParametrization.from_bezier_surface(s), m),
        args(st.one_of(ref("saddle", "biquad", "rational_surface"), st.sampled_from(BAD)), method("linear_algebra", "resultant", "groebner")),
    )
    E["eliminate"] = (lambda ps, e, k: algebra("eliminate", ps, e, k), args(st.one_of(st.lists(poly, min_size=1, max_size=2), st.sampled_from(BAD)), st.one_of(st.just([x]), st.sampled_from(BAD)), st.one_of(st.just([y]), st.sampled_from(BAD))))
    E["normal_form"] = (lambda f, b, g: algebra("normal_form", f, b, g), args(poly, st.one_of(st.lists(poly, max_size=2), st.sampled_from(BAD)), st.one_of(st.just([x, y]), st.sampled_from(BAD))))
    E["common_points"] = (lambda ps, g: algebra("common_points", ps, g), args(st.one_of(st.lists(poly, min_size=1, max_size=2), st.sampled_from(BAD)), st.one_of(st.just([x, y]), st.none(), st.sampled_from(BAD))))

    def reparam(name, *a):
        import exactcagd.reparam as rp

        return getattr(rp, name)(*a)

    pair = st.one_of(st.tuples(param, param), st.sampled_from(BAD))
    E["reparam.quadratic"] = (lambda s, a, b: reparam("quadratic", s, a, b), args(surface, pair, pair))
    E["reparam.cubic"] = (lambda s, a, b: reparam("cubic", s, a, b), args(surface, st.one_of(st.tuples(param, param, param), st.sampled_from(BAD)), st.one_of(st.tuples(param, param, param), st.sampled_from(BAD))))

    def numeric_evaluate_surface(s, us, vs):
        from exactcagd.numeric import evaluate_surface as f

        return f(s, us, vs)

    params = st.one_of(st.lists(param, max_size=3), st.sampled_from(BAD))
    E["numeric.evaluate_surface"] = (numeric_evaluate_surface, args(surface, params, params))

    def compose_homogeneous(s, c):
        from exactcagd.composition import compose_homogeneous as f

        return f(s, c)

    E["compose_homogeneous"] = (compose_homogeneous, args(surface, domain))
    E["BezierCurve.from_homogeneous"] = (lambda h: __import__("exactcagd").BezierCurve.from_homogeneous(h), args(_points(3)))
    E["BezierCurve.to_sympy"] = (lambda c, t: c.to_sympy(t), args(ref("line", "arc", "space_curve"), st.one_of(st.none(), st.just(sympy.Symbol("s")), st.sampled_from(BAD))))
    return E


ENTRIES = _entries()


# ---------------------------------------------------------------- the worker
def _serve(conn) -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_BYTES, MEMORY_BYTES))
    from exactcagd.errors import ExactCAGDError

    while True:
        message = conn.recv()
        if message is None:
            return
        name, args, kwargs = message
        try:  # a catalogue object that cannot be built is a defect of the test, not a package error
            args, kwargs = [_resolve(a) for a in args], {k: _resolve(v) for k, v in kwargs.items()}
        except BaseException as exc:  # noqa: BLE001
            conn.send(("harness", f"{type(exc).__name__}: {exc}"))
            continue
        try:
            ENTRIES[name][0](*args, **kwargs)
            conn.send(("ok", ""))
        except ExactCAGDError as exc:
            conn.send(("package", type(exc).__name__))
        except BaseException as exc:  # noqa: BLE001 - the property under test
            conn.send(("generic", f"{type(exc).__name__}: {str(exc)[:300]}\n{traceback.format_exc()[-3000:]}"))


class Worker:
    """A forked process running entry points, replaced after a hang."""

    def __init__(self, seconds: float = CALL_SECONDS):
        self.seconds = seconds
        self.context = multiprocessing.get_context("fork")
        self.process = None
        self.tally = {"calls": 0, "ok": 0, "package": {}, "generic": [], "hang": []}

    def _start(self):
        self.conn, child = self.context.Pipe()
        self.process = self.context.Process(target=_serve, args=(child,), daemon=True)
        self.process.start()
        child.close()

    def run(self, name, args, kwargs) -> tuple[str, str]:
        if self.process is None or not self.process.is_alive():
            self._start()
        self.tally["calls"] += 1
        try:
            self.conn.send((name, args, kwargs))
        except Exception as exc:  # noqa: BLE001 - unpicklable argument: a defect of the strategy
            raise AssertionError(f"{name}: cannot send the arguments ({exc})") from None
        if not self.conn.poll(self.seconds):
            self.stop()
            self.tally["hang"].append(f"{name}{_show(args, kwargs)}")
            return "hang", f"more than {self.seconds} s"
        try:
            kind, detail = self.conn.recv()
        except EOFError:  # the worker died (segfault, OOM kill)
            self.stop()
            self.tally["generic"].append(f"{name}: worker died")
            return "generic", "the worker process died"
        if kind == "ok":
            self.tally["ok"] += 1
        elif kind == "package":
            self.tally["package"][detail] = self.tally["package"].get(detail, 0) + 1
        else:
            self.tally["generic"].append(f"{name}{_show(args, kwargs)}: {detail.splitlines()[0]}")
        return kind, detail

    def stop(self):
        if self.process is not None:
            if self.process.is_alive():
                self.process.kill()
            self.process.join()
            self.process = None


def _show(args, kwargs) -> str:
    try:
        text = repr(args) + (repr(kwargs) if kwargs else "")
    except ValueError:  # repr of a 10^5000 int exceeds Python's 4300-digit limit
        text = "(arguments with huge integers)"
    return text if len(text) < 300 else text[:280] + "..."


@pytest.fixture(scope="module")
def worker():
    w = Worker()
    yield w
    w.stop()
    report = os.environ.get("FUZZ_REPORT")
    if report:
        with open(report, "a") as fh:
            fh.write(json.dumps(w.tally) + "\n")


def _check(worker, name, drawn):
    args, kwargs = drawn
    kind, detail = worker.run(name, args, kwargs)
    assert kind in ("ok", "package"), f"{name}{_show(args, kwargs)} -> {kind}: {detail}"


# ---------------------------------------------------------------- the property
def _cases():
    return sorted(ENTRIES)


@pytest.mark.parametrize("name", _cases())
@settings(max_examples=6, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
@given(data=st.data())
def test_every_call_returns_or_raises_a_package_error(worker, name, data):
    _check(worker, name, data.draw(ENTRIES[name][1], label="arguments"))


@pytest.mark.slow
@pytest.mark.parametrize("name", _cases())
@settings(max_examples=int(os.environ.get("FUZZ_EXAMPLES", "150")), deadline=None, suppress_health_check=list(HealthCheck))
@given(data=st.data())
def test_every_call_returns_or_raises_a_package_error_long(worker, name, data):
    _check(worker, name, data.draw(ENTRIES[name][1], label="arguments"))


def test_the_catalogue_builds():
    assert len(_catalogue()) == 14


def test_the_harness_catches_generic_exceptions_and_hangs():
    """The property can fail: a generic exception and a hang are reported as such."""
    ENTRIES["_raise"] = (lambda: {}["missing"], None)
    ENTRIES["_hang"] = (lambda: __import__("time").sleep(30), None)
    ENTRIES["_package"] = (lambda: __import__("exactcagd").BezierCurve([]), None)
    try:
        w = Worker()  # fresh worker: forked after the test entries exist
        try:
            assert w.run("_raise", (), {})[0] == "generic"
            assert w.run("_package", (), {}) == ("package", "InputError")
            w.seconds = 2
            assert w.run("_hang", (), {})[0] == "hang"
            assert w.tally["hang"] and w.tally["generic"] and w.tally["package"] == {"InputError": 1}
        finally:
            w.stop()
    finally:
        for key in ("_raise", "_hang", "_package"):
            del ENTRIES[key]
