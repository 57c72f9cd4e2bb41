"""The wall crash's "illusory" cause: the far end's change is spacelike to the contact.

An elastic wall bounce (Franklin 2012, Sec. 5, "Rigid body collisions", with epsilon = 1; V = 0.6,
L0 = 1, c = 1). The rod's far end changes velocity from T_1 = (-3/4, 5/4) to T'_1 = (3/4, 5/4) in
the lab, while the front touches the wall at the origin. Both ends of that change are spacelike to
the contact (interval -1), so their time order depends on the frame: in the frame of the rod
before, T_1 is simultaneous with the contact; in the lab it comes first. A light signal from the
contact reaches the far end only at (2, 2), after its whole change, in every frame: no signal from
the contact caused it.
"""

import numpy as np

import rigidrel_core as rr


def main() -> None:
    scene = rr.wall_collision(0.6, 1.0, 1.0)
    contact = np.zeros(2)
    arrival_lab = scene.signal_arrival((0.0, 0.0), 0, 1.0)
    assert arrival_lab is not None  # None would mean the far end stays out of the signal's reach
    print(f"light from the contact reaches the far end at lab (t, x) = {arrival_lab}")
    for name, frame in scene.frames.items():
        events = scene.events_in(frame=frame)
        arrival = scene.signal_arrival((0.0, 0.0), 0, 1.0, frame=frame)
        assert arrival is not None
        seen = frame @ np.array(arrival_lab)  # the same event, carried over from the lab
        t1, t1p = events["T_1"], events["T_1'"]
        order = "before" if t1[0] < 0 else "at the same time as" if t1[0] == 0 else "after"
        print(
            f"{name:10s}  T_1 t = {t1[0]:+.4f} ({order} the contact)  T_1' t = {t1p[0]:+.4f}"
            f"  arrival t = {arrival[0]:+.4f}  (the lab's arrival carried over: {seen[0]:+.4f})"
        )
    for end in ("T_1", "T_1'"):
        relation = rr.causal_relation(contact, scene.events_in(frame=rr.LAB)[end])
        print(f"contact -> {end}: {relation.kind}, interval {relation.interval:+.4f}")
    for verdict in scene.causal_verdicts():
        print(verdict.text)


if __name__ == "__main__":
    main()
