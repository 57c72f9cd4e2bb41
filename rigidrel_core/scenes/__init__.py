"""The scene catalogue: one module per scene family, each holding its constructors and their
:class:`~rigidrel_core.SceneDescription` s in a module-level ``SCENES`` tuple.

A module placed here is found by :func:`discover` (the registry's source); nothing else needs
to list it.

**Parameter names.** One name per quantity, the same in every constructor, the registry, the
command line (``--name`` with ``-`` for ``_``), scenario strings and lesson files; the paper's
symbol is the parameter's ``symbol``:

* ``v``: the paper's speed ``V`` (> 0) of a one-rod scene, whose direction the scene fixes (from
  rest to ``V``, from ``-V`` to rest, ``-V`` into a wall); a signed velocity is ``v`` and what it
  belongs to: ``v_initial``, ``v_final`` (``V_i``, ``V_f``), ``v1``, ``v2`` (rods 1 and 2);
* ``length``: a rest length (``L0``), ``length1``, ``length2`` for two rods (``L1``, ``L2``), or
  what it is the length of: ``ship_length``, ``barn_length``;
* ``mass``: a rest mass (``M``), ``mass1``, ``mass2`` for two rods (``M1``, ``M2``);
* ``a_front``, ``a_back``: the proper accelerations ``a'_F``, ``a'_B`` of a rod's front and back
  ends (Sec. 3, Eq. (15));
* ``eps``: the coefficient of restitution (Eq. (29)).

A parameter that was renamed is listed in its description's ``renamed`` (old name: new name), and
its old name is refused everywhere with the new one named.
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
