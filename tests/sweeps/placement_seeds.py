"""Every random crowded chart of ``tests/test_placement_orders.py``, seeds 0 to 39, in both areas:
placed again with the stuck labels first (never more stuck), and far rings made once per size.

The suite places seeds 0-7 (fast lane) and 8-15 (slow lane). Run from the repository's root::

    python -m tests.sweeps.placement_seeds
"""

from tests.sweeps import run

if __name__ == "__main__":
    raise SystemExit(run("tests/test_placement_orders.py"))
