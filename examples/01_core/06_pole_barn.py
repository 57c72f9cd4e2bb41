"""The pole in the barn: the door closes on the Born-rigid pole; the signal-limited one is caught.

A pole of rest length 1 moves at V = 0.8 into a barn 0.6 long with its back wall at x = 0 (c = 1).
In the barn frame the moving pole is 0.6 long and "just fits", and the door closes at t = 0, when
the rear end of an unstopped pole would pass it. But a wall stop cannot be instantaneous along the
pole. The Born-rigid stop (Franklin 2012, Sec. 5: the wall crash, epsilon = 0) begins at the rear
before the contact and leaves the pole at rest with length 1: its rear end comes to rest at x = 1,
so the door closes on the pole, in every frame. A signal-limited stop (a stop front moving in from
the contact at the speed of light) leaves each point moving at -V until the front reaches it: the
rear end passes the door as it closes, and the pole ends compressed by sqrt((1 - V)/(1 + V)) = 1/3,
its rear end at rest at x = 1/3, inside."""

import rigidrel_core as rr


def main() -> None:
    scene = rr.pole_barn(0.8, 1.0, 0.6, model="both")
    for rod, verdict in enumerate(scene.verdicts()):
        print(f"{scene.rods[rod].name}: rear end at rest at x = {scene.rear_rest_x(rod):.6f}")
        print(f"  {verdict.text}")


if __name__ == "__main__":
    main()
