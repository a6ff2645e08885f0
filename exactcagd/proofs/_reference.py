"""Independent references shared by proof modules (sympy from first principles, never the package under test)."""

from __future__ import annotations

import sympy


def composition_degree(surface, curve) -> int:
    """Degree of the reduced rational curve F(K(t)) by sympy substitution (max of numerator/denominator degrees).

    >>> from exactcagd import BezierCurve, BezierSurface
    >>> composition_degree(BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]), BezierCurve([[0, 0], [1, 1]]))
    2
    """
    u, v, t = sympy.symbols("u_ v_ t_")
    F = surface.to_sympy(u, v)
    K = curve.to_sympy(t)
    degs = []
    for comp in F:
        num, den = sympy.fraction(sympy.cancel(sympy.together(comp.subs({u: K[0], v: K[1]}, simultaneous=True))))
        degs.append(max(sympy.degree(num, t), sympy.degree(den, t)))
    # a common denominator: the curve's degree is the largest over components (one weight function)
    return max(degs)


def agrees_with_substitution(surface, curve, result, params=("0", "1/3", "5/7", "1")) -> bool:
    """``result(t) == F(K(t))`` at the given rational parameters, F and K evaluated by sympy from their Bernstein forms."""
    u, v, t = sympy.symbols("u_ v_ t_")
    F = surface.to_sympy(u, v)
    K = curve.to_sympy(t)
    for p in params:
        tv = sympy.Rational(p)
        kv = [k.subs(t, tv) for k in K]
        ref = [sympy.nsimplify(c.subs({u: kv[0], v: kv[1]}, simultaneous=True)) for c in F]
        got = [sympy.Rational(str(x)) for x in result.evaluate(p)]
        if any(sympy.simplify(a - b) != 0 for a, b in zip(ref, got)):
            return False
    return True
