"""Run every registered proof of the ledger (fast ones always, heavy ones under -m slow)."""
import pytest

from proofs._ledger import discover, run_claim

CLAIMS = discover()


def _params(slow: bool):
    return [pytest.param(c, id=c.key) for c in CLAIMS if c.slow == slow]


@pytest.mark.parametrize("claim", _params(False))
def test_fast_claim(claim):
    row = run_claim(claim)
    assert row.outcome is not None, row.error


@pytest.mark.slow
@pytest.mark.parametrize("claim", _params(True))
def test_slow_claim(claim):
    row = run_claim(claim)
    assert row.outcome is not None, row.error
