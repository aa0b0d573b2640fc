"""Every class of malformed input, fed in-process through the Python readers
(vtkLightFieldReader, vtkLightFieldScene, vtkMiddleburyImporter,
vtkImageFileReader): each must end in an error whose one-line message names
the file and says what is wrong, never in a crash, a hang or an exception
that takes the interpreter down (issue 8, items 3, 5, 6 and 10c)."""

import copy
import json
import os
import shutil
import tempfile

import lfdtesting as t
from vtkmodules.vtkCommonDataModel import vtkImageData

import lfd

WORK = t.temp_path("malformed", "x")[:-2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)

W, H, VIEWS = 6, 4, 3
VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT = 3, 5
cases = 0


def path(*parts):
    return os.path.join(WORK, *parts)


class CapturedStderr:
    """File descriptor 2 redirected to a file: what libraries print there."""
    def __enter__(self):
        self.file = tempfile.TemporaryFile()
        self.saved = os.dup(2)
        os.dup2(self.file.fileno(), 2)
        return self

    def __exit__(self, *_):
        os.dup2(self.saved, 2)
        os.close(self.saved)
        self.file.seek(0)
        self.text = self.file.read().decode(errors="replace")
        self.file.close()


def expect(name, message, *words, stderr=""):
    """One case: a non-empty one-line message holding every word, nothing
    from a library on stderr."""
    global cases
    cases += 1
    ok = (bool(message) and "\n" not in message and all(w in message for w in words)
          and "libpng" not in stderr)
    t.check(ok, f"{name} -> " + " / ".join(words), message + (f" [stderr: {stderr!r}]"
                                                              if "libpng" in stderr else ""))


def write_image(file, channels=3, scalar=VTK_UNSIGNED_CHAR, width=W, height=H, value=40):
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    image.AllocateScalars(scalar, channels)
    image.GetPointData().GetScalars().Fill(value)
    writer = lfd.vtkImageFileWriter()
    writer.SetInputData(image)
    writer.SetFileName(file)
    errors = t.error_observer(writer)
    writer.Write()
    assert writer.GetErrorCode() == 0, errors.GetErrorMessage()


def update_reader(reader, target):
    """Runs a reader on `target`: (error code 0, whether it reported an
    error, its message, what it printed on stderr)."""
    errors = t.error_observer(reader)
    reader.SetFileName(target)
    with CapturedStderr() as captured:
        reader.Update()
    return reader.GetErrorCode() == 0, errors.HasError(), errors.GetErrorMessage(), captured.text


def read_dataset(target):
    ok, reported, message, printed = update_reader(lfd.vtkLightFieldReader(), target)
    return ok and not reported, message, printed


def read_scene(target):
    scene = lfd.vtkLightFieldScene()
    errors = t.error_observer(scene)
    ok = scene.Read(target)
    return ok, errors.GetErrorMessage(), scene


def import_par(target):
    ok, _, message, printed = update_reader(lfd.vtkMiddleburyImporter(), target)
    return ok, message, printed


def read_image(target):
    ok, _, message, printed = update_reader(lfd.vtkImageFileReader(), target)
    return ok, message, printed


def fifo(name):
    target = path(name)
    os.mkfifo(target)
    return target


def deep(levels):
    return "[" * levels + "]" * levels


# ---------------------------------------------------------------- a valid dataset
light_field = lfd.vtkLightField()
light_field.SetLayout(W, H, VIEWS)
light_field.AllocatePass(lfd.vtkLightField.COAXIAL).Fill(40)
light_field.AllocatePass(lfd.vtkLightField.LABEL).Fill(1)
rig = lfd.vtkCameraRig()
rig.MakeCylinder([0, 0, 0], [0, 1, 0], 1.0, VIEWS, 1, [0.0], W, H, 30.0)
light_field.SetRig(rig)
writer = lfd.vtkLightFieldWriter()
writer.SetInputData(light_field)
valid = path("valid.lf")
writer.SetDirectory(valid)
errors = t.error_observer(writer)
writer.Write()
assert writer.GetErrorCode() == 0, errors.GetErrorMessage()
with open(os.path.join(valid, "lightfield.json")) as f:
    MANIFEST = json.load(f)
ok, message, _ = read_dataset(valid)
t.check(ok, "the valid dataset reads", message)

