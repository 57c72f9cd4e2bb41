"""The palette as a colour-blind viewer and a projector see it: every colour that tells things apart
(the rods, the frames, light) stays apart under protanopia, deuteranopia and tritanopia, and every
line meets 3:1 and every text 4.5:1 against its ground, in both themes (WCAG 2.1 1.4.3, 1.4.11)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from rigidrel_app.view.notice import NOTICE_COLOR
from rigidrel_app.view.objects import BARRIER_COLOR, MARKER_COLOR
from rigidrel_app.view.vocabulary import FRAME_COLOR, INK, LIGHT_COLOR, ROD_COLORS, SHADES, Shade, shaded

#: Machado, Oliveira and Fernandes (2009), severity 1: linear-RGB matrices of full dichromacy.
MACHADO = {
    "protanopia": np.array(
        [[0.152286, 1.052583, -0.204868], [0.114503, 0.786281, 0.099216], [-0.003882, -0.048116, 1.051998]]
    ),
    "deuteranopia": np.array(
        [[0.367322, 0.860646, -0.227968], [0.280085, 0.672501, 0.047413], [-0.011820, 0.042940, 0.968881]]
    ),
    "tritanopia": np.array(
        [[1.255528, -0.076749, -0.178779], [-0.078411, 0.930809, 0.147602], [0.004733, 0.691367, 0.303900]]
    ),
}
#: The colours a viewer must tell apart by colour: the rods (and their legend), the frames' axes
#: and labels, and light signals and cones.
TOLD_APART = {"rod 1": ROD_COLORS[0], "rod 2": ROD_COLORS[1], "rod 3": ROD_COLORS[2], "frame": FRAME_COLOR,
              "light": LIGHT_COLOR}  # fmt: skip
#: Lines and markers that carry meaning (3:1), and the colours text is drawn in (4.5:1).
LINES = {**TOLD_APART, "wall": BARRIER_COLOR, "marker": MARKER_COLOR, "ink": INK}
TEXTS = {"ink": INK, "frame": FRAME_COLOR, "light": LIGHT_COLOR, "notice": NOTICE_COLOR}
GROUND: dict[Shade, str] = {"light": "#FFFFFF", "dark": "#000000"}


def _linear(color: str) -> np.ndarray:
    c = np.array([int(color[i : i + 2], 16) for i in (1, 3, 5)]) / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def contrast(a: str, b: str) -> float:
    """WCAG 2.1's contrast ratio of two sRGB colours."""
    la, lb = (float(np.array([0.2126, 0.7152, 0.0722]) @ _linear(c)) for c in (a, b))
    return (max(la, lb) + 0.05) / (min(la, lb) + 0.05)


def lab(linear_rgb: np.ndarray) -> np.ndarray:
    """CIELAB (D65) of a linear-RGB colour."""
    m = np.array(
        [[0.4124564, 0.3575761, 0.1804375], [0.2126729, 0.7151522, 0.0721750], [0.0193339, 0.1191920, 0.9503041]]
    )
    xyz = m @ linear_rgb / np.array([0.95047, 1.0, 1.08883])
    f = np.where(xyz > (6 / 29) ** 3, np.cbrt(xyz), xyz / (3 * (6 / 29) ** 2) + 4 / 29)
    return np.array([116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])])


def seen_by(color: str, deficiency: str) -> np.ndarray:
    """``color`` in CIELAB as a viewer with ``deficiency`` sees it."""
    return lab(np.clip(MACHADO[deficiency] @ _linear(color), 0.0, 1.0))


def test_contrast_and_lab_agree_with_known_values() -> None:
    assert contrast("#FFFFFF", "#000000") == pytest.approx(21.0)
    assert contrast("#777777", "#FFFFFF") == pytest.approx(4.48, abs=0.01)
    assert lab(_linear("#FFFFFF")) == pytest.approx([100.0, 0.0, 0.0], abs=0.01)
    # the simulation merges what a dichromat cannot tell apart: pure red and green under deuteranopia
    assert np.linalg.norm(seen_by("#FF0000", "deuteranopia") - seen_by("#00CC00", "deuteranopia")) < 25


@pytest.mark.parametrize("shade", SHADES)
@pytest.mark.parametrize("deficiency", list(MACHADO))
def test_colours_that_tell_things_apart_stay_apart(shade: Shade, deficiency: str) -> None:
    for (a, ca), (b, cb) in itertools.combinations(TOLD_APART.items(), 2):
        delta = float(np.linalg.norm(seen_by(shaded(ca, shade), deficiency) - seen_by(shaded(cb, shade), deficiency)))
        assert delta >= 10.0, (shade, deficiency, a, b, round(delta, 1))


@pytest.mark.parametrize("shade", SHADES)
def test_lines_meet_3_to_1_and_text_4_5_to_1(shade: Shade) -> None:
    for name, color in LINES.items():
        assert contrast(shaded(color, shade), GROUND[shade]) >= 3.0, (shade, name)
    for name, color in TEXTS.items():
        assert contrast(shaded(color, shade), GROUND[shade]) >= 4.5, (shade, name)
