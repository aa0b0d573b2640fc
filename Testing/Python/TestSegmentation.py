"""Splitting a light field into parts (paper Sec. 4): projector segmentation
(Eq. 1 + CIELAB classification) on crafted pixels and on the synthetic fish
and figure against their true Label pass, label propagation through the
Depth pass, a visual hull and on the real templeRing, the box coverage
check, the render of a projector-split fish against the synthetic-label one,
and bad input. Thresholds sit just under the measured figures (README
results table)."""

import os
import sys

import lfdtesting as t
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader

import lfd

# Measured: fish 99.87 %, figure 99.98 %; with noise sigma 4 and 5 % room
# light, fish 99.87 % (sigma estimated 4.7) (99.5 %, 99.75 % and 98.9 %
# before the undecided pixels were completed through the Depth pass);
# propagation on the fish 99.6 % (depth), 93.3 % (visual hull); templeRing
# agreement 0.946 mean, 0.790 worst view (silhouette tolerance 1.5 px); split
# vs synthetic-label render 46.09 dB (41.7 dB before the completion; 92.6 %,
# 0.939, 0.787 and 46.57 dB before the silhouettes' holes were filled).
PROJECTOR_ACCURACY = 0.997
NOISY_ACCURACY = 0.997
DEPTH_PROPAGATION = 0.99
HULL_PROPAGATION = 0.91
TEMPLE_MEAN, TEMPLE_WORST = 0.93, 0.77
TEMPLE_BOX_MEAN, TEMPLE_BOX_WORST = 0.99, 0.95
SPLIT_RENDER_PSNR = 45.8


def quiet(algorithm):
    """Keeps an algorithm's expected errors off the log (ctest fails on them):
    they are recorded by an observer, kept as the algorithm's `errors`."""
    algorithm.errors = t.error_observer(algorithm)
    return algorithm


def palette(labels):
    colours = vtkUnsignedCharArray()
    chooser = lfd.vtkLabelPalette()
    chooser.SetNumberOfLabels(labels)
    chooser.Build(colours)
    return colours, chooser.GetMinimumDistance()


def light_field(coded, flood, colours):
    """A one-view light field of the given H x W x 3 Coded and Flood images."""
    h, w, _ = coded.shape
    lf = lfd.vtkLightField()
    lf.SetLayout(w, h, 1)
    for pass_id, image in ((lfd.vtkLightField.CODED, coded), (lfd.vtkLightField.FLOOD, flood)):
        array = lf.AllocatePass(pass_id)
        vtk_to_numpy(array)[:] = image[::-1].reshape(-1, 3)
    lf.SetPalette(colours)
    return lf


def labels_of(lf):
    w, h, v = lf.GetDimensions()
    return vtk_to_numpy(lf.GetPass(lfd.vtkLightField.LABEL)).reshape(v, h, w)


def segment(lf, **settings):
    seg = quiet(lfd.vtkProjectorSegmentation())
    for key, value in settings.items():
        getattr(seg, "Set" + key)(value)
    seg.SetInputData(lf)
    seg.Update()
    return seg


def capture(obj, projectors=4, noise=0.0, ambient=0.0):
    """90 views in one ring, with Depth, lit by projectors painting 3 parts."""
    return t.capture(obj, depth=True, ViewsPerRing=90, NumberOfRows=1, Palette=palette(3)[0],
                     NumberOfProjectors=projectors, ProjectorNoise=noise, ProjectorAmbient=ambient)


def accuracy(found, truth):
    """Fraction of the true object pixels with the true label, and the confusion."""
    object_pixels = truth > 0
    confusion = {int(l): np.bincount(found[truth == l], minlength=4)[:4].tolist()
                 for l in np.unique(truth[object_pixels])}
    return float((found[object_pixels] == truth[object_pixels]).mean()), confusion


# 1. Eq. 1 and the classification on crafted pixels.
colours, separation = palette(3)
pal = vtk_to_numpy(colours).astype(float)
t.check(separation > 100, "palette of 3: smallest CIELAB distance", round(separation, 1))
rows = []
expected = []
for label in (1, 2, 3):
    for albedo in (0.15, 0.4, 0.7, 1.0):  # albedo and shading variation
        rows.append((albedo * pal[label], albedo * np.full(3, 255.0)))
        expected.append(label)
