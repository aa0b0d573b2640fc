"""The real COLMAP on a synthetic turntable capture, end to end, without a
known lens: lfd synth captures a sphere with a band-pass noise texture (SfM
needs texture), lfd export colmap --binary writes its views, colmap (CPU)
self-calibrates one shared SIMPLE_RADIAL camera from the images alone
(feature_extractor --ImageReader.single_camera 1, matches between ring
neighbours through matches_importer, mapper), lfd import colmap reads the
mapper's binary model as it is, and the recovered rig matches the true one
up to a similarity (Umeyama): every view registered, rotation error in
degrees, centre error relative to the ring radius, focal length. On the way,
COLMAP's model_converter checks the binary model files both ways: lfd's
binary export read by COLMAP and written back as text, COLMAP's own binary
written from that text, and the mapper's binary model against its text
conversion, each imported to the same rig to 1e-9. Skipped (125) when colmap
is not installed."""

import os
import resource
import shutil
import subprocess
import time

import lfdtesting as t
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkTexturedSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

import lfd

VIEWS = 24
# Each view is matched with its next NEIGHBOURS views round the ring: a
# turntable's order is known, and 96 pairs cost a third of exhaustive
# matching's 276 (the neighbours beyond 60 degrees share few features).
NEIGHBOURS = 4
# A wide lens close to the object: strong perspective is what fixes the
# focal length (at 40 degrees and 1.6 radii, weak perspective, COLMAP's
# focal length wandered from -1.8 % to +5.9 % between runs).
VIEW_ANGLE = 60.0  # degrees, vertical: f = 120 / tan(30 degrees) = 207.8 pixels
RING_RADIUS = 1.1  # the sphere's radius is 0.5: it fills the frame
# Measured 2026-11-26 (24 views of 320x240, 2 shared cores, four runs; the
# mapper's RANSAC is seeded per thread, so runs differ): largest rotation
# error 0.21-0.28 degrees, largest centre error 0.25-0.34 % of the ring
# radius, focal length -2.75 to +0.5 % (one shared SIMPLE_RADIAL camera: the
# runs at -2.5 % found k = 0.02 instead of 0, f and k trading off; 36 views
# or 480x360 did the same). Six more runs on 2026-11-26 (one of them in a
# full test run on the loaded cores): 0.22-0.28 degrees and 0.26-0.35 %, and
# once 0.58 degrees and 0.62 %, which failed the earlier bounds of 0.4 degrees
# and 0.5 %; one thread per COLMAP step and a fixed --random_seed did not
# make the runs repeat. The bounds sit above that spread, far under the
# errors of a wrong convention (a transposed rotation or a camera centre
# taken for t: tens of degrees, whole radii).
MAX_ROTATION_DEGREES = 0.8
MAX_CENTRE_ERROR = 0.008
MAX_FOCAL_ERROR = 0.04

COLMAP = shutil.which("colmap")
if not COLMAP:
    print("skipped: colmap is not installed (Debian package colmap)")
    raise SystemExit(t.SKIP_RETURN_CODE)

WORK = t.temp_path("colmap-e2e", "x")[:-2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)


def cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


# A step takes 1-11 s here. COLMAP 3.8's CPU matcher rarely deadlocks once
# its work is done (seen once here, under load: matches_importer after its
# usual 4 s of CPU, both threads waiting on a futex; COLMAP fixed
# a deadlock of its matcher's cache and database transaction in 2025, PR
# 3373): a step that outlives this is killed and run once more.
STEP_TIMEOUT = 120


def run(*args, database=None):
    """Runs one step; ends the test when it fails. A step that hangs past
    STEP_TIMEOUT runs once more, on a copy of `database` (the COLMAP
    database it writes) as it was before the step (whole: SQLite folds its
    write-ahead log into the file when the step before closes it)."""
    name = os.path.basename(args[0]) + " " + args[1]
    if database:
        shutil.copyfile(database, database + ".before")
    for attempt in (1, 2):
        started, cpu = time.time(), cpu_seconds()
        try:
            result = subprocess.run(list(args), capture_output=True, text=True,
                                    timeout=STEP_TIMEOUT)
            break
        except subprocess.TimeoutExpired:
            if attempt == 2 or database is None:
                t.check(False, f"{name} finishes within {STEP_TIMEOUT} s", f"hung {attempt} time(s)")
                t.finish()
            print(f"{name}: no answer after {STEP_TIMEOUT} s, killed; once more")
            for stale in (database + "-wal", database + "-shm"):
                if os.path.exists(stale):
                    os.remove(stale)
            shutil.copyfile(database + ".before", database)
    t.check(result.returncode == 0,
            f"{name} ({time.time() - started:.1f} s, {cpu_seconds() - cpu:.1f} s CPU)",
            result.stderr.strip()[-400:] or "ok")
    if result.returncode != 0:
        t.finish()
    return result.stdout


