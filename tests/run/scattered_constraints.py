"""Writes a deck whose kinematic constraints tie nodes from all over the model, for the runs of
a distributed model (tests/run/mpi_scattered_constraints.sh, docs/parallel.md "Vectors by
rows"): a square lattice of SPRINGA springs, with crossed AXIAL connectors in each square and a
SPRING1 on u3 at each node, held along its first row and pulled at its last, under NLGEOM.
Nodes drawn at random (seeded) from the whole lattice are tied in threes to rigid bodies (their
reference nodes loaded by moments, one of them held) and to kinematic couplings on the
translations, and in pairs by *EQUATION on u2; every third equation reads the node the one
before ties, a chain of two maps (a chain through a rigid arm is not allowed under NLGEOM). A few tie nodes carry loads of their own. Equal shares of the node equations
then give most constraints nodes of several ranks.

With --dynamic the lattice has masses, the reference nodes rotary inertia, and dashpots; it is
loaded under automatic stabilization (STABILIZE, *STATIC) and then let go in a *DYNAMIC step
(HHT, INITIAL=YES), with the energies among its outputs.

Usage: scattered_constraints.py --size N --bodies B --couplings C --equations E [--dynamic]
                                --out FILE
"""

import argparse
import random


def write(size, bodies, couplings, equations, dynamic, out):
    rng = random.Random(7)
    node = lambda i, j: i * size + j + 1
    lines = ["*HEADING", "Lattice with scattered kinematic constraints (scattered_constraints.py)",
             "*NODE"]
    for i in range(size):
        for j in range(size):
            lines.append(f"{node(i, j)}, {float(j)}, {float(i)}, {0.1 * ((7 * i + 3 * j) % 5)}")
    free = [n for n in range(size + 1, size * size + 1)]  # not the held first row
    rng.shuffle(free)
    groups = [free[3 * k:3 * k + 3] for k in range(bodies + couplings)]
    free = free[3 * (bodies + couplings):]
    reference = size * size + 1
    for k, group in enumerate(groups):
        x = sum((n - 1) % size for n in group) / 3.0
        y = sum((n - 1) // size for n in group) / 3.0
        lines.append(f"{reference + k}, {x}, {y}, 0.5")
    for k, group in enumerate(groups):
        lines += [f"*NSET, NSET=G{k}", ", ".join(map(str, group))]
        if k < bodies:
            lines.append(f"*RIGID BODY, REF NODE={reference + k}, TIE NSET=G{k}")
        else:
            lines += [f"*KINEMATIC COUPLING, REF NODE={reference + k}", f"G{k}, 1, 3"]
    lines.append("*EQUATION")
    for k in range(equations):
        follower = free[k]
        # Every third equation reads the node the equation before ties: a chain of two maps.
        read = free[k - 1] if k % 3 == 2 else free[equations + k]
        lines += ["2", f"{follower}, 2, 1., {read}, 2, -1."]
    lines.append("*ELEMENT, TYPE=SPRINGA, ELSET=S")
    element = 1
    for i in range(size):
        for j in range(size):
            for a, b in ((i, j + 1), (i + 1, j)):
                if a < size and b < size:
                    lines.append(f"{element}, {node(i, j)}, {node(a, b)}")
                    element += 1
    lines += ["*SPRING, ELSET=S", "", "100.", "*ELEMENT, TYPE=CONN3D2, ELSET=C"]
    for i in range(size - 1):
        for j in range(size - 1):
            lines.append(f"{element}, {node(i, j)}, {node(i + 1, j + 1)}")
            lines.append(f"{element + 1}, {node(i, j + 1)}, {node(i + 1, j)}")
            element += 2
    lines += ["*CONNECTOR SECTION, ELSET=C, BEHAVIOR=AX", "AXIAL,",
              "*CONNECTOR BEHAVIOR, NAME=AX", "*CONNECTOR ELASTICITY, COMPONENT=1", "50.",
              "*ELEMENT, TYPE=SPRING1, ELSET=Z"]
    for n in range(1, size * size + 1):
        lines.append(f"{element}, {n}")
        element += 1
    lines += ["*SPRING, ELSET=Z", "3", "10."]
    lines += ["*NSET, NSET=BASE, GENERATE", f"1, {size}, 1",
              "*NSET, NSET=TOP, GENERATE", f"{node(size - 1, 0)}, {node(size - 1, size - 1)}, 1",
              "*NSET, NSET=SAMPLE"]
    sample = list(range(size + 1, size * size + 1, 7))
    lines += [", ".join(map(str, sample[k:k + 16])) for k in range(0, len(sample), 16)]
    lines += [
              "*NSET, NSET=REFS, GENERATE", f"{reference}, {reference + len(groups) - 1}, 1",
              "*NSET, NSET=TIES"]
    lines += [", ".join(map(str, group)) for group in groups[:6]]
    if dynamic:
        # A mass at every lattice node, a rotary inertia at every reference node, dashpots along
        # the squares' first diagonals.
        lines.append("*ELEMENT, TYPE=MASS, ELSET=M")
        for n in range(1, size * size + 1):
            lines.append(f"{element}, {n}")
            element += 1
        lines += ["*MASS, ELSET=M", "0.01", "*ELEMENT, TYPE=ROTARYI, ELSET=J"]
        for k in range(len(groups)):
            lines.append(f"{element}, {reference + k}")
            element += 1
        lines += ["*ROTARY INERTIA, ELSET=J", "0.02, 0.03, 0.04, 0.001, -0.002, 0.0015",
                  "*ELEMENT, TYPE=DASHPOTA, ELSET=D"]
        for i in range(0, size - 1, 2):
            for j in range(size - 1):
                lines.append(f"{element}, {node(i, j)}, {node(i + 1, j + 1)}")
                element += 1
        lines += ["*DASHPOT, ELSET=D", "", "0.5"]
    lines += ["*BOUNDARY", "BASE, 1, 3", f"{reference}, 1, 6"]
    output = ["*OUTPUT, HISTORY", "*NODE OUTPUT, NSET=SAMPLE", "U, RF",
              "*NODE OUTPUT, NSET=REFS", "UR", "*NODE OUTPUT, NSET=TIES", "CF",
              "*NODE OUTPUT, NSET=BASE", "RF", "*ELEMENT OUTPUT, ELSET=C", "CTF1"]
    controls = ["*CONTROLS, PARAMETERS=FIELD", "1e-9, 1e-9"]
    loads = ["*CLOAD", "TOP, 2, 2.", "TOP, 1, 1."]
    loads += [f"{reference + k}, 6, 0.5" for k in range(1, bodies)]
    for group in groups[1:6]:
        loads += [f"{group[0]}, 3, 0.7", f"{group[1]}, 1, -0.4"]
    if not dynamic:
        lines += ["*STEP, NLGEOM, INC=100", "*STATIC, DIRECT", "0.25, 1."] + controls + loads
        lines += output + ["*END STEP"]
    else:
        # Loaded under automatic stabilization, then let go: the loads on the top row drop to
        # half at once and the lattice vibrates, its dashpots and connectors dissipating.
        energies = ["*ENERGY OUTPUT", "ALLKE, ALLIE, ALLVD, ALLSD, ALLWK, ETOTAL"]
        lines += ["*STEP, NLGEOM, INC=100", "*STATIC, STABILIZE=0.0002, DIRECT", "0.25, 1."]
        lines += controls + loads + output
        lines += ["*ENERGY OUTPUT", "ALLIE, ALLVD, ALLSD, ALLWK, ETOTAL", "*END STEP"]
        lines += ["*STEP, NLGEOM, INC=100", "*DYNAMIC, DIRECT, ALPHA=-0.05, INITIAL=YES",
                  "0.02, 0.1"] + controls
        lines += ["*CLOAD, OP=NEW", "TOP, 2, 1.", "TOP, 1, 0.5"]
        lines += output + ["*NODE OUTPUT, NSET=SAMPLE", "V, A"] + energies + ["*END STEP"]
    with open(out, "w", encoding="ascii") as f:
        f.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, required=True)
    parser.add_argument("--bodies", type=int, required=True)
    parser.add_argument("--couplings", type=int, required=True)
    parser.add_argument("--equations", type=int, required=True)
    parser.add_argument("--dynamic", action="store_true")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    write(args.size, args.bodies, args.couplings, args.equations, args.dynamic, args.out)


if __name__ == "__main__":
    main()