rows.append((np.zeros(3), np.full(3, 3.0)))  # dark: no projector reaches it
expected.append(0)
for a, b in ((1, 2), (2, 3), (1, 3)):  # halfway between two palette colours
    rows.append((0.5 * (pal[a] + pal[b]), np.full(3, 255.0)))
    expected.append(0)
n = len(rows)
coded = np.repeat(np.array([r[0] for r in rows])[:, None, :], 7, axis=1)
flood = np.repeat(np.array([r[1] for r in rows])[:, None, :], 7, axis=1)
seg = segment(light_field(coded.round().astype(np.uint8), flood.astype(np.uint8), colours),
              NoiseSigma=0.0, MorphologyRadius=0)
found = labels_of(seg.GetOutput())[0][::-1][:, 3]
t.check(found.tolist() == expected, "Eq. 1 + nearest colour: albedo, dark and in-between pixels",
        found.tolist())
confidence = vtk_to_numpy(seg.GetOutput().GetPass(lfd.vtkLightField.CONFIDENCE))
t.check(confidence.max() == 255 and confidence.min() == 0, "confidence spans 0..255",
        (int(confidence.min()), int(confidence.max())))

# A red surface under a palette whose colours differ in green and blue only
# where it is dark: those channels cannot vote, a tie is unlabelled.
red_only = np.array([[[200, 0, 0]]], dtype=np.uint8)
tie = segment(light_field((red_only * 0).astype(np.uint8), red_only, colours),
              NoiseSigma=0.0, MorphologyRadius=0)
t.check(labels_of(tie.GetOutput()).item() == 0, "no information in the lit channel: unlabelled",
        labels_of(tie.GetOutput()).item())

# Noise: sigma 3 on a lit patch, estimated from the image.
rng = np.random.default_rng(7)
truth = np.kron(rng.integers(1, 4, size=(8, 8)), np.ones((8, 8), dtype=int))
albedo = np.linspace(0.4, 1.0, 64)[None, :, None] * np.ones((64, 1, 1))
coded = np.clip(albedo * pal[truth] + rng.normal(0, 3, (64, 64, 3)), 0, 255).round()
flood = np.clip(albedo * 255 + rng.normal(0, 3, (64, 64, 3)), 0, 255).round()
noisy = segment(light_field(coded.astype(np.uint8), flood.astype(np.uint8), colours),
                MorphologyRadius=0)
noisy_accuracy = float((labels_of(noisy.GetOutput())[0][::-1] == truth).mean())
t.check(noisy_accuracy > 0.99, "noisy crafted pixels classified", round(noisy_accuracy, 4))
t.check(2.0 < noisy.GetEstimatedNoise() < 4.0, "noise sigma 3 estimated from the Flood pass",
        round(noisy.GetEstimatedNoise(), 2))

# 2. Projector segmentation of the synthetic fish and figure.
fish, fish_lf = capture(lfd.vtkProceduralObjectSource.FISH)
projector_fish = lfd.vtkLightField()
for name, (obj, lf) in (("fish", (fish, fish_lf)),
                        ("figure", capture(lfd.vtkProceduralObjectSource.FIGURE))):
    seg = segment(lf)
    if name == "fish":
        projector_fish.ShallowCopy(seg.GetOutput())
    score, confusion = accuracy(labels_of(seg.GetOutput()), labels_of(lf))
    t.check(score >= PROJECTOR_ACCURACY, f"{name}: projector labels vs truth on object pixels",
            f"{100 * score:.2f} % (confusion truth -> [0,1,2,3]: {confusion})")
    unlabelled = int(((labels_of(seg.GetOutput()) == 0) & (labels_of(lf) > 0)).sum())
    t.check(seg.GetNumberOfCompletedPixels() > 0 and unlabelled == 0,
            f"{name}: object pixels no projector decided, completed through the Depth pass "
            "(completed, left unlabelled)", (seg.GetNumberOfCompletedPixels(), unlabelled))
_, noisy_fish = capture(lfd.vtkProceduralObjectSource.FISH, noise=4.0, ambient=0.05)
seg = segment(noisy_fish)
score, confusion = accuracy(labels_of(seg.GetOutput()), labels_of(noisy_fish))
t.check(score >= NOISY_ACCURACY, "fish with noise sigma 4 and 5 % room light",
        f"{100 * score:.2f} % (estimated sigma {seg.GetEstimatedNoise():.2f}; {confusion})")

