"""Application layer: CLI back-ends (proof ledger runner, benchmarks)."""
