"""The `lfd` command line: help on every subcommand, a small synth -> info ->
render -> eval run, the demo's outputs, and bad input: one readable error
line naming the file and field, exit status 1, and no output left behind."""

import json
import math
import os
import re
import shutil
import subprocess

import lfdtesting as t
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter

import lfd as lfd_module

WORK = t.temp_path("cli", "x")[:-2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)


def lfd(*args):
    result = subprocess.run([t.LFD, *args], capture_output=True, text=True, timeout=600)
    return result.returncode, result.stdout, result.stderr


def expect_error(args, *words):
    """Exit status 1 and exactly one 'lfd: error:' line containing every word."""
    code, _, err = lfd(*args)
    lines = [line for line in err.splitlines() if line.startswith("lfd: error:")]
    ok = code == 1 and len(lines) == 1 and all(w in lines[0] for w in words)
    t.check(ok, "lfd " + " ".join(args[:2]) + " -> " + " / ".join(words),
            f"exit {code}: {err.strip()}")


# Help.
code, out, _ = lfd("--help")
t.check(code == 0 and all(c in out for c in ("synth", "import", "info", "render", "eval", "lattice",
                                           "bench", "demo")), "lfd --help lists the subcommands",
        code)
for sub in (["synth"], ["import", "middlebury"], ["info"], ["render"], ["animate"], ["eval", "loo"],
            ["eval", "groundtruth"], ["lattice"], ["bench"], ["demo"], ["split", "projector"],
            ["split", "scanline"], ["split", "propagate"], ["split", "check"]):
    code, out, _ = lfd(*sub, "--help")
    t.check(code == 0 and "Options" in out, "lfd " + " ".join(sub) + " --help", code)
# `lfd help TOPIC` is the same text as the command's --help; `lfd help all`
# holds every command's; an unknown topic is one error naming the commands.
for sub in (["render"], ["split", "projector"]):
    _, expected, _ = lfd(*sub, "--help")
    expected = expected.replace("Usage: " + t.LFD + " ", "Usage: lfd ")  # --help names argv[0]
    code, out, _ = lfd("help", *sub)
    t.check(code == 0 and out == expected, "lfd help " + " ".join(sub) + " = its --help", out[:80])
code, out, _ = lfd("help", "all")
t.check(code == 0 and "Usage: lfd split projector" in out and "Usage: lfd studio" in out,
        "lfd help all holds every command's help", code)
expect_error(["help", "nope"], "help: no command 'nope'", "render")
code, out, _ = lfd("--version")
t.check(code == 0 and re.fullmatch(r"lfd \d+\.\d+\.\d+\n", out) is not None, "lfd --version", out)

# synth -> info -> render -> eval.
lf = os.path.join(WORK, "board.lf")
code, out, err = lfd("synth", "--object", "checkerboard", "--views", "24", "--rows", "1",
                     "--width", "64", "--height", "64", "--out", lf)
t.check(code == 0 and os.path.isfile(os.path.join(lf, "lightfield.json")), "synth writes a dataset",
        err.strip() or out.strip())
code, out, _ = lfd("info", lf)
t.check(code == 0 and "24 of 64 x 64" in out and "rows         1" in out, "info", out)
# Prefiltered: 2 x 2 samples per pixel, recorded in the provenance (which
# lfd eval groundtruth reads to prefilter its truth the same way).
prefiltered = os.path.join(WORK, "board2.lf")
code, out, err = lfd("synth", "--object", "checkerboard", "--views", "3", "--rows", "1",
                     "--width", "16", "--height", "16", "--supersample", "2", "--out", prefiltered)
provenance = (json.load(open(os.path.join(prefiltered, "lightfield.json"))).get("provenance", {})
              if code == 0 else {})
t.check(provenance.get("supersample") == 2, "synth --supersample 2: provenance supersample 2",
        provenance or err.strip())
expect_error(["synth", "--supersample", "9", "--out", prefiltered], "--supersample 9")

scene = os.path.join(WORK, "scene.json")
with open(scene, "w") as f:
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "board.lf",
               "camera": {"position": [0.4, 0.2, 4.0], "focal_point": [0, 0, 0],
                          "view_up": [0, 1, 0], "view_angle": 30.0, "width": 80, "height": 60},
               "render": {"focal_distance": 0.0, "subdivision": 1, "background": [0, 0, 0]}}, f)
