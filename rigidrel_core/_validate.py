"""Input validation: every bad value raises ValueError naming the parameter and its allowed range."""

from __future__ import annotations

import functools
import math
import numbers
from collections.abc import Callable, Iterable, Mapping
from typing import Any, ParamSpec, TypeVar, cast

import numpy as np
import numpy.typing as npt

P = ParamSpec("P")
R = TypeVar("R")

#: Largest |time| accepted by the samplers; beyond it float64 products may overflow.
MAX_ABS_TIME = 1e300


class ParameterError(ValueError):
    """A parameter outside its allowed range (a ValueError, so ``except ValueError`` works)."""

    def __init__(self, name: str, allowed: str, got: object) -> None:
        self.parameter = name
        self.allowed = allowed
        super().__init__(f"{name} must be {allowed}; got {got!r}")


class RenamedParameterError(ParameterError, TypeError):
    """An old name of a renamed parameter, refused with the new one named:
    ``rod_collision() got 'm2'; it is now 'mass2'``. A ``TypeError``, as Python's own error for an
    unknown keyword, and a :class:`ParameterError` (a ``ValueError``), as the registry's for an
    unknown parameter."""

    def __init__(self, who: str, renamed: Mapping[str, str], given: Iterable[str]) -> None:
        old = [name for name in given if name in renamed]
        new = [renamed[name] for name in old]
        if len(old) == 1:
            text = f"{who} got {old[0]!r}; it is now {new[0]!r}"
        else:
            text = f"{who} got {', '.join(map(repr, old))}; they are now {', '.join(map(repr, new))}"
        self.parameter = old[0]
        self.allowed = f"now called {new[0]!r}"
        self.renamed = dict(zip(old, new, strict=True))
        Exception.__init__(self, text)


def refuse_renamed(renamed: Mapping[str, str]) -> Callable[[Callable[P, R]], Callable[P, R]]:
    """Make a constructor refuse the old names of its renamed keywords (``{old: new}``) with a
    :class:`RenamedParameterError` naming the new ones (Python's own error names only the old)."""

    def decorate(constructor: Callable[P, R]) -> Callable[P, R]:
        who = f"{constructor.__name__}()"
        old_names = tuple(renamed)

        @functools.wraps(constructor)
        def refusing(*args: P.args, **kwargs: P.kwargs) -> R:
            for name in old_names:
                if name in kwargs:
                    raise RenamedParameterError(who, renamed, kwargs)
            return constructor(*args, **kwargs)

        return refusing

    return decorate


def as_real(name: str, value: object, allowed: str) -> float:
    """``value`` as a finite float (bools, text, complex, NaN and infinities are refused, naming ``name``)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ParameterError(name, allowed, value)
    x = float(value)
    if not math.isfinite(x):
        raise ParameterError(name, allowed, value)
    return x


def check_velocity(name: str, value: object) -> float:
    """A velocity in the open interval (-1, 1) (c = 1)."""
    if type(value) is float and -1.0 < value < 1.0:
        return value  # the common case, without the number checks
    allowed = "a finite number in (-1, 1)"
    x = as_real(name, value, allowed)
    if not -1.0 < x < 1.0:
        raise ParameterError(name, allowed, value)
    return x


_FLOAT64 = np.dtype(np.float64)


def _real_array(name: str, allowed: str, value: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """``value`` as a float64 array; complex, object or text arrays are refused, never cut to a part."""
    got: object = value  # what the error names
    if isinstance(value, np.ndarray):
        # isinstance narrows ArrayLike to ndarray[Unknown, ...]: numpy's stubs cannot say the shape type
        array = cast(npt.NDArray[Any], value)
        dtype = array.dtype
        if dtype == _FLOAT64:
            return array  # what astype(float64, copy=False) returns, without the call
        if dtype.kind in "biuf":
            return array.astype(np.float64, copy=False)
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):
        raise ParameterError(name, allowed, got) from None
    if raw.dtype.kind not in "biuf":
        raise ParameterError(name, allowed, got)
    return raw.astype(np.float64, copy=False)


#: Up to this many times are checked as Python floats: cheaper than numpy's two reductions.
_FEW_TIMES = 16
#: Below this many times the bound is checked on ``|t|`` (one reduction, a temporary copy); from
#: here on by min and max (no copy to allocate).
_FEW_TIMES_ABS = 4096


@functools.cache
def _times_allowed(name: str) -> str:
    return f"finite real numbers with |{name}| <= {MAX_ABS_TIME:g}"


def check_times(name: str, t: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Finite real times with ``|t| <= 1e300``; any shape."""
    return check_times_ordered(name, t, None)[0]


def check_times_ordered(
    name: str, t: npt.ArrayLike, order_from: int | None
) -> tuple[npt.NDArray[np.float64], bool | None]:
    """:func:`check_times`, and whether the times are sorted (for a sampler with a faster path for them).

    The order is found for 1-D input of at least ``order_from`` times (``None`` otherwise).
    A non-decreasing array holds no NaN (every comparison with NaN is false), so its bounds
    are its ends: one pass over the times instead of the two of ``min`` and ``max``.
    """
    allowed = _times_allowed(name)
    arr = _real_array(name, allowed, t)
    ordered: bool | None = None
    if arr.size <= _FEW_TIMES:
        for x in arr.ravel().tolist():
            if not -MAX_ABS_TIME <= x <= MAX_ABS_TIME:
                raise ParameterError(name, allowed, float(x))
        return arr, ordered
    if order_from is not None and arr.ndim == 1 and arr.size >= order_from:
        ordered = non_decreasing(arr)
    if ordered:
        within = arr[0] >= -MAX_ABS_TIME and arr[-1] <= MAX_ABS_TIME
    elif arr.size < _FEW_TIMES_ABS:  # one reduction of |t| (a small temporary) instead of min and max
        within = np.maximum.reduce(np.abs(arr), axis=None) <= MAX_ABS_TIME
    else:  # the ufuncs' own reductions: arr.min() and arr.max() add a Python layer (~10 % here)
        lo, hi = np.minimum.reduce(arr, axis=None), np.maximum.reduce(arr, axis=None)
        within = lo >= -MAX_ABS_TIME and hi <= MAX_ABS_TIME
    # NaN propagates through the reductions; inf fails the bound.
    if not within:
        bad = arr[~(np.abs(arr) <= MAX_ABS_TIME)].ravel()[0]
        raise ParameterError(name, allowed, float(bad))
    return arr, ordered


def check_fractions(name: str, f: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Material coordinates as fractions of the rest length, each in [0, 1]."""
    allowed = "an array of numbers in [0, 1]"
    arr = _real_array(name, allowed, f)
    if arr.ndim != 1 or not np.all((arr >= 0.0) & (arr <= 1.0)):
        raise ParameterError(name, allowed, f)
    return arr


#: Times compared first when checking an order: a shuffled input fails here, at little cost.
_ORDER_PROBE = 1024


def non_decreasing(t: npt.NDArray[np.float64]) -> bool:
    """Whether the 1-D ``t`` is sorted (``t[i] <= t[i + 1]``; false wherever a NaN is). Its first
    ``_ORDER_PROBE`` times are compared first, so a shuffled input costs almost nothing."""
    head = t[:_ORDER_PROBE]
    return bool(np.all(head[1:] >= head[:-1])) and bool(np.all(t[1:] >= t[:-1]))