def band_noise(rng, shape, sigma):
    """Gaussian noise low-passed at `sigma` texels (periodic: the texture
    wraps round the sphere seamlessly), unit variance."""
    ky = np.fft.fftfreq(shape[0])[:, None]
    kx = np.fft.fftfreq(shape[1])[None, :]
    gain = np.exp(-2.0 * (np.pi * sigma) ** 2 * (kx ** 2 + ky ** 2))
    band = np.real(np.fft.ifft2(np.fft.fft2(rng.standard_normal(shape)) * gain))
    return band / band.std()


def write_inputs():
    """A textured sphere (.vtp with texture coordinates, poles on z) and its
    texture: blobs of 3, 8 and 20 texels (about 1 to 10 pixels in the
    views, the scales SIFT detects) in brightness, with some colour."""
    sphere = vtkTexturedSphereSource()
    sphere.SetThetaResolution(96)
    sphere.SetPhiResolution(48)
    sphere.SetRadius(0.5)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(sphere.GetOutputPort())
    writer.SetFileName(os.path.join(WORK, "sphere.vtp"))
    writer.Write()
    rng = np.random.default_rng(7)
    shape = (512, 1024)
    brightness = sum(band_noise(rng, shape, sigma) for sigma in (3.0, 8.0, 20.0))
    brightness /= brightness.std()
    channels = [brightness + 0.5 * band_noise(rng, shape, 20.0) for _ in range(3)]
    texture = np.stack([np.clip(128.0 + 50.0 * c, 0, 255) for c in channels], -1)
    image = vtkImageData()
    image.SetDimensions(shape[1], shape[0], 1)
    image.GetPointData().SetScalars(
        numpy_to_vtk(texture.astype(np.uint8).reshape(-1, 3), deep=True))
    png = vtkPNGWriter()
    png.SetInputData(image)
    png.SetFileName(os.path.join(WORK, "noise.png"))
    png.Write()


def import_rig(model, images):
    """The rig of a COLMAP model folder (binary or text), read by vtkColmapImporter."""
    importer = lfd.vtkColmapImporter()
    errors = t.error_observer(importer)
    importer.SetFileName(model)
    importer.SetImageDirectory(images)
    importer.Update()
    t.check(not errors.HasError(), f"import {os.path.relpath(model, WORK)}",
            errors.GetErrorMessage() or ("binary" if importer.GetBinaryModel() else "text"))
    return importer.GetOutput().GetRig()


def read_rig(path):
    reader = lfd.vtkLightFieldReader()
    errors = t.error_observer(reader)
    reader.SetFileName(path)
    reader.Update()
    t.check(not errors.HasError(), f"read {os.path.basename(path)}", errors.GetErrorMessage())
    return reader.GetOutput().GetRig()


def rig_difference(a, b):
    """The largest difference of K, R, t and distortion between two rigs of
    the same views."""
    largest = 0.0
    for v in range(a.GetNumberOfViews()):
        for getter, n in (("GetIntrinsics", 9), ("GetRotation", 9), ("GetTranslation", 3),
                          ("GetDistortion", 5)):
            x, y = [0.0] * n, [0.0] * n
            getattr(a, getter)(v, x)
            getattr(b, getter)(v, y)
            largest = max(largest, float(np.abs(np.subtract(x, y)).max()))
    return largest


def check_same_rig(what, a, b):
    same = a.GetNumberOfViews() == b.GetNumberOfViews()
    difference = rig_difference(a, b) if same else float("inf")
    t.check(same and difference < 1e-9, what + ": largest K/R/t/distortion difference",
            f"{difference:.3g} (bound 1e-9)")


def convert(model, out, kind):
    os.makedirs(out)
    run(COLMAP, "model_converter", "--input_path", model, "--output_path", out, "--output_type",
        kind)
    return out


def poses(rig):
    """Per view name: (R 3x3, centre)."""
    result = {}
    for v in range(rig.GetNumberOfViews()):
        R = [0.0] * 9
        centre = [0.0] * 3
        rig.GetRotation(v, R)
        rig.GetCameraCenter(v, centre)
        result[rig.GetViewName(v)] = (np.array(R).reshape(3, 3), np.array(centre))
    return result


def umeyama(source, target):
    """Similarity (s, Q, T) with target ~ s Q source + T (Umeyama 1991)."""
    mu_s, mu_t = source.mean(0), target.mean(0)
    a, b = source - mu_s, target - mu_t
    U, D, Vt = np.linalg.svd(b.T @ a / len(source))
    S = np.eye(3)
    S[2, 2] = np.sign(np.linalg.det(U) * np.linalg.det(Vt))
    Q = U @ S @ Vt
    s = np.trace(np.diag(D) @ S) / (a ** 2).sum(1).mean()
    return s, Q, mu_t - s * Q @ mu_s


write_inputs()
started, started_cpu = time.time(), cpu_seconds()
truth_lf = os.path.join(WORK, "truth.lf")
run(t.LFD, "synth", "--mesh", os.path.join(WORK, "sphere.vtp"), "--texture",
    os.path.join(WORK, "noise.png"), "--rows", "1", "--views", str(VIEWS), "--width", "320",
    "--height", "240", "--view-angle", str(VIEW_ANGLE), "--radius", str(RING_RADIUS), "--axis", "0", "0",
    "1", "--no-depth", "--out", truth_lf)
