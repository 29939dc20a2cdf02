"""The spring-mass lattice of scripts/bench_dynamic_lattice.sh (docs/benchmarks.md "Implicit
dynamics on a spring-mass lattice") and its exact motion.

  generate_dynamic_lattice.py deck N DT PERIOD FILE.inp [nlgeom]   write the deck (N x N masses)
  generate_dynamic_lattice.py error N ROWS       max |u - u_exact| / amplitude over the probes

Model: N x N masses m = 1 on a square grid of spacing h = 1 inside a ring of held nodes, joined
to their horizontal and vertical neighbours by SPRINGA springs of stiffness k; DOF 3 held. Every
mass starts at rest position with the velocity field

  v1 = v2 = V s(i) s(j),   s(i) = sin(pi i / (N + 1)),  i, j = 1..N.

To first order in the displacement a horizontal spring carries only the x motion and a vertical
one only the y motion, so each row (for x) and each column (for y) is a fixed-fixed chain of N
masses whose lowest mode is s; every mass then moves exactly as

  u1 = u2 = (V / w) sin(w t) s(i) s(j),   w^2 = (4 k / m) sin^2(pi / (2 (N + 1))),

the motion of the space-discrete model, with no time-discretisation error. k is chosen so that
w = 2 pi (period 1). The amplitude is 1e-5 h: with `nlgeom` (the step under NLGEOM) the geometric
terms then change the motion by about 1e-5 of its amplitude, far below the time-discretisation
error measured. The corners of the ring, which no spring reaches, are left out.
"""
import math
import sys

V_AMPLITUDE = 1e-5  # displacement amplitude in units of h
OMEGA = 2.0 * math.pi
PROBES = [(1, 1), (None, None), (1, None)]  # corner, centre, edge middle (None: the middle)


def stiffness(n):
    return OMEGA ** 2 / (4.0 * math.sin(math.pi / (2.0 * (n + 1))) ** 2)


def label(n, i, j):
    """Node (i, j), 0..N+1 each, ring included."""
    return 1 + i * (n + 2) + j


def shape(n, i):
    return math.sin(math.pi * i / (n + 1))


def probes(n):
    middle = (n + 1) // 2
    return [(middle if i is None else i, middle if j is None else j) for i, j in PROBES]


def is_corner(n, i, j):
    return i in (0, n + 1) and j in (0, n + 1)


def write_deck(n, dt, period, path, nlgeom):
    k = stiffness(n)
    velocity = V_AMPLITUDE * OMEGA  # u amplitude = V / w
    with open(path, "w") as out:
        out.write(f"*HEADING\n{n}x{n} spring-mass lattice, SPRINGA k = {k!r}, MASS m = 1, "
                  f"free vibration in its lowest mode\n*NODE, NSET=ALL\n")
        for i in range(n + 2):
            for j in range(n + 2):
                if not is_corner(n, i, j):
                    out.write(f"{label(n, i, j)}, {float(i)!r}, {float(j)!r}, 0.\n")
        out.write("*NSET, NSET=RING\n")
        ring = [label(n, i, j) for i in range(n + 2) for j in range(n + 2)
                if (i in (0, n + 1) or j in (0, n + 1)) and not is_corner(n, i, j)]
        for start in range(0, len(ring), 16):
            out.write(", ".join(map(str, ring[start:start + 16])) + "\n")
        out.write("*NSET, NSET=PROBES\n" + ", ".join(str(label(n, i, j)) for i, j in probes(n))
                  + "\n*ELEMENT, TYPE=SPRINGA, ELSET=SPRINGS\n")
        element = 0
        for i in range(n + 2):
            for j in range(n + 2):
                for di, dj in ((1, 0), (0, 1)):
                    a, b = i + di, j + dj
                    if a > n + 1 or b > n + 1:
                        continue
                    # Springs between two ring nodes carry nothing; leave them out.
                    on_ring = i in (0, n + 1) or j in (0, n + 1)
                    if on_ring and (a in (0, n + 1) or b in (0, n + 1)):
                        continue
                    element += 1
                    out.write(f"{element}, {label(n, i, j)}, {label(n, a, b)}\n")
        # The blank first data line is the SPRINGA DOF line (CalculiX drops blank lines).
        out.write(f"*SPRING, ELSET=SPRINGS\n\n{k!r}\n*ELEMENT, TYPE=MASS, ELSET=MASSES\n")
        for i in range(1, n + 1):
            for j in range(1, n + 1):
                element += 1
                out.write(f"{element}, {label(n, i, j)}\n")
        out.write("*MASS, ELSET=MASSES\n1.\n*BOUNDARY\nRING, 1, 2\nALL, 3, 3\n"
                  "*INITIAL CONDITIONS, TYPE=VELOCITY\n")
        for i in range(1, n + 1):
            for j in range(1, n + 1):
                v = velocity * shape(n, i) * shape(n, j)
                # 13 digits: CalculiX reads at most 20 characters of a number.
                for dof in (1, 2):
                    out.write(f"{label(n, i, j)}, {dof}, {v:.12e}\n")
        # ALPHA written out: both codes then run the same HHT operator (beta, gamma from alpha).
        out.write(f"*STEP{', NLGEOM' if nlgeom else ''}, INC=100000\n"
                  f"*DYNAMIC, DIRECT, ALPHA=-0.05\n{dt!r}, {period!r}\n"
                  "*NODE PRINT, NSET=PROBES\nU\n*END STEP\n")


def exact(n, i, j, t):
    return V_AMPLITUDE * math.sin(OMEGA * t) * shape(n, i) * shape(n, j)


def error(n, rows_path):
    """Lines "t node u1 u2" (as bench_dynamic_lattice.sh extracts them from either code's output):
    the largest |u - u_exact| over the probes and increments, over the amplitude, and the count of
    (increment, probe) rows seen."""
    where = {label(n, i, j): (i, j) for i, j in probes(n)}
    worst, rows = 0.0, 0
    with open(rows_path) as text:
        for line in text:
            t, node, u1, u2 = line.split()
            i, j = where[int(node)]
            reference = exact(n, i, j, float(t))
            worst = max(worst, abs(float(u1) - reference), abs(float(u2) - reference))
            rows += 1
    if rows == 0:
        sys.exit(f"dynamic_lattice: no rows in {rows_path}")
    print(f"{worst / V_AMPLITUDE:.3e} {rows}")


if __name__ == "__main__":
    if sys.argv[1] == "deck":
        write_deck(int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5],
                   sys.argv[6:] == ["nlgeom"])
    elif sys.argv[1] == "error":
        error(int(sys.argv[2]), sys.argv[3])
