"""Slow stress tests mirroring benchmarks/stress_numeric.py: every enclosure must hold.

The exact answers come from independent routes (planted rational roots, flint's real
root isolation, the algebra layer's exact intersection); see the benchmark module.
"""

import pytest

from benchmarks import stress_numeric as stress

ROOT_CASES = list(stress.root_cases(quick=False))
INTERSECTION_CASES = list(stress.intersection_cases(quick=False))


@pytest.mark.slow
@pytest.mark.parametrize("case", ROOT_CASES, ids=[c[0] for c in ROOT_CASES])
def test_root_enclosures_hold(case):
    row = stress.run_root_case(*case)
    assert row["held"], row


@pytest.mark.slow
@pytest.mark.parametrize("method", stress.METHODS)
@pytest.mark.parametrize("case", INTERSECTION_CASES, ids=[c[0] for c in INTERSECTION_CASES])
def test_intersection_enclosures_hold(case, method):
    row = stress.run_intersection_case(*case, method)
    assert row["held"], row


def test_quick_case_lists_are_subsets():
    """(fast) the quick benchmark runs a subset of what the slow tests check."""
    full = {c[0] for c in ROOT_CASES} | {c[0] for c in INTERSECTION_CASES}
    quick = {c[0] for c in stress.root_cases(True)} | {c[0] for c in stress.intersection_cases(True)}
    assert quick <= full
