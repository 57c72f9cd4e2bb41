"""A frame that rides the rod: the comoving frame, the point's event in it, the horizon event."""

from __future__ import annotations

import numpy as np
import pytest

import rigidrel_core as rr

KINDS = tuple(rr.scene_descriptions())
TAUS = (-1.3, -1e-9, 0.0, 1e-9, 0.2, 0.45, 0.9, 3.0)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("fraction", [0.0, 0.5, 1.0])
def test_the_point_reads_its_proper_time_at_its_event(kind: str, fraction: float) -> None:
    scene = rr.build_scene(kind)
    frames = [scene.frame(n) for n in rr.describe(kind).frames] + [rr.Frame.from_velocity(-0.999)]
    for rod in range(scene.n_rods):
        for tau in TAUS:
            for frame in frames:
                t, x = scene.point_event(rod, fraction, proper_time=tau, frame=frame)
                f = np.array([fraction])
                read = scene.proper_times(np.array([t]), frame=frame, fractions=f)[rod, 0, 0]
                where = scene.material_positions(np.array([t]), frame=frame, fractions=f)[rod, 0, 0]
                scale = max(1.0, abs(t), abs(x))
                assert read == pytest.approx(tau, abs=4e-15 * scale), (kind, rod, tau, frame.name)
                assert where == pytest.approx(x, abs=4e-15 * scale), (kind, rod, tau, frame.name)


@pytest.mark.parametrize("kind", KINDS)
def test_in_the_comoving_frame_the_rod_has_its_rest_length(kind: str) -> None:
    """Born rigidity: at every instant of a point's clock, its comoving frame sees the rod at rest length."""
    scene = rr.build_scene(kind)
    for rod in range(scene.n_rods):
        if not scene.rods[rod].motion.born_rigid:
            continue  # a signal-limited stop is not rigid (tests/test_paradoxes.py)
        rest = scene.rods[rod].motion.length
        for fraction in (0.0, 0.3, 1.0):
            for tau in TAUS:
                frame = scene.comoving_frame(rod, fraction, proper_time=tau)
                t, _ = scene.point_event(rod, fraction, proper_time=tau, frame=frame)
                length = scene.lengths(np.array([t]), frame=frame)[rod, 0]
                assert length == pytest.approx(rest, rel=1e-12), (kind, rod, fraction, tau)
                # the point is momentarily at rest in its own comoving frame
                v = scene.velocities(np.array([t]), frame=frame, fractions=np.array([fraction]))[rod, 0, 0]
                assert abs(v) <= 1e-12


@pytest.mark.parametrize("kind", KINDS)
def test_every_comoving_line_of_simultaneity_passes_the_horizon_event(kind: str) -> None:
    scene = rr.build_scene(kind)
    for rod in range(scene.n_rods):
        motion = scene.rods[rod].motion
        if not motion.born_rigid:
            continue  # no change, no hyperbolas: a signal-limited stop has no horizon
        for fraction in (0.0, 1.0):
            change = motion.radius(fraction) * motion.rapidity_change
            for share in (0.1, 0.5, 0.9):
                frame = scene.comoving_frame(rod, fraction, proper_time=share * change)
                t_point, _ = scene.point_event(rod, fraction, proper_time=share * change, frame=frame)
                t_horizon, _ = scene.horizon_event(rod, frame=frame)
                assert t_horizon == pytest.approx(t_point, abs=1e-12 * max(1.0, abs(t_point)))


def test_horizon_of_the_paper_scenes() -> None:
    assert rr.build_scene("wall-collision").horizon_event(0) == (0.0, 0.0)
    accel = rr.constant_acceleration(0.6, 1.0, 0.5)
    # a'_B = a'_F / (1 - a'_F L0) = 1: the back end's hyperbola x = sqrt(1 + t^2) - 1 is centred on x = -1
    assert accel.horizon_event(0) == pytest.approx((0.0, -1.0), abs=1e-15)


def test_point_event_refuses_bad_input() -> None:
    scene = rr.build_scene("wall-collision")
    with pytest.raises(rr.ParameterError, match="proper_time"):
        scene.point_event(0, 1.0, proper_time=float("nan"))
    with pytest.raises(rr.ParameterError, match="fraction"):
        scene.point_event(0, 1.5, proper_time=0.0)
    with pytest.raises(rr.ParameterError, match="rod"):
        scene.point_event(3, 1.0, proper_time=0.0)


def test_the_ride_keeps_the_rest_length_and_the_point_on_the_line() -> None:
    from rigidrel_app.view.comoving import RidePoint, proper_time_window, ride, simultaneity_items
    from rigidrel_app.view.vocabulary import Polyline

    scene = rr.build_scene("wall-collision")
    point = RidePoint(0, 1.0)
    lo, hi = proper_time_window(scene, point, scene.time_window())
    assert lo < 0.0 < hi
    for tau in np.linspace(lo, hi, 9):
        instant = ride(scene, point, float(tau))
        assert instant.lengths[0] == pytest.approx(1.0, rel=1e-12)
        line = simultaneity_items(instant, 3.0)[0]
        assert isinstance(line, Polyline)
        # the lab line of simultaneity passes through the point's lab event
        te, xe = instant.event_lab
        t_on = np.interp(xe, np.sort(line.x), line.y[np.argsort(line.x)])
        assert t_on == pytest.approx(te, abs=1e-12)
    assert point.label(scene) == "comoving with rod at f = 1"
