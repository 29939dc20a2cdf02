"""Golden values of rigid_body_held_at_tie_node: the lever of rigid_lever_nlgeom, pinned at a tie
node instead of its reference node. The pivot, not the reference node, is where the body turns
about, so the equilibrium is the same scalar equation, and every node moves by (R - I)(X - X_pivot)
(docs/constraints.md "Conditions on a body's nodes")."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
import golden_lib as g  # noqa: E402

lever = g.case_reference("rigid_lever_nlgeom")


def nodes_at(theta, reaction):
    """Node 1 is the pivot (a tie node held in DOFs 1-5), node 3 the reference node (its
    translations follow the pivot; DOFs 4 and 5 held there, moved from the pivot)."""
    return {
        1: ([0.0] * 3, [0.0, 0.0, theta], reaction),
        2: (lever.turned([lever.L, 0.0, 0.0], theta), [0.0, 0.0, theta], [0.0] * 3),
        3: (lever.turned(lever.X3, theta), [0.0, 0.0, theta], [0.0] * 3),
        4: ([0.0] * 3, None, g.scale(-1.0, reaction)),
    }


names, rows = lever.golden(nodes_at)
g.write_golden(__file__, [
    "rigid_body_held_at_tie_node: the rigid_lever_nlgeom lever pinned at tie node 1 (the origin),",
    "reference node 3 at (0.75, 0.25) loaded by M = 1200 t about z; theta from the same equation;",
    "U = (R - I)(X - X_pivot) for every node; RF@1 = F d/l is the pivot's reaction",
], names, rows)
