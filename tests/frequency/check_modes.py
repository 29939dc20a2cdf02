"""*FREQUENCY steps against independent references (docs/dynamics.md "Natural frequencies").

Usage: check_modes.py CLINCH CASE OUTDIR [--petsc | --mpi [--spectra]], CASE one of chain, bushing, mechanism: runs the deck
tests/frequency/<deck>.inp through `clinch run`, reads <job>.modes.csv and compares each step's
eigenvalues, frequencies, generalized masses and mode shapes with a reference computed here:

- chain: a fixed-free chain of N equal masses m and springs k/2 (each a pair of springs k in
  series through a massless node) has omega_j = 2 sqrt(k/(2m)) sin((2j - 1) pi / (2(2N + 1))) and
  modes phi_i = sin(i (2j - 1) pi / (2N + 1)) at mass i; a massless node between two masses
  moves by the mean of theirs (its two springs are equal and it carries no inertia). A step that
  holds the last mass (*BOUNDARY in the *FREQUENCY step) is the fixed-fixed chain, and the step
  after it the fixed-free one again (docs/perturbation.md: a step's conditions end with it).
- bushing: K = T diag(k) T^T and M = diag(m, m, m, I) of the mounted node, assembled here from
  the deck's values (T: the BUSHING's axes from the *ORIENTATION points, for translations and
  rotations), and solved densely by Cholesky reduction and Jacobi rotations, without clinch's
  assembly, Spectra or LAPACK. The preloaded tangent of component 1 is the slope of the segment
  of its table where the preload of 600 lands (3e4).
- mechanism: K has only the stiffness of component 1 (k/m = 100); the two free components give
  two zero eigenvalues.
- rigid: a rigid body whose mass sits on its tie nodes, with a spring on a tie node and a further
  mass tied to it by an *EQUATION. In the reference node's six DOFs q a tie node at arm a moves
  by u = T q, T = [I, -skew(a)] (small displacements), so M = sum m T^T T and K = K_bushing +
  k t^T t over the rows t of T that the springs and the tied mass act on; assembled here from the
  deck's values and solved densely, without clinch's condensation.

With --petsc the run is `clinch run --solver petsc`, with --mpi `mpirun -n 2 clinch run --solver
petsc` (docs/parallel.md): SLEPc's Krylov-Schur with shift-and-invert (MUMPS) solves the problem,
its rows shared by the ranks, and the step's log line must name SLEPc and the number of ranks;
without either, or with --mpi --spectra (a build without SLEPc), the log line must name Spectra. The same references hold within the same
tolerances (see EIGEN_RTOL).

The interpreter CTest finds may have no numpy, so the dense solve is written out in pure Python.
"""

import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DECKS = {"chain": "spring_mass_chain", "bushing": "bushing_mount", "mechanism": "mechanism",
         "rigid": "rigid_body_mount"}

# Spectra's Lanczos iteration and SLEPc's Krylov-Schur (EPSSetTolerances 1e-12) both stop at a
# relative residual of 1e-12: eigenvalues (Rayleigh quotients, error of the order of the residual
# squared) agree to far better than 1e-9, and mode shapes to the residual over the relative gap
# between eigenvalues (at least 0.1 here), well within 1e-7. The dense path is exact to round-off.
EIGEN_RTOL = 1e-9
SHAPE_ATOL = 1e-7


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def close(a, b, rtol, atol=0.0):
    return abs(a - b) <= atol + rtol * abs(b)


# ---- dense symmetric eigensolver (pure Python) --------------------------------------------------

def cholesky(a):
    n = len(a)
    low = [[0.0] * n for _ in range(n)]
    for i in range(n):
        for j in range(i + 1):
            s = a[i][j] - sum(low[i][k] * low[j][k] for k in range(j))
            low[i][j] = math.sqrt(s) if i == j else s / low[j][j]
    return low


