"""How the geometry classes show themselves: a short ``repr`` with the first control points,
LaTeX for notebooks (``_repr_latex_``, via ``to_sympy``), and ``.plot`` (drawing lives in the
application layer, :mod:`exactcagd.plotting`, imported only when a picture is asked for).

>>> from exactcagd import BezierCurve
>>> BezierCurve([[0, 0], ["1/2", 2], [2, 0], [3, 1], [4, 4]])
<BezierCurve degree=4 dimension=2 points=[(0, 0), (1/2, 2), (2, 0), ... 2 more]>
"""

from __future__ import annotations

from ..exact.scalars import rational_str

#: control points shown by a repr
SHOWN = 3


def _point(point) -> str:
    return "(" + ", ".join(rational_str(x) if not isinstance(x, str) else x for x in point) + ")"


def points_preview(points, shown: int = SHOWN) -> str:
    """``[(x, y), ..., k more]``: the first ``shown`` points, exact."""
    points = list(points)
    text = ", ".join(_point(p) for p in points[:shown])
    more = len(points) - shown
    return f"[{text}{', ... ' + str(more) + ' more' if more > 0 else ''}]"


def latex(obj, name: str) -> str:
    r"""``$name = <sympy LaTeX of obj.to_sympy()>$`` (what Jupyter shows for the object)."""
    import sympy

    return f"${name} = {sympy.latex(obj.to_sympy())}$"


def plot(obj, ax=None, **style):
    """Draw ``obj`` with :func:`exactcagd.plotting.plot` (needs matplotlib) and return the axes."""
    from .. import plotting  # the application layer, only when a picture is wanted

    return plotting.plot(obj, ax=ax, **style)
