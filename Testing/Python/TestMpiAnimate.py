"""`mpirun -np 2 lfd animate`: the frames split across two MPI processes
(vtkMPIController) give the same folder as one process, file for file and
byte for byte (frames, ParaView series, movie); a frame that fails on the
second process, a scene that cannot be read and a command that does not
split are each one error line, said once, with nothing written."""
import filecmp
import os
import shutil
import subprocess

import lfdtesting as t

MPIEXEC = os.environ["LFD_MPIEXEC"]
WORK = t.temp_path("TestMpiAnimate", "x")[:-2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
# OpenMPI refuses root unless told (CI runs as root); 2 processes on any
# number of cores.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def lfd(*args, processes=0):
    command = [t.LFD, *args]
    if processes:
        command = [MPIEXEC, "-np", str(processes), "--oversubscribe", *command]
    result = subprocess.run(command, capture_output=True, text=True, timeout=300, env=ENV)
    return result.returncode, result.stdout, result.stderr


def error_lines(err):
    return [line for line in err.splitlines() if line.startswith("lfd: error:")]


code, _, err = lfd("synth", "--object", "checkerboard", "--views", "24", "--rows", "1",
                   "--width", "48", "--height", "48", "--no-depth",
                   "--out", os.path.join(WORK, "board.lf"))
t.check(code == 0, "a small light field", err.strip())

# A box around the board, its top twisted by 30 degrees over 2 keyframes;
# a second scene whose middle keyframe folds the box.
corners = [[x, y, z] for y in (-0.7, 0.7)
           for x, z in ((-0.7, 0.2), (0.7, 0.2), (0.7, -0.2), (-0.7, -0.2))]
twisted = [p if p[1] < 0 else [0.866 * p[0] + 0.5 * p[2], p[1], -0.5 * p[0] + 0.866 * p[2]]
           for p in corners]
folded = [list(p) for p in corners]
folded[6] = [-2.0, -2.0, -2.0]
camera = {"position": [0.3, 0.05, 4.0], "focal_point": [0, 0, 0], "view_up": [0, 1, 0],
          "view_angle": 30.0, "width": 40, "height": 30}


def write_scene(name, keyframes, lightfield="board.lf"):
    import json
    path = os.path.join(WORK, name)
    with open(path, "w") as f:
        json.dump({"format": "lfd-scene", "version": 1, "lightfield": lightfield,
                   "cage": {"rest_points": corners,
                            "boxes": [{"corners": list(range(8)), "label": 1}]},
                   "keyframes": [{"time": float(i), "points": p} for i, p in enumerate(keyframes)],
                   "camera": camera}, f)
    return path


scene = write_scene("twist.json", [corners, twisted])
fold = write_scene("fold.json", [corners, folded, corners])

# 5 frames: two full rounds of 2 and a last round of 1.
single, parallel = os.path.join(WORK, "single"), os.path.join(WORK, "parallel")
code, out, err = lfd("animate", scene, "--frames", "5", "--paraview", "--out", single)
t.check(code == 0, "one process", err.strip())
code, out, err = lfd("animate", scene, "--frames", "5", "--paraview", "--out", parallel,
                     processes=2)
t.check(code == 0 and out.count("frames    5 of 40x30") == 1 and err.count("lfd:") == 0,
        "two processes: one report, said by process 0", (code, out, err))
names = sorted(os.listdir(single))
expected = sorted([f"frame_{i:04d}.{e}" for i in range(5) for e in ("png", "vti")]
                  + [f"cage_{i:04d}.vtu" for i in range(5)] + ["animation.pvd", "cage.pvd"]
                  + (["animation.mp4"] if shutil.which("ffmpeg") else []))
t.check(names == expected, "the single-process folder", names)
t.check(sorted(os.listdir(parallel)) == names, "the same files from two processes",
        sorted(os.listdir(parallel)))
_, mismatch, errors = filecmp.cmpfiles(single, parallel, names, shallow=False)
t.check(not mismatch and not errors, "every file identical, byte for byte", mismatch + errors)
t.check(not [n for n in os.listdir(WORK) if ".tmp-" in n], "no temporary left", os.listdir(WORK))

# Frame 1 (time 1: the folded keyframe) is the second process's: its
# refusal is said once, by process 0; the earlier export is untouched.
before = {n: open(os.path.join(parallel, n), "rb").read() for n in names}
code, out, err = lfd("animate", fold, "--frames", "3", "--out", parallel, processes=2)
lines = error_lines(err)
t.check(code != 0 and len(lines) == 1 and "fold.json" in lines[0] and "box 0" in lines[0],
        "a frame failing on process 1: one error naming the scene and the box", err.strip())
t.check({n: open(os.path.join(parallel, n), "rb").read() for n in os.listdir(parallel)} == before,
        "the earlier export untouched", sorted(os.listdir(parallel)))

# Each process reads its piece of the views (process 1: views 12-23) and
# they exchange them: an image only process 1 reads, cut short, is its
# refusal, said once by process 0, naming the image; nothing is written.
shutil.copytree(os.path.join(WORK, "board.lf"), os.path.join(WORK, "broken.lf"))
cut = os.path.join(WORK, "broken.lf", "coaxial", "view_0020.png")
with open(cut, "r+b") as f:
    f.truncate(100)
broken = write_scene("broken.json", [corners, twisted], "broken.lf")
code, out, err = lfd("animate", broken, "--frames", "2", "--out", os.path.join(WORK, "none"),
                     processes=2)
lines = error_lines(err)
t.check(code != 0 and len(lines) == 1 and "coaxial/view_0020.png" in lines[0]
        and not os.path.exists(os.path.join(WORK, "none")),
        "an image of process 1's piece cut short: one error naming it", err.strip())

code, out, err = lfd("animate", os.path.join(WORK, "missing.json"), "--out",
                     os.path.join(WORK, "none"), processes=2)
lines = error_lines(err)
t.check(code != 0 and len(lines) == 1 and "missing.json" in lines[0]
        and not os.path.exists(os.path.join(WORK, "none")),
        "a missing scene: one error line from two processes", err.strip())
code, out, err = lfd("render", scene, "--out", os.path.join(WORK, "view.png"), processes=2)
lines = error_lines(err)
t.check(code != 0 and lines == ["lfd: error: lfd render runs as one process: only 'lfd animate' "
                                "splits its work across MPI processes (mpirun -np N lfd animate "
                                "...)"] and not os.path.exists(os.path.join(WORK, "view.png")),
        "lfd render under mpirun: refused once", err.strip())
t.finish()