def solve_lower(low, b):
    x = []
    for i in range(len(b)):
        x.append((b[i] - sum(low[i][k] * x[k] for k in range(i))) / low[i][i])
    return x


def solve_upper_transposed(low, b):
    n = len(b)
    x = [0.0] * n
    for i in reversed(range(n)):
        x[i] = (b[i] - sum(low[k][i] * x[k] for k in range(i + 1, n))) / low[i][i]
    return x


def jacobi(a):
    """Eigenvalues and eigenvectors (columns) of the symmetric matrix a by cyclic Jacobi."""
    n = len(a)
    a = [row[:] for row in a]
    v = [[float(i == j) for j in range(n)] for i in range(n)]
    for _ in range(100):
        off = sum(a[i][j] ** 2 for i in range(n) for j in range(n) if i != j)
        if off <= 1e-30 * sum(a[i][i] ** 2 for i in range(n)):
            break
        for p in range(n):
            for q in range(p + 1, n):
                if a[p][q] == 0.0:
                    continue
                theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q])
                t = math.copysign(1.0, theta) / (abs(theta) + math.sqrt(theta * theta + 1.0))
                c = 1.0 / math.sqrt(t * t + 1.0)
                s = t * c
                for k in range(n):
                    akp, akq = a[k][p], a[k][q]
                    a[k][p], a[k][q] = c * akp - s * akq, s * akp + c * akq
                for k in range(n):
                    apk, aqk = a[p][k], a[q][k]
                    a[p][k], a[q][k] = c * apk - s * aqk, s * apk + c * aqk
                for k in range(n):
                    vkp, vkq = v[k][p], v[k][q]
                    v[k][p], v[k][q] = c * vkp - s * vkq, s * vkp + c * vkq
    return [a[i][i] for i in range(n)], v


def generalized_eigen(k, m):
    """Ascending (lambda, phi) of K phi = lambda M phi, M positive definite, phi^T M phi = 1."""
    low = cholesky(m)
    n = len(k)
    # A = L^-1 K L^-T, column by column.
    cols = [solve_lower(low, [k[i][j] for i in range(n)]) for j in range(n)]  # L^-1 K
    rows = [solve_lower(low, [cols[j][i] for j in range(n)]) for i in range(n)]
    a = [[0.5 * (rows[i][j] + rows[j][i]) for j in range(n)] for i in range(n)]
    values, vectors = jacobi(a)
    pairs = []
    for idx in range(n):
        y = [vectors[i][idx] for i in range(n)]
        pairs.append((values[idx], solve_upper_transposed(low, y)))
    return sorted(pairs, key=lambda p: p[0])


# ---- references ---------------------------------------------------------------------------------

def signed_by_largest(phi):
    """phi with its largest component positive (clinch's sign convention)."""
    largest = max(phi, key=abs)
    return [x / math.copysign(1.0, largest) for x in phi]


def displacement_normalized(phi):
    largest = max(phi, key=abs)
    return [x / largest for x in phi]


