"""Golden values of spot_weld_kinks: spot-weld returns that end on a kink of the potential
(derived-components-and-potentials.md §1.4, §3; behaviors.md §6.4).

Same weld, elasticity and hardening as spot_weld_paths (k = 1e5 on 1-6, F_y = 40000 + 1e7 u_bar,
u_bar = lambda), and the same independent return mapping (nested bisections, SpotWeld in
../spot_weld_paths/reference.py), here allowed to shrink a group of the potential exactly to
zero: the moment resultant sqrt(m1^2 + m2^2) and the Macaulay term <f3> of `normal`, and |m3| of
`shear`. At such a state the flow rule holds with a subgradient of the group instead of the
minimum-norm choice; the reference asserts that this subgradient lies in the group's
subdifferential (the unit ball, or [0, 1] for the Macaulay term) and that every other row of the
discrete equations of §6.4 holds to 1e-12, and it asserts that each element spends plastic
increments on its kink.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
import golden_lib as g  # noqa: E402

weld = g.case_reference("spot_weld_paths")

# Targets of node b (u1, u2, u3, ur1, ur2, ur3) at the end of each step; unlisted dofs keep
# their value. Nodes b are 2, 4, 6.
TARGETS = {
    1: [{3: 0.012, 4: 0.0005}, {3: 0.02, 4: 0.001}, {3: 0.01}],
    2: [{4: 0.012, 3: 0.0003}, {4: 0.02, 3: 0.0006}, {5: 0.01}],
    3: [{1: 0.021, 6: 0.0005}, {1: 0.03, 2: 0.01, 6: 0.001}, {1: 0.0}],
}
# The group each element holds at zero: its component indices (0-based).
KINK = {1: (3, 4), 2: (2,), 3: (5,)}
NINC = 4

if __name__ == "__main__":
    on_kink = {el: 0 for el in TARGETS}
    kink_rows = {el: 0 for el in TARGETS}

    def observe(el, f, dl, res, w):
        if w.kink_rows > kink_rows[el]:
            kink_rows[el] = w.kink_rows
            assert all(f[i] == 0.0 for i in KINK[el]), (el, f)
            on_kink[el] += 1

    names, rows = weld.path_rows(TARGETS, NINC, {el: weld.SpotWeld(allow_kinks=True)
                                                 for el in TARGETS}, observe)
    assert all(n >= 4 for n in on_kink.values()), on_kink
    print("plastic increments on a kink per element:", on_kink)
    g.write_golden(__file__, [
        "spot_weld_kinks: the spot weld of spot_weld_paths (BUSHING, k = 1e5 on 1-6, F_y = 40000 +",
        "1e7 u_bar) on three paths whose returns end on a kink of the potential (moment resultant,",
        "Macaulay term <f3>, |m3| held at zero). Independent backward-Euler return by nested",
        "bisection (../spot_weld_paths/reference.py, allow_kinks); every plastic row satisfies the",
        "discrete equations of behaviors.md §6.4 to 1e-12 with an admissible subgradient on the kink",
    ], names, rows)
