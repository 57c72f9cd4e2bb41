"""The light cone of a chosen event, drawn on both diagrams (the Layers folder's "Light cone of" menu).

The cone's apex is the core's event in each diagram's frame, and its rays are at 45 degrees there:
the same cone, seen from two frames. Chosen from a list generated from the scene's events, written
``--cone EVENT`` in scenario strings; a name the scene does not have is a notice, never a traceback.
"""

from __future__ import annotations

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.view.scenario import ScenarioError, format_scenario, parse_scenario
from rigidrel_app.view.scene_view import build_drawing
from rigidrel_app.view.state import CUSTOM_FRAME, Settings, build, cone_events, resolve
from rigidrel_app.view.vocabulary import Area, Segments

KINDS = sorted(rr.scene_descriptions())


def _cone_apex(items: tuple[object, ...]) -> tuple[float, float]:
    """Where the cone's two rays cross, ``(t, x)``, from its dashed Segments (x0, y0) -> (x1, y1)."""
    rays = [it for it in items if isinstance(it, Segments) and it.style.group == "event cone"]
    assert len(rays) == 1
    r = rays[0]
    (xa0, xb0), (ta0, tb0), (xa1, xb1), (ta1, tb1) = r.x0, r.y0, r.x1, r.y1
    # each ray is x - x_k = ±(t - t_k): they cross at the midpoints of their ends
    slopes = ((ta1 - ta0) / (xa1 - xa0), (tb1 - tb0) / (xb1 - xb0))
    assert slopes[0] == pytest.approx(1.0) and slopes[1] == pytest.approx(-1.0)
    return 0.5 * (ta0 + ta1), 0.5 * (xa0 + xa1)


@pytest.mark.parametrize("kind", KINDS)
def test_every_event_cone_has_its_apex_at_the_core_event_in_both_diagrams(kind: str) -> None:
    scene = rr.build_scene(kind)
    for event in cone_events(scene):
        r = build(Settings(kind, cone=event))
        assert r.cone == event
        d = build_drawing(r)
        for chart, frame in ((d.lab_chart, rr.LAB), (d.frame_chart, r.frame)):
            t, x = _cone_apex(chart.items)
            te, xe = scene.source_event(event, frame=frame)
            size = max(1.0, abs(te), abs(xe))
            assert abs(t - te) <= 1e-9 * size and abs(x - xe) <= 1e-9 * size, (kind, event, frame.name)
            shaded = [it for it in chart.items if isinstance(it, Area) and it.style.group == "event cone"]
            assert shaded, (kind, event)  # the future (or the past) lies on the chart


def test_the_cone_is_named_chosen_and_refused_like_any_setting() -> None:
    s = Settings.of("wall-collision", v=0.6, eps=0.0)
    assert cone_events(rr.build_scene("wall-collision")) == ("contact", "T_1", "T_1'")
    d = build_drawing(build(Settings("wall-collision", s.values, cone="T_1")))
    names = {it.style.name for it in d.lab_chart.items if isinstance(it, Segments) and it.style.group == "event cone"}
    assert names == {"light cone of <b>T<sub>1</sub></b>"}  # its dotted rays, named with the event's subscript
    bad = resolve(Settings("wall-collision", s.values, cone="T_9"))
    assert isinstance(bad, str)
    assert bad.startswith("Light cone refused: cone must be an event of the scene: contact, T_1, T_1'; got 'T_9'")
    # another scene has other events: the cone goes
    assert Settings("wall-collision", s.values, cone="T_1").with_scene("rod-collision").cone is None
    # not drawn unless asked for
    assert not any(
        isinstance(it, Area) and it.style.group == "event cone" for it in build_drawing(build(s)).lab_chart.items
    )


def test_scenario_strings_carry_the_cone() -> None:
    line = "rod-collision --v1 0.6 --mass2 2 --v2 0 --length2 1 --eps 1 --frame barycentric --cone T_2"
    scenario = parse_scenario(line)
    assert scenario.settings.cone == "T_2"
    assert format_scenario(scenario.settings) == line
    quoted = parse_scenario('wall-collision --cone "T_1\'"').settings
    assert quoted.cone == "T_1'" and parse_scenario(format_scenario(quoted)).settings == quoted
    with pytest.raises(ScenarioError) as err:
        parse_scenario("wall-collision --cone T_2")
    assert err.value.parameter == "cone" and "contact, T_1, T_1'" in str(err.value)
    # a cone in a custom frame: the same settings back
    custom = Settings("rod-collision", (), CUSTOM_FRAME, -0.5, cone="contact")
    assert parse_scenario(format_scenario(custom)).settings == custom
    assert np.isfinite(custom.beta)