def chain_reference(rows):
    n, m, k = 30, 2.0, 1000.0
    modes = []
    for j in range(1, n + 1):
        omega = 2.0 * math.sqrt(k / 2.0 / m) * math.sin((2 * j - 1) * math.pi / (2 * (2 * n + 1)))
        at_mass = [math.sin(i * (2 * j - 1) * math.pi / (2 * n + 1)) for i in range(1, n + 1)]
        # Node 1 is held; mass i sits at node 2i + 1, the massless node 2i before it.
        shape = {"U1@1": 0.0}
        for i in range(1, n + 1):
            shape[f"U1@{2 * i + 1}"] = at_mass[i - 1]
            shape[f"U1@{2 * i}"] = 0.5 * (at_mass[i - 1] + (at_mass[i - 2] if i > 1 else 0.0))
        modes.append((omega * omega, shape))
    lowest = [(lam, displacement_normalized_dict(s)) for lam, s in modes]
    ranged = [(lam, mass_normalized_dict(s, m)) for lam, s in modes[6:10]]
    # Step 4 holds the last mass too (*BOUNDARY in the step): a fixed-fixed chain of 29 masses
    # between 30 springs k/2, omega_j = 2 sqrt(k/(2m)) sin(j pi / 60), phi_i = sin(i j pi / 30).
    # Step 5 has no condition of its own: step 4's hold is gone, its modes are step 1's.
    held = []
    for j in range(1, 6):
        omega = 2.0 * math.sqrt(k / 2.0 / m) * math.sin(j * math.pi / 60.0)
        at_mass = [math.sin(i * j * math.pi / 30.0) for i in range(1, n + 1)]
        shape = {"U1@1": 0.0}
        for i in range(1, n + 1):
            shape[f"U1@{2 * i + 1}"] = at_mass[i - 1]
            shape[f"U1@{2 * i}"] = 0.5 * (at_mass[i - 1] + (at_mass[i - 2] if i > 1 else 0.0))
        held.append((omega * omega, displacement_normalized_dict(shape)))
    return ({1: lowest[:5], 2: lowest, 3: ranged, 4: held, 5: lowest[:5]},
            {1: m, 2: m, 3: m, 4: m, 5: m})


def displacement_normalized_dict(shape):
    largest = max(shape.values(), key=abs)
    return {key: value / largest for key, value in shape.items()}


def mass_normalized_dict(shape, m):
    masses = {key: m for key in shape if int(key.split("@")[1]) % 2 == 1 and key != "U1@1"}
    norm = math.sqrt(sum(masses[key] * shape[key] ** 2 for key in masses))
    scaled = {key: value / norm for key, value in shape.items()}
    largest = max(scaled.values(), key=abs)
    return {key: value * math.copysign(1.0, largest) for key, value in scaled.items()}


def bushing_axes():
    a = [0.8, 0.6, 0.0]
    b = [-0.6, 0.8, 0.5]
    norm = math.sqrt(sum(x * x for x in a))
    x = [c / norm for c in a]
    dot = sum(b[i] * x[i] for i in range(3))
    y = [b[i] - dot * x[i] for i in range(3)]
    norm = math.sqrt(sum(c * c for c in y))
    y = [c / norm for c in y]
    z = [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]
    return [x, y, z]