variant_number = 0


def variant(change=None, text=None, files=None):
    """A copy of the valid dataset with its manifest changed (a function of
    the parsed JSON, or the raw text) and extra files made by `files(dir)`."""
    global variant_number
    variant_number += 1
    target = path(f"case{variant_number}.lf")
    shutil.copytree(valid, target)
    manifest = copy.deepcopy(MANIFEST)
    if change:
        change(manifest)
    if files:
        files(target)
    with open(os.path.join(target, "lightfield.json"), "w") as f:
        f.write(text if text is not None else json.dumps(manifest))
    return target


def dataset_case(name, target, *words):
    ok, message, stderr = read_dataset(target)
    expect("lightfield.json: " + name, "" if ok else message, *words, stderr=stderr)


def set_view(index, key, value):
    def change(m):
        m["views"][index][key] = value
    return change


# ---------------------------------------------------------------- lightfield.json
deep_provenance = json.dumps(MANIFEST)[:-1] + ', "provenance": ' + deep(100000) + "}"
dataset_case("100k-deep provenance", variant(text=deep_provenance), "lightfield.json",
             "nested deeper than 64")
dataset_case("65-deep provenance", variant(text=json.dumps(MANIFEST)[:-1] + ', "provenance": '
                                            + deep(65) + "}"), "nested deeper than 64")
os.makedirs(path("dirmanifest.lf", "lightfield.json"))
dataset_case("lightfield.json is a directory", path("dirmanifest.lf"), "lightfield.json",
             "is a directory")
os.makedirs(path("fifomanifest.lf"))
os.mkfifo(path("fifomanifest.lf", "lightfield.json"))
dataset_case("lightfield.json is a FIFO", path("fifomanifest.lf"), "not a regular file")
dataset_case("FileName is /dev/zero", "/dev/zero", "/dev/zero", "not a regular file")


def huge(m):
    m["width"] = m["height"] = 1048576


dataset_case("1048576^2 image size", variant(huge), "too large", "4 GiB limit")


def image_is(special):
    def change(m):
        m["passes"]["coaxial"][1] = special
    return change


dataset_case("image is a FIFO", variant(image_is(fifo("image.fifo"))), "passes.coaxial[1]",
             "not a regular file")
dataset_case("image is /dev/zero", variant(image_is("/dev/zero")), "passes.coaxial[1]",
             "not a regular file")
dataset_case("image is a directory", variant(image_is(".")), "passes.coaxial[1]",
             "is a directory")
dataset_case("R not a rotation", variant(set_view(1, "R", [2, 0, 0, 0, 1, 0, 0, 0, 1])),
             "views[1].R", "not a rotation")
dataset_case("R a reflection", variant(set_view(1, "R", [-1, 0, 0, 0, 1, 0, 0, 0, 1])),
             "views[1].R", "det R = -1")
dataset_case("zero K", variant(set_view(0, "K", [0] * 9)), "views[0].K",
             "not an intrinsic matrix")
dataset_case("singular K (fy = 0)", variant(set_view(0, "K", [10, 0, 3, 0, 0, 2, 0, 0, 1])),
             "views[0].K", "must be positive")
dataset_case("negative focal length", variant(set_view(2, "K", [-10, 0, 3, 0, 10, 2, 0, 0, 1])),
             "views[2].K", "must be positive")
dataset_case("t = 1e308", variant(set_view(2, "t", [0, 0, 1e308])), "views[2].t", "below 1e6")


def identical(m):
    m["views"][2] = copy.deepcopy(m["views"][0])


dataset_case("identical cameras", variant(identical), "views[2]", "same camera",
             "as view 0")


def case_variant_pass(m):
    m["passes"]["Coaxial"] = m["passes"]["coaxial"]


dataset_case("pass names differing in case", variant(case_variant_pass), "passes.Coaxial",
             "lower case")


def nul_path(m):
    m["passes"]["label"][0] = "label/view_0000.png\u0000.txt"


dataset_case("NUL in an image path", variant(nul_path), "passes.label[0]", "NUL")
dataset_case("label image with 3 channels",
             variant(files=lambda d: write_image(os.path.join(d, "label", "view_0001.png"), 3)),
             "passes.label[1]", "3 channels of 8-bit", "expected 1 channel of 8-bit")
