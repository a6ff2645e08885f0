"""Product handlers of the scene runner: what each product needs, skips, computes, writes.

Every handler family has four functions keyed by product kind:
``references`` (names it uses), ``plan`` (lines: computes / skips), ``compute``
(exact result + info dict with a one-line ``summary``) and ``render`` (output files).
Library calls are imported lazily so planning stays cheap.
"""

from __future__ import annotations

import io
import json

from ..errors import NotSupportedError
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve, BSplineSurface
from .checks import implicit_seconds, result_degree
from .serialize import to_json_value
from .spec import DEFAULT_APPROXIMATION

__all__ = ["references", "plan", "compute", "render"]


def references(product: dict) -> list[str]:
    """Names of the objects (and products) a product uses."""
    refs = []
    for key in ("surface", "curve", "lattice", "only_crossed_by"):
        if key in product:
            refs.append(product[key])
    refs += list(product.get("curves", [])) + list(product.get("of", []))
    return refs


# ----------------------------------------------------------------------------- planning
def plan(product: dict, runner) -> tuple[list[str], list[str]]:
    kind = product["kind"]
    objects = runner.objects
    if kind in ("image_curve", "approximation"):
        surface, curve = objects[product["surface"]], objects[product["curve"]]
        return _plan_on_surface(surface, curve, product)
    if kind == "patches":
        surface = objects[product["surface"]]
        if isinstance(surface, BezierSurface):
            return ["the surface is a single Bézier patch (nothing to extract)"], []
        total = _patch_count(surface)
        if "only_crossed_by" in product:
            crossed = _crossed(surface, objects[product["only_crossed_by"]])
            return [f"{len(crossed)} patch(es) crossed by {product['only_crossed_by']}"], [
                f"{total - len(crossed)} of {total} patches not crossed (not extracted)"
            ]
        return [f"all {total} Bézier patches by knot insertion"], []
    if kind == "picture":
        needs, skips = [], []
        for ref in product["of"]:
            if ref in objects:
                needs.append(f"float drawing of {ref}")
        pairs = _surface_curve_pairs(product, objects)
        for s, c in pairs:
            needs.append(f"F(K(t)) of {c} on {s} by float sampling of the exact objects")
            skips.append(f"exact composition of {c} on {s}: a picture needs points, not the degree-N(l+m) curve")
        return needs, skips
    if kind == "implicit":
        n = objects[product["curve"]].degree
        return [f"implicit equation of {product['curve']} ({product.get('method', 'moving_lines')}, degree {n}, ~{implicit_seconds(n):.2g} s)"], []
    if kind == "intersections":
        from ..numeric.intersection import exact_cost

        a, b = (objects[n] for n in product["curves"])
        method = product.get("method", "auto")
        cost = f"exact route for degrees {a.degree} x {b.degree}: ~{exact_cost(a.degree, b.degree):.2g} s"
        return [f"intersections of {product['curves'][0]} and {product['curves'][1]} by {method} ({cost})"], []
    if kind == "ffd":
        return [f"exact free-form deformation of {product['curve']} by {product['lattice']}"], []
    return [], []  # pragma: no cover - validated kinds only


def _patch_count(surface: BSplineSurface) -> int:
    bu, bv = surface.breakpoints()
    return (len(bu) - 1) * (len(bv) - 1)


def _crossed(surface, curve) -> set:
    from ..composition.splines import crossed_patches

    return crossed_patches(surface, curve)


def _plan_on_surface(surface, curve, product) -> tuple[list[str], list[str]]:
    needs, skips = [], []
    if isinstance(surface, BSplineSurface):
        crossed = _crossed(surface, curve)
        total = _patch_count(surface)
        needs.append(f"extract {len(crossed)} Bézier patch(es) crossed by {product['curve']}")
        if total > len(crossed):
            skips.append(f"{total - len(crossed)} of {total} patches are not crossed (never extracted)")
    if product["kind"] == "image_curve":
        degree = result_degree(surface, curve)
        needs.append(f"exact composition, stored degree {degree} per piece (isoparametric pieces use the shortcut)")
    else:
        needs.append(f"{product.get('method', DEFAULT_APPROXIMATION)} approximation to tol {product['tol']}")
        skips.append("exact output of the composed curve (only its certified distance is used)")
    return needs, skips


def _surface_curve_pairs(product, objects) -> list[tuple[str, str]]:
    refs = [r for r in product["of"] if r in objects]
    surfaces = [r for r in refs if isinstance(objects[r], (BezierSurface, BSplineSurface))]
    curves = [r for r in refs if isinstance(objects[r], (BezierCurve, BSplineCurve)) and objects[r].dimension == 2]
    return [(s, c) for s in surfaces for c in curves]


