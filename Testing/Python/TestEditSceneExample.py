"""Examples/EditScene.py, the editor without Qt from a script: on a small
`lfd demo` fish it plays a recorded drag of a shared corner (one command of
the scene logic, the point moved, the full-resolution frame after release),
undoes it, and the scene it saves is byte for byte the demo's; a missing
scene is one readable error."""

import os
import shutil
import subprocess
import sys

import lfdtesting as t

EXAMPLE = os.path.join(os.environ.get("LFD_SOURCE_DIR", ""), "Examples", "EditScene.py")
folder = os.path.join(t.TEMP_DIR, "TestEditSceneExample")
shutil.rmtree(folder, ignore_errors=True)
demo = subprocess.run([t.LFD, "demo", "--out", folder, "--frames", "1", "--size", "64", "--views", "36",
                       "--rows", "1", "--capture-size", "96"], capture_output=True, text=True, timeout=600)
t.check(demo.returncode == 0, "lfd demo writes the fish scene", demo.returncode or demo.stderr)
scene = os.path.join(folder, "swim.json")
saved = os.path.join(folder, "edited.json")


def example(*args):
    return subprocess.run([sys.executable, EXAMPLE, *args], capture_output=True, text=True, timeout=600)


run = example(scene, "--replay", "--save", saved)
print(run.stdout)
lines = run.stdout.splitlines()
t.check(run.returncode == 0, "the example runs", run.returncode or run.stderr)
t.check(len(lines) == 4 and lines[0].startswith("dragged point ") and " from " in lines[0], "it drags a point",
        lines[:1])
t.check("commands: 1, undo: Move 1 point" in lines, "the drag is one command of the scene logic", lines[1:2])
t.check("last frame: 800x600" in lines, "the release renders at full resolution", lines[2:3])
t.check("undone: True" in lines, "the undo puts the point back", lines[3:])
with open(scene, "rb") as a, open(saved, "rb") as b:
    t.check(a.read() == b.read(), "the scene saved after the undo is the demo's, byte for byte", saved)

missing = example(os.path.join(folder, "missing.json"))
t.check(missing.returncode == 1 and missing.stderr.strip() == "EditScene.py: {}: file not found".format(
    os.path.join(folder, "missing.json")), "a missing scene: one error line", missing.stderr.strip())
t.finish()
