"""Gröbner bases, ideal membership and elimination (notes 17.11).

:func:`groebner` returns the reduced Gröbner basis (monic over Q, sorted by
decreasing leading monomial) for the orders ``"lex"``, ``"grevlex"`` and
``"grlex"`` (the notes' *deglex*).

Engine (measured, ``benchmarks/bench_algebra.py`` and the table below): python-flint's
``fmpz_mpoly_vec.buchberger_naive`` (+ ``autoreduction``) is one to three orders
of magnitude faster than sympy's ``buchberger`` and ``f5b`` on small ideals
(cyclic-4, katsura-3, curve implicitization) but its lex computations can blow
up (katsura-4 lex: no result after 100 s, sympy f5b 3 s).  The ``"auto"`` engine
therefore runs flint with size limits.  For lex it first computes the (cheap) grevlex
basis, which decides the dimension: a zero-dimensional ideal gets flint's lex run and,
when a limit is hit, FGLM from the grevlex basis (sympy ``matrix_fglm``: katsura-4 in
0.3-0.8 s); a positive-dimensional one (an elimination, e.g. implicitization) gets
flint's lex run under tight limits only, since an aborted large run costs more than
sympy's ``f5b``, which is the fallback.

>>> import sympy
>>> x, y, z = sympy.symbols("x y z")
>>> [g.as_expr() for g in groebner([x + y + z - 6, x - y - z, x - 2*y + z - 3], [x, y, z])]
[x - 3, y - 1, z - 2]
"""

from __future__ import annotations

import flint
import sympy

from ..errors import InputError
from ._poly import polynomial_input, symbol_input, sympy_to_mpoly, zctx

__all__ = [
    "groebner",
    "groebner_basis",
    "normal_form",
    "ideal_contains",
    "ideals_equal",
    "eliminate",
    "is_zero_dimensional",
    "quotient_dimension",
    "ORDERS",
    "FLINT_LIMITS",
]

ORDERS = {"lex": "lex", "grevlex": "degrevlex", "grlex": "deglex"}
FLINT_LIMITS = (400, 20000, 4096)  # (ideal length, polynomial length, coefficient bits)
FLINT_LIMITS_POSITIVE_DIM = (60, 2000, 1024)  # lex on positive-dimensional ideals: give up early


def _check(gens, order):
    if order not in ORDERS:
        raise InputError(f"unknown monomial order {order!r}; choose one of {sorted(ORDERS)}")
    if not isinstance(gens, (list, tuple)):
        raise InputError(f"gens: expected a list of sympy Symbols, got {type(gens).__name__}")
    gens = [symbol_input(g, f"gens[{i}]") for i, g in enumerate(gens)]
    if not gens:
        raise InputError("gens: at least one generator (a sympy Symbol) is needed")
    if len(set(gens)) != len(gens) or not all(g.is_Symbol for g in gens):
        raise InputError("gens must be distinct symbols")
    return gens


def _to_flint(polys, gens, order):
    ctx = zctx([str(g) for g in gens], ORDERS[order])
    out = []
    for p in polys:
        q, _ = sympy_to_mpoly(p, gens, ctx)
        if q != 0:
            out.append(q)
    return ctx, out


def _monic_sympy(p, gens, order) -> sympy.Poly:
    data = {tuple(int(e) for e in m): sympy.Integer(int(c)) for m, c in p.to_dict().items()}
    P = sympy.Poly.from_dict(data, *gens, domain="QQ")
    return P.monic() if not P.is_zero else P


def _sort(polys, order):
    key = sympy.polys.orderings.monomial_key(order)
    return sorted(polys, key=lambda P: key(_lm(P, order)), reverse=True)


def _lm(P, order):
    key = sympy.polys.orderings.monomial_key(order)
    return max(P.monoms(), key=key)


def _flint_gb(fl, ctx, limits=FLINT_LIMITS):
    vec = flint.fmpz_mpoly_vec(fl, ctx)
    res, ok = vec.buchberger_naive(limits=limits)
    if not ok:
        return None
    return list(res.autoreduction())


