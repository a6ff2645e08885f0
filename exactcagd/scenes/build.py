"""Build exact exactcagd objects from validated scene specs.

Height expressions of grid generators are parsed with a small whitelist over
Python's ``ast`` (numbers, ``x``, ``y``, ``+ - * /``, integer powers, parentheses),
never ``eval`` or ``sympify``.  The expression is first *bounded without evaluating
it* (length, node count, depth, degree in x and y, an estimate of the coefficient
size: a nested power such as ``((x+9)**12)**12`` is refused from its tree alone),
then expanded exactly into a polynomial with rational coefficients.  Division is
allowed only by a non-zero constant, so ``z`` is a polynomial: ``1/(x-x)`` is refused
when the scene is read, not when the net is built.

>>> from exactcagd.scenes.build import parse_height
>>> from exactcagd.exact.scalars import to_rational
>>> f = parse_height("4*x*(1-x) + y**2/2", "z")
>>> f(to_rational("1/2"), to_rational(1))
mpq(3,2)
>>> f.degree
2
"""

from __future__ import annotations

import ast

from gmpy2 import mpq

from ..exact.scalars import float_policy, to_rational
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve, BSplineSurface
from .spec import LIMITS, SceneError, SceneLimitError

__all__ = ["HeightPolynomial", "parse_height", "build_surface", "build_curve"]

_MAX_POWER = 12


class HeightPolynomial:
    """An exact polynomial ``z(x, y) = sum c_ij x^i y^j`` (rational ``c_ij``), callable.

    ``terms`` maps ``(i, j)`` to the non-zero coefficient ``c_ij``; ``degree`` is the
    total degree (0 for the zero polynomial).
    """

    def __init__(self, terms: dict):
        self.terms = {k: v for k, v in terms.items() if v != 0}
        self.degree = max((i + j for i, j in self.terms), default=0)
        rows: dict = {}
        for (i, j), c in self.terms.items():
            rows.setdefault(i, {})[j] = c
        # rows[i] = coefficients of y^j in the coefficient of x^i, dense, highest power first
        self._rows = {i: [row.get(j, 0) for j in range(max(row), -1, -1)] for i, row in rows.items()}

    def __call__(self, x, y):
        """Exact value at rationals ``x, y`` (Horner in ``y`` for each power of ``x``)."""
        total = mpq(0)
        xpow = mpq(1)
        for i in range(max(self._rows, default=-1) + 1):
            row = self._rows.get(i)
            if row:
                inner = mpq(0)
                for c in row:
                    inner = inner * y + c
                total += xpow * inner
            xpow *= x
        return total


def _bits(value: int) -> int:
    return max(1, abs(value).bit_length())


def _bound(node, where: str, depth: int, count: list) -> tuple[int, int, int]:
    """``(degree, numerator bits, denominator bits)`` bounds of a whitelisted expression node,
    computed from the syntax tree without evaluating it.

    The bits bound the binary size of the expanded coefficients over a common
    denominator: a sum adds the denominators' sizes (their lcm divides their product),
    a product adds sizes plus the log of the number of terms, a power multiplies them.
    Raises :class:`SceneError` for a forbidden node or a bound beyond ``LIMITS``.
    """
    count[0] += 1
    if count[0] > LIMITS["max_expression_nodes"]:
        raise SceneLimitError(f"{where}: expression has more than {LIMITS['max_expression_nodes']} nodes")
    if depth > LIMITS["max_expression_depth"]:
        raise SceneLimitError(f"{where}: expression nested deeper than {LIMITS['max_expression_depth']} levels")
    if isinstance(node, ast.Expression):
        return _bound(node.body, where, depth + 1, count)
    if isinstance(node, ast.Constant) and isinstance(node.value, int) and not isinstance(node.value, bool):
        if _bits(node.value) > LIMITS["max_number_bits"]:
            raise SceneLimitError(f"{where}: integer literal of more than {LIMITS['max_number_bits']} bits")
        return 0, _bits(node.value), 0
    if isinstance(node, ast.Name) and node.id in ("x", "y"):
        return 1, 1, 0
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        return _bound(node.operand, where, depth + 1, count)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow):
        if not (isinstance(node.right, ast.Constant) and type(node.right.value) is int):
            raise SceneError(f"{where}: exponents must be integer literals")
        k = node.right.value
        if not 0 <= k <= _MAX_POWER:
            raise SceneError(f"{where}: exponent {k} outside 0..{_MAX_POWER}")
        degree, num, den = _bound(node.left, where, depth + 1, count)
        return _checked(degree * k, (num + 2 * (degree + 1).bit_length()) * k, den * k, where)
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub, ast.Mult, ast.Div)):
        d1, n1, e1 = _bound(node.left, where, depth + 1, count)
        d2, n2, e2 = _bound(node.right, where, depth + 1, count)
        if isinstance(node.op, (ast.Add, ast.Sub)):
            return _checked(max(d1, d2), max(n1 + e2, n2 + e1) + 1, e1 + e2, where)
        if isinstance(node.op, ast.Mult):
            return _checked(d1 + d2, n1 + n2 + 2 * (min(d1, d2) + 1).bit_length(), e1 + e2, where)
        return _checked(d1, n1 + e2, e1 + n2, where)  # the divisor is checked to be a constant when expanded
    raise SceneError(f"{where}: only numbers, x, y, + - * / and integer powers are allowed ({ast.dump(node)[:60]})")


