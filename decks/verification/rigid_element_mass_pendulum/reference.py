"""Golden values of rigid_element_mass_pendulum: a rigid body whose mass is that of its elements,
a brick of density 50 (x in [0.2, 1], y in [-0.1, 0.1], z in [-0.05, 0.05]) and a plate of
density 200 and thickness 0.01 (x in [0.8, 1.2], y in [0.2, 0.6], z = 0), turning about the
fixed point O = (0, 0) under gravity g along -y, released at rest. Each part's mass, centre and
inertia about z through its centre are those of a homogeneous box and plate,
m (a^2 + b^2) / 12 for sides a and b in the x-y plane (the plate's thickness adds nothing about
z). With theta the rotation about z, the exact equation of motion (moment of momentum about O) is

  I_O theta'' = -g sum m_i (X_i cos theta - Y_i sin theta),
  I_O = sum (I_i + m_i (X_i^2 + Y_i^2)),

(X_i, Y_i) the parts' centres, integrated by the classical fourth-order Runge-Kutta method with
h = 1e-4 (golden_lib.rigid_swing_rows checks it against h = 2e-4 and the energy integral).
U1, U2, V1, V2 are those of node 33 (X = 1.2, Y = 0.6), UR3 = theta and VR3 = theta' of the reference node,
ALLKE = I_O theta'^2 / 2 and ALLWK = the work of gravity.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

GRAV = 9.81


def part(density, lx, ly, lz, centre):
    """(mass, centre, inertia about z through the centre) of a homogeneous box lx * ly * lz."""
    mass = density * lx * ly * lz
    return mass, centre, mass * (lx * lx + ly * ly) / 12


PARTS = [part(50.0, 0.8, 0.2, 0.1, (0.6, 0.0)),    # the brick (two C3D8R)
         part(200.0, 0.4, 0.4, 0.01, (1.0, 0.4))]  # the plate (one S4R)
I_O = sum(i + m * (x * x + y * y) for m, (x, y), i in PARTS)
TRACKED = (1.2, 0.6)  # node 33
TIMES = [0.25 * i for i in range(1, 9)]


def angular_acceleration(theta):
    return -GRAV * sum(m * (x * math.cos(theta) - y * math.sin(theta))
                       for m, (x, y), _ in PARTS) / I_O


def fallen(theta):
    """sum m_i g (Y_i - y_i(theta)): the work of gravity."""
    return GRAV * sum(m * (y - (x * math.sin(theta) + y * math.cos(theta)))
                      for m, (x, y), _ in PARTS)


names = ["U1@33", "U2@33", "V1@33", "V2@33", "UR3@2", "VR3@2", "ALLKE", "ALLWK"]
rows = g.rigid_swing_rows(angular_acceleration, I_O, fallen, TRACKED, TIMES)

g.write_golden(__file__, [
    "rigid_element_mass_pendulum: rigid body of a C3D8R brick (density 50) and an S4R plate",
    "(density 200, thickness 0.01) about a fixed point, g = 9.81, released at rest; exact",
    f"equation of motion (I_O = {I_O:.15g}) integrated by RK4, h = 1e-4; rows every 0.25",
], names, rows)
