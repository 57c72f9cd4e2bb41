"""Frames compose with ``@`` and map events with ``@``; the light cone stays put.

A frame moving at 0.6 c relative to a frame that itself moves at 0.6 c moves at
(0.6 + 0.6)/(1 + 0.6 * 0.6) = 15/17 relative to the lab: rapidities add. ``frame @ events``
maps lab events (t, x) into the frame, and mapping in two steps is mapping once with the
composed frame. An event on the light cone (x = t) stays exactly on it, however fast the frame.
A custom frame works wherever a preset does, e.g. in ``scene.events_in``.
"""

import numpy as np

import rigidrel_core as rr


def main() -> None:
    a = rr.Frame.from_velocity(0.6)
    b = rr.Frame.from_velocity(0.6)
    ab = b @ a  # b's velocity taken relative to a
    print(f"0.6 (+) 0.6 = {ab.beta:.6f} (15/17 = {15 / 17:.6f})")
    print(f"rapidities add: {a.rapidity:.6f} + {b.rapidity:.6f} = {ab.rapidity:.6f}")

    events = np.array([[1.0, 0.0], [2.0, 1.0]])
    print("(t, x) = (1, 0), (2, 1) seen from a:", (a @ events).round(6).tolist())
    print("seen from b @ a:", (ab @ events).round(6).tolist())
    print("seen from b after a:", (b @ (a @ events)).round(6).tolist())

    for beta in (0.5, 0.99, 1 - 1e-9):
        t, x = rr.Frame.from_velocity(beta) @ np.array([1.0, 1.0])
        print(f"light ray event (1, 1) from beta = {beta}: t' = {t:.6e}, x' = {x:.6e}, t' - x' = {t - x}")

    scene = rr.build_scene("impulsive-start")  # Fig. 1's dashed curve: T_F = (3/4, 5/4)
    rocket = rr.Frame.from_velocity(0.6) @ scene.frame("rod after")  # overtakes the rod at 0.6 c
    t, x = scene.events_in(frame=rocket)["T_F"]
    print(f"a rocket at {rocket.beta:.6f} in the lab sees T_F at t' = {t:.6f}, x' = {x:.6f}")


if __name__ == "__main__":
    main()
