"""The exact intersection route under its historical name.

Its home is :mod:`exactcagd.numeric.intersection.exact` (implicit equations, flint
resultants, exact isolation, pairing without a bivariate solve; Sederberg's notes
003, 7.3 and chapter 17); this module only re-exports it.

>>> from exactcagd import BezierCurve
>>> p = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> q = BezierCurve([[0, "1/2"], [2, "1/2"]])
>>> [x.multiplicity for x in intersect_exact(p, q)]
[1, 1]
"""

from .intersection.exact import intersect_exact, share_component

__all__ = ["intersect_exact", "share_component"]