def _checked(degree: int, num: int, den: int, where: str) -> tuple[int, int, int]:
    if degree > LIMITS["max_expression_degree"]:
        raise SceneLimitError(f"{where}: expression of degree {degree} exceeds the limit {LIMITS['max_expression_degree']}")
    if num + den > LIMITS["max_expression_bits"]:
        raise SceneLimitError(f"{where}: expression coefficients may reach ~{num + den} bits (limit {LIMITS['max_expression_bits']})")
    return degree, num, den


def _expand(node, where: str) -> dict:
    """Exact expansion of a bounded expression into ``{(i, j): mpq}``."""
    if isinstance(node, ast.Expression):
        return _expand(node.body, where)
    if isinstance(node, ast.Constant):
        return {(0, 0): mpq(node.value)}
    if isinstance(node, ast.Name):
        return {(1, 0): mpq(1)} if node.id == "x" else {(0, 1): mpq(1)}
    if isinstance(node, ast.UnaryOp):
        inner = _expand(node.operand, where)
        return {k: -v for k, v in inner.items()} if isinstance(node.op, ast.USub) else inner
    left = _expand(node.left, where)
    if isinstance(node.op, ast.Pow):
        result = {(0, 0): mpq(1)}
        for _ in range(node.right.value):
            result = _times(result, left)
        return result
    right = _expand(node.right, where)
    if isinstance(node.op, ast.Add):
        return _plus(left, right, 1)
    if isinstance(node.op, ast.Sub):
        return _plus(left, right, -1)
    if isinstance(node.op, ast.Mult):
        return _times(left, right)
    right = {k: v for k, v in right.items() if v != 0}
    if not right:
        raise SceneError(f"{where}: the expression divides by zero")
    if set(right) != {(0, 0)}:
        raise SceneError(f"{where}: division only by a non-zero number (z must be a polynomial in x, y)")
    divisor = right[(0, 0)]
    return {k: v / divisor for k, v in left.items()}


def _plus(a: dict, b: dict, sign: int) -> dict:
    out = dict(a)
    for k, v in b.items():
        out[k] = out.get(k, 0) + sign * v
    return out


def _times(a: dict, b: dict) -> dict:
    out: dict = {}
    for (i1, j1), v1 in a.items():
        if v1 == 0:
            continue
        for (i2, j2), v2 in b.items():
            key = (i1 + i2, j1 + j2)
            out[key] = out.get(key, 0) + v1 * v2
    return out


def parse_height(text: str, where: str) -> HeightPolynomial:
    """Parse and bound a polynomial height expression ``z(x, y)``; expand it exactly.

    Parameters
    ----------
    text : str
        ``x``, ``y``, integer literals, ``+ - * /``, ``**`` with a literal exponent in
        0..12, parentheses.  Division only by a non-zero constant.
    where : str
        The scene key, for messages.

    Returns
    -------
    HeightPolynomial
        Callable ``z(x, y)`` on exact rationals.

    Raises
    ------
    SceneError
        Forbidden syntax, a bound of ``LIMITS`` exceeded (checked on the syntax tree before
        any arithmetic), division by zero or by a non-constant.

    Examples
    --------
    >>> parse_height("(x - 1/3)**2 * y", "z").terms[(2, 1)]
    mpq(1,1)
    """
    if not isinstance(text, str) or len(text) > LIMITS["max_expression_chars"]:
        raise SceneError(f"{where}: expected a polynomial expression in x, y of at most {LIMITS['max_expression_chars']} characters")
    try:
        tree = ast.parse(text, mode="eval")
    except (SyntaxError, RecursionError, MemoryError, ValueError) as exc:
        raise SceneError(f"{where}: cannot parse {text!r} ({getattr(exc, 'msg', exc)})") from None
    _bound(tree, where, 0, [0])
    return HeightPolynomial(_expand(tree, where))


def _grid_net(spec: dict, where: str):
    nu, nv = spec["size"]
    z = parse_height(spec.get("z", "0"), f"{where}.z")
    net = []
    for i in range(nu):
        x = to_rational(i) / (nu - 1)
        row = []
        for j in range(nv):
            y = to_rational(j) / (nv - 1)
            row.append([x, y, z(x, y)])
        net.append(row)
    return net


def build_surface(spec: dict, name: str, policy: str):
    """Exact BezierSurface or BSplineSurface from a validated spec."""
    net = spec["control_net"]
    if isinstance(net, dict):
        net = _grid_net(net, f"surfaces.{name}.control_net")
    with float_policy(policy):
        if spec["type"] == "bezier":
            return BezierSurface(net, spec.get("weights"))
        return BSplineSurface(net, spec["knots_u"], spec["knots_v"], spec.get("weights"))


def build_curve(spec: dict, name: str, policy: str):
    """Exact BezierCurve or BSplineCurve from a validated spec."""
    with float_policy(policy):
        if spec["type"] == "bezier":
            return BezierCurve(spec["control_points"], spec.get("weights"))
        return BSplineCurve(spec["control_points"], spec["knots"], spec.get("weights"))