# 3. Propagation from three views painted with the true labels.
truth = labels_of(fish_lf)
for proxy, threshold in ((lfd.vtkLabelPropagation.DEPTH, DEPTH_PROPAGATION),
                         (lfd.vtkLabelPropagation.VISUAL_HULL, HULL_PROPAGATION)):
    propagation = quiet(lfd.vtkLabelPropagation())
    for view in (0, 30, 60):
        painted = vtkImageData()
        painted.SetDimensions(fish_lf.GetWidth(), fish_lf.GetHeight(), 1)
        painted.GetPointData().SetScalars(numpy_to_vtk(truth[view].ravel().copy(), deep=True))
        propagation.SetPaintedView(view, painted)
    propagation.SetProxy(proxy)
    propagation.SetSilhouetteTolerance(0.0)  # the synthetic calibration is exact
    propagation.SetInputData(fish_lf)
    propagation.Update()
    score, confusion = accuracy(labels_of(propagation.GetOutput()), truth)
    name = "depth" if proxy == lfd.vtkLabelPropagation.DEPTH else "visual hull"
    t.check(score >= threshold, f"fish, 3 painted views -> 90 views through the {name}",
            f"{100 * score:.2f} % ({propagation.GetNumberOfProxyVoxels()} voxels; {confusion})")

# ... and on the real templeRing, from three painted views; consistency is the
# agreement with the same painting rule applied to every view.
sys.path.insert(0, os.path.join(os.path.dirname(t.BASELINE_DIR), "templeRing"))
import paint_labels  # noqa: E402

