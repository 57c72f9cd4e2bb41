"""The suite's plugins: the lanes and their check (:mod:`tests.lanes`)."""

pytest_plugins = ["tests.lanes"]
