"""Shared helpers of the reference.py scripts of tests/cae_corpus (python3, standard library only).

It puts decks/verification on the path so that each script can use golden_lib (vector algebra,
orientation triads, exact angle functions and the golden.csv writer), and adds the few helpers
that the corpus closed forms share.
"""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "decks", "verification"))
import golden_lib as g  # noqa: E402,F401


def ramp_rows(step, t_start, increments, period=1.0):
    """(step, increment, step_time, total_time, tau) of a fixed-increment step."""
    out = []
    for i in range(1, increments + 1):
        st = period * i / increments
        out.append((step, i, st, t_start + st, st / period))
    return out


def local_components(frame, v):
    """Components of the global vector v in the triad frame = (e1, e2, e3)."""
    return [g.dot(e, v) for e in frame]


def coincident_response(frame, force, moment, stiff):
    """Connector with coincident nodes (or node a fixed and only frame-a rows at b), node a fixed,
    force and moment on node b, NLGEOM=NO, aligned frames at zero relative rotation: the
    generalised force of component i is f_i = e_i.F (i = 1..3) and f_{3+k} = e_k.M. An available
    component with stiffness k moves by f/k; a constrained one carries f as CRF. Returns
    (f[6], c[6], u_b, ur_b), components indexed 0..5."""
    f = local_components(frame, force) + local_components(frame, moment)
    c = [f[i] / stiff[i] if stiff.get(i) else 0.0 for i in range(6)] if isinstance(stiff, dict) \
        else None
    u = [0.0, 0.0, 0.0]
    ur = [0.0, 0.0, 0.0]
    for i in range(3):
        u = g.add(u, g.scale(c[i], frame[i]))
        ur = g.add(ur, g.scale(c[3 + i], frame[i]))
    return f, c, u, ur


# The displacement-driven AXIAL pull (connector 1 from Point-1.1, held, to Point-2.1, whose u1 is
# prescribed): its history columns and, for each state (step, increment, step_time, total_time,
# u1 of Point-2.1), the closed form CU1 = u, CP1 = l0 + u, CTF1 = CEF1 = k u, RF1 = ∓k u.
AXIAL_PULL_COLUMNS = ["CP1@1", "CTF1@1", "CU1@1", "CEF1@1", "RF1@Point-1.1", "RF1@Point-2.1",
                      "U1@Point-1.1", "U1@Point-2.1"]


def axial_pull_rows(k, l0, states):
    return [(step, inc, st, tt, [l0 + u, k * u, u, k * u, -k * u, k * u, 0.0, u])
            for step, inc, st, tt, u in states]
