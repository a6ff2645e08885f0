"""Checks of a scene's products against its built objects, made before any product is computed.

:func:`exactcagd.scenes.spec.parse_scene` checks what the text alone decides (keys,
shapes, numbers, names).  What needs the exact objects is checked here, by
``exactcagd plan`` and at the start of ``exactcagd run``, so that a scene that would
fail later fails before any work, with the scene key in the message:

* a product kind that does not fit its input (an implicit equation or intersections
  of a B-spline or 3-D curve, a B-spline FFD lattice, a constant curve);
* a 3-D curve used as a domain curve;
* a domain curve leaving the surface's parameter domain (exactly: the control-polygon
  hull first, then exact sign decisions; :func:`exactcagd.composition.domain.check_inside`);
* exact result degrees beyond ``LIMITS["max_result_degree"]`` (the image of a degree-n
  domain curve on a degree (l, m) surface has degree ``n (l + m)``, Lasser & Bonneau
  (000) Theorem 1; the intersection polynomial of degree-m and degree-n curves has degree
  ``m n``, Sederberg's notes 17.8 and Bezout's theorem, 7.1).

Large implicitization and intersection products get a cost estimate and a warning.

>>> from exactcagd.scenes.spec import parse_scene
>>> from exactcagd.scenes.runner import Runner
>>> scene = parse_scene({"curves": {"k": {"type": "bezier", "control_points": [[0, 0, 0], [1, 1, 1]]}},
...                      "products": [{"kind": "implicit", "curve": "k"}]})
>>> Runner(scene, "out")  # doctest: +IGNORE_EXCEPTION_DETAIL
Traceback (most recent call last):
exactcagd.scenes.spec.SceneError: products[0].curve: 'k' is a 3-D curve; an implicit equation needs a planar Bézier curve
"""

from __future__ import annotations

from ..errors import ExactCAGDError
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve
from .spec import LIMITS, Scene, SceneError, SceneLimitError

__all__ = ["check_products", "result_degree", "implicit_seconds", "WARN_IMPLICIT_SECONDS", "WARN_INTERSECTION_DEGREE"]

#: Above this exact degree an intersections product gets a warning (measured on this machine:
#: intersections with a degree-36 polynomial take minutes).
WARN_INTERSECTION_DEGREE = 25
#: an implicitization estimated to take longer than this (seconds) gets a warning in plan
WARN_IMPLICIT_SECONDS = 10


def implicit_seconds(degree: int) -> float:
    """Rough time of implicitizing a degree-``degree`` curve by moving lines (the scene default).

    Measured on the project's 2-core machine on random planar Bézier curves (coordinates k/100)
    (``implicitize(method="moving_lines")``): 0.004 s at degree 8, 0.1 s at 12, 1.7 s at 16,
    18 s at 20, i.e. about 1.8x per degree from 12 on (issue 14: degree 40 ran over 300 s).

    >>> round(implicit_seconds(20))
    18
    """
    return 1.7 * 1.8 ** (degree - 16)


#: estimated seconds of exact intersection (numeric.intersection.exact_cost) above which plan warns
WARN_EXACT_SECONDS = 5


def _domain_box(surface):
    if isinstance(surface, BezierSurface):
        return ((0, 1), (0, 1))
    (u0, u1), (v0, v1) = surface.domain
    return ((u0, u1), (v0, v1))


def _bezier_segments(curve) -> list:
    if isinstance(curve, BezierCurve):
        return [((0, 1), curve)]
    return curve.to_bezier()


def _check_inside(curve, box, where: str, name: str, what: str, skip: bool = False) -> None:
    """Exact check that the domain curve stays in ``box`` (hull first, then exact roots)."""
    if skip:
        return
    from ..composition.domain import check_inside

    for span, segment in _bezier_segments(curve):
        try:
            check_inside(segment.homogeneous(), box, what=f"{what} {name!r}" + (f" (t in [{span[0]}, {span[1]}])" if isinstance(curve, BSplineCurve) else ""))
        except ExactCAGDError as exc:
            message = str(exc).split("; pass allow_outside")[0]
            raise SceneError(f"{where}: {message}") from None


def _planar(curve, where: str, name: str, purpose: str) -> None:
    if curve.dimension != 2:
        raise SceneError(f"{where}: {name!r} is a {curve.dimension}-D curve; {purpose}")


def _implicit_ready(curve, where: str, name: str) -> None:
    purpose = "an implicit equation needs a planar Bézier curve"
    if not isinstance(curve, BezierCurve):
        raise SceneError(f"{where}: {name!r} is a B-spline curve; {purpose} (split it into Bézier segments)")
    _planar(curve, where, name, purpose)
    points = curve.control_points
    if all(p == points[0] for p in points):
        raise SceneError(f"{where}: {name!r} is a constant curve (all control points equal): it has no implicit equation")


