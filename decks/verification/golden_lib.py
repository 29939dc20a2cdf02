"""Closed-form helpers shared by the reference.py scripts of the verification cases.

Standard library only. Each reference.py states its own closed form; this module holds the
vector algebra, the orientation triad of keywords.md §6, the exact angle definitions of
connection-types.md §2.3 (used to cross-check small-rotation B rows by finite differences) and
the writer of golden.csv in the history-table layout of cli-contract.md.
"""

import importlib.util
import math
import os


def case_reference(case):
    """The reference.py of another verification case, as a module (its solver reused; its
    golden.csv is written only when it runs as a script)."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), case, "reference.py")
    spec = importlib.util.spec_from_file_location(f"{case}_reference", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module

# Vectors and 3x3 matrices.


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def scale(s, a):
    return [s * x for x in a]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    return scale(1.0 / norm(a), a)


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def matvec(a, v):
    return [dot(row, v) for row in a]


def columns(e1, e2, e3):
    """Matrix whose columns are the three vectors (E = [e1 e2 e3])."""
    return [[e1[i], e2[i], e3[i]] for i in range(3)]


def column(m, j):
    return [m[i][j] for i in range(3)]


def solve3(a, b):
    """Cramer's rule for a 3x3 system."""
    det = dot(a[0], cross(a[1], a[2]))
    out = []
    for j in range(3):
        m = [row[:] for row in a]
        for i in range(3):
            m[i][j] = b[i]
        out.append(dot(m[0], cross(m[1], m[2])) / det)
    return out


