"""Shared test set-up: keep tests independent of each other's mpmath precision.

Several references use mpmath at 30-60 digits and set ``mpmath.mp.dps``; without this
fixture a later test would inherit whatever precision an earlier one left behind.
"""
import mpmath
import pytest


@pytest.fixture(autouse=True)
def _restore_mpmath_precision():
    prec = mpmath.mp.prec
    yield
    mpmath.mp.prec = prec
