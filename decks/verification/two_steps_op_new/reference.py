"""Golden values of two_steps_op_new (keywords.md §8, §10-§13; output-variables.md §2)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

TAB = [(0.0, 0.0), (0.5, 1.0), (1.0, 0.5)]
times = [(1, 0, 0.0, 0.0)] + [(1, i, 0.25 * i, 0.25 * i) for i in (1, 2, 3, 4)]
times += [(2, i, 0.5 * i, 1.0 + 0.5 * i) for i in (1, 2)]


def evolution(step, st):
    """Values of the four prescribed conditions at step time st (keywords.md §13)."""
    if step == 1:
        load1 = 100.0 * g.tabular(st, TAB)          # AMPLITUDE=TAB, VALUE=RELATIVE
        motion2 = 0.1 * g.smooth_step(st, 0.0, 0.0, 1.0, 1.0)
        cload3 = 40.0 * st                           # step amplitude RAMP from 0
        load4 = 0.0
        drive5 = 0.1 * st                            # prescribed U1@10, RAMP
    else:
        end1 = 100.0 * g.tabular(1.0, TAB)          # 50 at the end of step 1
        load1 = end1 * (1.0 - st)                    # removed by OP=NEW: ramps to zero
        motion2 = 0.1 + (0.2 - 0.1) * st             # OP=MOD, RAMP from the current value
        cload3 = 40.0                                # not mentioned: held at its last value
        load4 = 30.0 * st                            # new in step 2
        drive5 = 0.1 * (1.0 - st)                    # BC removed by OP=NEW: its reaction 40
                                                     # decays linearly, 400 u = 40 (1 - st)
    return load1, motion2, cload3, load4, drive5


names = [f"{v}1@{e}" for v in ("CU", "CTF", "CEF") for e in (1, 2, 3, 4, 5)]
names += ["CRF1@2", "CCF1@3"] + [f"U1@{n}" for n in (2, 4, 6, 8, 10)]
names += [f"RF1@{n}" for n in (1, 3, 5, 7, 9)] + ["RF1@10"]
rows = []
for step, inc, st, tt in times:
    load1, c2, p3, load4, u5 = evolution(step, st)
    cu = [load1 / 1000.0, c2, p3 / 200.0, load4 / 100.0, u5]
    cef = [load1, 500.0 * c2, p3, load4, 400.0 * u5]
    # Motion: node 4 is free along x, so the multiplier cancels the elastic force (CTF = 0).
    # Connector load: an applied pair on both nodes; CTF = CEF - CCF = 0 (output-variables §2).
    ctf = [load1, 0.0, 0.0, load4, cef[4]]
    crf2 = -cef[1]
    # RF at node a = internal force - applied load = -CTF (the pair's part on node a cancels
    # the elastic force there for element 3).
    rf = [-x for x in ctf]
    # Node 10 carries its BC only in step 1 (RF = +CTF there); in step 2 its x dof is free: 0.
    rf10 = ctf[4] if step == 1 else 0.0
    if inc == 0:
        rf, rf10 = [0.0] * 5, 0.0
    rows.append((step, inc, st, tt, cu + ctf + cef + [crf2, p3] + cu + rf + [rf10]))
g.write_golden(__file__, [
    "two_steps_op_new: step 1 (4 x 0.25): CLOAD 100 x TABULAR (0,0)(0.5,1)(1,0.5) on el. 1;",
    "connector motion 0.1 x SMOOTH STEP on el. 2; connector load ramped to 40 on el. 3.",
    "Step 2 (2 x 0.5): CLOAD OP=NEW -> el. 1 load ramps 50 -> 0, new load 30 on el. 4;",
    "motion OP=MOD to 0.2 ramped from 0.1; connector load held at 40; el. 5 driven to 0.1 in",
    "step 1, freed by BOUNDARY OP=NEW in step 2: reaction 40 decays, U1@10 = 0.05, 0",
    "(keywords.md §8, §13)",
], names, rows)
