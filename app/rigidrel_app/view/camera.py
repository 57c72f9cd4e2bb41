"""The 3-D view's camera: where a lecturer would put it, and the projection tests check pixels with.

World axes: x = the frames' x (lane units), z up (viser's default), the camera looks
along +y at the lanes, which stack in z: the lab lane on top, the chosen frame below.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]

#: A narrow field of view: nearly orthographic, so lengths compare across the view.
FOV = math.radians(28.0)


@dataclass(frozen=True)
class CameraPose:
    position: tuple[float, float, float]
    look_at: tuple[float, float, float]
    up: tuple[float, float, float] = (0.0, 0.0, 1.0)
    fov: float = FOV
    """Vertical field of view in radians (three.js convention)."""


def fit_lanes(
    x_range: tuple[float, float], z_range: tuple[float, float], aspect: float, fov: float = FOV, margin: float = 1.08
) -> CameraPose:
    """A camera on -y looking at the middle of the lanes, far enough that both fit the view."""
    xc = 0.5 * (x_range[0] + x_range[1])
    zc = 0.5 * (z_range[0] + z_range[1])
    half_w = 0.5 * (x_range[1] - x_range[0]) * margin
    half_h = 0.5 * (z_range[1] - z_range[0]) * margin
    tan_v = math.tan(0.5 * fov)
    distance = max(half_h / tan_v, half_w / (tan_v * max(aspect, 1e-3)))
    return CameraPose((xc, -distance, zc), (xc, 0.0, zc), (0.0, 0.0, 1.0), fov)


def project(points: FloatArray, pose: CameraPose, width: int, height: int) -> FloatArray:
    """Pixel coordinates ``(u, v)`` (origin top-left) of world points ``(..., 3)``, pinhole model."""
    p = np.asarray(points, dtype=np.float64)
    eye = np.asarray(pose.position)
    forward = np.asarray(pose.look_at) - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, np.asarray(pose.up))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    rel = p - eye
    depth = rel @ forward
    tan_v = math.tan(0.5 * pose.fov)
    aspect = width / height
    ndc_x = (rel @ right) / depth / (tan_v * aspect)
    ndc_y = (rel @ up) / depth / tan_v
    return np.stack([(ndc_x + 1.0) * 0.5 * width, (1.0 - ndc_y) * 0.5 * height], axis=-1)


def page_clip(pose: CameraPose) -> tuple[float, float]:
    """The near and far planes for a camera on the page (:func:`fit_page`): a tenth and three
    times its distance from the page, which keeps depth resolution for the page's layers."""
    distance = abs(pose.position[1])
    return 0.1 * distance, 3.0 * distance


def fit_page(width: float, height: float, fov: float = FOV) -> CameraPose:
    """A camera on -y looking at the middle of a ``width`` x ``height`` page (page px, z up, the
    page in the plane y = 0), as far as makes one page px one canvas CSS px."""
    distance = 0.5 * height / math.tan(0.5 * fov)
    xc, zc = 0.5 * width, 0.5 * height
    return CameraPose((xc, -distance, zc), (xc, 0.0, zc), (0.0, 0.0, 1.0), fov)
