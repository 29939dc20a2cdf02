"""Golden values of axial_nonlinear_table (behaviors.md §4.2, §4.5 E2)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

TABLE = [(-0.1, -100.0), (0.0, 0.0), (0.1, 100.0), (0.2, 150.0)]  # (u, F)


def force(u, linear):
    """Piecewise-linear F(u); outside the table CONSTANT holds the end value, LINEAR continues
    the end segment (behaviors.md §1.2, §4.2)."""
    if u <= TABLE[0][0] or u >= TABLE[-1][0]:
        (ua, fa), (ub, fb) = (TABLE[0], TABLE[1]) if u <= TABLE[0][0] else (TABLE[-2], TABLE[-1])
        if not linear:
            return fa if u <= TABLE[0][0] else fb
        return fa + (fb - fa) * (u - ua) / (ub - ua)
    return g.tabular(u, [(u_, f_) for u_, f_ in TABLE])


# (element, node b, end displacement, LINEAR extrapolation?)
ELEMENTS = [(1, 2, 0.3, False), (2, 4, 0.3, True), (3, 6, -0.3, False), (4, 8, -0.3, True)]
names = [f"CU1@{e}" for e, *_ in ELEMENTS] + [f"CTF1@{e}" for e, *_ in ELEMENTS]
names += [f"CEF1@{e}" for e, *_ in ELEMENTS] + [f"RF1@{b}" for _, b, *_ in ELEMENTS]

rows = []
for inc, t in enumerate([0.0, 0.25, 0.5, 0.75, 1.0]):
    cu = [u * t for _, _, u, _ in ELEMENTS]
    f = [force(c, lin) for c, (_, _, _, lin) in zip(cu, ELEMENTS)]
    rf = f if inc > 0 else [0.0] * 4  # node b along +x: RF1@b = +f (behaviors.md §4.5)
    rows.append((1, inc, t, t, cu + f + f + rf))

g.write_golden(__file__, [
    "axial_nonlinear_table: AXIAL, table (u, F) = (-0.1,-100) (0,0) (0.1,100) (0.2,150)",
    "closed form: CTF1 = CEF1 = F(CU1), piecewise linear; CONSTANT holds +150 / -100 outside,",
    "LINEAR continues the end segments (slope 500 above 0.2, slope 1000 below -0.1)",
    "(behaviors.md §1.2, §4.2, §4.5 E2)",
], names, rows)
