"""Shared settings and helpers of the quadsect Python tests."""

import os

from hypothesis import HealthCheck, settings

# Exact arithmetic makes some examples slower than hypothesis' default
# deadline on a loaded 2-core machine: no deadline, a bounded example count.
settings.register_profile(
    "ci",
    max_examples=int(os.environ.get("QUADSECT_HYPOTHESIS_EXAMPLES", "60")),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
    print_blob=True,
    database=None,
)
settings.load_profile("ci")
