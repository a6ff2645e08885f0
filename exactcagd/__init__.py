"""exactcagd: exact computer algebra for computer-aided geometric design.

Every construction is carried in exact rational (or polynomial-ring) arithmetic;
float evaluators with certified error bounds sit on top in :mod:`exactcagd.numeric`.

>>> from exactcagd import BezierCurve
>>> BezierCurve([[0, 0], [1, 1]]).evaluate("1/3")
(mpq(1,3), mpq(1,3))

The public names below are imported on first use (PEP 562), so ``import exactcagd``
and ``exactcagd --version`` do not load sympy, numpy and python-flint.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from . import _sympy_bridge
from ._version import __version__

_sympy_bridge.install()  # mpq * Symbol stays exact, whichever of sympy and exactcagd comes first

if TYPE_CHECKING:  # what type checkers and IDEs see; at run time see __getattr__
    from . import errors, limits
    from .composition import compose
    from .exact.scalars import float_policy, set_float_policy, to_rational
    from .geometry.bezier_curve import BezierCurve
    from .geometry.bezier_surface import BezierSurface
    from .geometry.bspline import BSplineCurve, BSplineSurface

#: public name -> module that defines it (relative to this package)
_LAZY = {
    "errors": ".errors",
    "limits": ".limits",
    "to_rational": ".exact.scalars",
    "float_policy": ".exact.scalars",
    "set_float_policy": ".exact.scalars",
    "BezierCurve": ".geometry.bezier_curve",
    "BezierSurface": ".geometry.bezier_surface",
    "BSplineCurve": ".geometry.bspline",
    "BSplineSurface": ".geometry.bspline",
    "compose": ".composition",
}

__all__ = ["__version__", *_LAZY]


def __getattr__(name: str) -> Any:
    try:
        module_name = _LAZY[name]
    except KeyError:
        raise AttributeError(f"module 'exactcagd' has no attribute {name!r}") from None
    module = importlib.import_module(module_name, __name__)
    value = module if name in ("errors", "limits") else getattr(module, name)
    globals()[name] = value  # later lookups skip __getattr__
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
