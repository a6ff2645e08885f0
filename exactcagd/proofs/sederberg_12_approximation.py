"""Sederberg's notes, 12.3: approximation by interval polynomials, eqs. (12.35)-(12.57) and 12.3.3.

Every check is sympy from first principles (Lagrange and Hermite interpolation, remainders,
Bernstein derivatives); no exactcagd function is under test here, these rows check the text.
"""

from __future__ import annotations

import random

import sympy as sp

from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified, verified_range

DOC = "sederberg"
t = sp.Symbol("t")


def _lagrange_basis(nodes):
    """(12.37): L_k(t) = prod_{j != k} (t - t_j)/(t_k - t_j)."""
    return [sp.prod([(t - tj) / (tk - tj) for j, tj in enumerate(nodes) if j != k]) for k, tk in enumerate(nodes)]


@claim(doc=DOC, section="12.3", ref="(12.35)-(12.38)", statement="F_n = sum f_k L_k with L_k = prod_{j != k} (t - t_j)/(t_k - t_j) is the unique degree-n interpolant; L_k(t_j) = delta_jk")
def lagrange_interpolant():
    for n in (1, 2, 3):
        # symbolic nodes for n <= 2, rational nodes for n = 3 (symbolic cancellation is slow there)
        nodes = sp.symbols(f"t0:{n + 1}") if n < 3 else (sp.Integer(0), sp.Rational(1, 3), sp.Rational(3, 4), sp.Integer(2))
        fs = sp.symbols(f"f0:{n + 1}")
        Ls = _lagrange_basis(nodes)
        for k in range(n + 1):
            for j in range(n + 1):
                assert sp.cancel(Ls[k].subs(t, nodes[j]) - (1 if j == k else 0)) == 0
        F = sum(f * Lk for f, Lk in zip(fs, Ls))
        assert sp.Poly(sp.together(F).as_numer_denom()[0], t).degree() <= n
        # reproduces every polynomial of degree n (uniqueness): interpolating t^n gives t^n
        assert sp.cancel(sp.together(sum(nd**n * Lk for nd, Lk in zip(nodes, Ls)) - t**n)) == 0
    return verified("symbolic nodes and values, n = 1, 2, 3 (sympy)",
                    compared="printed (12.36)-(12.38) vs sympy evaluation of the product (12.37) at the nodes and reproduction of t^n",
                    reference="sympy")


@claim(doc=DOC, section="12.3.1", ref="(12.39)-(12.43)", statement="E_n = f - F_n = f^(n+1)(xi)/(n+1)! prod (t - t_k); f(t) in F_n(t) + [f^(n+1)_min, f^(n+1)_max]/(n+1)! prod (t - t_k), an interval polynomial of degree n + 1 in Bernstein form on [a, b]")
def cauchy_remainder():
    rng = random.Random(1239)
    count = 0
    for n in (1, 2, 3):
        nodes = sorted({sp.Rational(rng.randint(0, 20), 20) for _ in range(6)})[: n + 1]
        if len(nodes) < n + 1:
            continue
        # f of degree n + 1: f^(n+1) is constant, so (12.40) is an identity
        f = sum(sp.Rational(rng.randint(-9, 9), 4) * t**k for k in range(n + 2)) + t ** (n + 1)
        F = sum(f.subs(t, nd) * Lk for nd, Lk in zip(nodes, _lagrange_basis(nodes)))
        w = sp.prod([t - nd for nd in nodes])
        assert sp.expand(f - F - sp.diff(f, t, n + 1) / sp.factorial(n + 1) * w) == 0
        # f of degree n + 2: f^(n+1) is linear, bounded by its end values on [0, 1]: (12.42) contains f
        g = f * (t + 2)
        G = sum(g.subs(t, nd) * Lk for nd, Lk in zip(nodes, _lagrange_basis(nodes)))
        d = sp.diff(g, t, n + 1)
        lo, hi = sorted([d.subs(t, 0), d.subs(t, 1)])
        for k in range(21):
            x = sp.Rational(k, 20)
            ends = sorted([(G + lo / sp.factorial(n + 1) * w).subs(t, x), (G + hi / sp.factorial(n + 1) * w).subs(t, x)])
            assert ends[0] <= g.subs(t, x) <= ends[1]
            count += 1
    return verified_range(f"n = 1, 2, 3; {count} exact points of [0, 1]",
                          "(12.40) is an identity when f^(n+1) is constant; with f^(n+1) linear, f lies in the interval polynomial (12.42) at every sample",
                          compared="printed (12.40), (12.42) vs exact Lagrange interpolation in sympy", reference="sympy")


