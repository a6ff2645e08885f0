"""Build exact exactcagd objects from validated scene specs.

Height expressions of grid generators are parsed with a small whitelist over
Python's ``ast`` (numbers, ``x``, ``y``, ``+ - * /``, integer powers, parentheses),
never ``eval``; they are evaluated in exact rationals.

>>> from exactcagd.scenes.build import parse_height
>>> f = parse_height("4*x*(1-x) + y**2/2", "z")
>>> f(to_rational("1/2"), to_rational(1))
mpq(3,2)
"""

from __future__ import annotations

import ast

from ..exact.scalars import float_policy, to_rational
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve, BSplineSurface
from .spec import SceneError

__all__ = ["parse_height", "build_surface", "build_curve", "to_rational"]

_MAX_POWER = 12


def parse_height(text: str, where: str):
    """Compile a polynomial height expression ``z(x, y)`` into an exact function."""
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as exc:
        raise SceneError(f"{where}: cannot parse {text!r} ({exc.msg})") from None

    def compile_node(node):
        if isinstance(node, ast.Expression):
            return compile_node(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, int) and not isinstance(node.value, bool):
            value = to_rational(node.value)
            return lambda x, y: value
        if isinstance(node, ast.Name) and node.id in ("x", "y"):
            return (lambda x, y: x) if node.id == "x" else (lambda x, y: y)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            inner = compile_node(node.operand)
            return (lambda x, y: -inner(x, y)) if isinstance(node.op, ast.USub) else inner
        if isinstance(node, ast.BinOp):
            left = compile_node(node.left)
            if isinstance(node.op, ast.Pow):
                if not (isinstance(node.right, ast.Constant) and isinstance(node.right.value, int)):
                    raise SceneError(f"{where}: exponents must be integer literals")
                k = node.right.value
                if not 0 <= k <= _MAX_POWER:
                    raise SceneError(f"{where}: exponent {k} outside 0..{_MAX_POWER}")
                return lambda x, y: left(x, y) ** k
            right = compile_node(node.right)
            ops = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b, ast.Mult: lambda a, b: a * b, ast.Div: _div}
            for op_type, op in ops.items():
                if isinstance(node.op, op_type):
                    return lambda x, y, op=op: op(left(x, y), right(x, y))
        raise SceneError(f"{where}: only numbers, x, y, + - * / and integer powers are allowed ({ast.dump(node)[:60]})")

    return compile_node(tree)


def _div(a, b):
    if b == 0:
        raise SceneError("height expression divides by zero")
    return a / b


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
