"""The README's tour runs as written (issue 8, item 8): the shell blocks after
the markers `<!-- tour: ... -->` are run line by line, in order, from a folder
laid out like the repository root (`build` -> this build, `lfd-demo/` written
by `lfd demo` as `bash Utilities/run.sh demo` does, `../shared/data/templeRing`
-> the test data), and every line must exit 0. The templeRing block is skipped
(exit 125 after the first block passed) when its data is missing."""
import os
import re
import shlex
import shutil
import subprocess
import sys

import lfdtesting as t

readme = open(os.path.join(os.environ["LFD_SOURCE_DIR"], "README.md")).read()
blocks = re.findall(r"<!-- tour: ([^>]*?) -->\s*```sh\n(.*?)```", readme, re.S)
t.check(len(blocks) == 2, "the README has two tour blocks", [name for name, _ in blocks])

root = os.path.join(t.TEMP_DIR, "readme-tour")
shutil.rmtree(root, ignore_errors=True)
repo = os.path.join(root, "repo")
os.makedirs(os.path.join(root, "shared", "data"))
os.makedirs(repo)
# build/bin/lfd is the executable under test.
os.symlink(os.path.dirname(os.path.dirname(t.LFD)), os.path.join(repo, "build"))
if os.path.isfile(os.path.join(t.TEMPLERING_DIR, "templeR_par.txt")):
    os.symlink(t.TEMPLERING_DIR, os.path.join(root, "shared", "data", "templeRing"))

# What `bash Utilities/run.sh demo` leaves behind (a smaller animation).
demo = subprocess.run([t.LFD, "demo", "--frames", "4"], cwd=repo, capture_output=True, text=True)
t.check(demo.returncode == 0, "lfd demo (the README's first command) writes lfd-demo/",
        demo.returncode or "ok")
if demo.returncode:
    t.finish()


def run_block(name, text, environment=None):
    """Runs the block's lines in one shell (`export PATH=...` carries over, as
    in a terminal), echoing each line before it runs; stops at the first
    failing line."""
    lines = [line for line in text.replace("\\\n", " ").splitlines() if line.strip()]
    script = "set -e -o pipefail\n" + "".join(
        f"printf '+ %s\\n' {shlex.quote(line)} >&2\n{line}\n" for line in lines)
    result = subprocess.run(["bash", "-c", script], cwd=repo, capture_output=True, text=True,
                            env=environment)
    t.check(result.returncode == 0, f"tour block '{name}': {len(lines)} lines run as written",
            "ok" if result.returncode == 0 else result.stderr[-2000:])


run_block(*blocks[0])
for produced in ("view.png", "frames/frame_0005.png", "fish4.lf", "split.lf", "bent.json", "bent.png",
                 "parts.json", "view10.png", "parts.lf", "series/cage.pvd", "series/frame_0003.vti",
                 "paraview/rig.vtp", "paraview/cage.vtu", "paraview/vtkjs/index.json"):
    t.check(os.path.exists(os.path.join(repo, produced)), f"the tour wrote {produced}", "")
if os.path.islink(os.path.join(root, "shared", "data", "templeRing")):
    # The same terminal: the first block's `export PATH=...` still holds.
    terminal = dict(os.environ, PATH=os.path.join(repo, "build", "bin") + os.pathsep + os.environ["PATH"])
    run_block(*blocks[1], terminal)
    for produced in ("temple.lf", "temple-rows.lf", "lfd-demo-temple/contact_sheet.png"):
        t.check(os.path.exists(os.path.join(repo, produced)), f"the tour wrote {produced}", "")
else:
    t.skipped.append("the templeRing block of the tour")
t.finish()
