"""Writes the friction lattice of scripts/bench_friction.sh: an n x n grid of sliders on a floor.

Every grid node b (free in translation) sits on its own ground node a (held, ENCASTRE) through a
floor connector (CONN3D2, orientation GLOBAL at a; component 1, global x, is the normal, 2 and 3
slide):
- --type cartesian (default): CARTESIAN with linear elasticity --floor in component 1 (a stiff
  normal spring, no multiplier) and, with --friction, *CONNECTOR FRICTION, CONTACT FORCE=1 with
  the circular potential on components 2 and 3 (F_N = |f1|, the elastic normal force);
- --type slide-plane: SLIDE-PLANE (the normal is a constraint with a Lagrange multiplier) with,
  with --friction, predefined friction.
Neighbouring sliders are joined by CARTESIAN connectors with linear elasticity in components 2 and
3 (stiffness --spring), so the tangent is a real sparse system (a 5-point grid stencil in y and z
coupled to x through the friction), not block diagonal. Step 1 presses every slider on the floor
with a *CLOAD of -F_N in x. Step 2 holds the row z = 0 and moves the row z = (n - 1) h by
(delta, delta / 2) in (y, z), in automatic increments (initial and largest --increment). With
friction the sliders near the moved row slip and the slip front moves into the grid; delta is
chosen so that the front reaches about --front rows (default n / 2):
delta = mu F_N front^2 / (2 k_spring) (a chain in which each slider holds mu F_N). Without
friction the deck is linear.

Each slider has its own ground node; with --shared-ground one held ground node (node 1) carries
every floor connector, whose DOFs stay in the pattern as a dense row and column (the case of
docs/benchmarks.md "Connector friction" that direct LU handled worst).

Solvers clinch picks (the .log's "step 2:" line): CARTESIAN with friction, UMFPACK on the full
pattern (the friction tangent is unsymmetric: the capacity follows f1); without friction, CHOLMOD
on the upper triangle. SLIDE-PLANE without friction: UMFPACK on the upper triangle (symmetric,
but the multipliers make it indefinite).

Usage: generate_friction_lattice.py --n N [--friction] [--type cartesian|slide-plane]
                                    --out FILE.inp [--mu 0.3] [--normal 10] [--spring 1000]
                                    [--floor 1e6] [--stick 1e5] [--increment 0.25]
                                    [--front ROWS | --delta D]
Connectors: n^2 floor connectors (with friction: n^2 friction connectors) + 2 n (n - 1) springs;
3 n^2 - 2 n free DOFs (clinch counts every DOF of the nodes as an equation), plus n^2
multipliers for SLIDE-PLANE.
"""