dataset_case("16-bit coaxial image",
             variant(files=lambda d: write_image(os.path.join(d, "coaxial", "view_0000.png"), 3,
                                                 VTK_UNSIGNED_SHORT)),
             "passes.coaxial[0]", "16-bit", "expected 3 channels of 8-bit")


def depth_as_png(m):
    m["passes"]["depth"] = ["label/view_0000.png"] * VIEWS


dataset_case("8-bit depth image", variant(depth_as_png), "passes.depth[0]",
             "expected 1 channel of 32-bit float")

ok_png = path("ok.png")
write_image(ok_png)
with open(ok_png, "rb") as f:
    PNG = f.read()
CORRUPT = PNG[:40] + b"\0" * 20 + PNG[60:]
TRUNCATED = PNG[:50]


def corrupt_view(d):
    with open(os.path.join(d, "coaxial", "view_0002.png"), "wb") as f:
        f.write(TRUNCATED)


dataset_case("truncated PNG", variant(files=corrupt_view), "passes.coaxial[2]", "view_0002.png")

# ---------------------------------------------------------------- scene.json
SCENE = {"format": "lfd-scene", "version": 1, "lightfield": "valid.lf",
         "camera": {"position": [0, 0, 5], "focal_point": [0, 0, 0], "view_up": [0, 1, 0],
                    "view_angle": 30, "width": 64, "height": 64},
         "cage": {"rest_points": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                                  [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
                  "boxes": [{"corners": list(range(8)), "label": 1}]}}
scene_number = 0


def scene_file(change=None, text=None):
    global scene_number
    scene_number += 1
    target = path(f"scene{scene_number}.json")
    document = copy.deepcopy(SCENE)
    if change:
        change(document)
    with open(target, "w") as f:
        f.write(text if text is not None else json.dumps(document))
    return target


def scene_case(name, target, *words):
    ok, message, _ = read_scene(target)
    expect("scene.json: " + name, "" if ok else message, *words)


ok, message, _ = read_scene(scene_file())
t.check(ok, "the valid scene reads", message)
scene_case("100k-deep keyframes", scene_file(text=json.dumps(SCENE)[:-1] + ', "keyframes": '
                                             + deep(100000) + "}"),
           "scene", "nested deeper than 64")
scene_case("a dataset where a scene is expected", valid, "valid.lf", "is a directory")
scene_case("scene is a FIFO", fifo("scene.fifo"), "scene.fifo", "not a regular file")
scene_case("scene is /dev/zero", "/dev/zero", "/dev/zero", "not a regular file")


def camera(key, value):
    def change(s):
        s["camera"][key] = value
    return change


scene_case("camera.width = 65536", scene_file(camera("width", 65536)), "camera.width",
           "[1, 16384]")
scene_case("camera.height = 65536", scene_file(camera("height", 65536)), "camera.height",
           "[1, 16384]")
scene_case("position = focal point", scene_file(camera("focal_point", [0, 0, 5])),
           "camera.focal_point", "must differ from the camera position")
scene_case("view_up parallel to the view direction", scene_file(camera("view_up", [0, 0, 2])),
           "camera.view_up", "parallel")
scene_case("view_angle 0.1", scene_file(camera("view_angle", 0.1)), "camera.view_angle",
           "[0.5, 179]")
scene_case("view_angle 179.5", scene_file(camera("view_angle", 179.5)), "camera.view_angle",
           "[0.5, 179]")


def subdivision(s):
    s["render"] = {"subdivision": 1024}


scene_case("subdivision 1024", scene_file(subdivision), "render.subdivision", "[1, 16]")


def duplicate_times(s):
    points = s["cage"]["rest_points"]
    s["keyframes"] = [{"time": 0, "points": points}, {"time": 1, "points": points},
                      {"time": 1, "points": points}]


scene_case("duplicate keyframe times", scene_file(duplicate_times), "keyframes[2].time",
           "same time")


def nul_light_field(s):
    s["lightfield"] = "valid.lf\u0000/x"


scene_case("NUL in the light-field path", scene_file(nul_light_field), "lightfield", "NUL")

no_light_field = scene_file(lambda s: s.pop("lightfield"))
ok, message, scene = read_scene(no_light_field)
errors = t.error_observer(scene)
configured = scene.ConfigureReader(lfd.vtkLightFieldReader())
expect("scene.json: no lightfield", "" if configured else errors.GetErrorMessage(),
       no_light_field, 'field "lightfield"', "missing")
missing_light_field = scene_file(lambda s: s.update(lightfield="gone.lf"))
read_scene(missing_light_field)
ok, message, scene = read_scene(missing_light_field)
errors = t.error_observer(scene)
configured = scene.ConfigureReader(None)
expect("scene.json: lightfield not found", "" if configured else errors.GetErrorMessage(),
       missing_light_field, 'field "lightfield"', "gone.lf", "not found")
writer_scene = read_scene(scene_file())[2]
writer_scene.SetSubdivision(200)
errors = t.error_observer(writer_scene)
written = writer_scene.Write(path("written.json"))
expect("scene Write refuses what Read refuses", "" if written else errors.GetErrorMessage(),
       "written.json", "render.subdivision")

# ---------------------------------------------------------------- Middlebury par files
CAMERA = " 100 0 4 0 100 3 0 0 1  1 0 0 0 1 0 0 0 1  0 0 {}\n"
write_image(path("a.png"), 3, width=8, height=6)
write_image(path("b.png"), 3, width=8, height=6)
write_image(path("deep16.png"), 3, VTK_UNSIGNED_SHORT, width=8, height=6)
par_number = 0


def par_file(lines):
    global par_number
    par_number += 1
    target = path(f"case{par_number}_par.txt")
    with open(target, "w") as f:
        f.write(f"{len(lines)}\n" + "".join(lines))
    return target


def par_case(name, target, *words):
    ok, message, stderr = import_par(target)
    expect("par: " + name, "" if ok else message, *words, stderr=stderr)


ok, message, _ = import_par(par_file(["a.png" + CAMERA.format(1), "b.png" + CAMERA.format(2)]))
t.check(ok, "a valid par file imports", message)
par_case("R not a rotation", par_file(["a.png 100 0 4 0 100 3 0 0 1 2 0 0 0 1 0 0 0 1 0 0 1\n"]),
         "_par.txt:2:", "r11..r33", "not a rotation")
par_case("zero K", par_file(["a.png 0 0 0 0 0 0 0 0 0 1 0 0 0 1 0 0 0 1 0 0 1\n"]),
         "_par.txt:2:", "k11..k33", "not an intrinsic matrix")
par_case("t = 1e308", par_file(["a.png" + CAMERA.format("1e308")]), "_par.txt:2:", "below 1e6")
par_case("identical cameras", par_file(["a.png" + CAMERA.format(1), "b.png" + CAMERA.format(1)]),
         "_par.txt:3:", "same camera")
par_case("16-bit image", par_file(["deep16.png" + CAMERA.format(1)]), "deep16.png", "16-bit",
         "expected 8-bit")
par_case("par file is a directory", WORK, "is a directory")
par_case("par file is a FIFO", fifo("fifo_par.txt"), "not a regular file")
par_case("image is a FIFO", par_file(["image.fifo" + CAMERA.format(1)]), "image.fifo",
         "not a regular file")


# A PPM header announcing 50000^2 RGB (7 GiB) in front of no pixels.
with open(path("huge.ppm"), "wb") as f:
    f.write(b"P6\n50000 50000\n255\n")
par_case("image header of 50000^2", par_file(["huge.ppm" + CAMERA.format(1)]), "huge.ppm",
         "too large", "4 GiB limit")

# ---------------------------------------------------------------- single images
for name, data in (("corrupt.png", CORRUPT), ("truncated.png", TRUNCATED)):
    with open(path(name), "wb") as f:
        f.write(data)
    ok, message, stderr = read_image(path(name))
    expect("image: " + name, "" if ok else message, name, stderr=stderr)
ok, message, stderr = read_image(fifo("single.fifo"))
expect("image: a FIFO", "" if ok else message, "single.fifo", "not a regular file")
ok, message, stderr = read_image("/dev/zero")
expect("image: /dev/zero", "" if ok else message, "/dev/zero", "not a regular file")
ok, message, stderr = read_image(WORK)
expect("image: a directory", "" if ok else message, "is a directory")

EXPECTED_CASES = 52
t.check(cases == EXPECTED_CASES, "malformed-input cases run", f"{cases} (expected {EXPECTED_CASES})")
t.finish()
