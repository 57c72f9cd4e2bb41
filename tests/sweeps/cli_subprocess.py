"""Every ``rigidrel events`` case of ``tests/test_cli.py`` in a new interpreter, as a user runs it:
each table, JSON report, help and refusal, with its exit status and stderr as a shell sees them.

The suite runs these cases in-process (``rigidrel_app.cli.main``) and only a representative few in
a new interpreter. Run from the repository's root::

    python -m tests.sweeps.cli_subprocess
"""

from tests.sweeps import run

if __name__ == "__main__":
    raise SystemExit(run("tests/test_cli.py"))
