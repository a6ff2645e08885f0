"""Rules over every registered ledger claim (issue 17), read from the claims' source (AST).

- every erratum / reconstructed / convention row is differential (printed and corrected
  forms as data and a check the runner evaluates on both);
- no row rests on the code under test: no assert on a package flag (``g1_verified``), no
  check made only of stored degrees / shapes, no package function on both sides of a
  comparison.
"""
import ast
import inspect
import textwrap

from exactcagd.proofs._ledger import discover

CLAIMS = discover()
#: elementary vector operations: the same one on both sides is not "the code under test"
ELEMENTARY = {"dot", "cross", "length_squared"}

# ---------------------------------------------------------------- rules over the registered claims
DIFFERENTIAL = ("erratum", "reconstructed", "convention")


def _returns(func):
    tree = ast.parse(textwrap.dedent(inspect.getsource(func)))
    calls = [n for n in ast.walk(tree) if isinstance(n, ast.Return) and isinstance(n.value, ast.Call)]
    return tree, [(c.value.func.id if isinstance(c.value.func, ast.Name) else None, c.value) for c in calls]


def _kw(call, name):
    return any(k.arg == name for k in call.keywords)


def test_every_erratum_reconstruction_and_convention_is_differential():
    """Each such row passes printed and corrected forms and a check (the runner evaluates both)."""
    missing = []
    for c in CLAIMS:
        _, rets = _returns(c.func)
        for name, call in rets:
            if name in DIFFERENTIAL and not _kw(call, "check"):
                missing.append(c.key)
    assert not missing, f"{len(missing)} rows are not differential: {missing}"


FLAG_ATTRS = {"g1_verified", "continuity", "is_valid", "verified"}
SHAPE_ATTRS = {"degree", "shape", "true_degree", "ndim"}


def _names(node):
    """Attributes read (not called): ``x.degree`` is a stored degree, ``p.degree()`` / ``sympy.degree(...)`` a computation."""
    called = {id(n.func) for n in ast.walk(node) if isinstance(n, ast.Call)}
    return {n.attr for n in ast.walk(node) if isinstance(n, ast.Attribute) and id(n) not in called}


def _package_function(func, dotted: str):
    """The exactcagd function (not a class, not a proof helper) ``dotted`` names in ``func``'s module, or None."""
    obj = func.__globals__
    parts = dotted.split(".")
    try:
        obj = obj[parts[0]] if parts[0] in obj else None
        for p in parts[1:]:
            obj = getattr(obj, p)
    except (AttributeError, KeyError, TypeError):
        return None
    if obj is None or isinstance(obj, type):
        return None
    module = getattr(obj, "__module__", "") or ""
    if dotted.rsplit('.', 1)[-1] in ELEMENTARY:
        return None
    return obj if module.startswith("exactcagd.") and not module.startswith("exactcagd.proofs") else None


def _callees(func, node):
    return {ast.unparse(n.func) for n in ast.walk(node) if isinstance(n, ast.Call) and _package_function(func, ast.unparse(n.func))}


def _self_referential(func, test: ast.AST) -> bool:
    """``f(a) == ... f(b) ...``: the same package function on both sides of a comparison."""
    if not isinstance(test, ast.Compare) or len(test.comparators) != 1:
        return False
    return bool(_callees(func, test.left) & _callees(func, test.comparators[0]))


def test_no_row_rests_on_the_code_under_test():
    """Reject checks that assert a package flag, only degrees/shapes, or one function against itself."""
    offenders = []
    for c in CLAIMS:
        tree, _ = _returns(c.func)
        asserts = [n.test for n in ast.walk(tree) if isinstance(n, ast.Assert)]
        for t in asserts:
            if _names(t) & FLAG_ATTRS:
                offenders.append((c.key, "asserts a package flag: " + ast.unparse(t)))
            if _self_referential(c.func, t):
                offenders.append((c.key, "same function on both sides: " + ast.unparse(t)))
        if asserts and all(_names(t) and _names(t) <= SHAPE_ATTRS for t in asserts):
            offenders.append((c.key, "asserts only stored degrees / shapes"))
    assert not offenders, "\n".join(f"{k}: {why}" for k, why in offenders)


def test_verified_rows_state_their_reference_kind_when_they_say_what_was_compared():
    for c in CLAIMS:
        _, rets = _returns(c.func)
        for name, call in rets:
            if name in ("verified", "verified_range") and _kw(call, "compared"):
                assert _kw(call, "reference"), f"{c.key}: compared= without reference="




def test_every_verified_row_states_what_was_compared_with_what():
    """Issue 17 §2: a verified row says which printed text it tested against which
    independent reference (``compared=``), so a reader can audit the verdict."""
    silent = []
    for c in CLAIMS:
        _, rets = _returns(c.func)
        for name, call in rets:
            if name in ("verified", "verified_range") and not _kw(call, "compared"):
                silent.append(c.key)
    assert not silent, f"{len(silent)} verified rows do not say what was compared: {sorted(set(silent))}"