image = os.path.join(WORK, "view.png")
code, out, err = lfd("render", scene, "--out", image)
size = None
if code == 0:
    reader = vtkPNGReader()
    reader.SetFileName(image)
    reader.Update()
    size = reader.GetOutput().GetDimensions()
t.check(size == (80, 60, 1), "render writes an 80x60 PNG", size or err.strip())

code, out, err = lfd("eval", "loo", lf, "--stride", "6")
t.check(code == 0 and out.count("\n") == 6 and "mean" in out, "eval loo over 4 views", out)

# A deformed scene: one box around the board, its top twisted by 30 degrees.
# VTK hexahedron order: each face counter-clockwise seen from +y (its top).
corners = [[x, y, z] for y in (-0.7, 0.7) for x, z in ((-0.7, 0.2), (0.7, 0.2), (0.7, -0.2),
                                                        (-0.7, -0.2))]
def twisted(degrees):
    a = math.radians(degrees)
    return [p if p[1] < 0 else [p[0] * math.cos(a) + p[2] * math.sin(a), p[1],
                                 -p[0] * math.sin(a) + p[2] * math.cos(a)] for p in corners]
twist_scene = os.path.join(WORK, "twist.json")
with open(twist_scene, "w") as f:
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "board.lf",
               "cage": {"rest_points": corners, "points": twisted(30),
                        "boxes": [{"corners": list(range(8)), "label": 1}]},
               "keyframes": [{"time": 0.0, "points": corners},
                             {"time": 1.0, "points": twisted(30)}],
               "camera": {"position": [0.3, 0.05, 4.0], "focal_point": [0, 0, 0],
                          "view_up": [0, 1, 0], "view_angle": 30.0, "width": 64, "height": 64},
               "render": {"focal_distance": 0.0, "subdivision": 1, "background": [0, 0, 0]}}, f)
code, out, err = lfd("render", twist_scene, "--out", os.path.join(WORK, "twist.png"))
t.check(code == 0 and os.path.isfile(os.path.join(WORK, "twist.png")), "render a deformed scene",
        err.strip() or out.strip())
code, out, err = lfd("eval", "groundtruth", twist_scene, "--mesh", "checkerboard")
iou = float(out.split("silhouette IoU")[1].split()[0]) if code == 0 else 0.0
t.check(iou > 0.9, "eval groundtruth of the twisted board: silhouette IoU > 0.9",
        err.strip() or iou)
code, out, err = lfd("animate", twist_scene, "--frames", "3", "--out", os.path.join(WORK, "anim"))
frames = sorted(f for f in os.listdir(os.path.join(WORK, "anim")) if f.endswith(".png")) \
    if code == 0 else []
t.check(frames == ["frame_0000.png", "frame_0001.png", "frame_0002.png"], "animate writes 3 frames",
        frames or err.strip())
folded = os.path.join(WORK, "folded.json")
with open(folded, "w") as f:
    points = [list(p) for p in corners]
    points[6] = [-2.0, -2.0, -2.0]
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "board.lf",
               "cage": {"rest_points": corners, "points": points,
                        "boxes": [{"corners": list(range(8)), "label": 1}]}}, f)
expect_error(["render", folded, "--out", os.path.join(WORK, "never.png")], "folded.json", "box 0")

# A mesh of the user's, split into parts by a scene's rest boxes.
sphere = vtkSphereSource()
sphere.SetThetaResolution(32)
sphere.SetPhiResolution(32)
sphere.Update()
mesh = sphere.GetOutput()
colors = vtkUnsignedCharArray()
colors.SetName("RGB")
colors.SetNumberOfComponents(3)
for i in range(mesh.GetNumberOfPoints()):
    x, y, z = mesh.GetPoint(i)
    colors.InsertNextTuple3(128 + 120 * x, 128 + 120 * y, 200)
mesh.GetPointData().AddArray(colors)
ply = os.path.join(WORK, "sphere.ply")
writer = vtkPLYWriter()
writer.SetFileName(ply)
writer.SetInputData(mesh)
writer.SetArrayName("RGB")
writer.Write()
# Each layer counter-clockwise seen from +y: VTK hexahedron order (synth refuses inverted boxes).
layers = [[[x, y, z] for x, z in ((-1, 1), (1, 1), (1, -1), (-1, -1))] for y in (-1, 0, 1)]
boxes = os.path.join(WORK, "boxes.json")
with open(boxes, "w") as f:
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "sphere.lf",
               "cage": {"rest_points": [p for layer in layers for p in layer],
                        "boxes": [{"corners": list(range(0, 8)), "label": 1},
                                  {"corners": list(range(4, 12)), "label": 2}]}}, f)
