"""The scene catalogue: one module per scene family, each holding its constructors and their
:class:`~rigidrel_core.SceneDescription` s in a module-level ``SCENES`` tuple.

A module placed here is found by :func:`discover` (the registry's source); nothing else needs
to list it.
"""

from __future__ import annotations

import importlib
import pkgutil

from .._description import SceneDescription


def discover() -> tuple[SceneDescription, ...]:
    """Every description in this package's modules, in teaching order (``order``, then name)."""
    found: list[SceneDescription] = []
    for info in pkgutil.iter_modules(__path__):
        module = importlib.import_module(f"{__name__}.{info.name}")
        found.extend(getattr(module, "SCENES", ()))
    return tuple(sorted(found, key=lambda d: (d.order, d.kind)))
