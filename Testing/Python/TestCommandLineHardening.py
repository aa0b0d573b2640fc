"""The `lfd` command line behaves like one tool (issue 8): usage errors are one
`lfd: error:` line and exit 2, refused input is one line and exit 1, numeric
options are range-checked, `--version`, commands that need OpenGL say so
without an X display, a folder or FIFO given as a scene is named as such, no
exception escapes, and a failed `lfd animate` leaves nothing behind."""

import concurrent.futures
import json
import os
import re
import shutil
import subprocess

import lfdtesting as t

WORK = t.temp_path("cli-hardening", "x")[:-2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def lfd(*args, env=None):
    result = subprocess.run([t.LFD, *args], capture_output=True, text=True, timeout=600, env=env,
                            cwd=WORK)
    return result.returncode, result.stdout, result.stderr


def expect(args, status, line, env=None):
    """Exit `status` and stderr's only error line exactly `line` (a str) or
    matching it (a compiled pattern); no other error line."""
    code, _, err = lfd(*args, env=env)
    errors = [l for l in err.splitlines() if l.startswith("lfd: error:")]
    matches = len(errors) == 1 and (errors[0] == line if isinstance(line, str)
                                    else line.fullmatch(errors[0]) is not None)
    t.check(code == status and matches and "terminate called" not in err,
            f"lfd {' '.join(args)[:60]} -> exit {status}: {line if isinstance(line, str) else line.pattern}",
            f"exit {code}: {err.strip()}")


def listing(folder):
    """Every file under `folder` with its bytes."""
    files = {}
    for root, _, names in os.walk(folder):
        for name in names:
            path = os.path.join(root, name)
            with open(path, "rb") as f:
                files[os.path.relpath(path, folder)] = f.read()
    return files


def leftovers():
    return sorted(n for n in os.listdir(WORK) if ".tmp-" in n or ".old-" in n)


# Refusals that need no data, run side by side (lfd takes a second to start: it loads ~300 libraries).
no_display = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
CASES = [
    # Usage errors: one line, exit 2, a suggestion when a name is close.
    (["rendr"], 2, "unknown command 'rendr' (did you mean 'render'?)"),
    (["eval", "lo", "x.lf"], 2, "unknown command 'eval lo' (did you mean 'eval loo'?)"),
    (["animate", "scene.json", "--frame", "3", "--out", "o"], 2,
     "lfd animate: unknown option '--frame' (did you mean '--frames'?)"),
    (["demo", "--scene", "fosh"], 2,
     "lfd demo: --scene: fosh not in {fish,twist,checkerboard,temple} (see lfd demo --help)"),
    (["render"], 2, "lfd render: SCENE is required (see lfd render --help)"),
    # Numeric options out of range or not a number: refused input, exit 1.
    (["bench", "--repeat", "0"], 1, "--repeat 0: expected an integer from 1 to 1000"),
    (["bench", "--threads", "-1"], 1, "--threads -1: expected an integer from 0 to 1024"),
    (["synth", "--views", "0", "--out", "n.lf"], 1, "--views 0: expected an integer from 1 to 100000"),
    (["synth", "--rows", "0", "--out", "n.lf"], 1, "--rows 0: expected an integer from 1 to 1000"),
    (["synth", "--width", "0", "--out", "n.lf"], 1, "--width 0: expected an integer from 1 to 16384"),
    (["animate", "s.json", "--frames", "0", "--out", "n"], 1,
     "--frames 0: expected an integer from 1 to 100000"),
    (["animate", "s.json", "--frames", "-1", "--out", "n"], 1,
     "--frames -1: expected an integer from 1 to 100000"),
    (["animate", "s.json", "--frames", "1e9", "--out", "n"], 1,
     "--frames 1e9: expected an integer from 1 to 100000"),
    (["demo", "--size", "0", "--out", "n"], 1, "--size 0: expected an integer from 1 to 16384"),
    (["eval", "loo", "x.lf", "--stride", "0"], 1, "--stride 0: expected an integer >= 1"),
    (["render", "s.json", "--time", "inf", "--out", "n.png"], 1, "--time inf: expected a number"),
    (["render", "s.json", "--cache-size", "12X", "--out", "n.png"], 1,
     "--cache-size 12X: expected a size of at least 1M: an integer with an optional unit K, M or G "
     "(e.g. 512M)"),
    (["animate", "s.json", "--cache-size", "512K", "--out", "n"], 1,
     "--cache-size 512K: expected a size of at least 1M: an integer with an optional unit K, M or G "
     "(e.g. 512M)"),
    (["tile", "x.lf", "--tile-size", "8", "--out", "t.lf"], 1,
     "--tile-size 8: expected an integer from 16 to 4096"),
]
# Without an X display, the commands that open an OpenGL window say so.
for args in (["synth", "--out", "n.lf"], ["eval", "groundtruth", "s.json", "--mesh", "fish"]):
    name = "lfd " + " ".join(a for a in args[:2] if not a.startswith("-") and "." not in a)
    CASES.append((args, 1, f"{name} renders with OpenGL and needs an X display (DISPLAY is not "
                  f"set); run it as: xvfb-run -a {name} ...", no_display))
with concurrent.futures.ThreadPoolExecutor(2) as pool:
    results = list(pool.map(lambda c: (c, lfd(*c[0], env=c[3] if len(c) > 3 else None)), CASES))
for (args, status, line, *_), (code, _, err) in results:
    errors = [l for l in err.splitlines() if l.startswith("lfd: error:")]
    t.check(code == status and errors == ["lfd: error: " + line],
            f"lfd {' '.join(args)[:50]} -> exit {status}: {line}", f"exit {code}: {err.strip()}")
t.check(sorted(os.listdir(WORK)) == [], "refused commands write nothing", os.listdir(WORK))

# --version prints the CMake project version; the help states the exit statuses.
with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
    version = re.search(r"project\(\S+ VERSION (\S+)", f.read()).group(1)
code, out, err = lfd("--version")
t.check(code == 0 and out == f"lfd {version}\n", f"lfd --version prints 'lfd {version}'", out + err)
code, out, _ = lfd("animate", "--help")
out = " ".join(out.split())
t.check(code == 0 and "replaces OUT when complete" in out and "Exit status: 0 done; 1 refused input"
        in out and "2 malformed command line" in out,
        "animate --help: replaces OUT when complete; exit statuses", out)

# A small light field and scenes over it.
lf = os.path.join(WORK, "board.lf")
code, out, err = lfd("synth", "--object", "checkerboard", "--views", "12", "--rows", "1", "--width",
                     "32", "--height", "32", "--out", lf)
t.check(code == 0, "synth a small light field", err.strip())
# VTK hexahedron order: each face counter-clockwise seen from +y (its top).
corners = [[x, y, z] for y in (-0.7, 0.7) for x, z in ((-0.7, 0.2), (0.7, 0.2), (0.7, -0.2),
                                                        (-0.7, -0.2))]
folded = [list(p) for p in corners]
folded[6] = [-2.0, -2.0, -2.0]


def write_scene(name, rest, keyframes=None):
    scene = {"format": "lfd-scene", "version": 1, "lightfield": "board.lf",
             "cage": {"rest_points": rest, "boxes": [{"corners": list(range(8)), "label": 1}]},
             "camera": {"position": [0.3, 0.05, 4.0], "focal_point": [0, 0, 0],
                        "view_up": [0, 1, 0], "view_angle": 30.0, "width": 32, "height": 32},
             "render": {"focal_distance": 0.0, "subdivision": 1, "background": [0, 0, 0]}}
    if keyframes:
        scene["keyframes"] = [{"time": time, "points": points} for time, points in keyframes]
    path = os.path.join(WORK, name)
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


good = write_scene("good.json", corners, [(0.0, corners), (1.0, corners)])
# Rest at t = 0 and 1, folded at t = 2: frames 0 and 1 of 5 render, a later one is refused.
failing = write_scene("failing.json", corners, [(0.0, corners), (1.0, corners), (2.0, folded)])
duplicate = write_scene("duplicate.json", corners, [(0.0, corners), (1.0, corners), (1.0, corners)])
inverted = write_scene("inverted.json", [corners[i] for i in (4, 5, 6, 7, 0, 1, 2, 3)])

# A dataset, a folder or a FIFO where a scene file is expected.
expect(["render", lf, "--out", "n.png"], 1,
       f"lfd: error: {lf}: is a light-field dataset, not a scene file; write a scene.json whose "
       "\"lightfield\" names it (see Data/README.md), or try 'lfd demo'")
os.makedirs(os.path.join(WORK, "folder"))
expect(["animate", os.path.join(WORK, "folder"), "--out", "n"], 1,
       f"lfd: error: {os.path.join(WORK, 'folder')}: is a folder, not a scene file (scene.json)")
fifo = os.path.join(WORK, "fifo.json")
os.mkfifo(fifo)
expect(["render", fifo, "--out", "n.png"], 1,
       f"lfd: error: {fifo}: is not a regular file; a scene file (scene.json) was expected")
# An exception from deep inside (a manifest that is a folder) is one line, not an abort.
weird = os.path.join(WORK, "weird.lf")
os.makedirs(os.path.join(weird, "lightfield.json"))
expect(["info", weird], 1, re.compile(r"lfd: error: .+"))

# Refusals of the scene: exit 1, nothing written.
expect(["animate", duplicate, "--frames", "3", "--out", os.path.join(WORK, "dup")], 1,
       f"lfd: error: {duplicate}: field \"keyframes[2].time\": another keyframe has the same time 1.000000; keyframe times must differ")
expect(["synth", "--object", "checkerboard", "--scene", inverted, "--views", "4", "--rows", "1",
        "--width", "16", "--height", "16", "--out", os.path.join(WORK, "inverted.lf")], 1,
       re.compile(re.escape(f"lfd: error: {inverted}: cage: box 0 (label 1): the rest box is "
                            "inverted") + ".*"))
code, _, render_err = lfd("render", inverted, "--out", os.path.join(WORK, "n.png"))
t.check(code == 1 and "rest box is inverted" in render_err,
        "render refuses the same inverted box as synth", render_err.strip())
t.check(not any(os.path.exists(os.path.join(WORK, n)) for n in ("dup", "inverted.lf", "n.png")),
        "the refused scenes wrote nothing", os.listdir(WORK))

# With ffmpeg installed (Utilities/setup.sh) animate also writes the MP4.
MOVIE = ["animation.mp4"] if shutil.which("ffmpeg") else []
# A failed animate leaves nothing behind: neither the frames before the
# failure nor the temporary, and an existing output folder is untouched.
anim = os.path.join(WORK, "anim")
code, out, err = lfd("animate", failing, "--frames", "5", "--out", anim)
t.check(code == 1 and "failing.json: cage: box 0 (label 1): the deformed box folds" in err
        and err.count("animating: frame") >= 2,
        "animate fails after frame 2 on the folded keyframe", err.strip())
t.check(not os.path.exists(anim) and leftovers() == [], "a failed animate leaves no frames, no temporary",
        (os.path.exists(anim), leftovers()))
code, out, err = lfd("animate", good, "--frames", "2", "--out", anim)
before = listing(anim) if code == 0 else {}
t.check(sorted(before) == sorted(["frame_0000.png", "frame_0001.png"] + MOVIE)
        and f"in {anim}/frame_*.png" in out
        and ".tmp-" not in out + err, "animate writes 2 frames and names the target", out + err)
code, out, err = lfd("animate", failing, "--frames", "5", "--out", anim)
t.check(code == 1 and listing(anim) == before and leftovers() == [],
        "a failed animate leaves the existing output folder untouched", sorted(listing(anim)))
code, out, err = lfd("animate", good, "--frames", "3", "--out", anim)
t.check(code == 0 and sorted(f for f in listing(anim) if f.endswith(".png")) ==
        ["frame_0000.png", "frame_0001.png", "frame_0002.png"] and leftovers() == [],
        "a successful animate replaces the folder", sorted(listing(anim)))
# Out of core (issue 14): an untiled dataset is refused naming its first
# image; `lfd tile` makes one the cache reads, and the render equals the
# in-memory one byte for byte; a missing tile file is named.
expect(["render", good, "--cache-size", "16M", "--out", "n.png"], 1,
       f"lfd: error: {lf}/lightfield.json: field \"passes.coaxial[0]\": image {lf}/coaxial/view_0000.png: "
       "not tiled, so it cannot be read through the image cache (convert the dataset with `lfd tile`)")
tiled = os.path.join(WORK, "tiled.lf")
code, out, err = lfd("tile", lf, "--tile-size", "16", "--out", tiled)
t.check(code == 0 and os.path.isfile(os.path.join(tiled, "coaxial", "view_0000.tif")),
        "lfd tile writes tiled TIFF views", err.strip())
with open(good) as f:
    tiled_scene = json.load(f)
tiled_scene["lightfield"] = "tiled.lf"
tiled_json = os.path.join(WORK, "tiled.json")
with open(tiled_json, "w") as f:
    json.dump(tiled_scene, f)
renders = {}
for name, extra in (("memory.png", []), ("cached.png", ["--cache-size", "16M"])):
    code, out, err = lfd("render", tiled_json, *extra, "--out", os.path.join(WORK, name))
    renders[name] = open(os.path.join(WORK, name), "rb").read() if code == 0 else name
t.check(renders["memory.png"] == renders["cached.png"],
        "render --cache-size 16M equals the in-memory render byte for byte", err.strip())
os.remove(os.path.join(tiled, "coaxial", "view_0003.tif"))
expect(["render", tiled_json, "--cache-size", "16M", "--out", "n.png"], 1,
       f"lfd: error: {tiled}/lightfield.json: field \"passes.coaxial[3]\": image "
       f"{tiled}/coaxial/view_0003.tif: file not found")

mine = os.path.join(WORK, "mine")
os.makedirs(mine)
with open(os.path.join(mine, "notes.txt"), "w") as f:
    f.write("keep")
expect(["animate", good, "--frames", "2", "--out", mine], 1,
       f"lfd: error: --out {mine}: holds 'notes.txt', which lfd animate does not write; it "
       "replaces the whole folder, so choose a new or empty one")
t.check(os.listdir(mine) == ["notes.txt"], "a folder of the user's is never replaced", os.listdir(mine))
t.finish()
