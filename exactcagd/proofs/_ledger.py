"""The ledger mechanism: register a claim of a source document and the check that decides it.

A claim is a function decorated with :func:`claim`.  It runs an independent derivation
(sympy from first principles, exact arithmetic, an independent algorithm) and returns
one of the outcomes below; a failed check raises ``AssertionError`` (the runner then
reports the claim as ``FAILED``, never hides it).

Outcomes
--------
``verified``        the printed claim holds; ``compared`` says what was compared with what;
``verified-range``  it holds over the stated finite range (plus random exact instances);
``erratum``         the printed form is wrong; the corrected form is right;
``convention``      printed and corrected agree up to a common factor, a sign of all
                    weights, a scaling or a stated normalisation (not an error);
``reconstructed``   the extracted text was damaged; the reconstruction is verified;
``not-checkable``   cannot be decided by computation, or the document makes no such claim (with why).

The differential check
----------------------
``erratum``, ``reconstructed`` and ``convention`` rows carry the printed form and the
corrected form *as data* (sympy expressions, numbers, matrices, callables) and a
``check``: a function of one form that returns ``None`` when the form agrees with an
independent derivation and a counterexample otherwise.  The runner (:func:`run_claim`)
evaluates both: the printed form must fail (its counterexample is stored and shown in the
ledger), the corrected form must pass; otherwise the row is ``FAILED``.  A ``convention``
row also gives ``normalise`` (the stated factor / normalisation): the normalised printed
form must pass.  Content lost in the extraction is given as ``printed_form=LOST``.

Example
-------
>>> import sympy
>>> from exactcagd.proofs._ledger import Claim, claim, erratum, run_claim, same_expr, verified
>>> x = sympy.Symbol("x")
>>> def _square():
...     return erratum("(x+1)^2 = x^2 + 1", "(x+1)^2 = x^2 + 2x + 1", "sympy expansion",
...                    printed_form=x**2 + 1, corrected_form=x**2 + 2*x + 1,
...                    check=same_expr(sympy.expand((x + 1) * (x + 1))))
>>> row = run_claim(Claim("sederberg", "2.3", "(x)", "a square", False, _square))
>>> row.status, row.outcome.counterexample
('erratum', 'at x = 1/3: form = 10/9, reference = 16/9')
"""

from __future__ import annotations

import dataclasses
import importlib
import itertools
import pkgutil
import re
import time
from typing import Any, Callable

STATUSES = ("verified", "verified-range", "erratum", "convention", "reconstructed", "not-checkable")
DIFFERENTIAL_STATUSES = ("erratum", "convention", "reconstructed")
#: what a verified row's reference is (never "the function under test")
REFERENCE_KINDS = ("sympy", "exact", "independent-algorithm", "enumeration", "mpmath", "text")
DOCS = {
    "lasser": "Lasser & Bonneau, Bezier Representation of Trim Curves (1993)",
    "yang": "Yang et al., G1 continuous approximate curves on NURBS surfaces (2012)",
    "sederberg": "Sederberg, Computer Aided Geometric Design course notes (2012)",
}


class _Lost:
    """The printed form is absent from the extracted text (lost figure, damaged formula)."""

    def __repr__(self):
        return "LOST"


LOST = _Lost()


@dataclasses.dataclass
class Outcome:
    status: str
    detail: str = ""
    printed: str | None = None
    corrected: str | None = None
    range: str | None = None
    compared: str | None = None
    reference: str | None = None
    printed_form: Any = None
    corrected_form: Any = None
    check: Callable[[Any], Any] | None = None
    normalise: Callable[[Any], Any] | None = None
    counterexample: str | None = None
    lost_reason: str | None = None

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"unknown ledger status {self.status!r}")
        if self.reference is not None and self.reference not in REFERENCE_KINDS:
            raise ValueError(f"unknown reference kind {self.reference!r}; one of {REFERENCE_KINDS}")

    @property
    def differential(self) -> bool:
        """True when the row carries both forms and a check (the runner evaluates them)."""
        return self.check is not None


