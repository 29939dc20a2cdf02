"""Golden values of rotational_types: every rotational basic type loaded about each available
component, small rotations, NLGEOM=NO (connection-types.md §2.3, §3.3, §3.4)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

I3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
C30 = 0.8660254037844387
ORI30 = g.orientation([C30, 0.5, 0.0], [-0.5, C30, 0.0])
RX90 = g.orientation([1.0, 0.0, 0.0], [0.0, 0.0, 1.0])        # ORIB90 of the deck
RX30 = g.orientation([1.0, 0.0, 0.0], [0.0, C30, 0.5])         # ORIBX30 of the deck
K = [100.0, 200.0, 400.0]                                      # components 4, 5, 6
M = 2.0                                                        # moment magnitude
T15 = math.tan(math.radians(15.0))

# Analytic small-rotation rows b_k (dc_k = b_k . omega, omega = theta_b - theta_a, global):
# CARDAN/ROTATION/PROJECTION F-T with aligned relative frames: b_k = e_k^a (§3.4).
# EULER, a global, b = Rx(90 deg): alpha = acos... gives g1 = e3a, g2 = e1a, g3 = e3b = -e2,
#   J = -sin(beta0) = -1, dual rows g^1 = e3, g^2 = e1, g^3 = -e2 (§2.3, §3.3).
# FLEXION-TORSION, a global, b = Rx(30 deg): flexion d(alpha) = omega_1; torsion
#   d(beta) = omega_3 - tan(15 deg) omega_2; sweep d(theta) = cot(30 deg) omega_2 + omega_3.
TYPES = {
    "CARDAN": (ORI30, ORI30, [ORI30[0], ORI30[1], ORI30[2]], g.cardan),
    "ROTATION": (I3, I3, [I3[0], I3[1], I3[2]], g.rotation_vector),
    "EULER": (I3, RX90, [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0]], g.euler313),
    "FLEXION-TORSION": (I3, RX30, [[1.0, 0.0, 0.0], [0.0, -T15, 1.0],
                                   [0.0, 1.0 / math.tan(math.radians(30.0)), 1.0]],
                        g.flexion_torsion),
    "PROJECTION FLEXION-TORSION": (I3, I3, [I3[0], I3[1], I3[2]],
                                   g.projection_flexion_torsion),
}
# Independent route: the rows from central finite differences of the exact angle formulas.
for name, (ea, eb, rows_, fn) in TYPES.items():
    fd = g.angle_rows(fn, ea, eb)
    for r_an, r_fd in zip(rows_, fd):
        g.assert_close(r_an, r_fd, 1e-7, f"{name} rows")

# element -> (type, loaded component k in 1..3 of the rotational block, or a full moment)
ELEMENTS = {}
label = 1
for name in ("CARDAN", "ROTATION", "EULER", "FLEXION-TORSION", "PROJECTION FLEXION-TORSION"):
    for k in (1, 2, 3):
        ELEMENTS[label] = (name, k)
        label += 1


def free_element(name, k):
    """Moment M = m b_k at node b: equilibrium sum_j m_j b_j = M gives m_k = m, the other
    components 0 (the rows are independent). c_k = m / K_k; omega = (m / K_k) b_k^dual."""
    rows_ = TYPES[name][2]
    load = g.scale(M, rows_[k - 1])
    ctf = [0.0, 0.0, 0.0]
    ctf[k - 1] = M
    cu = [f / kk for f, kk in zip(ctf, K)]
    omega = g.solve3(rows_, cu)
    return load, ctf, cu, omega


names = []
final = []
for el, (name, k) in ELEMENTS.items():
    load, ctf, cu, omega = free_element(name, k)
    names += [f"CTF{i}@{el}" for i in (4, 5, 6)] + [f"CU{i}@{el}" for i in (4, 5, 6)]
    names += [f"UR{i}@{2 * el}" for i in (1, 2, 3)] + [f"RM{i}@{2 * el - 1}" for i in (1, 2, 3)]
    final += ctf + cu + omega + g.scale(-1.0, load)  # node a: theta_a rows are -b_k
# REVOLUTE (16): available 4, constrained 5, 6; aligned frames; M = (10, 20, 30).
# UNIVERSAL (17): available 4, 6, constrained 5; M = (10, 20, 0). (18): M = (0, 0, 30).
for el, mom, avail in ((16, [10.0, 20.0, 30.0], (4,)), (17, [10.0, 20.0, 0.0], (4, 6)),
                       (18, [0.0, 0.0, 30.0], (4, 6))):
    ctf = mom[:]
    cu = [mom[i - 4] / K[i - 4] if i in avail else 0.0 for i in (4, 5, 6)]
    crf = [0.0 if i in avail else mom[i - 4] for i in (4, 5, 6)]
    names += [f"CTF{i}@{el}" for i in (4, 5, 6)] + [f"CU{i}@{el}" for i in (4, 5, 6)]
    names += [f"CRF{i}@{el}" for i in (4, 5, 6)]
    names += [f"UR{i}@{2 * el}" for i in (1, 2, 3)] + [f"RM{i}@{2 * el - 1}" for i in (1, 2, 3)]
    final += ctf + cu + crf + cu + g.scale(-1.0, mom)
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names)), (1, 1, 1.0, 1.0, final)]
g.write_golden(__file__, [
    "rotational_types: CARDAN, ROTATION, EULER (non-aligned frames), FLEXION-TORSION (initial",
    "flexion 30 deg), PROJECTION FLEXION-TORSION, REVOLUTE, UNIVERSAL; NLGEOM=NO, node a fixed,",
    "moment M = 2 b_k at node b with b_k the small-rotation row of component k: CTF = 2 on k,",
    "CU = 2/K_k, UR_b = B^-1 CU, RM_a = -M. Rows: dual basis of connection-types.md §3.3, each",
    "confirmed against central finite differences of the exact angles of §2.3 (to 1e-7).",
    "REVOLUTE/UNIVERSAL: aligned frames, constrained components carry CTF = CRF = applied moment",
], names, rows)
