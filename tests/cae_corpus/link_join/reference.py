"""Golden values of link_join: LINK and JOIN carry the loads through their constraints only."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, local_components  # noqa: E402

# LINK: node a at the origin, node b at (0, 0, 5) with u1 = u2 = 0, load 70 along z.
# JOIN: coincident nodes at (10, 0, 0), "Datum csys-3" = global axes turned 90 degrees about 3.
E = g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], axis=3, angle_deg=90.0)
FJ = [10.0, 20.0, 30.0]
names = ["CTF1@1", "CRF1@1", "CU1@1", "CTF1@2", "CTF2@2", "CTF3@2", "CRF1@2", "CRF2@2", "CRF3@2",
         "RF1@Point-1.1", "RF2@Point-1.1", "RF3@Point-1.1",
         "RF1@Point-3.1", "RF2@Point-3.1", "RF3@Point-3.1",
         "U1@Point-2.1", "U2@Point-2.1", "U3@Point-2.1", "U1@Point-4.1", "U2@Point-4.1", "U3@Point-4.1"]
rows = []
for tau in (0.0, 1.0):
    link = 70.0 * tau
    fj = local_components(E, g.scale(tau, FJ))
    values = [link, link, 0.0] + fj + fj + [0.0, 0.0, -link] + g.scale(-tau, FJ) + [0.0] * 6
    rows.append((1, 1 if tau else 0, tau, tau, values))
g.write_golden(__file__, [
    "link_join: LINK (length 5 along z, load 70 along the link) and JOIN (coincident, datum turned 90 deg about 3)",
    "closed form: LINK CTF1 = CRF1 = 70, CU1 = 0, RF3(a) = -70; JOIN CTF_i = CRF_i = e_i.F, RF(a) = -F,",
    "node b does not move",
], names, rows)