def is_zero_dimensional(leading_monomials, nvars: int) -> bool:
    """Finitely many solutions iff every variable has a pure power among the leading monomials."""
    pure = set()
    for m in leading_monomials:
        nz = [i for i, e in enumerate(m) if e]
        if len(nz) == 1:
            pure.add(nz[0])
    return len(pure) == nvars


def groebner_basis(polys, gens, order: str = "lex", engine: str = "auto") -> list[sympy.Poly]:
    """Reduced Gröbner basis with a chosen engine.

    engine : ``"auto"`` (see module docstring), ``"flint"`` (python-flint only, no
        limits), ``"buchberger"`` or ``"f5b"`` (sympy).
    """
    gens = _check(gens, order)
    if not isinstance(polys, (list, tuple)):
        raise InputError(f"polys: expected a list of polynomials, got {type(polys).__name__}")
    polys = [polynomial_input(p, f"polys[{i}]") for i, p in enumerate(polys)]
    exprs = [p.as_expr() if isinstance(p, sympy.Poly) else sympy.sympify(p) for p in polys]
    exprs = [e for e in exprs if sympy.expand(e) != 0]
    for i, e in enumerate(exprs):
        domain = sympy.Poly(e, *gens).domain
        if not (domain.is_ZZ or domain.is_QQ):
            raise InputError(f"polys[{i}]: coefficients must be rational in {gens}, got domain {domain}")
    if not exprs:
        return []
    if engine in ("buchberger", "f5b"):
        G = sympy.groebner(exprs, *gens, order=order, method=engine)
        return _sort([sympy.Poly(g, *gens, domain="QQ").monic() for g in G.exprs], order)
    ctx, fl = _to_flint(exprs, gens, order)
    if engine == "flint":
        res = list(flint.fmpz_mpoly_vec(fl, ctx).buchberger_naive().autoreduction())
        return _sort([_monic_sympy(p, gens, order) for p in res], order)
    if engine != "auto":
        raise InputError(f"unknown Gröbner engine {engine!r}")
    if order != "lex":
        res = _flint_gb(fl, ctx)
        if res is not None:
            return _sort([_monic_sympy(p, gens, order) for p in res], order)
    else:
        # a grevlex basis is cheap and tells the dimension: zero-dimensional ideals get
        # flint's lex Buchberger, then FGLM; positive-dimensional ones (eliminations) get
        # flint only under tight limits -- an aborted large lex run costs more than f5b
        # (benchmarks/results/full/algebra.md: implicitize n = 4, 48 ms -> see the rerun)
        gctx, gfl = _to_flint(exprs, gens, "grevlex")
        gres = _flint_gb(gfl, gctx)
        zero_dim = gres is not None and is_zero_dimensional([tuple(int(e) for e in p.monoms()[0]) for p in gres], len(gens))
        res = _flint_gb(fl, ctx, FLINT_LIMITS if zero_dim else FLINT_LIMITS_POSITIVE_DIM)
        if res is not None:
            return _sort([_monic_sympy(p, gens, order) for p in res], order)
        if zero_dim:
            return _fglm(gres, gens)
    G = sympy.groebner(exprs, *gens, order=order, method="f5b")
    return _sort([sympy.Poly(g, *gens, domain="QQ").monic() for g in G.exprs], order)


def _fglm(grevlex_basis, gens) -> list[sympy.Poly]:
    from sympy import QQ
    from sympy.polys.fglmtools import matrix_fglm
    from sympy.polys.orderings import grevlex, lex
    from sympy.polys.rings import ring

    R, *_ = ring([str(g) for g in gens], QQ, grevlex)
    F = [R.from_dict({tuple(int(e) for e in m): QQ(int(c)) for m, c in p.to_dict().items()}).monic() for p in grevlex_basis]
    L = matrix_fglm(F, R, lex)
    out = [sympy.Poly(R.to_sympy(p) if hasattr(R, "to_sympy") else p.as_expr(), *gens, domain="QQ").monic() for p in L]
    return _sort(out, "lex")