importer = t.templering("templeRing label propagation")
if importer:
    temple_dir = t.temp_path("segmentation", "temple.lf")
    temple = lfd.vtkLightField()
    temple.ShallowCopy(importer.GetOutput())
    writer = lfd.vtkLightFieldWriter()
    writer.SetInputData(temple)
    writer.SetDirectory(temple_dir)
    writer.Write()
    propagation = quiet(lfd.vtkLabelPropagation())
    for view in (0, 16, 32):
        reader = vtkPNGReader()
        reader.SetFileName(os.path.join(os.path.dirname(t.BASELINE_DIR), "templeRing",
                                        f"painted_view_{view:04d}.png"))
        reader.Update()
        painted = vtkImageData()
        painted.DeepCopy(reader.GetOutput())
        propagation.SetPaintedView(view, painted)
    propagation.SetThreshold(60)
    propagation.SetInputData(temple)
    propagation.Update()
    propagated = labels_of(propagation.GetOutput())
    signs = paint_labels.axis_signs(temple_dir)
    w, h, v = temple.GetDimensions()
    coaxial = vtk_to_numpy(temple.GetPass(lfd.vtkLightField.COAXIAL)).reshape(v, h, w, 3)
    agreement = []
    for view in range(v):
        rule = paint_labels.paint(coaxial[view].astype(float), signs[view])
        agreement.append(float((propagated[view][rule > 0] == rule[rule > 0]).mean()))
    t.check(np.mean(agreement) >= TEMPLE_MEAN and min(agreement) >= TEMPLE_WORST,
            "templeRing: 3 painted views -> 47, agreement with the painting rule (mean, worst)",
            (round(float(np.mean(agreement)), 3), round(min(agreement), 3)))

    # ... and by the box check: one slab per label along the ring axis, between
    # the heights where view 0's painted band starts and ends (projected along
    # the axis through the ring's centre), as wide as the temple.
    rig = temple.GetRig()
    centre, axis, radius = np.array(rig.GetCenter()), np.array(rig.GetAxis()), rig.GetRadius()
    K, R, tr = [0.0] * 9, [0.0] * 9, [0.0] * 3
    rig.GetIntrinsics(0, K)
    rig.GetRotation(0, R)
    rig.GetTranslation(0, tr)
    K, R, tr = np.array(K).reshape(3, 3), np.array(R).reshape(3, 3), np.array(tr)
    heights = np.linspace(-radius, radius, 2001)
    columns = [(K @ (R @ (centre + h * axis) + tr)) for h in heights]
    columns = np.array([c[0] / c[2] for c in columns])
    order = np.argsort(columns)
    painted0 = propagated[0][::-1]
    side = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 0.0, 1.0])
    side /= np.linalg.norm(side)
    other = np.cross(axis, side)
    # Half the box's side: the temple's largest width across the axis in the
    # painted views (image rows there, as the cameras are rolled), plus 10 %.
    distance = np.linalg.norm(R @ centre + tr)
    half = 0.55 * max(np.ptp(np.nonzero(propagated[v].any(axis=1))[0]) for v in (0, 16, 32)) \
        * distance / K[1, 1]
    cage = lfd.vtkDeformationCage()
    for label in (1, 2, 3):
        band = np.nonzero((painted0 == label).any(axis=0))[0]
        low, high = sorted(np.interp([band.min() - 0.5, band.max() + 0.5], columns[order], heights[order]))
        ids = [cage.AddPoint(list(centre + h * axis + half * (a * side + b * other)))
               for h in (low, high) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        cage.AddBox(ids, label)
    check = lfd.vtkBoxCoverageCheck()
    check.SetInputData(0, propagation.GetOutput())
    check.SetCageData(cage)
    check.Update()
    table = vtk_to_numpy(check.GetOutput().GetColumnByName("Fraction"))
    worst = [round(check.GetWorstFraction(i), 3) for i in range(check.GetNumberOfLabels())]
    t.check(float(np.mean(table)) > TEMPLE_BOX_MEAN and min(worst) > TEMPLE_BOX_WORST,
            "templeRing: propagated labels inside slab boxes from view 0 (mean over views, worst per label)",
            (round(float(np.mean(table)), 3), worst))
    swapped = lfd.vtkDeformationCage()
    swapped.DeepCopy(cage)
    swapped.GetCellData().GetArray("Label").SetValue(0, 3)
    swapped.GetCellData().GetArray("Label").SetValue(2, 1)
    check.SetCageData(swapped)
    check.Update()
    table = vtk_to_numpy(check.GetOutput().GetColumnByName("Fraction"))
    t.check(float(np.mean(table)) < 0.75, "templeRing: the same slabs with labels 1 and 3 swapped fail",
            round(float(np.mean(table)), 3))

# 4. Box coverage: the fish's part boxes hold their labels; without a box a
# label covers nothing.
parts = lfd.vtkPartCageSource()
parts.SetInputConnection(fish.GetOutputPort())
parts.Update()
check = lfd.vtkBoxCoverageCheck()
check.SetInputData(0, projector_fish)
check.SetCageData(parts.GetOutput())
check.Update()
worst = [round(check.GetWorstFraction(i), 4) for i in range(check.GetNumberOfLabels())]
t.check(check.GetNumberOfLabels() == 3 and check.GetPassed() and min(worst) > 0.97,
        "projector-split fish inside its part boxes (worst fraction per label)", worst)
t.check(list(check.GetLabelsWithoutBox()) == [] and list(check.GetBoxLabelsWithoutPixels()) == [],
        "the fish's labels and its boxes' labels match",
        (check.GetLabelsWithoutBox(), check.GetBoxLabelsWithoutPixels()))
table = check.GetOutput()
split_labels = labels_of(projector_fish)
pairs = sum(len(set(np.unique(view).tolist()) - {0}) for view in split_labels)
t.check(table.GetNumberOfRows() == pairs, "coverage table: one row per label seen in a view",
        (table.GetNumberOfRows(), pairs))
relabelled = lfd.vtkDeformationCage()
relabelled.DeepCopy(parts.GetOutput())
labels_array = relabelled.GetCellData().GetArray("Label")
for box in range(labels_array.GetNumberOfTuples()):
    if labels_array.GetValue(box) == 1:  # label 1's boxes now claim label 3
        labels_array.SetValue(box, 3)
check.SetCageData(relabelled)
check.Update()
t.check(not check.GetPassed() and check.GetWorstFraction(0) == 0.0,
        "a label without a box fails the check", check.GetWorstFraction(0))
t.check(list(check.GetLabelsWithoutBox()) == [1] and list(check.GetBoxLabelsWithoutPixels()) == [],
        "label 1 has pixels but no box (its boxes claim label 3)",
        (check.GetLabelsWithoutBox(), check.GetBoxLabelsWithoutPixels()))
relabelled_labels = relabelled.GetCellData().GetArray("Label")
relabelled_labels.SetValue(0, 7)  # a box of a label no pixel has
relabelled.Modified()
check.Update()
t.check(7 in list(check.GetBoxLabelsWithoutPixels()),
        "a box label without pixels is listed", check.GetBoxLabelsWithoutPixels())

# 5. The projector-split fish deforms like the synthetic-label one.
pose = t.pose(parts.GetOutputPort(), lfd.vtkCagePoseFilter.SWIM, 20.0, (0, 0, 1), 1.0)
camera = t.side_camera(fish_lf.GetRig())
renders = []
for lf in (fish_lf, projector_fish):
    renderer = lfd.vtkLightFieldRenderer()
    renderer.SetInputData(lf)
    renderer.SetCageData(pose.GetOutput())
    renderer.SetCamera(camera)
    renderer.SetWidth(256)
    renderer.SetHeight(256)
    renderer.Update()
    renders.append(t.image_array(renderer.GetOutput()).astype(float))
psnr = t.psnr(renders[0], renders[1])
t.check(psnr >= SPLIT_RENDER_PSNR, "swimming fish: projector-split vs synthetic-label render (PSNR dB)",
        round(psnr, 2))

# 6. Bad input: clear errors.
no_flood = lfd.vtkLightField()
no_flood.DeepCopy(fish_lf)
no_flood.GetPointData().RemoveArray("Flood")
seg = segment(no_flood)
t.check("no Flood pass" in seg.errors.GetErrorMessage(), "missing Flood pass",
        seg.errors.GetErrorMessage())
# Projector labels on an object the Coaxial pass does not show: the
# completion has no hull to carry them through, one error says so.
unseen = light_field(np.tile(pal[1].astype(np.uint8), (8, 8, 1)), np.full((8, 8, 3), 255, np.uint8),
                     colours)
unseen.AllocatePass(lfd.vtkLightField.COAXIAL).Fill(0)
seg = segment(unseen, NoiseSigma=0.0, MorphologyRadius=0)
t.check(seg.errors.GetErrorMessage() == "vtkProjectorSegmentation: completing the pixels no "
        "projector decided through the visual hull (Coaxial brighter than ObjectThreshold 20): "
        "vtkLabelPropagation: no painted pixel lands on the proxy (are the label images empty, "
        "or of other views?)" and seg.GetOutput().GetNumberOfPoints() == 0,
        "completion without an object in the Coaxial pass: one error, no output",
        seg.errors.GetErrorMessage())
no_palette = lfd.vtkLightField()
no_palette.DeepCopy(fish_lf)
no_palette.SetPalette(None)
seg = segment(no_palette)
t.check("palette" in seg.errors.GetErrorMessage(), "missing palette", seg.errors.GetErrorMessage())
masks = vtkImageData()
masks.SetDimensions(10, 10, 4)
masks.GetPointData().SetScalars(numpy_to_vtk(np.zeros((400, 3), np.uint8), deep=True))


def failed_capture(**settings):
    """A 4-view capture of the fish that must fail: its error message, and
    whether it left an empty output."""
    source = lfd.vtkProceduralObjectSource()
    cap = quiet(lfd.vtkLightFieldCapture())
    cap.SetInputConnection(source.GetOutputPort())
    cap.SetViewsPerRing(4)
    cap.SetNumberOfRows(1)
    for name, value in settings.items():
        getattr(cap, "Set" + name)(value)
    cap.Update()
    return cap.errors.GetErrorMessage(), cap.GetOutput().GetNumberOfPoints() == 0


message, empty = failed_capture(NumberOfProjectors=4, ProjectorMasks=masks)
t.check(empty and "10x10x4" in message, "masks of the wrong size: one error, no output", message)
short_palette = vtkUnsignedCharArray()
short_palette.SetNumberOfComponents(3)
short_palette.InsertNextTuple3(0, 0, 0)
short_palette.InsertNextTuple3(255, 0, 0)
message, empty = failed_capture(NumberOfProjectors=2, Palette=short_palette)
t.check(empty and "part label 3" in message, "a palette with fewer colours than parts", message)
wrong = vtkImageData()
wrong.SetDimensions(10, 10, 1)
wrong.GetPointData().SetScalars(numpy_to_vtk(np.ones(100, np.uint8), deep=True))
propagation = quiet(lfd.vtkLabelPropagation())
propagation.SetPaintedView(0, wrong)
propagation.SetInputData(fish_lf)
propagation.Update()
message = propagation.errors.GetErrorMessage()
t.check("10x10" in message and "256x256" in message, "painted label image of the wrong size",
        message)
t.finish()