def verified(detail: str = "", *, compared: str | None = None, reference: str | None = None) -> Outcome:
    """The printed claim holds; ``compared`` = "printed (x.y) vs <independent derivation>"."""
    return Outcome("verified", detail, compared=compared, reference=reference)


def verified_range(range: str, detail: str = "", *, compared: str | None = None, reference: str | None = None) -> Outcome:
    return Outcome("verified-range", detail, range=range, compared=compared, reference=reference)


def _differential(status, printed, corrected, detail, printed_form, corrected_form, check, reference, normalise=None, lost_reason=None):
    if check is not None and (printed_form is None or corrected_form is None):
        raise ValueError("a differential row needs printed_form and corrected_form (LOST for absent text)")
    if printed_form is LOST and not lost_reason:
        raise ValueError("printed_form=LOST needs lost_reason")
    return Outcome(status, detail, printed=printed, corrected=corrected, reference=reference,
                   printed_form=printed_form, corrected_form=corrected_form, check=check,
                   normalise=normalise, lost_reason=lost_reason)


def erratum(printed: str, corrected: str, detail: str, *, printed_form=None, corrected_form=None,
            check: Callable | None = None, reference: str | None = "sympy") -> Outcome:
    """The printed form is wrong: ``check(printed_form)`` must give a counterexample, ``check(corrected_form)`` None."""
    return _differential("erratum", printed, corrected, detail, printed_form, corrected_form, check, reference)


def reconstructed(printed: str, corrected: str, detail: str, *, printed_form=None, corrected_form=None,
                  check: Callable | None = None, reference: str | None = "sympy", lost_reason: str | None = None) -> Outcome:
    """The extraction damaged the text; the damaged form fails the check, the reconstruction passes."""
    return _differential("reconstructed", printed, corrected, detail, printed_form, corrected_form, check, reference,
                         lost_reason=lost_reason)


def convention(printed: str, corrected: str, detail: str, *, printed_form, corrected_form, check: Callable,
               normalise: Callable, reference: str | None = "sympy") -> Outcome:
    """Printed = corrected up to a stated factor/normalisation: ``check(normalise(printed_form))`` must pass."""
    if normalise is None:
        raise ValueError("a convention row states its normalisation")
    return _differential("convention", printed, corrected, detail, printed_form, corrected_form, check, reference,
                         normalise=normalise)


def not_checkable(why: str) -> Outcome:
    return Outcome("not-checkable", why)


# ------------------------------------------------------------------ check builders
def _sympy():
    import sympy

    return sympy


def _is_zero(expr) -> bool:
    sp = _sympy()
    expr = sp.sympify(expr)
    if getattr(expr, "is_Matrix", False):
        return all(_is_zero(e) for e in expr)
    return sp.simplify(sp.cancel(sp.expand(expr))) == 0


def _witness(diff, form, reference):
    """A rational point where ``diff`` is non-zero (a readable counterexample)."""
    sp = _sympy()
    syms = sorted(sp.sympify(diff).free_symbols, key=str)
    values = [sp.Rational(1, 3), 2, sp.Rational(2, 5), 3, 1, -1, 5]
    for point in itertools.islice(itertools.product(values, repeat=len(syms)), 400):
        sub = dict(zip(syms, point))
        try:
            d = sp.simplify(sp.sympify(diff).subs(sub))
        except Exception:  # noqa: BLE001 - a pole: try the next point
            continue
        if d.is_zero is False and d.is_finite:
            at = ", ".join(f"{k} = {v}" for k, v in sub.items())
            f = sp.simplify(sp.sympify(form).subs(sub))
            r = sp.simplify(sp.sympify(reference).subs(sub))
            return f"at {at}: form = {f}, reference = {r}" if at else f"form = {f}, reference = {r}"
    return f"form - reference = {sp.factor(diff)}"


