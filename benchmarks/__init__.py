"""exactcagd benchmarks: each ``bench_<topic>.py`` has ``main(quick=False)`` and writes
``benchmarks/results/<topic>.md`` (and plots).  Run one with
``python -m benchmarks.bench_<topic> [--quick]``."""