@claim(doc=DOC, section="12.3.2", ref="(12.44)", covers=["(12.45)"], statement="a sequence m+1 consecutive nodes t_k, t_{k+1}, ..., t_{k+m+1} are allowed to merge; F_n matches f(t_k) and the first m derivatives")
def hermite_merging_nodes():
    m = sp.Symbol("m", integer=True, nonnegative=True)

    def count_matches(last_offset):
        # the merged nodes t_k .. t_{k+last} number last + 1; they must give the m + 1 conditions f, f', ..., f^(m)
        diff = sp.simplify((last_offset + 1) - (m + 1))
        return None if diff == 0 else f"t_k .. t_(k+{last_offset}) are {last_offset + 1} nodes for m + 1 conditions"

    return erratum(
        "t_k, t_{k+1}, ..., t_{k+m+1} (m + 1 consecutive nodes)",
        "t_k, t_{k+1}, ..., t_{k+m}",
        "an m-fold osculation matches f(t_k), f'(t_k), ..., f^(m)(t_k): m + 1 conditions, the limit of m + 1 merging nodes; "
        "the printed last index k + m + 1 lists m + 2 nodes",
        printed_form=m + 1, corrected_form=m, check=L.predicate(count_matches), reference="text",
    )


@claim(doc=DOC, section="12.3.2", ref="(12.46), (12.47)", covers=["(12.48)"], statement="F_n^(i)(t_k) = f^(i)(t_k) for i = 0..m_r and k = 0..r (m_0 + ... + m_r + r = n); E_n = f^(n+1)(xi)/(n+1)! prod (t - t_k)^(m_k + 1)")
def hermite_conditions():
    ms = (1, 0, 2)  # r = 2, n = m_0 + m_1 + m_2 + r = 5
    nodes = (sp.Integer(0), sp.Rational(1, 2), sp.Integer(1))
    n = sum(ms) + len(ms) - 1
    rng = random.Random(1246)
    f = sum(sp.Rational(rng.randint(-9, 9), 3) * t**k for k in range(n + 2))  # degree n + 1

    def hermite_remainder_holds(upper):
        cs = sp.symbols(f"c0:{n + 1}")
        F = sum(c * t**k for k, c in enumerate(cs))
        eqs = [sp.diff(F - f, t, i).subs(t, nodes[k]) for k in range(len(ms)) for i in range(upper(k) + 1)]
        if len(eqs) != n + 1:
            return f"{len(eqs)} conditions for the {n + 1} coefficients of F_{n} (m = {ms})"
        sol = sp.solve(eqs, cs, dict=True)
        if len(sol) != 1:
            return "the conditions do not determine F_n"
        E = sp.expand(f - F.subs(sol[0]))
        ref = sp.expand(sp.diff(f, t, n + 1) / sp.factorial(n + 1) * sp.prod([(t - nd) ** (mk + 1) for nd, mk in zip(nodes, ms)]))
        return None if sp.expand(E - ref) == 0 else f"E_n - (12.47) = {sp.factor(E - ref)}"

    return erratum(
        "for i = 0, ..., m_r and k = 0, ..., r",
        "for i = 0, ..., m_k and k = 0, ..., r (m_k derivatives at node t_k)",
        "nodes 0, 1/2, 1 with m = (1, 0, 2), n = 5, f of degree 6 (sympy): with i <= m_k the n + 1 conditions determine F_n and "
        "the error is exactly (12.47); with i <= m_r there are 9 conditions for 6 coefficients",
        printed_form=lambda k: ms[-1], corrected_form=lambda k: ms[k], check=L.predicate(hermite_remainder_holds),
    )


