# %% [markdown]
# # boltzone in a notebook
# Cells in the `# %%` format (VS Code, Jupyter with jupytext, Spyder): the report's Table 1,
# an interface pressure with matplotlib, and the field's VTU opened with meshio.
# Run as a script: `python notebook.py [OUT_DIR]` (figures and files go to OUT_DIR).

# %%
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # no display needed; in Jupyter drop this line
import matplotlib.pyplot as plt
import meshio
import pandas as pd

import boltzone

out = Path(sys.argv[1] if len(sys.argv) > 1 else "notebook_out")
out.mkdir(parents=True, exist_ok=True)
scenes = Path(__file__).resolve().parents[2] / "examples" / "scenes"

# %% [markdown]
# ## Table 1 of the report: R_o / A, single plate against two plates (lengths in inches)

# %%
t1 = boltzone.table1()
a = t1["ours.geometry.a"]
table = pd.DataFrame({
    "A/D": a / t1["ours.geometry.d"], "B/A": t1["ours.geometry.b"] / a,
    "single R_o/A": t1["ours.single.value"] / a, "two-plate R_o/A": t1["ours.two.value"] / a,
    "+-": t1["ours.two.error"] / a, "report single": t1["report.single"],
    "report two-plate": t1["report.two"]})
print(table.to_string(index=False))

# %% [markdown]
# ## The interface pressure of Table 1's first geometry (two plates, frictionless)

# %%
scene = boltzone.Scene.from_toml(scenes / "table1_row1.toml").replace(
    **{"outputs.interface_pressure": str(out / "interface.csv"),
       "outputs.field": str(out / "field.vtu")})
r = boltzone.solve(scene, strict=True)
curve = r.interface
print(r)
fig, ax = plt.subplots(figsize=(6, 3.5))
ax.plot(curve["r [in]"], curve["p [psi]"], marker=".")
ax.axvline(r.r_o, color="grey", linestyle="--", label="R_o = %.4f in" % r.r_o)
ax.set_xlabel("r [in]")
ax.set_ylabel("interface pressure p [psi]")
ax.legend()
fig.tight_layout()
fig.savefig(out / "interface_pressure.png", dpi=120)

# %% [markdown]
# ## The finest mesh's field, read back from the VTU with meshio

# %%
mesh = meshio.read(out / "field.vtu")
print("VTU: %d points, cells %s, point data %s"
      % (len(mesh.points), [c.type for c in mesh.cells], sorted(mesh.point_data)))
same = r.field
assert len(same.points) == len(mesh.points)
print("largest von Mises stress: %.4g psi" % mesh.point_data["von_mises"].max())
