"""Hypothesis strategies generated from the scene registry (``rr.scene_descriptions()``).

Every range drawn here comes from a scene's :class:`rigidrel_core.Parameter` s, so a scene
registered in ``rigidrel_core/scenes/`` is drawn, sampled in every frame and fed bad values
with no edit to the tests. Speeds and velocities (parameters in units of c) are clamped at
``vmax``; asking for a ``vmax`` beyond a parameter's range also draws speeds between the
range's top and ``vmax``, log-uniformly in their gap ``1 - |v|`` to light speed.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterator, Sequence

from hypothesis import reject
from hypothesis import strategies as st

import rigidrel_core as rr

#: The fastest speed drawn unless asked: the app's sliders stop at 0.99 c.
DEFAULT_VMAX = 0.99
#: A range whose ends differ by more than this factor is drawn log-uniformly.
LOG_SPAN = 100.0
#: Wrong types and non-finite numbers, refused for every parameter (``None`` only where not optional).
WRONG_TYPES: tuple[object, ...] = (math.nan, math.inf, -math.inf, None, "0.5", True, 1j, [0.5])


def is_velocity(parameter: rr.Parameter) -> bool:
    """Speeds and velocities: the parameters measured in units of c."""
    return parameter.unit == "c"


def log_uniform(lo: float, hi: float) -> st.SearchStrategy[float]:
    """Floats in ``[lo, hi]`` (``0 < lo < hi``) spread evenly over the decades."""
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda u: min(max(10.0**u, lo), hi))


def parameter_values(parameter: rr.Parameter, vmax: float = DEFAULT_VMAX) -> st.SearchStrategy[float | None]:
    """Values of ``parameter`` from its :meth:`~rigidrel_core.Parameter.sample_range` (``None`` too if optional)."""
    lo, hi = parameter.sample_range()
    parts: list[st.SearchStrategy[float]] = []
    if is_velocity(parameter):
        lo, hi = max(lo, -vmax), min(hi, vmax)
        top = max(abs(lo), abs(hi))
        if vmax > top:  # closer to light than the range: gaps 1 - |v| from 1 - top down to 1 - vmax
            near = log_uniform(1.0 - vmax, 1.0 - top).map(lambda gap: 1.0 - gap)
            if hi >= top:
                parts.append(near)
            if -lo >= top:
                parts.append(near.map(lambda v: -v))
    wide = lo > 0.0 and hi / lo > LOG_SPAN
    log_slider = parameter.slider is not None and parameter.slider.scale == "log"
    parts.insert(0, log_uniform(lo, hi) if (wide or log_slider) else st.floats(lo, hi))
    values: st.SearchStrategy[float | None] = st.one_of(parts)
    if parameter.optional:
        values = st.one_of(st.none(), values)
    return values


def descriptions(kinds: Sequence[str] | None = None) -> list[rr.SceneDescription]:
    """The registered descriptions (in teaching order), or those named in ``kinds``."""
    registry = rr.scene_descriptions()
    return [registry[k] for k in kinds] if kinds is not None else list(registry.values())


@st.composite
def scene_values(
    draw: st.DrawFn, vmax: float = DEFAULT_VMAX, kinds: Sequence[str] | None = None
) -> tuple[rr.SceneDescription, dict[str, float | None]]:
    """A registered description and one value for each of its parameters (not yet checked together)."""
    description = draw(st.sampled_from(descriptions(kinds)))
    return description, {p.name: draw(parameter_values(p, vmax)) for p in description.parameters}


@st.composite
def scenes(draw: st.DrawFn, vmax: float = DEFAULT_VMAX, kinds: Sequence[str] | None = None) -> rr.Scene:
    """A scene of any registered kind (or of ``kinds``), built with ``description.build``.

    Combinations the constructor refuses (cross-parameter constraints such as ``v2 < v1`` or
    ``a_front * length < 1``, or a scene too large for float64) are rejected, not repaired.
    """
    description, values = draw(scene_values(vmax, kinds))
    try:
        return description.build(**values)
    except rr.ParameterError:
        reject()


def frames(max_speed: float = DEFAULT_VMAX) -> st.SearchStrategy[rr.Frame]:
    """Frames moving with any velocity in ``[-max_speed, max_speed]``."""
    return st.floats(-max_speed, max_speed).map(rr.Frame.from_velocity)


@st.composite
def scene_and_frame(
    draw: st.DrawFn,
    vmax: float = DEFAULT_VMAX,
    max_speed: float = DEFAULT_VMAX,
    kinds: Sequence[str] | None = None,
) -> tuple[rr.Scene, rr.Frame]:
    """A scene and either one of its preset frames (a rod's rest frame, the barycentric frame, ...)
    or a frame of any velocity up to ``max_speed``."""
    scene = draw(scenes(vmax, kinds))
    frame = draw(st.one_of(st.sampled_from(list(scene.frames.values())), frames(max_speed)))
    return scene, frame


def outside(domain: rr.Interval) -> list[float]:
    """Finite numbers just and far outside ``domain``: its open ends, their neighbours, 0, ±1e300."""
    candidates = [0.0]
    if math.isfinite(domain.lo):
        candidates += [domain.lo, math.nextafter(domain.lo, -math.inf), domain.lo - max(1.0, abs(domain.lo)), -1e300]
    if math.isfinite(domain.hi):
        candidates += [domain.hi, math.nextafter(domain.hi, math.inf), domain.hi + max(1.0, abs(domain.hi)), 1e300]
    found: list[float] = []
    for x in candidates:
        if x not in domain and x not in found:
            found.append(x)
    return found


def bad_values(parameter: rr.Parameter) -> Iterator[object]:
    """Values ``parameter.check`` must refuse: numbers outside its domain, non-finite numbers and
    wrong types (``None`` only when the parameter is not optional)."""
    yield from outside(parameter.domain)
    for value in WRONG_TYPES:
        if value is not None or not parameter.optional:
            yield value
    yield object()


def bad_numbers(parameter: rr.Parameter) -> st.SearchStrategy[object]:
    """Any float outside ``parameter.domain``, or one of :func:`bad_values`."""
    domain = parameter.domain
    parts: list[st.SearchStrategy[object]] = [st.sampled_from(list(bad_values(parameter)))]
    if math.isfinite(domain.lo):
        parts.append(st.floats(max_value=domain.lo, exclude_max=domain.lo_closed, allow_nan=False))
    if math.isfinite(domain.hi):
        parts.append(st.floats(min_value=domain.hi, exclude_min=domain.hi_closed, allow_nan=False))
    return st.one_of(parts)


@contextlib.contextmanager
def isolated_registry() -> Iterator[None]:
    """Scenes registered inside the block are forgotten after it.

    The registry is global to the process, and other test files list it (the app's menus, the
    command line): a scene a test or an example registers must not outlive that test.
    """
    before = set(rr.scene_descriptions())
    try:
        yield
    finally:
        for kind in set(rr.scene_descriptions()) - before:
            rr.unregister_scene(kind)
