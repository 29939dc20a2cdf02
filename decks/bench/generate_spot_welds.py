"""Writes a `clinch run` deck of N spot welds loaded into plasticity, for the whole-run benchmark
(scripts/bench_whole_runs.sh).

Each weld is a BUSHING with the behaviour of decks/bench/spot_weld_behavior.inp (uncoupled
elasticity, coupled plasticity through the elliptical potential over the `normal` and `shear`
derived components, beta = 1.5), between two coincident nodes: node a held (ENCASTRE), node b free
in all six DOFs and loaded by a *CLOAD of forces and moments. The welds sit on a square grid and
share nothing, so the model has 12 DOFs per weld (6 of them free).

The load of weld i is proportional and points in its own direction: the share of `normal`
against `shear` sweeps from pure tension to pure shear over the welds, part of `shear` is a
torsion, and the in-plane shear turns with i. There is no bending moment: with one, the plastic
tangent of some welds leaves ur1 without stiffness at first yield and the run stops on a singular
system, a case for the stress test (tests/stress/plastic_paths.py), not for a timing. Its size is
LOAD_FACTOR times first yield, measured in the potential (P = F_y(0) = 40000 at first yield), so
every weld yields at 1/LOAD_FACTOR of the step and hardens up to F_y = LOAD_FACTOR * 40000, below
the end of the hardening table (70000). The step runs in INCREMENTS fixed increments
(*STATIC, DIRECT).

Usage: generate_spot_welds.py [--welds N] [--increments K] [--load-factor F] --out FILE
"""

import argparse
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# The potential's scales and derived-component weights of spot_weld_behavior.inp: P is
# ((N / R_N)^BETA + (S / R_S)^BETA)^(1 / BETA) with N = <f3> + OR_N sqrt(m1^2 + m2^2) and
# S = OR_S |m3| + sqrt(f1^2 + f2^2). The loads below keep f3 >= 0 and m1 = m2 = 0.
R_N, R_S, BETA = 0.02, 0.05, 1.5
OR_N = 1.0 / math.sqrt(30.68 / 19.63)
OR_S = OR_N / 2.0
FIRST_YIELD = 40000.0
TORSION_SHARE = 0.2  # of S, carried by m3


def weld_load(i, count, load_factor):
    """(f1, f2, f3, m1, m2, m3) of weld i whose potential P is load_factor * first yield."""
    psi = 0.5 * math.pi * (i + 0.5) / count  # 0: tension, pi/2: shear
    n_dir, s_dir = math.cos(psi), math.sin(psi)
    # Scale the direction (n_dir, s_dir) in the (N/R_N, S/R_S) plane onto P = target.
    norm = (n_dir**BETA + s_dir**BETA) ** (1.0 / BETA)
    target = load_factor * FIRST_YIELD
    normal = R_N * target * n_dir / norm
    shear = R_S * target * s_dir / norm
    chi = 2.0 * math.pi * ((i * 0.6180339887498949) % 1.0)  # direction of the in-plane shear
    in_plane = (1.0 - TORSION_SHARE) * shear
    return (in_plane * math.cos(chi), in_plane * math.sin(chi), normal, 0.0, 0.0,
            TORSION_SHARE * shear / OR_S)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--welds", type=int, default=2000)
    parser.add_argument("--increments", type=int, default=20)
    parser.add_argument("--load-factor", type=float, default=1.3)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    if args.welds < 1 or args.increments < 1 or not 1.0 < args.load_factor < 1.75:
        parser.error("need welds >= 1, increments >= 1 and 1 < load factor < 1.75 (the table "
                     "ends at 70000 = 1.75 * first yield)")
    with open(os.path.join(HERE, "spot_weld_behavior.inp")) as f:
        behavior = f.read()
    n = args.welds
    side = math.ceil(math.sqrt(n))
    out = [f"*HEADING\n{n} spot welds loaded into plasticity, {args.increments} increments\n",
           behavior]
    out.append("*NODE\n")
    for i in range(n):
        x, y = 20.0 * (i % side), 20.0 * (i // side)
        out.append(f"{2 * i + 1}, {x:.1f}, {y:.1f}, 0.\n{2 * i + 2}, {x:.1f}, {y:.1f}, 0.\n")
    out.append(f"*NSET, NSET=HELD, GENERATE\n1, {2 * n - 1}, 2\n")
    out.append(f"*NSET, NSET=LOADED, GENERATE\n2, {2 * n}, 2\n")
    out.append("*ELEMENT, TYPE=CONN3D2, ELSET=WELDS\n")
    out.extend(f"{i + 1}, {2 * i + 1}, {2 * i + 2}\n" for i in range(n))
    # A few welds across the sweep from tension to shear for the history output.
    watched = sorted({1, n} | {1 + k * n // 4 for k in range(1, 4)})
    out.append("*ELSET, ELSET=WATCHED\n" + ", ".join(map(str, watched)) + "\n")
    out.append("*NSET, NSET=WATCHED_B\n" + ", ".join(str(2 * e) for e in watched) + "\n")
    out.append("*ORIENTATION, NAME=GLOBAL\n1., 0., 0., 0., 1., 0.\n")
    out.append("*CONNECTOR SECTION, ELSET=WELDS, BEHAVIOR=weld\nBUSHING,\nGLOBAL\n")
    out.append("*BOUNDARY\nHELD, ENCASTRE\n")
    dt = 1.0 / args.increments
    out.append(f"*STEP, NLGEOM=NO\n*STATIC, DIRECT\n{dt:.12g}, 1.0\n*CLOAD\n")
    for i in range(n):
        for dof, value in enumerate(weld_load(i, n, args.load_factor), start=1):
            if value != 0.0:
                out.append(f"{2 * i + 2}, {dof}, {value:.9g}\n")
    out.append("*OUTPUT, HISTORY\n*ELEMENT OUTPUT, ELSET=WATCHED\nCTF, CU, CUP\n"
               "*NODE OUTPUT, NSET=WATCHED_B\nU\n*END STEP\n")
    with open(args.out, "w") as f:
        f.write("".join(out))


if __name__ == "__main__":
    main()
