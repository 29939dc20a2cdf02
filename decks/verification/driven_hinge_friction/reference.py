"""Golden values of driven_hinge_friction, written with Abaqus's names for the rotational
components (CTM1, CUR1, CEM1, CRM1, CSM1, CNM1: output-variables.md §1.1), so that `clinch
compare` is checked on a golden in Abaqus's naming against a run in clinch's (CTF4, CU4, ...).

HINGE, component 4 (rotation about local axis 1) driven by *Connector Motion: 0 -> 0.5 rad in
step Open, 0.5 -> -0.5 in Close, -0.5 -> 0.5 in Reopen, each over step time 1 in 10 DIRECT
increments (ramps, keywords.md §13). Elasticity CEM1 = 100 CUR1. Uncoupled friction on
component 4 (friction.md §2.1 form 2): no CONTACT FORCE, internal contact force 50, so F_N = 50
and mu F_N = 10; stick stiffness K = 1e5. Backward-Euler Coulomb update per increment (friction.md
§3): trial f = K (u - u_s); stick if |f| <= 10, else f = 10 sgn(f), slip dgamma = (|f| - 10)/K.
The motion is prescribed, so the connector carries no net moment: CTM1 = 0 and the reaction of
the motion is CRM1 = -(CEM1 + CSM1) (CTF = CEF + CVF + CSF + CRF, output-variables.md §2).
Constrained components 1-3, 5, 6 carry nothing (no load): CTF1 = CU2 = 0 are listed as samples.
"""
import os
import sys

sys.dont_write_bytecode = True

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402

K_ELASTIC, K_STICK, LIMIT = 100.0, 1.0e5, 0.2 * 50.0
steps = [(1, 0.5), (2, -0.5), (3, 0.5)]  # (step, target rotation)
names = ["CTM1@1", "CUR1@1", "CEM1@1", "CSM1@1", "CRM1@1", "CNM1@1", "CASU4@1", "CTF1@1",
         "CU2@1"]

u, u_slip, gamma, t0 = 0.0, 0.0, 0.0, 0.0
rows = []
margin = float("inf")  # the smallest distance of a trial from the slip limit, relative
for step, target in steps:
    start = u
    for inc, t in enumerate(fl.increments(0.1, 1.0), start=1):
        u = fl.ramp(start, target, t, 1.0)
        trial = K_STICK * (u - u_slip)
        margin = min(margin, abs(abs(trial) - LIMIT) / LIMIT)
        if abs(trial) <= LIMIT:
            friction = trial
        else:
            friction = LIMIT if trial > 0 else -LIMIT
            slip = (abs(trial) - LIMIT) / K_STICK
            u_slip += slip if trial > 0 else -slip
            gamma += slip
        elastic = K_ELASTIC * u
        rows.append((step, inc, t, t0 + t, [0.0, u, elastic, friction, -(elastic + friction),
                                            50.0, gamma, 0.0, 0.0]))
    t0 += 1.0
# Every increment slips by a wide margin: no stick/slip decision sits near the limit.
assert margin > 100.0, margin
# The friction loop: at the ends of Open and Reopen the actuator applies 100 * 0.5 + 10 = 60; at
# the end of Close, -60.
assert abs(rows[9][4][4] + 60.0) < 1e-12 and abs(rows[19][4][4] - 60.0) < 1e-12
assert abs(rows[29][4][4] + 60.0) < 1e-12

g.write_golden(__file__, [
    "driven_hinge_friction: HINGE driven by *Connector Motion (0 -> 0.5 -> -0.5 -> 0.5 rad),",
    "CEM1 = 100 CUR1, Coulomb friction on component 4 with F_N = 50, mu = 0.2, K = 1e5;",
    "CTM1 = 0, CRM1 = -(CEM1 + CSM1). Abaqus labels (CTM1 = CTF4, CUR1 = CU4, ...).",
], names, rows)
