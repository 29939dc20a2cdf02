"""Golden values of cae_rigid_door_hinge: the rigid door turns about the hinge axis (global z
through the hinge node at the origin) by theta = M_z/k, M_z the moment of the loads about that
axis; every point follows u = theta e_z x X (small displacements); the frame node reacts to
all the loads (docs/constraints.md, rigid bodies)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K = 1000.0
RP = [0.5, 0.05, 1.0]
CORNER = [0.0, 0.1, 2.0]
FORCE = [20.0, 0.0, 0.0]
MOMENT = [0.0, 0.0, 50.0]

# Moment of the loads about the origin; the hinge lets only its z part turn the door.
total = g.add(MOMENT, g.cross(RP, FORCE))
theta = total[2] / K
turn = [0.0, 0.0, theta]
names = [f"U{i}@1" for i in (1, 2, 3)] + [f"UR{i}@1" for i in (1, 2, 3)]
names += [f"U{i}@Door-1.12" for i in (1, 2, 3)]
names += [f"RF{i}@2" for i in (1, 2, 3)] + [f"RM{i}@2" for i in (1, 2, 3)]
names += ["CU4@1", "CEF4@1"]
values = g.cross(turn, RP) + turn + g.cross(turn, CORNER)
values += g.scale(-1.0, FORCE) + g.scale(-1.0, total) + [theta, K * theta]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names)), (1, 1, 1.0, 1.0, values)]
g.write_golden(__file__, [
    "cae_rigid_door_hinge: theta = M_z / k with M = (0, 0, 50) + X_RP x (20, 0, 0), k = 1000;",
    "u = theta e_z x X at the reference point and the door's corner node; the frame node's",
    "reaction balances the loads: RF = -F, RM = -(M + X_RP x F)",
], names, rows)