sphere_lf = os.path.join(WORK, "sphere.lf")
code, out, err = lfd("synth", "--mesh", ply, "--scene", boxes, "--views", "12", "--rows", "1",
                     "--width", "48", "--height", "48", "--out", sphere_lf)
labels = []
if code == 0:
    reader = lfd_module.vtkLightFieldReader()
    reader.SetFileName(sphere_lf)
    reader.Update()
    labels = sorted(set(vtk_to_numpy(reader.GetOutput().GetPass(lfd_module.vtkLightField.LABEL))))
t.check(labels == [0, 1, 2], "synth --mesh --scene: the boxes' labels reach the Label pass",
        labels or err.strip())

# Splitting the sphere: projectors, rows, painted views, and the box check.
projected = os.path.join(WORK, "sphere_projected.lf")
code, out_synth, err = lfd("synth", "--mesh", ply, "--scene", boxes, "--views", "12", "--rows", "1",
                           "--width", "64", "--height", "64", "--projectors", "3", "--out", projected)
t.check(code == 0 and os.path.isdir(os.path.join(projected, "coded"))
        and len(os.listdir(os.path.join(projected, "projectors"))) == 3,
        "synth --projectors 3: Coded, Flood and 3 masks", err.strip() or out_synth.strip())
split_lf = os.path.join(WORK, "sphere_split.lf")
code, out, err = lfd("split", "projector", projected, "--truth", projected, "--out", split_lf)
accuracy = [float(line.split()[4]) for line in out.splitlines() if line.startswith("accuracy")]
t.check(code == 0 and accuracy and accuracy[0] > 97.0 and os.path.isdir(os.path.join(split_lf, "confidence")),
        "split projector: accuracy against the true labels (%)", accuracy or err.strip())
code, out, err = lfd("split", "check", split_lf, "--scene", boxes)
t.check(code == 0 and "every label is inside its boxes" in out, "split check passes", out + err)
one_box = os.path.join(WORK, "one_box.json")
with open(one_box, "w") as f:
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "sphere.lf",
               "cage": {"rest_points": [p for layer in layers for p in layer],
                        "boxes": [{"corners": list(range(0, 8)), "label": 1}]}}, f)
expect_error(["split", "check", split_lf, "--scene", one_box], "one_box.json", "sphere_split.lf",
             "do not match")
code, _, err = lfd("split", "check", split_lf, "--scene", one_box)
t.check(f"lfd: warning: {split_lf}: label 2 has no box in {one_box}" in err.splitlines(),
        "split check warns of a label without a box", err.strip())
three_boxes = os.path.join(WORK, "three_boxes.json")
with open(three_boxes, "w") as f:
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "sphere.lf",
               "cage": {"rest_points": [p for layer in layers for p in layer],
                        "boxes": [{"corners": list(range(0, 8)), "label": 1},
                                  {"corners": list(range(4, 12)), "label": 2},
                                  {"corners": list(range(4, 12)), "label": 3}]}}, f)
code, _, err = lfd("split", "check", split_lf, "--scene", three_boxes)
errors = [line for line in err.splitlines() if line.startswith("lfd: error:")]
t.check(code == 1 and f"lfd: warning: {three_boxes}: box label 3 has no pixels in {split_lf}"
        in err.splitlines() and len(errors) == 1 and "do not match" in errors[0],
        "split check: a box label without pixels warns and exits 1", err.strip())
unlabelled = os.path.join(WORK, "unlabelled.lf")
shutil.copytree(projected, unlabelled)
with open(os.path.join(unlabelled, "lightfield.json")) as f:
    manifest = json.load(f)
del manifest["passes"]["label"]
with open(os.path.join(unlabelled, "lightfield.json"), "w") as f:
    json.dump(manifest, f)
expect_error(["split", "check", unlabelled, "--scene", boxes], "unlabelled.lf", "no Label pass")
code, out, err = lfd("split", "scanline", projected, "--rows", "20,40", "--labels", "3,1,2",
                     "--out", os.path.join(WORK, "sphere_rows.lf"))
