"""Scene files: parsing and validation with messages that point at the offending key.

A scene (TOML or JSON) names exact objects and the products wanted from them::

    [scene]
    name = "hill"                     # [A-Za-z0-9_-], used for output file names
    float_policy = "reject"           # or "exact": floats taken at their binary value

    [surfaces.hill]
    type = "bspline"                  # "bezier" | "bspline"
    knots_u = [0, 0, 0, 0, 1, 1, 1, 1]
    knots_v = [0, 0, 0, 0, 1, 1, 1, 1]
    control_net = [[[0, 0, 0], ...], ...]      # or a generator table, see below
    weights = [[1, ...], ...]                  # optional (NURBS / rational)

    [curves.trim]
    type = "bezier"                   # "bezier" | "bspline"
    control_points = [["1/4", "1/4"], ["3/4", "1/2"]]

    [[products]]
    kind = "image_curve"              # see PRODUCT_KINDS
    name = "trim_on_hill"
    surface = "hill"
    curve = "trim"

Numbers are integers or ``"p/q"``/decimal strings (exact); floats only under
``float_policy = "exact"``.  A control net may instead be generated exactly::

    control_net = { generator = "grid", size = [17, 17], z = "x*(1-x)*y*(1-y)*4" }

which places ``(i/(nu-1), j/(nv-1), z)`` with ``z`` a polynomial expression in x, y
with rational coefficients (evaluated exactly).

Everything the text decides is checked before any work starts: unknown keys, wrong
shapes, huge degrees, absurd counts, NaN, unsafe names, non-positive weights, references
that are not names of this scene.  Inputs are bounded *before* they are evaluated
(``LIMITS``): number strings by their digits and decimal exponent (``"1e100000000"`` is
refused, not expanded), height expressions by length, node count, depth, degree and an
estimate of their coefficient size taken from the syntax tree.  What needs the built
objects (a 3-D or out-of-domain domain curve, a product kind that does not fit its input,
result degrees) is checked next by :mod:`exactcagd.scenes.checks`, still before any work.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import InputError, LimitError

__all__ = ["SceneError", "SceneLimitError", "Scene", "load_scene", "parse_scene", "LIMITS", "PRODUCT_KINDS"]

#: Hard limits that reject absurd scenes before any work starts.
LIMITS = {
    "max_degree": 40,
    "max_control_points": 20000,
    "max_products": 64,
    "max_objects": 256,
    "max_grid": 400,
    "max_result_degree": 400,
    "max_samples": 20000,
    # bits of one number's numerator or denominator (ints and number strings, "1e100000000"
    # included), checked by exactcagd.limits before the number is built (~1200 digits)
    "max_number_bits": 4000,
    # height expressions of grid generators (bounded on the syntax tree, before evaluation)
    "max_expression_chars": 500,
    "max_expression_nodes": 400,
    "max_expression_depth": 100,
    "max_expression_degree": 60,
    "max_expression_bits": 20000,
}

NAME = re.compile(r"^[A-Za-z0-9_-]{1,64}$")

#: product kind -> (required keys, optional keys)
PRODUCT_KINDS = {
    "image_curve": ({"surface", "curve"}, {"reduce"}),
    "approximation": ({"surface", "curve", "tol"}, {"method"}),
    "implicit": ({"curve"}, {"method"}),
    "intersections": ({"curves"}, {"method"}),
    "patches": ({"surface"}, {"only_crossed_by"}),
    "ffd": ({"lattice", "curve"}, set()),
    "picture": ({"of"}, {"samples", "title"}),
}
_COMMON_PRODUCT_KEYS = {"kind", "name"}

# Yang et al.'s parabola method: exact G1 in Q(sqrt D) and lies exactly on the surface
# (Lasser & Bonneau's "cubic" of VIII is available too, but lies off the surface).
DEFAULT_APPROXIMATION = "parabola"


class SceneError(InputError):
    """A scene file is malformed; the message names the offending key."""


class SceneLimitError(SceneError, LimitError):
    """A scene exceeds one of ``LIMITS`` (raise one deliberately: ``spec.LIMITS[name] = value``)."""


@dataclass
class Scene:
    """A validated scene: raw (exact-convertible) specs of objects and products."""

    name: str
    float_policy: str
    surfaces: dict = field(default_factory=dict)
    curves: dict = field(default_factory=dict)
    products: list = field(default_factory=list)
    source: str = ""

    def object_spec(self, name: str) -> dict:
        if name in self.surfaces:
            return self.surfaces[name]
        return self.curves[name]


def load_scene(path) -> Scene:
    """Read and validate a ``.toml`` or ``.json`` scene file."""
    path = Path(path)
    if not path.is_file():
        raise SceneError(f"scene file {str(path)!r} does not exist")
    text = path.read_text()
    if path.suffix == ".toml":
        try:
            import tomllib
        except ModuleNotFoundError:  # Python 3.10: tomllib is the standard library's copy of tomli
            import tomli as tomllib

        try:
            data = tomllib.loads(text)
        except (tomllib.TOMLDecodeError, ValueError, RecursionError) as exc:
            raise SceneError(f"{path}: not valid TOML ({exc})") from None
    elif path.suffix == ".json":
        try:
            data = json.loads(text, parse_constant=_reject_constant)
        except (json.JSONDecodeError, ValueError, RecursionError) as exc:  # ValueError: integers of > 4300 digits
            raise SceneError(f"{path}: not valid JSON ({exc})") from None
    else:
        raise SceneError(f"{path}: scene files end in .toml or .json")
    scene = parse_scene(data)
    scene.source = str(path)
    return scene


def _reject_constant(name):
    raise SceneError(f"JSON constant {name} is not a finite number")


def parse_scene(data: dict) -> Scene:
    """Validate a scene given as a dict (already parsed TOML/JSON)."""
    _expect_dict(data, "scene file")
    _only_keys(data, {"scene", "surfaces", "curves", "products"}, "")
    head = data.get("scene", {})
    _expect_dict(head, "scene")
    _only_keys(head, {"name", "float_policy", "description"}, "scene")
    name = head.get("name", "scene")
    _check_name(name, "scene.name")
    policy = head.get("float_policy", "reject")
    if policy not in ("exact", "reject"):
        raise SceneError(f"scene.float_policy: expected 'exact' or 'reject', got {policy!r}")
    scene = Scene(name=name, float_policy=policy)
    surfaces, curves = data.get("surfaces", {}), data.get("curves", {})
    _expect_dict(surfaces, "surfaces")
    _expect_dict(curves, "curves")
    if len(surfaces) + len(curves) > LIMITS["max_objects"]:
        raise SceneError(f"too many objects ({len(surfaces) + len(curves)} > {LIMITS['max_objects']})")
    for key, spec in surfaces.items():
        scene.surfaces[key] = _check_surface(spec, f"surfaces.{key}", key, policy)
    for key, spec in curves.items():
        if key in scene.surfaces:
            raise SceneError(f"curves.{key}: name already used by a surface")
        scene.curves[key] = _check_curve(spec, f"curves.{key}", key, policy)
    products = data.get("products", [])
    if not isinstance(products, list) or not products:
        raise SceneError("products: expected a non-empty list of [[products]] tables")
    if len(products) > LIMITS["max_products"]:
        raise SceneError(f"products: {len(products)} > limit {LIMITS['max_products']}")
    seen = set()
    for i, spec in enumerate(products):
        product = _check_product(spec, f"products[{i}]", scene)
        if product["name"] in seen:
            raise SceneError(f"products[{i}].name: duplicate product name {product['name']!r}")
        if product["name"] in scene.surfaces or product["name"] in scene.curves:
            raise SceneError(f"products[{i}].name: {product['name']!r} is already the name of an object (pictures refer to both)")
        seen.add(product["name"])
        scene.products.append(product)
    for i, product in enumerate(scene.products):
        if product["kind"] == "picture":
            for ref in product["of"]:
                if ref not in seen and ref not in scene.surfaces and ref not in scene.curves:
                    raise SceneError(f"products[{i}].of: {ref!r} is neither a product nor an object of this scene")
    return scene


# ----------------------------------------------------------------------------- helpers
def _expect_dict(value, where: str) -> None:
    if not isinstance(value, dict):
        raise SceneError(f"{where}: expected a table/object, got {type(value).__name__}")


def _only_keys(value: dict, allowed: set, where: str) -> None:
    unknown = sorted(set(value) - allowed)
    if unknown:
        prefix = f"{where}." if where else ""
        raise SceneError(f"{prefix}{unknown[0]}: unknown key (allowed: {', '.join(sorted(allowed))})")


def _check_name(name, where: str) -> None:
    if not isinstance(name, str) or not NAME.match(name):
        raise SceneError(f"{where}: names are 1-64 characters of [A-Za-z0-9_-] (got {name!r})")


def _check_number(x, where: str, policy: str):
    """Exact value of a scene number; its size is bounded before it is built.

    The bound is the package's ``max_input_bits`` check (:mod:`exactcagd.limits`), tightened to
    ``LIMITS["max_number_bits"]`` for scenes: ``"1e100000000"`` is refused from its digits and
    exponent, not expanded.
    """
    from .. import limits
    from ..exact.scalars import to_rational

    if isinstance(x, bool) or not isinstance(x, (int, float, str)):
        raise SceneError(f"{where}: expected a number or 'p/q' string, got {type(x).__name__}")
    bound = min(b for b in (limits.get("max_input_bits"), LIMITS["max_number_bits"]) if b is not None)
    try:
        with limits.raised(max_input_bits=bound):
            return to_rational(x, policy=policy, where=where)
    except LimitError as exc:
        raise SceneLimitError(f"{str(exc).split('; raise it')[0]} (scenes: LIMITS['max_number_bits'])") from None
    except InputError as exc:
        raise SceneError(str(exc)) from None


def _check_positive(value, where: str, policy: str) -> None:
    """Weights of rational objects are positive numbers (checked when the scene is read)."""
    if isinstance(value, list):
        for i, v in enumerate(value):
            _check_positive(v, f"{where}[{i}]", policy)
    elif _check_number(value, where, policy) <= 0:
        raise SceneError(f"{where}: weights must be positive, got {value!r}")


def _shape(value, where: str) -> tuple:
    """Shape of a rectangular nested list (raises on ragged)."""
    shape = []
    level = [value]
    while isinstance(level[0], list):
        lengths = {len(v) if isinstance(v, list) else -1 for v in level}
        if len(lengths) != 1 or -1 in lengths:
            raise SceneError(f"{where}: ragged nested list at depth {len(shape)}")
        n = lengths.pop()
        if n == 0:
            raise SceneError(f"{where}: empty list at depth {len(shape)}")
        shape.append(n)
        level = [x for v in level for x in v]
        if len(level) > LIMITS["max_control_points"] * 4:
            raise SceneError(f"{where}: more than {LIMITS['max_control_points']} entries")
    for i, x in enumerate(level):
        if isinstance(x, list):  # pragma: no cover - caught above
            raise SceneError(f"{where}: ragged nested list")
    return tuple(shape)


def _check_numbers(value, where: str, policy: str) -> None:
    if isinstance(value, list):
        for i, v in enumerate(value):
            _check_numbers(v, f"{where}[{i}]", policy)
    else:
        _check_number(value, where, policy)


def _check_knots(knots, n: int, where: str, policy: str) -> int:
    if not isinstance(knots, list) or not knots:
        raise SceneError(f"{where}: expected a list of knots")
    _check_numbers(knots, where, policy)
    degree = len(knots) - n - 1
    if degree < 1:
        raise SceneError(f"{where}: {len(knots)} knots for {n} control points give degree {degree} (< 1)")
    if degree > LIMITS["max_degree"]:
        raise SceneError(f"{where}: degree {degree} exceeds the limit {LIMITS['max_degree']}")
    from ..exact.knots import check_knots

    try:
        check_knots(knots, n, degree)
    except InputError as exc:
        raise SceneError(f"{where}: {exc}") from None
    return degree


def _check_grid_generator(spec: dict, where: str) -> tuple:
    _only_keys(spec, {"generator", "size", "z", "domain"}, where)
    if spec.get("generator") != "grid":
        raise SceneError(f"{where}.generator: only 'grid' is supported")
    size = spec.get("size")
    if not (isinstance(size, list) and len(size) == 2 and all(isinstance(s, int) and not isinstance(s, bool) for s in size)):
        raise SceneError(f"{where}.size: expected [nu, nv] integers")
    if not all(2 <= s <= LIMITS["max_grid"] for s in size):
        raise SceneError(f"{where}.size: each count must be in 2..{LIMITS['max_grid']}")
    z = spec.get("z", "0")
    if not isinstance(z, str) or len(z) > 500:
        raise SceneError(f"{where}.z: expected a short polynomial expression in x, y")
    from .build import parse_height

    parse_height(z, f"{where}.z")
    return (size[0], size[1], 3)


def _check_surface(spec, where: str, name: str, policy: str) -> dict:
    _check_name(name, where)
    _expect_dict(spec, where)
    kind = spec.get("type")
    if kind == "bezier":
        _only_keys(spec, {"type", "control_net", "weights"}, where)
    elif kind == "bspline":
        _only_keys(spec, {"type", "control_net", "weights", "knots_u", "knots_v"}, where)
    else:
        raise SceneError(f"{where}.type: expected 'bezier' or 'bspline', got {kind!r}")
    net = spec.get("control_net")
    if net is None:
        raise SceneError(f"{where}.control_net: missing")
    if isinstance(net, dict):
        shape = _check_grid_generator(net, f"{where}.control_net")
    else:
        shape = _shape(net, f"{where}.control_net")
        if len(shape) != 3 or shape[2] not in (2, 3):
            raise SceneError(f"{where}.control_net: expected shape (nu, nv, 3), got {shape}")
        _check_numbers(net, f"{where}.control_net", policy)
    if shape[0] * shape[1] > LIMITS["max_control_points"]:
        raise SceneError(f"{where}.control_net: {shape[0] * shape[1]} control points exceed {LIMITS['max_control_points']}")
    if "weights" in spec:
        wshape = _shape(spec["weights"], f"{where}.weights")
        if wshape != shape[:2]:
            raise SceneError(f"{where}.weights: shape {wshape} does not match the net {shape[:2]}")
        _check_positive(spec["weights"], f"{where}.weights", policy)
    if kind == "bezier":
        if max(shape[:2]) - 1 > LIMITS["max_degree"]:
            raise SceneError(f"{where}.control_net: degree {max(shape[:2]) - 1} exceeds {LIMITS['max_degree']}")
    else:
        for axis, key in ((0, "knots_u"), (1, "knots_v")):
            if key not in spec:
                raise SceneError(f"{where}.{key}: missing")
            _check_knots(spec[key], shape[axis], f"{where}.{key}", policy)
    return dict(spec)


def _check_curve(spec, where: str, name: str, policy: str) -> dict:
    _check_name(name, where)
    _expect_dict(spec, where)
    kind = spec.get("type")
    if kind == "bezier":
        _only_keys(spec, {"type", "control_points", "weights"}, where)
    elif kind == "bspline":
        _only_keys(spec, {"type", "control_points", "weights", "knots"}, where)
    else:
        raise SceneError(f"{where}.type: expected 'bezier' or 'bspline', got {kind!r}")
    pts = spec.get("control_points")
    if pts is None:
        raise SceneError(f"{where}.control_points: missing")
    shape = _shape(pts, f"{where}.control_points")
    if len(shape) != 2 or shape[1] not in (2, 3):
        raise SceneError(f"{where}.control_points: expected shape (n, 2) or (n, 3), got {shape}")
    if shape[0] > LIMITS["max_control_points"]:
        raise SceneError(f"{where}.control_points: too many points")
    _check_numbers(pts, f"{where}.control_points", policy)
    if "weights" in spec:
        if _shape(spec["weights"], f"{where}.weights") != (shape[0],):
            raise SceneError(f"{where}.weights: expected {shape[0]} weights")
        _check_positive(spec["weights"], f"{where}.weights", policy)
    if kind == "bezier" and shape[0] - 1 > LIMITS["max_degree"]:
        raise SceneError(f"{where}.control_points: degree {shape[0] - 1} exceeds {LIMITS['max_degree']}")
    if kind == "bspline":
        if "knots" not in spec:
            raise SceneError(f"{where}.knots: missing")
        _check_knots(spec["knots"], shape[0], f"{where}.knots", policy)
    return dict(spec)


def _check_product(spec, where: str, scene: Scene) -> dict:
    _expect_dict(spec, where)
    kind = spec.get("kind")
    if not isinstance(kind, str) or kind not in PRODUCT_KINDS:
        raise SceneError(f"{where}.kind: expected one of {sorted(PRODUCT_KINDS)}, got {kind!r}")
    required, optional = PRODUCT_KINDS[kind]
    _only_keys(spec, required | optional | _COMMON_PRODUCT_KEYS, where)
    for key in sorted(required):
        if key not in spec:
            raise SceneError(f"{where}.{key}: missing (required for kind {kind!r})")
    product = dict(spec)
    product.setdefault("name", f"{kind}_{where[len('products['):-1]}")
    _check_name(product["name"], f"{where}.name")

    def need(key, table, what):
        ref = spec[key]
        if not isinstance(ref, str):
            raise SceneError(f"{where}.{key}: expected the name of a {what}, got {type(ref).__name__}")
        if ref not in table:
            raise SceneError(f"{where}.{key}: no {what} named {ref!r}")

    if "surface" in required:
        need("surface", scene.surfaces, "surface")
    if kind == "ffd":
        need("lattice", scene.surfaces, "surface (lattice)")
    if "curve" in required:
        need("curve", scene.curves, "curve")
    if kind == "intersections":
        refs = spec["curves"]
        if not (isinstance(refs, list) and len(refs) == 2 and all(isinstance(r, str) and r in scene.curves for r in refs)):
            raise SceneError(f"{where}.curves: expected two curve names of this scene")
    if kind == "approximation":
        tol = _check_number(spec["tol"], f"{where}.tol", "exact")
        if tol <= 0:
            raise SceneError(f"{where}.tol: tolerance must be positive")
        method = spec.get("method", DEFAULT_APPROXIMATION)
        if method not in ("cubic", "parabola", "hyperbola", "polyline", "fit"):
            raise SceneError(f"{where}.method: expected cubic, parabola, hyperbola, polyline or fit")
    if kind == "picture":
        if not isinstance(spec["of"], list) or not spec["of"] or not all(isinstance(r, str) for r in spec["of"]):
            raise SceneError(f"{where}.of: expected a non-empty list of names")
        samples = spec.get("samples", 200)
        if type(samples) is not int or not 2 <= samples <= LIMITS["max_samples"]:
            raise SceneError(f"{where}.samples: expected an integer in 2..{LIMITS['max_samples']}")
    if kind == "patches" and "only_crossed_by" in spec:
        if not isinstance(spec["only_crossed_by"], str) or spec["only_crossed_by"] not in scene.curves:
            raise SceneError(f"{where}.only_crossed_by: no curve named {spec['only_crossed_by']!r}")
    if "reduce" in spec and not isinstance(spec["reduce"], bool):
        raise SceneError(f"{where}.reduce: expected true or false")
    if "title" in spec and not (isinstance(spec["title"], str) and len(spec["title"]) <= 200):
        raise SceneError(f"{where}.title: expected a string of at most 200 characters")
    if kind == "implicit" and spec.get("method", "moving_lines") not in ("resultant", "bezier", "moving_lines"):
        raise SceneError(f"{where}.method: expected resultant, bezier or moving_lines")
    if kind == "intersections" and spec.get("method", "auto") not in ("auto", "exact", "clipping", "subdivision", "interval"):
        raise SceneError(f"{where}.method: expected auto, exact, clipping, subdivision or interval")
    return product
