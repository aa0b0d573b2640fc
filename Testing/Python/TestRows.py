"""Rows found right and captures that cover the camera (issue 11, items 1-2):
the real templeRing is one row of 47 views (skipped without its data);
`lfd synth` places rows by --rows/--row-spacing, --row-heights or
--elevations, and with --scene over the heights the scene's camera looks up;
`lfd render` warns in one line when its camera extrapolates beyond the rows
(vtkCameraRig.DescribeExtrapolation, reachable from Python)."""

import json
import os
import shutil

import lfdtesting as t

import lfd as lfd_module

lfd = t.run_lfd
WORK = os.path.join(t.TEMP_DIR, "rows")
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)


def last(text):
    """The last line of a command's output (its error or warning)."""
    lines = text.strip().splitlines()
    return lines[-1] if lines else ""


def info_rows(path):
    """(rows, [views per row]) as `lfd info` prints them."""
    code, out, err = lfd("info", path)
    rows = [line for line in out.splitlines() if line.startswith("row ")]
    counts = [int(line.split(",")[1].split()[0]) for line in rows]
    return len(rows), counts, err


SMALL = ("--object", "fish", "--views", "12", "--width", "24", "--height", "24", "--no-depth")

# --rows with an explicit spacing (metres: the built-in objects' unit),
# closer than the near-duplicate distance (0.01 x radius): rows all the same.
lf = os.path.join(WORK, "five.lf")
code, out, err = lfd("synth", *SMALL, "--rows", "5", "--row-spacing", "0.02", "--out", lf)
rows, counts, _ = info_rows(lf)
t.check(code == 0 and rows == 5 and counts == [12] * 5, "--rows 5 --row-spacing 0.02: 5 rows of 12",
        (code, rows, counts, last(err)))
t.check("rows: -0.04, -0.02, 0, 0.02, 0.04" in out, "synth prints the fitted row heights", out)

# Explicit heights and elevations.
lf = os.path.join(WORK, "heights.lf")
code, out, err = lfd("synth", *SMALL, "--row-heights", "-0.05,0.01,0.08", "--out", lf)
rows, counts, _ = info_rows(lf)
# Printed heights are about the fitted centre (the cameras' mean height).
t.check(code == 0 and rows == 3 and "rows: -0.06333, -0.003333, 0.06667" in out,
        "--row-heights -0.05,0.01,0.08: 3 rows there", (code, rows, out, last(err)))
lf = os.path.join(WORK, "elevations.lf")
code, out, err = lfd("synth", *SMALL, "--elevations", "-5,0,5,10", "--out", lf)
rows, counts, _ = info_rows(lf)
t.check(code == 0 and rows == 4 and counts == [12] * 4, "--elevations -5,0,5,10: 4 rows of 12",
        (code, rows, counts, last(err)))
code, _, err = lfd("synth", *SMALL, "--elevations", "0,5", "--row-heights", "0,1", "--out", lf)
t.check(code != 0 and "excludes" in err, "--elevations and --row-heights exclude each other",
        last(err))
code, _, err = lfd("synth", *SMALL, "--elevations", "0,95", "--out", lf)
t.check(code == 1 and "--elevations 95: expected a number from -89 to 89" in err,
        "an elevation beyond 89 degrees refused", last(err))

# 11 rows at the default spacing cannot be framed: the error names real options.
code, _, err = lfd("synth", *SMALL, "--rows", "11", "--out", lf)
lines = [line for line in err.splitlines() if line.startswith("lfd: error:")]
t.check(code == 1 and len(lines) == 1 and "--row-spacing" in lines[0] and "--view-angle" in lines[0],
        "--rows 11: one error line naming --row-spacing and --view-angle", last(err))

# A scene whose camera looks down on the fish from above the default rows:
# render warns; synth --scene places rows that cover it, and render is quiet.
base = os.path.join(WORK, "base.lf")
code, out, err = lfd("synth", *SMALL, "--out", base)
t.check(code == 0, "default synth", last(err))
rig_code, rig_out, _ = lfd("info", base)
radius = float([line for line in rig_out.splitlines() if line.startswith("rig radius")][0].split()[2])
scene_path = os.path.join(WORK, "above.json")
fish = lfd_module.vtkProceduralObjectSource()
fish.SetObjectToFish()
fish.Update()
b = fish.GetOutput().GetBounds()
# One box around the whole fish: every triangle is part 1.
scene = {"format": "lfd-scene", "version": 1, "lightfield": "base.lf",
         "cage": {"rest_points": [[x, y, z] for z in (b[4] - 0.01, b[5] + 0.01)
                                  for y in (b[2] - 0.01, b[3] + 0.01)
                                  for x in (b[0] - 0.01, b[1] + 0.01)],
                  "boxes": [{"corners": [0, 1, 3, 2, 4, 5, 7, 6], "label": 1}]},
         "camera": {"position": [0.0, 0.25 * radius, 1.2 * radius], "focal_point": [0, 0, 0],
                    "view_up": [0, 1, 0], "view_angle": 30, "width": 32, "height": 32}}
with open(scene_path, "w") as f:
    json.dump(scene, f)
png = os.path.join(WORK, "above.png")
code, out, err = lfd("render", scene_path, "--out", png)
warnings = [line for line in err.splitlines() if line.startswith("lfd: warning:")]
t.check(code == 0 and len(warnings) == 1 and "above the highest of the 3 captured rows" in warnings[0],
        "render from above the rows: one warning line", last(err))
covered = os.path.join(WORK, "covered.lf")
# The rig's cameras look level at the axis (as a gantry's rows do), so rows
# this high need a wider view; the radius is kept.
code, out, err = lfd("synth", *SMALL, "--scene", scene_path, "--radius", str(radius),
                     "--view-angle", "60", "--out", covered)
t.check(code == 0 and "warning" not in err, "synth --scene covers the scene camera",
        last(err) or last(out))
rows, counts, _ = info_rows(covered)
t.check(rows == 3 and counts == [12] * 3, "synth --scene: 3 rows of 12", (rows, counts))
scene["lightfield"] = "covered.lf"
with open(scene_path, "w") as f:
    json.dump(scene, f)
code, out, err = lfd("render", scene_path, "--out", png)
t.check(code == 0 and "warning" not in err, "render over covering rows: no warning", last(err))

# templeRing: one row of 47 views; the extrapolation test from Python.
importer = t.templering("templeRing rows")
if importer:
    ring = importer.GetOutput().GetRig()
    in_row = sum(1 for v in range(ring.GetNumberOfViews()) if ring.GetRow(v) == 0)
    t.check(ring.GetNumberOfRows() == 1 and in_row == 47, "templeRing: 1 row of 47 views",
            (ring.GetNumberOfRows(), in_row))
    c0 = [0.0] * 3
    ring.GetCameraCenter(0, c0)
    t.check(ring.DescribeExtrapolation(c0) == "", "templeRing from view 0: no extrapolation",
            ring.DescribeExtrapolation(c0))
    above = [c0[i] + 0.5 * ring.GetRadius() * ring.GetAxis()[i] for i in range(3)]
    message = ring.DescribeExtrapolation(above)
    t.check("above the highest of the 1 captured rows" in message,
            "templeRing from half a radius above view 0: extrapolates", message)
t.finish()