@claim(doc=DOC, section="12.3.2", ref="(12.49)-(12.53)", statement="symmetric Hermite basis of odd degree n: d^j H_k/dt^j (0) = d^j H_(n-k)/dt^j (1) = delta_jk; F_n = sum f^(k)(0) H_k + f^(k)(1) H_(n-k); E_n = f^(n+1)(xi)/(n+1)! t^((n+1)/2) (t-1)^((n+1)/2); cubic basis 2t^3-3t^2+1, t^3-2t^2+t, t^3-t^2, -2t^3+3t^2")
def hermite_basis():
    printed = [2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t, t**3 - t**2, -2 * t**3 + 3 * t**2]
    for n in (1, 3, 5):
        h = (n - 1) // 2
        cs = sp.symbols(f"c0:{n + 1}")
        basis = []
        for k in range(n + 1):  # solve (12.50) for H_k: the conditions at 0 (k <= h) or at 1 (k >= n - h)
            H = sum(c * t**i for i, c in enumerate(cs))
            eqs = [sp.diff(H, t, j).subs(t, 0) - (1 if j == k else 0) for j in range(h + 1)]
            eqs += [sp.diff(H, t, j).subs(t, 1) - (1 if j == n - k else 0) for j in range(h + 1)]
            basis.append(sp.expand(H.subs(sp.solve(eqs, cs, dict=True)[0])))
        if n == 3:
            assert [sp.expand(b - p) for b, p in zip(basis, printed)] == [0, 0, 0, 0]
        f = sum(sp.Rational(i + 2, i + 1) * (-t) ** i for i in range(n + 2))  # degree n + 1
        F = sum(sp.diff(f, t, k).subs(t, 0) * basis[k] + sp.diff(f, t, k).subs(t, 1) * basis[n - k] for k in range(h + 1))
        E = sp.expand(f - F)
        assert sp.expand(E - sp.diff(f, t, n + 1) / sp.factorial(n + 1) * t ** ((n + 1) // 2) * (t - 1) ** ((n + 1) // 2)) == 0
    return verified("the basis solved from (12.50) for n = 1, 3, 5 (sympy); for n = 3 it is (12.53); (12.51) interpolates and its error "
                    "for a degree-(n+1) f is exactly (12.52)",
                    compared="printed (12.53) basis and (12.51), (12.52) vs the sympy solution of the conditions (12.50)", reference="sympy")


@claim(doc=DOC, section="12.3.2", ref="(12.54)-(12.57)", statement="F_1 = f0 (1-t) + f1 t; f = F_1 + f''(xi)/2 t(t-1); f(t) in F_1(t) - [f'']/2 t(1-t) on [0, 1]")
def linear_interval_remainder():
    rng = random.Random(1254)
    count = 0
    for _ in range(5):
        f = sum(sp.Rational(rng.randint(-9, 9), rng.randint(1, 4)) * t**k for k in range(4))  # cubic: f'' linear
        F1 = f.subs(t, 0) * (1 - t) + f.subs(t, 1) * t
        fpp = sp.diff(f, t, 2)
        lo, hi = sorted([fpp.subs(t, 0), fpp.subs(t, 1)])
        for k in range(11):
            x = sp.Rational(k, 10)
            a, b = sorted([(F1 - lo / 2 * t * (1 - t)).subs(t, x), (F1 - hi / 2 * t * (1 - t)).subs(t, x)])
            assert a <= f.subs(t, x) <= b
            count += 1
    q = 3 * t**2 - t + 2  # f'' constant: (12.55) is an identity
    assert sp.expand(q - (q.subs(t, 0) * (1 - t) + q.subs(t, 1) * t) - sp.diff(q, t, 2) / 2 * t * (t - 1)) == 0
    return verified_range(f"5 random cubics, {count} exact points", "(12.55) is an identity for quadratics; f lies in (12.57) with [f''] the range of the linear f''",
                          compared="printed (12.54)-(12.57) vs exact evaluation (sympy)", reference="sympy")


@claim(doc=DOC, section="12.3.3", ref="(12.67)-(12.69)", statement="f^(r)(t) = n!/(n-r)! sum Delta^r p_k B_k^(n-r)(t); n!/(n-r)! min Delta^r p_k <= f^(r) <= n!/(n-r)! max Delta^r p_k on [0, 1]")
def bernstein_derivative_bounds():
    rng = random.Random(1267)
    for n in (2, 3, 5):
        p = [sp.Rational(rng.randint(-20, 20), rng.randint(1, 5)) for _ in range(n + 1)]
        f = sum(pk * sp.binomial(n, k) * t**k * (1 - t) ** (n - k) for k, pk in enumerate(p))
        for r in range(1, n + 1):
            d = list(p)
            for _ in range(r):
                d = [d[i + 1] - d[i] for i in range(len(d) - 1)]
            c = sp.factorial(n) / sp.factorial(n - r)
            formula = c * sum(dk * sp.binomial(n - r, k) * t**k * (1 - t) ** (n - r - k) for k, dk in enumerate(d))
            assert sp.expand(sp.diff(f, t, r) - formula) == 0
            for k in range(11):
                v = sp.diff(f, t, r).subs(t, sp.Rational(k, 10))
                assert c * min(d) <= v <= c * max(d)
    return verified("n = 2, 3, 5, every r (sympy differentiation of the Bernstein form; bounds at 11 exact points)",
                    compared="printed (12.68) vs sympy's r-th derivative; (12.69) at exact sample points", reference="sympy")


@claim(doc=DOC, section="12.4", ref="(12.70)-(12.75)",
       statement="vector Lagrange interpolant P_n = sum P_k L_k; componentwise remainders with xi_1 != xi_2; P(t) in P_n(t) + [P^(n+1)]/(n+1)! prod (t - t_k) with the box (12.73); cubic Hermite arcs P(0) H0 + P'(0) H1 + P'(1) H2 + P(1) H3")
def vector_interpolation():
    nodes = (sp.Integer(0), sp.Rational(1, 2), sp.Integer(1))
    n = len(nodes) - 1
    Px, Py = t**4 - 2 * t**3 + t, t**5 + 3 * t**3  # P''' linear in x, quadratic (monotone on [0, 1]) in y
    Ls = _lagrange_basis(nodes)
    Xn = sum(Px.subs(t, nd) * Lk for nd, Lk in zip(nodes, Ls))
    Yn = sum(Py.subs(t, nd) * Lk for nd, Lk in zip(nodes, Ls))
    w = sp.prod([t - nd for nd in nodes])
    dx, dy = sp.diff(Px, t, n + 1), sp.diff(Py, t, n + 1)  # linear: extremes at t = 0, 1
    bx = sorted([dx.subs(t, 0), dx.subs(t, 1)])
    by = sorted([dy.subs(t, 0), dy.subs(t, 1)])
    count = 0
    for k in range(1, 20):
        s = sp.Rational(k, 20)
        for comp, interp, (lo, hi) in ((Px, Xn, bx), (Py, Yn, by)):
            ends = sorted([(interp + lo / sp.factorial(n + 1) * w).subs(t, s), (interp + hi / sp.factorial(n + 1) * w).subs(t, s)])
            assert ends[0] <= comp.subs(t, s) <= ends[1]
            count += 1
        # (12.72): the x and y remainders need different xi in general (here at s = 1/4)
    xi = sp.Symbol("xi")
    s = sp.Rational(1, 4)
    sx = sp.solve(sp.Eq((Px - Xn).subs(t, s), dx.subs(t, xi) / 6 * w.subs(t, s)), xi)
    sy = sp.solve(sp.Eq((Py - Yn).subs(t, s), dy.subs(t, xi) / 6 * w.subs(t, s)), xi)
    sx = [r for r in sx if r.is_real and 0 < r < 1]
    sy = [r for r in sy if r.is_real and 0 < r < 1]
    assert sx and sy and set(sx).isdisjoint(sy)
    # (12.75): a cubic curve is reproduced by its cubic Hermite form with the basis (12.53)
    H = [2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t, t**3 - t**2, -2 * t**3 + 3 * t**2]
    C = sp.Matrix([t**3 - t + 2, 4 * t**2 - t**3])
    Cd = C.diff(t)
    herm = C.subs(t, 0) * H[0] + Cd.subs(t, 0) * H[1] + Cd.subs(t, 1) * H[2] + C.subs(t, 1) * H[3]
    assert (herm - C).applyfunc(sp.expand) == sp.zeros(2, 1)
    return verified(f"the curve (t^4 - 2t^3 + t, t^5 + 3t^3), nodes 0, 1/2, 1: the box remainder (12.74) contains the curve at {count} exact points; "
                    "the componentwise xi of (12.72) differ (xi_x != xi_y at t = 1/4); (12.75) reproduces a cubic exactly (sympy)",
                    compared="printed (12.70)-(12.75) vs exact Lagrange/Hermite interpolation in sympy", reference="sympy")
