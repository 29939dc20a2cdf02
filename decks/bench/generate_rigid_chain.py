"""Writes a `clinch run` deck of a chain of N rigid bodies joined by connectors, or of the same
chain with each body replaced by one node (--nodes-only), for the scale case of rigid bodies
(docs/benchmarks.md "Rigid-body chain").

Body i has its reference node at (i, 0, 0) and two tie nodes at (i - 0.25, 0, 0) and
(i + 0.25, 0, 0) (*RIGID BODY, TIE NSET). A BUSHING with elasticity on all six components
joins the second tie node of body i to the first tie node of body i + 1. Without the bodies, the
BUSHING joins reference node i to reference node i + 1 directly: the same chain, its links
twice as long. The first reference node is held (ENCASTRE); the last is pulled along the chain,
twisted, under NLGEOM: the twist grows along the chain to a quarter turn at the tip (the moment
is scaled with N), so every connector carries a load and every body turns through a finite
rotation. (Bending a chain twisted this far buckles it sideways: a benchmark of the elimination's
cost keeps to a load path that both variants follow in a few iterations.)

Usage: generate_rigid_chain.py --bodies N [--nodes-only] --out FILE
"""

import argparse


def write_chain(bodies, nodes_only, out):
    lines = ["*HEADING",
             f"Chain of {bodies} {'nodes' if nodes_only else 'rigid bodies'} joined by BUSHING "
             "connectors (generate_rigid_chain.py)", "*NODE"]
    for i in range(bodies):
        lines.append(f"{3 * i + 1}, {i}., 0., 0.")
        if not nodes_only:
            lines.append(f"{3 * i + 2}, {i - 0.25}, 0., 0.")
            lines.append(f"{3 * i + 3}, {i + 0.25}, 0., 0.")
    if not nodes_only:
        for i in range(bodies):
            lines += [f"*NSET, NSET=B{i}", f"{3 * i + 2}, {3 * i + 3}",
                      f"*RIGID BODY, REF NODE={3 * i + 1}, TIE NSET=B{i}"]
    lines.append("*ELEMENT, TYPE=CONN3D2, ELSET=JOINTS")
    for i in range(bodies - 1):
        a, b = (3 * i + 1, 3 * i + 4) if nodes_only else (3 * i + 3, 3 * i + 5)
        lines.append(f"{i + 1}, {a}, {b}")
    lines += ["*ORIENTATION, NAME=GLOBAL", "1., 0., 0., 0., 1., 0.",
              "*CONNECTOR SECTION, ELSET=JOINTS, BEHAVIOR=JOINT", "BUSHING,", "GLOBAL",
              "*CONNECTOR BEHAVIOR, NAME=JOINT",
              "*CONNECTOR ELASTICITY, COMPONENT=1", "1.e5",
              "*CONNECTOR ELASTICITY, COMPONENT=2", "1.e5",
              "*CONNECTOR ELASTICITY, COMPONENT=3", "1.e5",
              "*CONNECTOR ELASTICITY, COMPONENT=4", "2.e4",
              "*CONNECTOR ELASTICITY, COMPONENT=5", "2.e4",
              "*CONNECTOR ELASTICITY, COMPONENT=6", "2.e4",
              "*NSET, NSET=TIP", f"{3 * (bodies - 1) + 1}",
              "*BOUNDARY", "1, ENCASTRE",
              "*STEP, NLGEOM=YES, INC=1000", "*STATIC", "0.25, 1.",
              # Newton to 1e-8 of the forces: runs that solve differently (ranks, backends)
              # meet at the same converged state.
              "*CONTROLS, PARAMETERS=FIELD", "1.e-8, 1.e-8",
              "*CLOAD", "TIP, 1, 1000.",
              f"TIP, 4, {2.e4 * 1.5707963267948966 / (bodies - 1)!r}",
              "*OUTPUT, HISTORY", "*NODE OUTPUT, NSET=TIP", "U", "*END STEP"]
    out.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bodies", type=int, default=10000)
    parser.add_argument("--nodes-only", action="store_true")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    with open(args.out, "w", encoding="utf-8") as out:
        write_chain(args.bodies, args.nodes_only, out)


if __name__ == "__main__":
    main()