rows = []
if code == 0:
    reader = lfd_module.vtkLightFieldReader()
    reader.SetFileName(os.path.join(WORK, "sphere_rows.lf"))
    reader.Update()
    rows = vtk_to_numpy(reader.GetOutput().GetPass(lfd_module.vtkLightField.LABEL)).reshape(12, 64, 64)
    rows = [sorted(set(rows[0][::-1][y].tolist()) - {0}) for y in (19, 20, 39, 40)]
t.check(rows == [[3], [1], [1], [2]], "split scanline: bands 3 | 1 | 2 at rows 20 and 40",
        rows or err.strip())
code, out, err = lfd("split", "propagate", projected, "--paint",
                     "0=" + os.path.join(projected, "label", "view_0000.png"), "--paint",
                     "6=" + os.path.join(projected, "label", "view_0006.png"), "--truth", projected,
                     "--out", os.path.join(WORK, "sphere_propagated.lf"))
accuracy = [float(line.split()[4]) for line in out.splitlines() if line.startswith("accuracy")]
t.check(code == 0 and accuracy and accuracy[0] > 97.0,
        "split propagate from 2 views through the depth (%)", accuracy or err.strip())
# Painted masks: every projector shows label 2's colour, so every lit
# object pixel is split as label 2.
palette_line = [line for line in out_synth.splitlines() if line.startswith("palette:")]
colour = [int(v) for v in palette_line[0].split("2=(")[1].split(")")[0].split(",")] if palette_line else [0, 0, 0]
masks = []
for p in range(3):
    image = vtkImageData()
    image.SetDimensions(32, 32, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(np.tile(np.array(colour, np.uint8), (32 * 32, 1)), deep=True))
    masks.append(os.path.join(WORK, f"mask_{p}.png"))
    png = vtkPNGWriter()
    png.SetInputData(image)
    png.SetFileName(masks[-1])
    png.Write()
painted_lf = os.path.join(WORK, "sphere_painted.lf")
code, out, err = lfd("synth", "--mesh", ply, "--scene", boxes, "--views", "12", "--rows", "1",
                     "--width", "64", "--height", "64", "--projectors", "3",
                     *[arg for m in masks for arg in ("--projector-mask", m)], "--out", painted_lf)
split_labels = []
if code == 0:
    code, out, err = lfd("split", "projector", painted_lf, "--out", os.path.join(WORK, "painted_split.lf"))
    reader = lfd_module.vtkLightFieldReader()
    reader.SetFileName(os.path.join(WORK, "painted_split.lf"))
    reader.Update()
    split_labels = sorted(set(vtk_to_numpy(reader.GetOutput().GetPass(lfd_module.vtkLightField.LABEL)).tolist()))
t.check(split_labels == [0, 2], "synth --projector-mask: painted masks decide the labels",
        split_labels or err.strip())
expect_error(["synth", "--mesh", ply, "--scene", boxes, "--views", "12", "--rows", "1", "--projectors",
              "2", "--projector-mask", masks[0], "--out", os.path.join(WORK, "never.lf")],
             "2 projectors")
expect_error(["split", "propagate", projected, "--paint", "zero.png", "--out",
              os.path.join(WORK, "never.lf")], "VIEW=LABELS.png")
expect_error(["split", "propagate", projected, "--paint",
              "0=" + os.path.join(projected, "coaxial", "view_0000.png"), "--out",
              os.path.join(WORK, "never.lf")], "view_0000.png", "one channel")
expect_error(["split", "propagate", projected, "--paint",
              "0=" + os.path.join(os.path.dirname(t.BASELINE_DIR), "templeRing", "painted_view_0000.png"),
              "--out", os.path.join(WORK, "never.lf")], "640x480", "64x64")
expect_error(["split", "projector", lf, "--out", os.path.join(WORK, "never.lf")], "board.lf",
             "no Coded pass")
t.check(not os.path.exists(os.path.join(WORK, "never.lf")), "a failed split writes nothing", False)

# Demo outputs (a small capture: the checks are on the files).
MOVIE = ["animation.mp4"] if shutil.which("ffmpeg") else []
demo = os.path.join(WORK, "demo")
code, out, err = lfd("demo", "--out", demo, "--frames", "4", "--size", "96", "--views", "36",
                     "--rows", "1", "--capture-size", "96")