import argparse


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--n", type=int, required=True, help="sliders per grid side")
    p.add_argument("--friction", action="store_true")
    p.add_argument("--shared-ground", action="store_true",
                   help="one ground node for every floor connector")
    p.add_argument("--out", required=True)
    p.add_argument("--mu", type=float, default=0.3)
    p.add_argument("--normal", type=float, default=10.0, help="normal load F_N per slider")
    p.add_argument("--spring", type=float, default=1000.0)
    p.add_argument("--stick", type=float, default=1.0e5)
    p.add_argument("--type", choices=["cartesian", "slide-plane"], default="cartesian")
    p.add_argument("--floor", type=float, default=1.0e6,
                   help="normal stiffness of the CARTESIAN floor connector")
    p.add_argument("--increment", type=float, default=0.25)
    p.add_argument("--front", type=float,
                   help="rows the slip front should reach (default n / 2)")
    p.add_argument("--delta", type=float, help="displacement of the moved row in y")
    a = p.parse_args()
    n = a.n
    rows = a.front if a.front is not None else n / 2
    delta = a.delta if a.delta is not None else a.mu * a.normal * rows ** 2 / (2 * a.spring)

    def slider(i, j):  # free node b
        return 2 * (i * n + j) + 2

    def ground(i, j):
        return 1 if a.shared_ground else 2 * (i * n + j) + 1

    out = open(a.out, "w")
    w = out.write
    w("*HEADING\n")
    w(f"{n}x{n} sliders on a floor ({a.type}), {'with' if a.friction else 'without'} friction "
      "(decks/bench/generate_friction_lattice.py)\n*NODE, NSET=ALL\n")
    for i in range(n):  # i: z index, j: y index
        for j in range(n):
            y, z = float(j), float(i)
            if ground(i, j) == 2 * (i * n + j) + 1:
                w(f"{ground(i, j)}, 0., {y}, {z}\n")
            w(f"{slider(i, j)}, 0., {y}, {z}\n")
    w("*NSET, NSET=GROUND, GENERATE\n")
    w(f"1, {1 if a.shared_ground else 2 * n * n - 1}, 2\n")
    w("*NSET, NSET=BOTTOM, GENERATE\n")
    w(f"{slider(0, 0)}, {slider(0, n - 1)}, 2\n")
    w("*NSET, NSET=TOP, GENERATE\n")
    w(f"{slider(n - 1, 0)}, {slider(n - 1, n - 1)}, 2\n")
    w("*NSET, NSET=SLIDERS, GENERATE\n")
    w(f"2, {2 * n * n}, 2\n")
    w("*ELEMENT, TYPE=CONN3D2, ELSET=FLOOR\n")
    for i in range(n):
        for j in range(n):
            w(f"{i * n + j + 1}, {ground(i, j)}, {slider(i, j)}\n")
    w("*ELEMENT, TYPE=CONN3D2, ELSET=SPRINGS\n")
    label = n * n
    for i in range(n):
        for j in range(n):
            if j + 1 < n:
                label += 1
                w(f"{label}, {slider(i, j)}, {slider(i, j + 1)}\n")
            if i + 1 < n:
                label += 1
                w(f"{label}, {slider(i, j)}, {slider(i + 1, j)}\n")
    w("*ORIENTATION, NAME=GLOBAL\n1., 0., 0., 0., 1., 0.\n")
    if a.type == "slide-plane":
        w("*CONNECTOR SECTION, ELSET=FLOOR, BEHAVIOR=FLOOR\nSLIDE-PLANE,\nGLOBAL\n")
        w("*CONNECTOR BEHAVIOR, NAME=FLOOR\n")
        if a.friction:
            w(f"*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS={a.stick:g}\n"
              f"*FRICTION\n{a.mu:g}\n")
    else:
        w("*CONNECTOR SECTION, ELSET=FLOOR, BEHAVIOR=FLOOR\nCARTESIAN,\nGLOBAL\n")
        w(f"*CONNECTOR BEHAVIOR, NAME=FLOOR\n*CONNECTOR ELASTICITY, COMPONENT=1\n"
          f"{a.floor:g}\n")
        if a.friction:
            w(f"*CONNECTOR FRICTION, CONTACT FORCE=1, STICK STIFFNESS={a.stick:g}\n"
              f"*CONNECTOR POTENTIAL\n2\n3\n*FRICTION\n{a.mu:g}\n")
    w("*CONNECTOR SECTION, ELSET=SPRINGS, BEHAVIOR=SPRING\nCARTESIAN,\n")
    w("*CONNECTOR BEHAVIOR, NAME=SPRING\n")
    for comp in (2, 3):
        w(f"*CONNECTOR ELASTICITY, COMPONENT={comp}\n{a.spring:g}\n")
    # The CARTESIAN springs make the sliders' rotations active; nothing restrains them.
    w("*BOUNDARY\nGROUND, ENCASTRE\nBOTTOM, 2, 3\nSLIDERS, 4, 6\n")
    w("*STEP, NAME=PRESS\n*STATIC\n1.0, 1.0\n")
    w(f"*CLOAD\nSLIDERS, 1, {-a.normal:g}\n")
    w("*OUTPUT, HISTORY\n*NODE OUTPUT, NSET=TOP\nU2\n*END STEP\n")
    w("*STEP, NAME=SHEAR, INC=10000\n*STATIC\n"
      f"{a.increment:g}, 1.0, 1e-6, {a.increment:g}\n")
    w(f"*BOUNDARY\nTOP, 2, 2, {delta:.10g}\nTOP, 3, 3, {delta / 2:.10g}\n*END STEP\n")
    out.close()


if __name__ == "__main__":
    main()