exported = os.path.join(WORK, "exported")
run(t.LFD, "export", "colmap", "--binary", truth_lf, "--out", exported)
images = os.path.join(exported, "images")
truth = read_rig(truth_lf)

# The binary layouts against COLMAP's own: lfd's binary export read by
# COLMAP (-> text), and COLMAP's binary written from that text.
as_text = convert(os.path.join(exported, "sparse"), os.path.join(WORK, "exported-txt"), "TXT")
as_binary = convert(as_text, os.path.join(WORK, "exported-bin"), "BIN")
check_same_rig("lfd's binary export, COLMAP's text of it", truth, import_rig(as_text, images))
check_same_rig("COLMAP's binary of that text", truth, import_rig(as_binary, images))

# Self-calibration: no lens given, one camera shared by every view.
database = os.path.join(WORK, "database.db")
run(COLMAP, "feature_extractor", "--database_path", database, "--image_path", images,
    "--ImageReader.single_camera", "1", "--ImageReader.camera_model", "SIMPLE_RADIAL",
    "--SiftExtraction.use_gpu", "0", "--SiftExtraction.num_threads", "2")
names = sorted(os.listdir(images))
pairs = os.path.join(WORK, "pairs.txt")
with open(pairs, "w") as stream:
    for i, name in enumerate(names):
        for step in range(1, NEIGHBOURS + 1):
            stream.write(f"{name} {names[(i + step) % len(names)]}\n")
run(COLMAP, "matches_importer", "--database_path", database, "--match_list_path", pairs,
    "--match_type", "pairs", "--SiftMatching.use_gpu", "0", "--SiftMatching.num_threads", "2",
    database=database)
mapped = os.path.join(WORK, "mapped")
os.makedirs(mapped)
run(COLMAP, "mapper", "--database_path", database, "--image_path", images, "--output_path", mapped,
    "--Mapper.num_threads", "2")
model = os.path.join(mapped, "0")
recovered_lf = os.path.join(WORK, "recovered.lf")
run(t.LFD, "import", "colmap", model, "--images", images, "--out", recovered_lf)
print(f"synth + export + colmap + import: {time.time() - started:.1f} s, "
      f"{cpu_seconds() - started_cpu:.1f} s CPU")
recovered_rig = read_rig(recovered_lf)
check_same_rig("the mapper's binary model, its text conversion", recovered_rig,
               import_rig(convert(model, os.path.join(WORK, "mapped-txt"), "TXT"), images))

recovered = poses(recovered_rig)
true_by_image = poses(import_rig(os.path.join(exported, "sparse"), images))
registered = sorted(set(recovered) & set(true_by_image))
t.check(len(registered) == VIEWS, "every view registered by COLMAP",
        f"{len(registered)} of {VIEWS}")
true_centres = np.array([true_by_image[n][1] for n in registered])
s, Q, T = umeyama(np.array([recovered[n][1] for n in registered]), true_centres)
radius = np.linalg.norm(true_centres - true_centres.mean(0), axis=1).mean()
centre_error = max(np.linalg.norm(s * Q @ recovered[n][1] + T - true_by_image[n][1])
                   for n in registered)
rotation_error = 0.0
for n in registered:
    # World-to-camera rotation of the recovered view in the true frame: R Q^T.
    relative = true_by_image[n][0] @ (recovered[n][0] @ Q.T).T
    angle = np.degrees(np.arccos(np.clip((np.trace(relative) - 1.0) / 2.0, -1.0, 1.0)))
    rotation_error = max(rotation_error, angle)
t.check(rotation_error < MAX_ROTATION_DEGREES, "largest rotation error (degrees)",
        f"{rotation_error:.4f} (bound {MAX_ROTATION_DEGREES})")
t.check(centre_error / radius < MAX_CENTRE_ERROR, "largest centre error / ring radius",
        f"{centre_error / radius:.5f} (bound {MAX_CENTRE_ERROR})")
K_true, K = [0.0] * 9, [0.0] * 9
truth.GetIntrinsics(0, K_true)
recovered_rig.GetIntrinsics(0, K)
focal_error = K[0] / K_true[0] - 1.0
shared = all(recovered_rig.GetIntrinsics(v, K_view) or K_view == K
             for v in range(recovered_rig.GetNumberOfViews()) for K_view in [[0.0] * 9])
t.check(shared and K[0] == K[4], "one camera shared by every view, fx = fy", shared)
t.check(abs(focal_error) < MAX_FOCAL_ERROR, "self-calibrated focal length (pixels)",
        f"{K[0]:.2f} against {K_true[0]:.2f}: {100 * focal_error:+.2f} % "
        f"(bound {100 * MAX_FOCAL_ERROR} %)")
t.finish()