def same_expr(reference) -> Callable[[Any], str | None]:
    """Check: the form equals the sympy expression/matrix ``reference`` identically."""
    sp = _sympy()

    def check(form):
        if getattr(reference, "is_Matrix", False) or getattr(form, "is_Matrix", False):
            A, B = sp.Matrix(form), sp.Matrix(reference)
            if A.shape != B.shape:
                return f"shape {A.shape} vs reference {B.shape}"
            for (i, j) in itertools.product(range(A.rows), range(A.cols)):
                if not _is_zero(A[i, j] - B[i, j]):
                    return f"entry ({i}, {j}): {A[i, j]} vs reference {B[i, j]}"
            return None
        diff = sp.sympify(form) - sp.sympify(reference)
        return None if _is_zero(diff) else _witness(diff, form, reference)

    return check


def same_value(reference) -> Callable[[Any], str | None]:
    """Check: the form equals ``reference`` (numbers, tuples, strings; exact ``==``)."""

    def check(form):
        return None if form == reference else f"{form!r} != reference {reference!r}"

    return check


def predicate(test: Callable[[Any], Any]) -> Callable[[Any], str | None]:
    """Check from a function returning None/True (agrees) or a counterexample (str) / False."""

    def check(form):
        out = test(form)
        if out is None or out is True:
            return None
        return "does not hold" if out is False else str(out)

    return check


# ------------------------------------------------------------------ registry
_TAG = re.compile(r"\((\d+(?:\.\d+)?)\)")
_RANGE = re.compile(r"\((\d+)\.(\d+)\)\s*[-–]\s*\((\d+)\.(\d+)\)")
_PLAIN_RANGE = re.compile(r"\((\d+)\)\s*[-–]\s*\((\d+)\)")


def tags_in(ref: str) -> list[str]:
    """Equation tags named in a ref label, ranges expanded.

    >>> tags_in("(18.28)-(18.31), (7)")
    ['(18.28)', '(18.29)', '(18.30)', '(18.31)', '(7)']
    """
    out = []
    for m in _PLAIN_RANGE.finditer(ref):
        a, b = int(m.group(1)), int(m.group(2))
        if a <= b:
            out += [f"({k})" for k in range(a, b + 1)]
    for m in _RANGE.finditer(ref):
        a, i, b, j = (int(g) for g in m.groups())
        if a == b and i <= j:
            out += [f"({a}.{k})" for k in range(i, j + 1)]
    for m in _TAG.finditer(ref):
        tag = f"({m.group(1)})"
        if tag not in out:
            out.append(tag)
    return out


@dataclasses.dataclass
class Claim:
    doc: str
    section: str
    ref: str
    statement: str
    slow: bool
    func: Callable[[], Outcome]
    trace: Callable[[], None] | None = None
    covers: tuple = ()

    @property
    def key(self) -> str:
        return f"{self.func.__module__}.{self.func.__name__}"

    @property
    def label(self) -> str:
        """The label ``verify`` prints (accepted by ``verify --trace``)."""
        return f"{self.doc} {self.section} {self.ref}"

    @property
    def covered(self) -> list[str]:
        """Items of the document this row covers: its section, the tags in ``ref``, and ``covers``."""
        items = [f"§{self.section}"] + tags_in(self.ref) + list(self.covers)
        return list(dict.fromkeys(items))


REGISTRY: list[Claim] = []


def claim(doc: str, section: str, ref: str, statement: str, slow: bool = False, trace: Callable | None = None,
          covers: tuple | list = ()):
    """Register the decorated function as the check of one printed claim.

    Parameters
    ----------
    doc : "lasser" | "yang" | "sederberg"
    section : section of the document (e.g. "III", "4.3", "17.4")
    ref : equation / theorem / example label as printed (e.g. "(7)", "Theorem 1")
    statement : the claim as printed (plain text, short)
    slow : heavy checks (run by ``exactcagd verify`` and ``pytest -m slow``)
    trace : optional function printing the derivation step by step (teaching mode)
    covers : further items this row covers: equation tags "(12.35)", sections "§12.3.3",
        worked examples "Example 7.7.7" (see :mod:`exactcagd.proofs.coverage`)
    """
    if doc not in DOCS:
        raise ValueError(f"unknown document {doc!r}")

    def decorate(func):
        REGISTRY.append(Claim(doc, section, ref, statement, slow, func, trace, tuple(covers)))
        return func

    return decorate


