"""Golden values of rigid_lever_nlgeom: a rigid lever turned by a moment under NLGEOM, solved
from its scalar equilibrium equation by bisection (docs/constraints.md, rigid bodies)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K, L, H, M = 1000.0, 1.5, 1.0, 1200.0
X3 = [0.75, 0.25, 0.0]
TIMES = [0.0, 0.25, 0.5, 0.75, 1.0]


def connector(theta):
    """Node 2 at L(cos, sin), node 4 at (L, -H): the AXIAL length l, force F = k (l - H) and the
    moment it puts on the body about z (the force on node 2 is -F d/l, d = x2 - x4)."""
    x2 = [L * math.cos(theta), L * math.sin(theta), 0.0]
    d = g.sub(x2, [L, -H, 0.0])
    length = g.norm(d)
    force = K * (length - H)
    moment = g.cross(x2, g.scale(-force / length, d))[2]
    return x2, d, length, force, moment


def turn(applied):
    """theta with applied + moment(theta) = 0, by bisection on [0, pi/2] (the connector's
    moment falls monotonically there for these numbers; 200 halvings reach round-off)."""
    lo, hi = 0.0, math.pi / 2
    assert applied + connector(hi)[4] < 0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if applied + connector(mid)[4] > 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def golden(nodes_at):
    """Column names and rows over TIMES; nodes_at(theta, reaction) gives each node's
    (U, UR or None, RF) at the lever's angle, `reaction` = F d/l being what the pivot holds."""
    names = ["CU1@1", "CTF1@1"]
    names += [f"{v}{i}@{n}" for n in (1, 2, 3, 4) for v in ("U", "UR", "RF") for i in (1, 2, 3)
              if not (v == "UR" and n in (4,))]
    rows = []
    for inc, t in enumerate(TIMES):
        theta = turn(M * t) if t > 0 else 0.0
        _, d, length, force, _ = connector(theta)
        by_node = nodes_at(theta, g.scale(force / length, d))
        values = [length - H, force]
        for n in (1, 2, 3, 4):
            u, ur, rf = by_node[n]
            values += u
            if ur is not None:
                values += ur
            values += rf
        rows.append((1, inc, t, t, values))
    return names, rows


def turned(x, theta):
    """(R - I) x for the rotation by theta about z."""
    c, s = math.cos(theta), math.sin(theta)
    return [c * x[0] - s * x[1] - x[0], s * x[0] + c * x[1] - x[1], 0.0]


def main():
    def nodes_at(theta, reaction):
        return {
            1: ([0.0] * 3, [0.0, 0.0, theta], reaction),
            2: (turned([L, 0.0, 0.0], theta), [0.0, 0.0, theta], [0.0] * 3),
            3: (turned(X3, theta), [0.0, 0.0, theta], [0.0] * 3),
            4: ([0.0] * 3, None, g.scale(-1.0, reaction)),
        }

    names, rows = golden(nodes_at)
    g.write_golden(__file__, [
        "rigid_lever_nlgeom: lever of arm L = 1.5 turning about z by theta, AXIAL k = 1000 from tie",
        "node 2 to node 4 at (L, -1); M = 1200 t = F L (H cos theta + L sin theta)/l with F = k (l - 1),",
        "l = |x2 - x4|, solved by bisection; U of tie nodes = (R - I)(X - X_ref); RF@1 = F d/l",
    ], names, rows)


if __name__ == "__main__":
    main()