frames = sorted(os.listdir(os.path.join(demo, "frames"))) if code == 0 else []
t.check(code == 0 and frames == sorted([f"frame_000{i}.png" for i in range(4)] + MOVIE),
        "demo writes 4 frames (and the MP4 with ffmpeg)",
        frames or err.strip())
t.check(os.path.isfile(os.path.join(demo, "contact_sheet.png")), "demo writes a contact sheet",
        code)

# The built-in scenes: the single-box twist of the figure (Fig. 1) and the
# twisted checkerboard under coaxial and under scene-fixed light (Figs. 4, 5).


def read_image(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def check_demo_scene(folder, scene_file, light_field, frames_dir, boxes):
    """The scene validates against its light field, has 9 keyframes and its
    3 frames show the object."""
    scene = lfd_module.vtkLightFieldScene()
    errors = t.error_observer(scene)
    read = scene.Read(os.path.join(folder, scene_file))
    reader = lfd_module.vtkLightFieldReader()
    reader.SetFileName(os.path.join(folder, light_field))
    reader.Update()
    cage = lfd_module.vtkDeformationCage()
    cage.InitializeFromGrid(scene.GetCage())
    why = cage.Validate(reader.GetOutput())
    t.check(read and cage.GetNumberOfBoxes() == boxes and scene.GetNumberOfKeyframes() == 9 and
            why == "",
            f"demo {scene_file}: {boxes} box(es), 9 keyframes, validates against {light_field}",
            errors.GetErrorMessage() or why or cage.GetNumberOfBoxes())
    files = sorted(os.listdir(os.path.join(folder, frames_dir)))
    t.check(files == sorted([f"frame_000{i}.png" for i in range(3)] + MOVIE),
            f"demo {scene_file}: {frames_dir} holds exactly 3 frames", files)
    lit = [int((t.image_array(read_image(os.path.join(folder, frames_dir, f))) > 0).any(axis=2).sum())
           for f in files if f.endswith(".png")]
    t.check(min(lit) > 100, f"demo {scene_file}: every frame shows the object (pixels)", lit)
    return read_image(os.path.join(folder, frames_dir, "frame_0002.png"))


twist_demo = os.path.join(WORK, "demo-twist")
SMALL = ("--frames", "3", "--size", "64", "--views", "36", "--rows", "1", "--capture-size", "96")
code, out, err = lfd("demo", "--scene", "twist", "--out", twist_demo, *SMALL)
listing = sorted(os.listdir(twist_demo)) if code == 0 else []
t.check(listing == ["contact_sheet.png", "figure.lf", "frames", "twist.json"],
        "demo --scene twist writes the light field, scene, frames and contact sheet",
        listing or err.strip())
if listing:
    check_demo_scene(twist_demo, "twist.json", "figure.lf", "frames", 1)
# The ground truth takes its parts from the scene's one box, as the light
# field did: the figure's own three parts agreed on 0.126 of the pixels
# (measured 0.978 now).
code, out, err = lfd("eval", "groundtruth", os.path.join(twist_demo, "twist.json"), "--mesh", "figure")
figures = dict(line.rsplit(None, 1) for line in out.splitlines() if line[:1].isalpha()) if code == 0 else {}
t.check(float(figures.get("label agreement", 0)) > 0.95 and "SSIM (object)" in figures
        and "PSNR (object)" in out, "eval groundtruth --mesh figure: parts from the scene's box",
        figures or err.strip())

board_demo = os.path.join(WORK, "demo-board")
code, out, err = lfd("demo", "--scene", "checkerboard", "--out", board_demo, *SMALL)
listing = sorted(os.listdir(board_demo)) if code == 0 else []
t.check(listing == ["checkerboard.json", "checkerboard.lf", "checkerboard_fixed_light.json",
                    "checkerboard_fixed_light.lf", "contact_sheet.png",
                    "contact_sheet_fixed_light.png", "frames", "frames_fixed_light"],
        "demo --scene checkerboard writes both lights' files", listing or err.strip())
if listing:
    # The last frame has the top turned by 60 degrees: darker than the bottom
    # under the coaxial light only (measured 0.833 and 0.967).
    coaxial = t.top_over_bottom(check_demo_scene(board_demo, "checkerboard.json",
                                                 "checkerboard.lf", "frames", 1))
    fixed = t.top_over_bottom(check_demo_scene(board_demo, "checkerboard_fixed_light.json",
                                               "checkerboard_fixed_light.lf",
                                               "frames_fixed_light", 1))
    t.check(coaxial < 0.9 and fixed > 0.95,
            "demo checkerboard: the turned top darkens under coaxial light only",
            f"top / bottom {coaxial:.3f} coaxial, {fixed:.3f} scene-fixed")

# A lattice (Sederberg-Parry FFD) bows the twist scene's box, sampled into 2^3 boxes.
bow = os.path.join(WORK, "bow.json")
moves = [str(v) for j in (1, 2) for i in (0, 1) for k in (0, 1) for v in (i, j, k, 0.2, 0, 0)]
moves = sum((["--move", *moves[n:n + 6]] for n in range(0, len(moves), 6)), [])
code, out, err = lfd("lattice", os.path.join(twist_demo, "twist.json"), "--out", bow,
                     "--dimensions", "2", "4", "2", "--subdivision", "2", *moves)
bow_scene = lfd_module.vtkLightFieldScene()
read = code == 0 and bow_scene.Read(bow)
boxes = bow_scene.GetCage().GetNumberOfCells() if read else 0
t.check(read and boxes == 8 and bow_scene.GetNumberOfKeyframes() == 0 and
        os.path.isdir(bow_scene.GetResolvedLightFieldPath()),
        "lattice writes a scene of 8 boxes whose light field resolves", err.strip() or boxes)
code, out, err = lfd("eval", "groundtruth", bow, "--mesh", "figure")
iou = float(out.split("silhouette IoU")[1].split()[0]) if code == 0 else 0.0
t.check(iou > 0.9, "eval groundtruth of the bowed figure: silhouette IoU > 0.9",
        iou if code == 0 else err.strip())
expect_error(["lattice", os.path.join(twist_demo, "twist.json"), "--out", bow, "--move", "2", "0",
              "0", "1", "0", "0"], "--move 2 0 0", "0..1")
expect_error(["lattice", os.path.join(twist_demo, "twist.json"), "--out",
              os.path.join(WORK, "folded_bow.json"), "--move", "0", "0", "0", "3", "0", "0",
              "--move", "1", "1", "1", "-3", "0", "0"], "folded_bow.json", "box 0")
t.check(not os.path.exists(os.path.join(WORK, "folded_bow.json")),
        "a refused lattice writes no scene", False)

# Bad input.
bad = os.path.join(WORK, "bad.lf")
shutil.copytree(lf, bad)
manifest = os.path.join(bad, "lightfield.json")
with open(manifest) as f:
    text = f.read()
with open(manifest, "w") as f:
    f.write(text[: len(text) // 2])
expect_error(["info", bad], "lightfield.json")

shutil.rmtree(bad)
shutil.copytree(lf, bad)
os.remove(os.path.join(bad, "coaxial", sorted(os.listdir(os.path.join(bad, "coaxial")))[3]))
expect_error(["info", bad], "coaxial")

par = os.path.join(WORK, "broken_par.txt")
with open(par, "w") as f:
    f.write("1\nview.png 1 0 0 0 1 0 0 0 1 1 0 0 0 1 0 0 0 1 0 0\n")
out_dir = os.path.join(WORK, "never.lf")
expect_error(["import", "middlebury", par, "--out", out_dir], "broken_par.txt", "2")
t.check(not os.path.exists(out_dir), "a failed import leaves no output", os.path.exists(out_dir))

broken_scene = os.path.join(WORK, "broken_scene.json")
with open(broken_scene, "w") as f:
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "board.lf",
               "cage": {"rest_points": [[0, 0, 0]] * 8,
                        "boxes": [{"corners": [0, 1, 2, 3, 4, 5, 6, 9], "label": 1}]}}, f)
expect_error(["render", broken_scene, "--out", os.path.join(WORK, "never.png")],
             "broken_scene.json", "corners")
t.check(not os.path.exists(os.path.join(WORK, "never.png")), "a failed render writes no image",
        False)
expect_error(["synth", "--mesh", os.path.join(WORK, "missing.ply"), "--out", out_dir],
             "missing.ply")
t.finish()