def discover() -> list[Claim]:
    """Import every proof module in the ``exactcagd.proofs`` package; return the registry."""
    import exactcagd.proofs as proofs

    for info in pkgutil.iter_modules(proofs.__path__):
        if not info.name.startswith("_") and info.name not in ("coverage", "ledger_html"):
            importlib.import_module(f"exactcagd.proofs.{info.name}")
    seen, out = set(), []
    for c in REGISTRY:
        if c.key not in seen:
            seen.add(c.key)
            out.append(c)
    return out


@dataclasses.dataclass
class Row:
    claim: Claim
    outcome: Outcome | None
    error: str | None
    seconds: float

    @property
    def status(self) -> str:
        return "FAILED" if self.outcome is None else self.outcome.status


def evaluate_differential(o: Outcome) -> None:
    """Run a row's check on both forms; raise AssertionError unless printed fails and corrected passes."""
    if o.printed_form is LOST:
        o.counterexample = f"printed form lost in the extraction: {o.lost_reason}"
    else:
        cx = o.check(o.printed_form)
        if cx is None:
            raise AssertionError(f"{o.status}: the printed form passes the reference check (not an {o.status})")
        o.counterexample = str(cx)
    bad = o.check(o.corrected_form)
    if bad is not None:
        raise AssertionError(f"{o.status}: the corrected form fails the reference check: {bad}")
    if o.status == "convention":
        bad = o.check(o.normalise(o.printed_form))
        if bad is not None:
            raise AssertionError(f"convention: the normalised printed form fails the reference check: {bad}")


def run_claim(c: Claim) -> Row:
    """Run one claim (and the differential check of its outcome); an exception becomes a ``FAILED`` row."""
    start = time.perf_counter()
    try:
        outcome = c.func()
        if not isinstance(outcome, Outcome):
            raise TypeError(f"proof returned {outcome!r}, not an Outcome")
        if outcome.differential:
            evaluate_differential(outcome)
        error = None
    except Exception as exc:  # noqa: BLE001 - the ledger reports every failure
        outcome, error = None, f"{type(exc).__name__}: {exc}"
    return Row(c, outcome, error, time.perf_counter() - start)


def form_text(form) -> str | None:
    """Plain text of a form (sympy ``str``; callables by name)."""
    if form is None:
        return None
    if form is LOST:
        return "LOST"
    if callable(form) and not hasattr(form, "free_symbols"):
        return getattr(form, "__name__", repr(form))
    return str(form)


def form_latex(form) -> str | None:
    """LaTeX of a sympy form (None when the form is not a sympy object)."""
    if form is None or form is LOST:
        return None
    sp = _sympy()
    try:
        if isinstance(form, (sp.Basic, sp.MatrixBase)):
            return sp.latex(form)
        if isinstance(form, (list, tuple)) and all(isinstance(f, sp.Basic) for f in form):
            return r"\left(" + ", ".join(sp.latex(f) for f in form) + r"\right)"
    except Exception:  # noqa: BLE001
        return None
    return None


def form_mathml(form) -> str | None:
    """Presentation MathML of a sympy form (renders in browsers without any script)."""
    if form is None or form is LOST:
        return None
    sp = _sympy()
    from sympy.printing.mathml import mathml

    try:
        if isinstance(form, (sp.Basic, sp.MatrixBase)):
            body = mathml(form, printer="presentation")
        elif isinstance(form, (list, tuple)) and form and all(isinstance(f, sp.Basic) for f in form):
            body = "<mo>(</mo>" + "<mo>,</mo>".join(mathml(f, printer="presentation") for f in form) + "<mo>)</mo>"
        else:
            return None
    except Exception:  # noqa: BLE001
        return None
    return f'<math xmlns="http://www.w3.org/1998/Math/MathML">{body}</math>'
