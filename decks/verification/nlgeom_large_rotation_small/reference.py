"""Golden values of nlgeom_large_rotation_small: the NLGEOM=NO twin of nlgeom_large_rotation,
computed by the same script (connection-types.md §3.2, §3.4, §5.4)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "nlgeom_large_rotation"))
sys.path.insert(0, os.path.join(HERE, ".."))
import golden_lib as g  # noqa: E402
import reference as twin  # noqa: E402

g.write_golden(__file__, twin.provenance(False), *twin.golden(False))