def result_degree(surface, curve) -> int:
    """Degree ``n (l + m)`` of the exact image of a degree-``n`` domain curve on a degree-``(l, m)`` surface.

    Lasser & Bonneau (000), Theorem 1 (isoparametric lines have lower degree; this is the
    bound the planner checks against ``LIMITS["max_result_degree"]``).

    >>> from exactcagd import BezierCurve, BezierSurface
    >>> S = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    >>> result_degree(S, BezierCurve([[0, 0], ["1/2", 1], [1, 0]]))
    4
    """
    l, m = surface.degree
    return curve.degree * (l + m)


def _check_degree(degree: int, where: str, what: str) -> None:
    if degree > LIMITS["max_result_degree"]:
        raise SceneLimitError(f"{where}: {what} would have degree {degree}, above LIMITS['max_result_degree'] = {LIMITS['max_result_degree']}")


def check_products(scene: Scene, objects: dict, cached=frozenset()) -> list[str]:
    """Check every product of ``scene`` against the built ``objects``; return warnings.

    ``cached`` names products whose outputs are cached.  Their cheap checks (kinds,
    dimensions, degrees) are made all the same; the exact domain check and the cost
    estimates are not: nothing will be computed for them, an entry is stored only after
    its product passed these checks with the same specs and code (both are in the key),
    and they would load the machinery a cache hit should not (composition, sympy).

    Raises
    ------
    SceneError
        The first product that cannot be computed as asked, naming its scene key.
    """
    warnings = []
    for index, product in enumerate(scene.products):
        where = f"products[{index}]"
        kind = product["kind"]
        if kind in ("image_curve", "approximation"):
            surface, curve = objects[product["surface"]], objects[product["curve"]]
            _planar(curve, f"{where}.curve", product["curve"], "a domain curve must be planar (points (u, v))")
            if surface.dimension < 2:
                raise SceneError(f"{where}.surface: {product['surface']!r} lies in dimension {surface.dimension} (< 2)")
            _check_inside(curve, _domain_box(surface), f"{where}.curve", product["curve"], "domain curve", skip=product["name"] in cached)
            if kind == "image_curve" or product.get("method") in ("cubic", "fit"):
                _check_degree(result_degree(surface, curve), where, f"the exact image of {product['curve']} on {product['surface']}")
        elif kind == "patches" and "only_crossed_by" in product:
            curve = objects[product["only_crossed_by"]]
            _planar(curve, f"{where}.only_crossed_by", product["only_crossed_by"], "a domain curve must be planar (points (u, v))")
            _check_inside(curve, _domain_box(objects[product["surface"]]), f"{where}.only_crossed_by", product["only_crossed_by"], "domain curve", skip=product["name"] in cached)
        elif kind == "implicit":
            curve = objects[product["curve"]]
            _implicit_ready(curve, f"{where}.curve", product["curve"])
            n = curve.degree
            seconds = implicit_seconds(n)
            if seconds > WARN_IMPLICIT_SECONDS and product["name"] not in cached:
                warnings.append(
                    f"{where} ({product['name']}): implicit equation of degree {n} with {(n + 1) * (n + 2) // 2} "
                    f"exact coefficients, estimated ~{seconds:.2g} s (about 1.8x more per degree)"
                )
        elif kind == "intersections":
            a, b = (objects[name] for name in product["curves"])
            for k, (name, curve) in enumerate(zip(product["curves"], (a, b))):
                _implicit_ready(curve, f"{where}.curves[{k}]", name)
            degree = a.degree * b.degree
            _check_degree(degree, where, "the intersection polynomial")
            if product["name"] not in cached:
                from ..numeric.intersection import exact_cost

                cost = exact_cost(a.degree, b.degree)
                if cost > WARN_EXACT_SECONDS or degree > WARN_INTERSECTION_DEGREE:
                    warnings.append(
                        f"{where} ({product['name']}): intersection polynomial of degree {degree} "
                        f"(= {a.degree} x {b.degree}); the exact route (method 'exact', or the fallback of "
                        f"'{product.get('method', 'auto')}' on tangencies) takes ~{cost:.0f} s"
                    )
        elif kind == "ffd":
            lattice, curve = objects[product["lattice"]], objects[product["curve"]]
            if not isinstance(lattice, BezierSurface):
                raise SceneError(f"{where}.lattice: {product['lattice']!r} is a B-spline surface; an FFD lattice is one Bézier patch")
            _planar(curve, f"{where}.curve", product["curve"], "free-form deformation moves planar curves")
            _check_inside(curve, ((0, 1), (0, 1)), f"{where}.curve", product["curve"], "curve to deform", skip=product["name"] in cached)
            _check_degree(result_degree(lattice, curve), where, f"the deformed curve {product['curve']}")
    return warnings
