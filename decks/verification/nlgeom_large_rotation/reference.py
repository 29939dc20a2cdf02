"""Golden values of nlgeom_large_rotation (NLGEOM=YES); nlgeom_large_rotation_small imports
golden() from here for the same deck with NLGEOM=NO (connection-types.md §2.3, §3.2, §5.2, §5.4)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

C30 = 0.8660254037844387
ORI30 = g.orientation([C30, 0.5, 0.0], [-0.5, C30, 0.0])
K_AX, K_ROT = 1000.0, 100.0
TIMES = [0.0, 0.25, 0.5, 0.75, 1.0]
# The deck's amplitudes hold these exact arc points (node 2 at (cos(pi/2 t), sin(pi/2 t), 0)).
ARC = {t: (math.cos(math.pi / 8 * i) - 1.0, math.sin(math.pi / 8 * i)) for i, t in enumerate(TIMES)}
# connection-types.md §5.2 table (phi = 0.3 and 1.2 about global x, ORI30 at a): exact Cardan.
SPEC_CARDAN = {0.25: [0.26174700590426947, -0.14830313118757030, 0.01955575930681060],
               1.0: [1.14883758162471450, -0.48478658167115746, 0.31736587564870680]}
SPEC_LINEAR = {0.25: [0.25980762113533160, -0.15, 0.0], 1.0: [1.03923048454132650, -0.6, 0.0]}
# connection-types.md §5.4.2: CARTESIAN, node a turned pi/2 about z, node b following rigidly.
SPEC_CART_LINEAR = [-1.1514235671818869, 0.005675880608775108, 0.0]
K_CART = [1000.0, 2000.0, 4000.0]


def cardan_dual(ea, eb, angles):
    """Dual basis g^k of the Cardan rotation axes (connection-types.md §2.3, §3.3)."""
    alpha = angles[0]
    g1 = ea[0]
    g2 = g.add(g.scale(math.cos(alpha), ea[1]), g.scale(math.sin(alpha), ea[2]))
    g3 = eb[2]
    j = g.dot(g1, g.cross(g2, g3))
    return [g.scale(1.0 / j, g.cross(g2, g3)), g.scale(1.0 / j, g.cross(g3, g1)),
            g.scale(1.0 / j, g.cross(g1, g2))]


def cartesian_swing(nlgeom, t, ux, uy, inc):
    """Element 4: node a turned by theta = pi/2 t about z, node b on the arc. NLGEOM=YES: the
    frame turns with a and d = R_a d0, so c = E_a^T d - x0 = 0 (stress free). NLGEOM=NO:
    c_i = e_i . u_b + (e_i x d0) . theta_a (B0 row of §3.4). RF at node b = sum f_i e_i."""
    theta_a = [0.0, 0.0, math.pi / 2.0 * t]
    ub = [ux, uy, 0.0]
    d0 = [1.0, 0.0, 0.0]
    if nlgeom:
        ea = [g.matvec(g.expm(theta_a), e) for e in ORI30]
        d = g.add(d0, ub)
        c = [g.dot(e, d) - g.dot(e0, d0) for e, e0 in zip(ea, ORI30)]
        g.assert_close(c, [0.0, 0.0, 0.0], 1e-15, "rigid motion of CARTESIAN")
    else:
        ea = ORI30
        c = [g.dot(e, ub) + g.dot(g.cross(e, d0), theta_a) for e in ORI30]
        if t == 1.0:
            g.assert_close(c, SPEC_CART_LINEAR, 1e-15, "linear CARTESIAN vs spec §5.4.2")
    f = [k * ci for k, ci in zip(K_CART, c)]
    rf = [0.0] * 3
    for fi, e in zip(f, ea):
        rf = g.add(rf, g.scale(fi, e))
    return f + c + (rf if inc else [0.0] * 3)


def golden(nlgeom):
    names = ["CTF1@1", "CU1@1", "RF1@2", "RF2@2", "RF3@2"]
    names += [f"CTF{i}@2" for i in (4, 5, 6)] + [f"CU{i}@2" for i in (4, 5, 6)]
    names += [f"RF{i}@4" for i in (1, 2, 3)] + [f"RM{i}@4" for i in (1, 2, 3)]
    names += [f"CTF{i}@3" for i in (4, 5, 6)] + [f"CU{i}@3" for i in (4, 5, 6)]
    names += [f"RF{i}@6" for i in (1, 2, 3)] + [f"RM{i}@6" for i in (1, 2, 3)]
    names += [f"CTF{i}@4" for i in (1, 2, 3)] + [f"CU{i}@4" for i in (1, 2, 3)]
    names += [f"RF{i}@8" for i in (1, 2, 3)]
    rows = []
    for inc, t in enumerate(TIMES):
        ux, uy = ARC[t]
        phi = [1.2 * t, 0.0, 0.0]
        eb = [g.matvec(g.expm(phi), e) for e in ORI30]  # b's frame: R_b E_b0, E_b0 = E_a0
        if nlgeom:
            d = [1.0 + ux, uy, 0.0]
            length = g.norm(d)
            c1 = length - 1.0                      # exact length change
            rf2 = g.scale(K_AX * c1 / length, d)   # f q at node b
            rrel = g.r_rel(ORI30, eb)
            card = g.cardan(rrel)
            dual = cardan_dual(ORI30, eb, card)
            fd = g.angle_rows(g.cardan, ORI30, eb)
            for a_row, f_row in zip(dual, fd):
                g.assert_close(a_row, f_row, 1e-7, "Cardan dual basis vs finite differences")
            if t in SPEC_CARDAN:
                g.assert_close(card, SPEC_CARDAN[t], 1e-14, "Cardan angles vs spec §5.2")
            rot = g.rotation_vector(rrel)
            # For a rotation about one fixed axis, T^-T m = m when m is parallel to phi, so the
            # moment at b is E_a m as in the linear case (§3.3); confirmed by differences.
            rot_rows = ORI30
            fd_rows = g.angle_rows(g.rotation_vector, ORI30, eb)
            m_fd = [0.0] * 3
            for k in range(3):
                m_fd = g.add(m_fd, g.scale(rot[k], fd_rows[k]))
            m_an = [0.0] * 3
            for k in range(3):
                m_an = g.add(m_an, g.scale(rot[k], ORI30[k]))
            g.assert_close(m_fd, m_an, 1e-8, "ROTATION moment vs finite differences")
        else:
            c1 = ux                                # n0 . u_b with n0 = x
            rf2 = [K_AX * c1, 0.0, 0.0]
            card = [g.dot(e, phi) for e in ORI30]  # e_k . theta_b (§3.4)
            dual = ORI30
            if t in SPEC_LINEAR:
                g.assert_close(card, SPEC_LINEAR[t], 1e-14, "linear angles vs spec §5.2")
            rot = card[:]
            rot_rows = ORI30
        m_card = [K_ROT * a for a in card]
        m_rot = [K_ROT * a for a in rot]
        rm4, rm6 = [0.0] * 3, [0.0] * 3
        for k in range(3):
            rm4 = g.add(rm4, g.scale(m_card[k], dual[k]))
            rm6 = g.add(rm6, g.scale(m_rot[k], rot_rows[k]))
        if inc == 0:
            rf2, rm4, rm6 = [0.0] * 3, [0.0] * 3, [0.0] * 3
        values = [K_AX * c1, c1] + rf2 + m_card + card + [0.0] * 3 + rm4
        values += m_rot + rot + [0.0] * 3 + rm6
        values += cartesian_swing(nlgeom, t, ux, uy, inc)
        rows.append((1, inc, t, t, values))
    return names, rows


def provenance(nlgeom):
    regime = "NLGEOM=YES (exact measures)" if nlgeom else "NLGEOM=NO (linearised at t = 0)"
    return [
        f"nlgeom_large_rotation{'' if nlgeom else '_small'}: {regime}.",
        "AXIAL l0 = 1, k = 1000, node b on the arc (cos(pi/2 t), sin(pi/2 t), 0): YES CU1 = |d| - 1",
        "= 0, NO CU1 = n0 . u_b = cos(pi/2 t) - 1 (-1 at t = 1, CTF1 = -1000). CARDAN/ROTATION,",
        "ORI30 at a, node b turned 1.2 t about global x, k = 100: YES exact Cardan angles of R_rel",
        "(spec §5.2 table asserted at t = 0.25, 1), NO e_k . theta_b; RM at b = sum m_k g^k (dual",
        "basis, asserted against finite differences). CARTESIAN with node a turned pi/2 t and b",
        "following rigidly: YES c = 0; NO c_i = e_i . u_b + (e_i x d0) . theta_a, at t = 1",
        "(-1.15142, 0.00568, 0) (connection-types.md §2.3, §3.2, §3.4, §5.2, §5.4)",
    ]


if __name__ == "__main__":
    g.write_golden(__file__, provenance(True), *golden(True))
