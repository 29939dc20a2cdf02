"""Golden values of rigid_compound_pendulum: a rigid body of point masses m_i at body points
(X_i, Y_i) turning about the fixed point O = (0, 0) under gravity g along -y, released at rest.
With theta its rotation about z, the masses are at R(theta) X_i and the exact equation of motion
(the moment of momentum about O) is

  I_O theta'' = -g sum m_i (X_i cos theta - Y_i sin theta),   I_O = sum m_i (X_i^2 + Y_i^2),

integrated here by the classical fourth-order Runge-Kutta method with h = 1e-4 (its error, checked
by golden_lib.rigid_swing_rows against h = 2e-4, is below 1e-10). U1, U2, V1, V2 are those of node 4 (X = 1, Y = 0.2),
UR3 = theta and VR3 = theta' of the reference node, ALLKE = I_O theta'^2 / 2 and ALLWK = the work
of gravity, g sum m_i (the height each mass has fallen).
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

GRAV = 9.81
MASSES = [((0.5, 0.0), 1.0), ((1.0, 0.2), 2.0)]
I_O = sum(m * (x * x + y * y) for (x, y), m in MASSES)
TRACKED = (1.0, 0.2)  # node 4
TIMES = [0.25 * i for i in range(1, 9)]


def angular_acceleration(theta):
    return -GRAV * sum(m * (x * math.cos(theta) - y * math.sin(theta))
                       for (x, y), m in MASSES) / I_O


def fallen(theta):
    """sum m_i g (Y_i - y_i(theta)): the work of gravity."""
    return GRAV * sum(m * (y - (x * math.sin(theta) + y * math.cos(theta)))
                      for (x, y), m in MASSES)


names = ["U1@4", "U2@4", "V1@4", "V2@4", "UR3@2", "VR3@2", "ALLKE", "ALLWK"]
rows = g.rigid_swing_rows(angular_acceleration, I_O, fallen, TRACKED, TIMES)

g.write_golden(__file__, [
    "rigid_compound_pendulum: rigid body of point masses 1 at (0.5, 0) and 2 at (1, 0.2) about",
    "a fixed point, g = 9.81, released at rest; exact equation of motion integrated by RK4,",
    "h = 1e-4; rows every 0.25",
], names, rows)
