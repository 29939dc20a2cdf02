#!/usr/bin/env python3
"""The natural frequencies of tests/frequency/rigid_element_mass.inp against closed-form mass
properties of its four rigid bodies (docs/dynamics.md "Inertia on constrained nodes"): each body
moves in one translation u and the rotation theta about z at its reference node, on two grounded
springs k and kr. A point r of the body moves by u e + theta e_z x r, so the kinetic energy is
(m u'^2 + 2 s u' theta' + I theta'^2) / 2 with m the mass, s the first moment that couples them
and I = integral (x^2 + y^2) dm about the reference node; the eigenvalues solve the 2 x 2 problem
det(diag(k, kr) - lambda M) = 0 by the quadratic formula.

Mass properties, integrated by hand:
- brick a x b x c from the corner: m = rho a b c; along x, s = -m b / 2; I = m (a^2 + b^2) / 3;
- plate a x c in the x-z plane (normal y), thickness t: m = rho t a c; along y, s = m a / 2;
  I = m a^2 / 3 + m t^2 / 12 (the thickness spreads the mass in y);
- corner tetrahedron with edges a, b, c: m = rho a b c / 6; along x, s = -m b / 4;
  I = m (a^2 + b^2) / 10 (integral x^2 dV = V a^2 / 10);
- beam of length L along x with a RECT profile w (along y, its n1) x h, a box: m = rho w h L;
  along y, s = m L / 2; I = m L^2 / 3 + m w^2 / 12 (the profile's width across z; with n1
  misread as the default (0, 0, -1) it would be m h^2 / 12).
The tolerance 1e-11 relative: the quadrature is exact for these polynomials; only rounding is
left.

Usage: check_rigid_element_mass.py CLINCH WORKDIR
"""
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def eigenvalues(m, s, inertia, k, kr):
    # det([[k - l m, -l s], [-l s, kr - l I]]) = (m I - s^2) l^2 - (k I + kr m) l + k kr = 0
    a = m * inertia - s * s
    b = -(k * inertia + kr * m)
    c = k * kr
    root = math.sqrt(b * b - 4 * a * c)
    return sorted([(-b - root) / (2 * a), (-b + root) / (2 * a)])


def main():
    clinch, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    subprocess.run([clinch, "run", "--quiet", "--out", work,
                    os.path.join(HERE, "rigid_element_mass.inp")], check=True)
    with open(os.path.join(work, "rigid_element_mass.modes.csv"), newline="") as f:
        got = sorted(float(r["eigenvalue"]) for r in csv.DictReader(f))

    expected = []
    a, b, c, rho = 2.0, 1.0, 0.5, 3.0  # brick
    m = rho * a * b * c
    expected += eigenvalues(m, -m * b / 2, m * (a * a + b * b) / 3, 1000.0, 500.0)
    a, c, t, rho = 2.0, 0.8, 0.1, 5.0  # plate
    m = rho * t * a * c
    expected += eigenvalues(m, m * a / 2, m * a * a / 3 + m * t * t / 12, 800.0, 300.0)
    a, b, c, rho = 1.5, 1.0, 2.0, 2.0  # tetrahedron
    m = rho * a * b * c / 6
    expected += eigenvalues(m, -m * b / 4, m * (a * a + b * b) / 10, 600.0, 200.0)
    length, w, h, rho = 2.0, 0.3, 0.1, 4.0  # beam
    m = rho * w * h * length
    expected += eigenvalues(m, m * length / 2, m * length * length / 3 + m * w * w / 12, 400.0,
                            100.0)
    expected.sort()

    if len(got) != len(expected):
        print(f"FAIL: {len(got)} eigenvalues, expected {len(expected)}")
        return 1
    worst = max(abs(g - e) / e for g, e in zip(got, expected))
    for g, e in zip(got, expected):
        print(f"  {g:.15g}  expected {e:.15g}")
    print(f"worst relative error {worst:.2e}")
    return 0 if worst <= 1e-11 else 1


if __name__ == "__main__":
    sys.exit(main())
