"""exactcagd: exact computer algebra for computer-aided geometric design.

Every construction is carried in exact rational (or polynomial-ring) arithmetic;
float evaluators with certified error bounds sit on top in :mod:`exactcagd.numeric`.

>>> from exactcagd import BezierCurve
>>> BezierCurve([[0, 0], [1, 1]]).evaluate("1/3")
(mpq(1,3), mpq(1,3))
"""

__version__ = "0.1.0"

from . import errors  # noqa: E402
from .exact.scalars import float_policy, set_float_policy, to_rational  # noqa: E402
from .geometry.bezier_curve import BezierCurve  # noqa: E402
from .geometry.bezier_surface import BezierSurface  # noqa: E402
from .geometry.bspline import BSplineCurve, BSplineSurface  # noqa: E402
from .composition import compose  # noqa: E402

__all__ = [
    "__version__",
    "errors",
    "to_rational",
    "float_policy",
    "set_float_policy",
    "BezierCurve",
    "BezierSurface",
    "BSplineCurve",
    "BSplineSurface",
    "compose",
]