def groebner(polys, gens, order: str = "lex") -> list[sympy.Poly]:
    """Reduced Gröbner basis of the ideal generated by ``polys`` (notes 17.11.5).

    Parameters
    ----------
    polys : sympy expressions / Poly with rational coefficients
    gens : the variables, in decreasing order (``x > y > z`` for ``[x, y, z]``)
    order : ``"lex"`` (default), ``"grevlex"`` or ``"grlex"`` (deglex)

    Returns
    -------
    list of monic sympy ``Poly`` over QQ, decreasing leading monomials.  The ideal
    ``<1>`` gives ``[1]``.
    """
    return groebner_basis(polys, gens, order, "auto")


def normal_form(f, basis, gens, order: str = "lex"):
    """Remainder of ``f`` on division by a Gröbner ``basis`` (sympy ``reduced``)."""
    gens = _check(gens, order)
    if not isinstance(basis, (list, tuple)):
        raise InputError(f"basis: expected a list of polynomials, got {type(basis).__name__}")
    basis = [polynomial_input(b, f"basis[{i}]") for i, b in enumerate(basis)]
    f = polynomial_input(f, "f")
    exprs = [b.as_expr() if isinstance(b, sympy.Poly) else b for b in basis]
    for i, e in enumerate(exprs):
        domain = sympy.Poly(e, *gens).domain
        if not (domain.is_ZZ or domain.is_QQ):
            raise InputError(f"basis[{i}]: coefficients must be rational in {gens}, got domain {domain}")
    exprs = [e for e in exprs if sympy.expand(e) != 0]  # dividing by 0 is no reduction
    fe = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    if not exprs:
        return sympy.expand(fe)
    _, r = sympy.reduced(fe, exprs, *gens, order=order)
    return sympy.expand(r)


def ideal_contains(f, polys, gens, order: str = "grevlex") -> bool:
    """Ideal membership: ``f`` in ``<polys>`` iff its normal form is 0 (17.11.4)."""
    G = groebner(polys, gens, order)
    return normal_form(f, G, gens, order) == 0


def ideals_equal(A, B, gens) -> bool:
    """``<A> == <B>`` (each generator of one lies in the other, 17.11.1 theorem)."""
    GA = groebner(A, gens, "grevlex")
    GB = groebner(B, gens, "grevlex")
    return [g.as_expr() for g in GA] == [g.as_expr() for g in GB]


def eliminate(polys, eliminated, kept, order: str = "lex") -> list[sympy.Poly]:
    """Generators of the elimination ideal ``<polys> ∩ Q[kept]`` (lex, eliminated > kept)."""
    if not isinstance(eliminated, (list, tuple)) or not isinstance(kept, (list, tuple)):
        raise InputError("eliminated and kept must be lists of sympy Symbols")
    eliminated = [symbol_input(v, "eliminated") for v in eliminated]
    kept = [symbol_input(v, "kept") for v in kept]
    G = groebner(polys, eliminated + kept, order)
    out = []
    for g in G:
        if not (g.as_expr().free_symbols & set(eliminated)):
            out.append(sympy.Poly(g.as_expr(), *kept, domain="QQ"))
    return out


def quotient_dimension(polys, gens) -> int:
    """``dim_Q Q[gens] / <polys>`` (number of solutions with multiplicity) for a
    zero-dimensional ideal, by counting standard monomials of a grevlex basis."""
    G = groebner(polys, gens, "grevlex")
    if not G:
        raise InputError("the zero ideal is not zero-dimensional")
    lms = [_lm(g, "grevlex") for g in G]
    if any(all(e == 0 for e in m) for m in lms):
        return 0
    if not is_zero_dimensional(lms, len(gens)):
        raise InputError("the ideal is not zero-dimensional (infinitely many solutions)")
    bounds = [0] * len(gens)
    for m in lms:
        nz = [i for i, e in enumerate(m) if e]
        if len(nz) == 1:
            b = m[nz[0]]
            bounds[nz[0]] = b if bounds[nz[0]] == 0 else min(bounds[nz[0]], b)
    import itertools

    count = 0
    for mono in itertools.product(*[range(b) for b in bounds]):
        if not any(all(mono[i] >= m[i] for i in range(len(gens))) for m in lms):
            count += 1
    return count
