"""A full disk never costs a file (issue 8, item 2): on a small tmpfs holding
an existing PNG, scene and dataset, every writer (Python and `lfd render
--out`) fails with an error naming the target, the previous files stay byte
for byte, and no temporary is left. A stale temporary of a dead process is
removed by the next write of the same target. Needs root (mount); prints
SKIP and exits 125 when mounting is not permitted."""

import errno
import os
import shutil
import subprocess
import sys

import lfdtesting as t
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData

import lfd

WORK = t.temp_path("diskfull", "x")[:-2]
MOUNT = os.path.join(WORK, "mnt")
subprocess.run(["umount", MOUNT], capture_output=True)
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(MOUNT)
mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", MOUNT],
                         capture_output=True, text=True)
if mounted.returncode != 0:
    print("SKIP: cannot mount a tmpfs:", mounted.stderr.strip())
    sys.exit(125)


def noise_image(seed, size=64):
    image = vtkImageData()
    image.SetDimensions(size, size, 1)
    values = np.random.default_rng(seed).integers(0, 256, (size * size, 3), dtype=np.uint8)
    array = numpy_to_vtk(values, deep=True)
    image.GetPointData().SetScalars(array)
    return image


def run_writer(writer, data):
    """Writes `data` with a writer whose target is set: (success, message)."""
    writer.SetInputData(data)
    errors = t.error_observer(writer)
    return writer.Write(), errors.GetErrorMessage()


def write_png(image, target):
    writer = lfd.vtkImageFileWriter()
    writer.SetFileName(target)
    return run_writer(writer, image)


def light_field(fill):
    result = lfd.vtkLightField()
    result.SetLayout(16, 12, 3)
    result.AllocatePass(lfd.vtkLightField.COAXIAL).Fill(fill)
    rig = lfd.vtkCameraRig()
    rig.MakeCylinder([0, 0, 0], [0, 1, 0], 1.0, 3, 1, [0.0], 16, 12, 30.0)
    result.SetRig(rig)
    return result


def write_dataset(data, target):
    writer = lfd.vtkLightFieldWriter()
    writer.SetDirectory(target)
    return run_writer(writer, data)


def snapshot(root):
    """Every file under `root` (but the filler) and its bytes."""
    files = {}
    for folder, _, names in os.walk(root):
        for name in names:
            full = os.path.join(folder, name)
            if name != "filler":
                with open(full, "rb") as f:
                    files[os.path.relpath(full, root)] = f.read()
    return files


def temporaries(root):
    return sorted(os.path.relpath(os.path.join(folder, name), root)
                  for folder, dirs, names in os.walk(root) for name in dirs + names
                  if ".tmp-" in name)


def fill(root):
    """Writes a filler file until the file system refuses another byte."""
    with open(os.path.join(root, "filler"), "wb", buffering=0) as f:
        for block in (65536, 4096, 1):
            try:
                while True:
                    f.write(b"\0" * block)
            except OSError as e:
                assert e.errno == errno.ENOSPC, e


def dead_pid():
    pid = 999999
    while True:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return pid
        except PermissionError:
            pass
        pid -= 1


try:
    # Existing outputs on the small disk.
    png = os.path.join(MOUNT, "view.png")
    scene_path = os.path.join(MOUNT, "scene.json")
    dataset = os.path.join(MOUNT, "data.lf")
    ok, message = write_png(noise_image(1), png)
    t.check(ok == 1, "the first PNG is written", message or "ok")
    scene = lfd.vtkLightFieldScene()
    scene_errors = t.error_observer(scene)
    scene.SetLightFieldPath("data.lf")
    ok = scene.Write(scene_path)
    t.check(ok, "the first scene is written", scene_errors.GetErrorMessage() or "ok")
    ok, message = write_dataset(light_field(10), dataset)
    t.check(ok == 1, "the first dataset is written", message or "ok")
    before = snapshot(MOUNT)

    # The CLI's light field and scene live outside the small disk.
    board = os.path.join(WORK, "board.lf")
    code = subprocess.run([t.LFD, "synth", "--object", "checkerboard", "--views", "24", "--rows",
                           "1", "--width", "48", "--height", "48", "--out", board],
                          capture_output=True, text=True, timeout=600)
    render_scene = os.path.join(WORK, "scene.json")
    cli_scene = lfd.vtkLightFieldScene()
    cli_scene.SetLightFieldPath(board)
    cli_scene.GetCamera().SetPosition(0.4, 0.2, 4.0)
    cli_scene.SetWidth(200)
    cli_scene.SetHeight(200)
    cli_scene.Write(render_scene)
    rendered = subprocess.run([t.LFD, "render", render_scene, "--out",
                               os.path.join(WORK, "free.png")], capture_output=True, text=True,
                              timeout=600)
    t.check(code.returncode == 0 and rendered.returncode == 0,
            "lfd render works on a free disk", rendered.stderr.strip() or "exit 0")

    fill(MOUNT)

    ok, message = write_png(noise_image(2), png)
    t.check(ok == 0 and message.startswith(png + ": ") and "No space left" in message
            and ".tmp-" not in message, "vtkImageFileWriter on a full disk fails", message)

    scene.SetLightFieldPath("other.lf")
    scene_errors.Clear()
    ok = scene.Write(scene_path)
    message = scene_errors.GetErrorMessage()
    t.check(not ok and message.startswith(scene_path + ": ") and "No space left" in message
            and ".tmp-" not in message, "vtkLightFieldScene.Write on a full disk fails", message)

    ok, message = write_dataset(light_field(200), dataset)
    t.check(ok == 0 and message.startswith(dataset + ": ") and ".tmp-" not in message,
            "vtkLightFieldWriter on a full disk fails", message)

    cli = subprocess.run([t.LFD, "render", render_scene, "--out", png], capture_output=True,
                         text=True, timeout=600)
    t.check(cli.returncode != 0 and "view.png" in cli.stderr and ".tmp-" not in cli.stderr,
            "lfd render --out on a full disk exits non-zero",
            f"exit {cli.returncode}: {cli.stderr.strip()}")

    after = snapshot(MOUNT)
    t.check(after == before, "the previous files are byte-identical",
            f"{len(before)} files, changed: "
            f"{sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))}")
    t.check(temporaries(MOUNT) == [], "no temporary is left", temporaries(MOUNT))

    # Stale temporaries of a dead process go with the next write of a target.
    os.remove(os.path.join(MOUNT, "filler"))
    pid = dead_pid()
    stale_file = os.path.join(MOUNT, f"view.tmp-{pid}.png")
    stale_folder = os.path.join(MOUNT, f"data.lf.tmp-{pid}")
    stale_other = os.path.join(MOUNT, f"other.tmp-{pid}.png")
    for target in (stale_file, stale_other):
        with open(target, "wb") as f:
            f.write(b"half")
    os.makedirs(os.path.join(stale_folder, "coaxial"))
    live = os.path.join(MOUNT, f"view.tmp-{os.getppid()}.png")
    with open(live, "wb") as f:
        f.write(b"a running writer's")
    ok_png, _ = write_png(noise_image(3), png)
    ok_data, _ = write_dataset(light_field(30), dataset)
    t.check(ok_png == 1 and ok_data == 1, "writes succeed once there is space", (ok_png, ok_data))
    t.check(temporaries(MOUNT) == sorted([os.path.basename(stale_other), os.path.basename(live)]),
            "stale temporaries of the written targets are removed, others kept",
            temporaries(MOUNT))
finally:
    subprocess.run(["umount", MOUNT], check=False)

t.finish()