def bushing_matrices(k1):
    axes = bushing_axes()
    stiffness = [k1, 2.0e4, 3.5e4, 400.0, 650.0, 900.0]
    k = [[0.0] * 6 for _ in range(6)]
    for c in range(6):
        axis = axes[c % 3]
        offset = 3 * (c // 3)
        for i in range(3):
            for j in range(3):
                k[offset + i][offset + j] += stiffness[c] * axis[i] * axis[j]
    m = [[0.0] * 6 for _ in range(6)]
    for i in range(3):
        m[i][i] = 5.0
    inertia = [[0.30, 0.05, -0.03], [0.05, 0.45, 0.08], [-0.03, 0.08, 0.60]]
    for i in range(3):
        for j in range(3):
            m[3 + i][3 + j] = inertia[i][j]
    return k, m


def bushing_reference(rows):
    names = ["U1@2", "U2@2", "U3@2", "UR1@2", "UR2@2", "UR3@2"]
    references = {}
    for step, k1, mass_normalized in ((1, 1.0e4, False), (3, 3.0e4, True)):
        k, m = bushing_matrices(k1)
        modes = []
        for lam, phi in generalized_eigen(k, m):
            phi = signed_by_largest(phi) if mass_normalized else displacement_normalized(phi)
            shape = dict(zip(names, phi))
            shape.update({n.replace("@2", "@1"): 0.0 for n in names})
            modes.append((lam, shape))
        references[step] = modes
    return references, {1: None, 3: None}


def mechanism_reference(rows):
    lam = 400.0 / 4.0
    return {1: [(0.0, None), (0.0, None), (lam, {"U1@2": 1.0, "U2@2": 0.0, "U3@2": 0.0})]}, {1: None}


def rigid_rows(arm):
    """The rows of T = [I, -skew(arm)]: u_i = u_i + (theta x arm)_i over (u1..u3, theta1..3)."""
    ax, ay, az = arm
    return [[1.0, 0.0, 0.0, 0.0, az, -ay],
            [0.0, 1.0, 0.0, -az, 0.0, ax],
            [0.0, 0.0, 1.0, ay, -ax, 0.0]]


def rigid_matrices():
    masses = {(1.0, 0.0, 0.0): 2.0, (0.0, 1.0, 0.5): 3.0, (-0.5, -0.5, 0.2): 1.5}
    m = [[0.0] * 6 for _ in range(6)]
    k = [[0.0] * 6 for _ in range(6)]
    for i, value in enumerate([1.0e4, 2.0e4, 3.0e4, 500.0, 800.0, 1200.0]):
        k[i][i] = value  # the BUSHING in the global axes

    def add(matrix, row, value):
        for i in range(6):
            for j in range(6):
                matrix[i][j] += value * row[i] * row[j]
    for arm, mass in masses.items():
        for row in rigid_rows(arm):
            add(m, row, mass)
    add(k, rigid_rows((1.0, 0.0, 0.0))[1], 4000.0)  # SPRING1 on U2 of node 3
    tied = rigid_rows((0.0, 1.0, 0.5))[0]  # node 6 follows U1 of node 4
    add(m, tied, 1.0)
    add(k, tied, 2500.0)
    return k, m


def rigid_reference(rows):
    names = ["U1@2", "U2@2", "U3@2", "UR1@2", "UR2@2", "UR3@2"]
    k, m = rigid_matrices()
    modes = []
    for lam, phi in generalized_eigen(k, m):
        shape = dict(zip(names, displacement_normalized(phi)))
        shape.update({n.replace("@2", "@1"): 0.0 for n in names})
        modes.append((lam, shape))
    return {1: modes}, {1: None}


# ---- the comparison -----------------------------------------------------------------------------

def generalized_mass(row, case):
    """phi^T M phi from the modes file's shape, with the deck's masses (independent of clinch's)."""
    if case == "chain":
        return sum(2.0 * float(row[f"U1@{2 * i + 1}"]) ** 2 for i in range(1, 31))
    if case == "bushing":
        _, m = bushing_matrices(1.0)
        phi = [float(row[n]) for n in ["U1@2", "U2@2", "U3@2", "UR1@2", "UR2@2", "UR3@2"]]
        return sum(phi[i] * m[i][j] * phi[j] for i in range(6) for j in range(6))
    if case == "rigid":
        _, m = rigid_matrices()
        phi = [float(row[n]) for n in ["U1@2", "U2@2", "U3@2", "UR1@2", "UR2@2", "UR3@2"]]
        return sum(phi[i] * m[i][j] * phi[j] for i in range(6) for j in range(6))
    return 4.0 * sum(float(row[f"U{d}@2"]) ** 2 for d in (1, 2, 3))


def oriented(shape, row):
    """A mode whose largest components tie in magnitude with opposite signs (a symmetric chain's
    even modes) has no sign that round-off does not decide: compared up to its sign."""
    if not shape or abs(max(shape.values()) + min(shape.values())) > 1e-9:
        return shape
    if sum(value * float(row[name]) for name, value in shape.items()) >= 0:
        return shape
    return {name: -value for name, value in shape.items()}


def main():
    clinch, case, out = sys.argv[1], sys.argv[2], sys.argv[3]
    deck = DECKS[case]
    command = [clinch, "run", "--quiet", "--out", out, os.path.join(HERE, deck + ".inp")]
    env = dict(os.environ)
    mode = sys.argv[4:]
    spectra = "by Spectra Lanczos"
    eigensolver = spectra
    if mode == ["--petsc"]:
        command += ["--solver", "petsc"]
        eigensolver = "by SLEPc Krylov-Schur, shift-and-invert with MUMPS, on 1 rank"
    if mode[:1] == ["--mpi"]:
        # Open MPI refuses root without these; --oversubscribe lets 2 ranks share fewer cores.
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        command = ["mpirun", "--oversubscribe", "-n", "2"] + command + ["--solver", "petsc"]
        eigensolver = spectra if mode[1:] == ["--spectra"] else (
            "by SLEPc Krylov-Schur, shift-and-invert with MUMPS, on 2 ranks")
    run = subprocess.run(command, capture_output=True, text=True, env=env)
    if run.returncode != 0:
        fail(f"clinch run exited {run.returncode}: {run.stderr}")
    with open(os.path.join(out, deck + ".log"), encoding="utf-8") as f:
        named = [line for line in f if "eigenvalues nearest the shift" in line]
    if not named or not all(eigensolver in line for line in named):
        fail(f"the log's eigensolver lines {named} do not all say '{eigensolver}'")
    with open(os.path.join(out, deck + ".modes.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    reference, _ = {"chain": chain_reference, "bushing": bushing_reference,
                    "mechanism": mechanism_reference, "rigid": rigid_reference}[case](rows)
    compared = 0
    for step, modes in reference.items():
        got = [r for r in rows if int(r["step"]) == step]
        if len(got) != len(modes):
            fail(f"step {step}: {len(got)} modes, expected {len(modes)}")
        for number, (row, (lam, shape)) in enumerate(zip(got, modes), start=1):
            eigenvalue = float(row["eigenvalue"])
            scale = max(abs(m[0]) for m in modes)
            if int(row["mode"]) != number or not close(eigenvalue, lam, EIGEN_RTOL,
                                                       EIGEN_RTOL * scale):
                fail(f"step {step} mode {number}: eigenvalue {eigenvalue}, expected {lam}")
            omega = math.sqrt(max(lam, 0.0))
            if not close(float(row["frequency_rad"]), omega, EIGEN_RTOL, 1e-6) or not close(
                    float(row["frequency_cycles"]), omega / (2 * math.pi), EIGEN_RTOL, 1e-6):
                fail(f"step {step} mode {number}: frequencies {row['frequency_rad']}, "
                     f"{row['frequency_cycles']}, expected {omega}")
            if not close(float(row["generalized_mass"]), generalized_mass(row, case), 1e-9):
                fail(f"step {step} mode {number}: generalized mass {row['generalized_mass']}, "
                     f"expected {generalized_mass(row, case)} from the shape")
            shape = oriented(shape, row)
            for name, value in (shape or {}).items():
                if not close(float(row[name]), value, 0.0, SHAPE_ATOL * max(1.0, abs(value))):
                    fail(f"step {step} mode {number}: {name} = {row[name]}, expected {value}")
            compared += 1
    extra(case, out, deck)
    print(f"PASS: {compared} modes of {case}")


def extra(case, out, deck):
    """bushing: the general step after the perturbation step continues from the preload."""
    if case != "bushing":
        return
    with open(os.path.join(out, deck + ".history.csv"), newline="") as f:
        history = list(csv.DictReader(f))
    # Row 0 (the initial state) is step 1, increment 0; the frequency steps 1 and 3 add none.
    if [(r["step"], r["increment"]) for r in history if r["step"] in ("1", "3")] != [("1", "0")]:
        fail("a frequency step wrote history rows")
    cu1 = 0.01 + 500.0 / 3.0e4
    last = history[-1]
    if int(last["step"]) != 4:
        fail("the last history row is not step 4's")
    for name, value in (("U1@2", 0.8 * cu1), ("U2@2", 0.6 * cu1), ("U3@2", 0.0)):
        # Newton's converged state of a piecewise-linear law: exact to round-off.
        if not close(float(last[name]), value, 1e-9, 1e-12):
            fail(f"step 4: {name} = {last[name]}, expected {value} (the preloaded state)")


if __name__ == "__main__":
    main()