def solve(a, b):
    """Gaussian elimination with partial pivoting for a small dense system (lists of lists)."""
    n = len(b)
    m = [list(row) + [b[i]] for i, row in enumerate(a)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            for k in range(c, n + 1):
                m[r][k] -= f * m[c][k]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        x[r] = (m[r][n] - sum(m[r][k] * x[k] for k in range(r + 1, n))) / m[r][r]
    return x


def skew(v):
    return [[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]]


def expm(v):
    """Rotation matrix exp(v^) (connection-types.md §3.2)."""
    t = norm(v)
    s = skew(v)
    s2 = matmul(s, s)
    a = math.sin(t) / t if t > 1e-12 else 1.0
    b = (1.0 - math.cos(t)) / (t * t) if t > 1e-6 else 0.5
    eye = [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]
    return [[eye[i][j] + a * s[i][j] + b * s2[i][j] for j in range(3)] for i in range(3)]


def rot_axis(k, angle):
    """Right-handed rotation by angle (radians) about global axis k (1, 2, 3)."""
    return expm(scale(angle, [1.0 if i == k - 1 else 0.0 for i in range(3)]))


# Orientation (keywords.md §6).


def orientation(a, b, c=(0.0, 0.0, 0.0), axis=1, angle_deg=0.0):
    """Triad (e1, e2, e3) of a rectangular *ORIENTATION, with the optional extra rotation."""
    e1 = unit(sub(a, c))
    e3 = unit(cross(e1, sub(b, c)))
    e2 = cross(e3, e1)
    e = [e1, e2, e3]
    if angle_deg != 0.0:
        psi = math.radians(angle_deg)
        i, j = axis % 3, (axis + 1) % 3  # the two axes that rotate, cyclic after k
        ei, ej = e[i], e[j]
        e[i] = add(scale(math.cos(psi), ei), scale(math.sin(psi), ej))
        e[j] = add(scale(-math.sin(psi), ei), scale(math.cos(psi), ej))
    return e


# Angles (connection-types.md §2.3).


def r_rel(ea, eb):
    """R_ij = e_i^a . e_j^b."""
    return [[dot(ea[i], eb[j]) for j in range(3)] for i in range(3)]


def cardan(r):
    return [math.atan2(-r[1][2], r[2][2]), math.asin(r[0][2]), math.atan2(-r[0][1], r[0][0])]


def euler313(r):
    return [math.atan2(r[0][2], -r[1][2]), math.acos(r[2][2]), math.atan2(r[2][0], r[2][1])]


def rotation_vector(r):
    c = max(-1.0, min(1.0, 0.5 * (r[0][0] + r[1][1] + r[2][2] - 1.0)))
    t = math.acos(c)
    w = [r[2][1] - r[1][2], r[0][2] - r[2][0], r[1][0] - r[0][1]]
    f = t / (2.0 * math.sin(t)) if t > 1e-12 else 0.5
    return scale(f, w)


def flexion_torsion(r):
    """(flexion alpha, torsion beta, sweep theta) from R_rel, in clinch's component order."""
    e3b = column(r, 2)  # e3b in a-components
    alpha = math.atan2(norm(cross([0.0, 0.0, 1.0], e3b)), e3b[2])  # accurate near 0
    n = unit(cross([0.0, 0.0, 1.0], e3b))
    theta = math.atan2(n[1], n[0])
    beta = math.atan2(r[1][0] - r[0][1], r[0][0] + r[1][1])
    return [alpha, beta, theta]


def projection_flexion_torsion(r):
    """(alpha1, alpha2, beta) with the mid frame E_m = F(alpha/2, n) Rz(beta/2), a-components."""
    e3b = column(r, 2)
    alpha = math.atan2(norm(cross([0.0, 0.0, 1.0], e3b)), e3b[2])  # accurate near 0
    beta = math.atan2(r[1][0] - r[0][1], r[0][0] + r[1][1])
    if alpha < 1e-14:
        return [0.0, 0.0, beta]
    n = unit(cross([0.0, 0.0, 1.0], e3b))
    em = matmul(expm(scale(alpha / 2.0, n)), rot_axis(3, beta / 2.0))
    return [alpha * dot(n, column(em, 0)), alpha * dot(n, column(em, 1)), beta]


def angle_rows(angles, ea0, eb0, h=1e-6):
    """Rows dc_k/d(omega) of the angles at zero relative spin omega = theta_b - theta_a (global).

    Central finite differences of the exact angle function, the independent route used to
    confirm the analytic dual-basis rows of connection-types.md §3.3 (truncation ~h^2).
    """
    rows = [[0.0] * 3 for _ in range(3)]
    for j in range(3):
        d = [0.0, 0.0, 0.0]
        d[j] = h
        plus = angles(r_rel(ea0, [matvec(expm(d), e) for e in eb0]))
        minus = angles(r_rel(ea0, [matvec(expm(scale(-1.0, d)), e) for e in eb0]))
        for k in range(3):
            rows[k][j] = (plus[k] - minus[k]) / (2.0 * h)
    return rows


def assert_close(a, b, tol, what):
    diff = max(abs(x - y) for x, y in zip(a, b))
    if diff > tol:
        raise SystemExit(f"reference check failed for {what}: {a} vs {b} (diff {diff})")


# Amplitudes (keywords.md §8).


def smooth_step(t, t0, a0, t1, a1):
    if t <= t0:
        return a0
    if t >= t1:
        return a1
    x = (t - t0) / (t1 - t0)
    return a0 + (a1 - a0) * x ** 3 * (10.0 - 15.0 * x + 6.0 * x * x)


def tabular(t, points):
    if t <= points[0][0]:
        return points[0][1]
    for (ta, aa), (tb, ab) in zip(points, points[1:]):
        if t <= tb:
            return aa + (ab - aa) * (t - ta) / (tb - ta)
    return points[-1][1]


# golden.csv in the history-table layout (cli-contract.md).


def integrate_second_order(acceleration, x0, v0, times, h):
    """(x, x') at each of `times` (multiples of h, increasing) of x'' = acceleration(x) from
    (x0, v0) at t = 0, by the classical fourth-order Runge-Kutta method with step h."""
    x, v, t, out = x0, v0, 0.0, []
    for target in times:
        for _ in range(int(round((target - t) / h))):
            k1 = (v, acceleration(x))
            k2 = (v + h / 2 * k1[1], acceleration(x + h / 2 * k1[0]))
            k3 = (v + h / 2 * k2[1], acceleration(x + h / 2 * k2[0]))
            k4 = (v + h * k3[1], acceleration(x + h * k3[0]))
            x += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
            v += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        t = target
        out.append((x, v))
    return out


def rigid_swing_rows(angular_acceleration, inertia, fallen, tracked, times):
    """History rows of a rigid body turning about a fixed point O from rest at theta = 0, with
    I_O theta'' = inertia * angular_acceleration(theta) and fallen(theta) the work of gravity:
    a row at t = 0 and at each of `times` with U1, U2, V1, V2 of the body point `tracked` (its
    coordinates from O), UR3 = theta, VR3 = theta', ALLKE = I_O theta'^2 / 2 and ALLWK. RK4 with
    h = 1e-4, checked here (of the integration, not of clinch) against h = 2e-4 to 1e-10 and
    against the energy integral to 1e-9."""
    states = integrate_second_order(angular_acceleration, 0.0, 0.0, times, 1e-4)
    coarse = integrate_second_order(angular_acceleration, 0.0, 0.0, times, 2e-4)
    assert_close([s[0] for s in coarse], [s[0] for s in states], 1e-10, "RK4 h = 2e-4 against 1e-4")
    for theta, rate in states:
        assert_close([0.5 * inertia * rate * rate], [fallen(theta)], 1e-9, "energy conservation")
    rows = [(1, 0, 0.0, 0.0, [0.0] * 8)]
    x, y = tracked
    for i, (t, (theta, rate)) in enumerate(zip(times, states), start=1):
        c, s = math.cos(theta), math.sin(theta)
        u1, u2 = x * c - y * s - x, x * s + y * c - y
        v1, v2 = -(x * s + y * c) * rate, (x * c - y * s) * rate
        rows.append((1, i, t, t, [u1, u2, v1, v2, theta, rate, 0.5 * inertia * rate * rate,
                                  fallen(theta)]))
    return rows


def write_golden(script_file, provenance, names, rows):
    """Write golden.csv next to script_file, or <case>.golden.csv into $GOLDEN_OUT_DIR when it is
    set (tests/regression/check_references.sh). rows: (step, increment, step_time, total_time,
    values)."""
    case_dir = os.path.dirname(os.path.abspath(script_file))
    path = os.path.join(case_dir, "golden.csv")
    if os.environ.get("GOLDEN_OUT_DIR"):
        path = os.path.join(os.environ["GOLDEN_OUT_DIR"], os.path.basename(case_dir) + ".golden.csv")
    with open(path, "w", encoding="utf-8") as out:
        for line in provenance:
            out.write(f"# {line}\n")
        out.write("# generated by reference.py (python3, standard library only)\n")
        out.write(",".join(["step", "increment", "step_time", "total_time"] + list(names)) + "\n")
        for step, inc, st, tt, values in rows:
            if len(values) != len(names):
                raise SystemExit("row width does not match the header")
            cells = [str(step), str(inc), repr(float(st)), repr(float(tt))]
            cells += [repr(float(v) + 0.0) for v in values]
            out.write(",".join(cells) + "\n")