# ----------------------------------------------------------------------------- computing
def compute(product: dict, runner, results: dict):
    kind = product["kind"]
    objects = runner.objects
    if kind == "image_curve":
        return _compute_image(objects[product["surface"]], objects[product["curve"]], product)
    if kind == "patches":
        return _compute_patches(objects[product["surface"]], product, objects)
    if kind == "picture":
        return None, {"summary": f"{len(product['of'])} item(s) drawn"}
    if kind == "implicit":
        from ..algebra import implicitize

        poly = implicitize(objects[product["curve"]], method=product.get("method", "moving_lines"))
        return poly, {"summary": f"degree {poly.total_degree()} implicit equation"}
    if kind == "intersections":
        from ..numeric.intersection import intersect

        a, b = (objects[n] for n in product["curves"])
        # default: clipping, certified, with the exact route on what it cannot certify
        points = intersect(a, b, method=product.get("method", "auto"), progress=True)
        arcs = "".join(f", shared arc t1 in [{o.t1_interval[0]}, {o.t1_interval[1]}]" for o in points.overlaps)
        return points, {"summary": f"{len(points)} intersection(s){arcs}"}
    if kind == "approximation":
        return _compute_approximation(objects[product["surface"]], objects[product["curve"]], product)
    if kind == "ffd":
        from ..composition import ffd

        deformed = ffd(objects[product["lattice"]], objects[product["curve"]])
        return deformed, {"summary": f"deformed curve of degree {getattr(deformed, 'degree', '?')}"}
    raise NotSupportedError(f"product kind {kind!r}")  # pragma: no cover


def _compute_image(surface, curve, product):
    if isinstance(surface, BezierSurface) and isinstance(curve, BezierCurve):
        from ..composition import compose

        from ..composition.splines import ComposedPiece, SplineComposition
        from ..exact.scalars import to_rational

        image = compose(surface, curve, reduce=bool(product.get("reduce", False)))
        # the same output shape as a B-spline surface's image: one exact piece over [0, 1]
        zero, one = to_rational(0), to_rational(1)
        piece = ComposedPiece(image, (zero, one), (zero, one), (0, 0), ((zero, one), (zero, one)), 0)
        result = SplineComposition([piece], [], (zero, one))
        return result, {"summary": f"1 piece, degree {image.degree} (true degree {image.true_degree()})"}
    from ..composition.splines import compose_spline

    result = compose_spline(surface, curve)
    degrees = sorted({piece.curve.degree for piece in result.pieces})
    return result, {"summary": f"{len(result.pieces)} piece(s), degrees {degrees}"}


def _compute_patches(surface, product, objects):
    if isinstance(surface, BezierSurface):
        return {(0, 0): surface}, {"summary": "1 patch"}
    if "only_crossed_by" in product:
        crossed = _crossed(surface, objects[product["only_crossed_by"]])
        patches = surface.to_bezier_patches(pairs=crossed)
    else:
        patches = surface.to_bezier_patches()
    return {f"{i},{j}": {"u_span": list(span[0]), "v_span": list(span[1]), "patch": s} for (i, j), (span, s) in patches.items()}, {
        "summary": f"{len(patches)} patch(es) extracted"
    }


def _compute_approximation(surface, curve, product):
    method = product.get("method", DEFAULT_APPROXIMATION)
    tol = product["tol"]
    if method == "cubic":
        from ..composition.cubic_approx import approximate_cubic

        result = approximate_cubic(surface, curve, tol)
    else:
        from ..curves_on_surfaces import approximate

        result = approximate(surface, curve, tol, method=method)
    segments = getattr(result, "segments", [])
    return result, {"summary": f"{len(segments)} segment(s), distance bound {float(result.distance_bound):.3g}"}


# ----------------------------------------------------------------------------- rendering
def render(product: dict, result, runner, results: dict) -> tuple[dict, dict]:
    """Output files of one product and the run-dependent data kept out of them.

    Returns ``({suffix: bytes}, timings)``: the exact JSON (or the PNG of a picture), and
    the wall-clock timings a result carries (they go to ``timings.json``, so that two
    runs of one scene write byte-identical outputs).
    """
    if product["kind"] == "picture":
        return {".png": _picture(product, runner, results)}, {}
    value = to_json_value({"product": product, "result": result})
    timings = {}
    if isinstance(value["result"], dict) and isinstance(value["result"].get("timings"), dict):
        timings = value["result"].pop("timings")
    return {".json": json.dumps(value, indent=1, allow_nan=False).encode()}, timings


def _picture(product: dict, runner, results: dict) -> bytes:
    from . import pictures

    buffer = io.BytesIO()
    specs = {p["name"]: p for p in runner.scene.products}
    fig = pictures.draw(product, runner.objects, results, specs)
    # no software/date stamp: the same scene gives the same bytes
    fig.savefig(buffer, format="png", dpi=110, metadata={"Software": None})
    pictures.close(fig)
    return buffer.getvalue()
