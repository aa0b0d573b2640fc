"""Where the deformation loss comes from (issue 11 item 5): the figure
twisted 40 degrees and the swimming fish against their ground truth
(vtkGroundTruthEvaluator), split into

  (a) warp exactness: the paper's single straight warped ray per box (k = 1)
      against the tessellated warp that follows the curved rest-space image
      of each view ray (k = 8, 1/64 of the straight ray's deviation), and
      the automatic subdivision (the k it picks from the measured warp
      deviation: 1 at rest, more for a stronger twist);
  (b) the focal surface in rest space: optional (--focal, slow), the same
      loss from a ring of 4x as many views, where a wrong focal surface
      ghosts 4x less;
  (c) label edges: PSNR over the object pixels, over the interior (2 pixels
      or more away from every label edge in both images) and over the edge
      band, with hard label edges (the vote) and anti-aliased silhouettes;
  (d) lighting: the same loss with the light field and the ground truth
      captured unlit (ambient 1), where shading cannot fail to follow the
      deformation.

Prints the README's table; checks the figures a little under the measured
ones. Run alone for the table: python3 TestDeformationLoss.py [--focal]."""

import sys

import lfdtesting as t
import numpy as np

import lfd

SIZE = 256
FOCAL = "--focal" in sys.argv


def erode(mask, pixels):
    """`mask` without the pixels within `pixels` (4-neighbour steps) of its outside."""
    for _ in range(pixels):
        p = np.pad(mask, 1)
        mask = p[1:-1, 1:-1] & p[:-2, 1:-1] & p[2:, 1:-1] & p[1:-1, :-2] & p[1:-1, 2:]
    return mask


def regions(ev):
    """(object, interior, edge band) PSNR of an evaluation's render against its truth."""
    render = t.image_array(ev.GetOutput(0)).astype(float)
    truth = t.image_array(ev.GetOutput(1)).astype(float)
    label = t.image_array(ev.GetOutput(0), "Label")[..., 0]
    true_label = t.image_array(ev.GetOutput(1), "Label")[..., 0]
    obj = (label > 0) | (true_label > 0)
    interior = np.zeros_like(obj)
    for part in np.unique(true_label[true_label > 0]):
        interior |= erode((label == part) & (true_label == part), 2)
    return (t.psnr(render, truth, obj), t.psnr(render, truth, interior),
            t.psnr(render, truth, obj & ~interior))


def evaluate(source, lf, cage, camera, subdivision=1, anti_aliasing=False, ambient=0.1):
    return regions(t.evaluate(f"k={subdivision} aa={anti_aliasing:d} ambient={ambient}", source,
                              lf, cage, camera, subdivision, SIZE, anti_aliasing=anti_aliasing,
                              ambient=ambient))


def automatic_k(lf, cage, camera):
    """The largest k the automatic subdivision picks for `cage` from `camera`."""
    renderer = lfd.vtkLightFieldRenderer()
    renderer.SetInputData(lf)
    renderer.SetCageData(cage)
    renderer.SetCamera(camera)
    renderer.SetWidth(SIZE)
    renderer.SetHeight(SIZE)
    renderer.SetSubdivision(0)
    renderer.Update()
    return renderer.GetLastMaximumSubdivision()


def case(name, obj, pose, camera_of, **capture):
    """The rows of one object and pose: {row: (object, interior, edge) PSNR},
    and the automatic k for the cage at rest and posed."""
    rows = {}
    for ambient in (0.1, 1.0):
        source, lf = t.capture(obj, Ambient=ambient, **capture)
        parts = lfd.vtkPartCageSource()
        parts.SetInputConnection(source.GetOutputPort())
        parts.Update()
        camera = camera_of(lf.GetRig())
        posed = pose(parts.GetOutputPort())
        lit = "" if ambient < 1.0 else " unlit"
        rows["rest" + lit] = evaluate(source, lf, parts.GetOutput(), camera, ambient=ambient)
        rows["k=1" + lit] = evaluate(source, lf, posed, camera, ambient=ambient)
        if ambient < 1.0:
            rows["k=8"] = evaluate(source, lf, posed, camera, 8)
            rows["k=1 aa"] = evaluate(source, lf, posed, camera, 1, True)
            rows["auto aa"] = evaluate(source, lf, posed, camera, 0, True)
            ks = (automatic_k(lf, parts.GetOutput(), camera), automatic_k(lf, posed, camera))
    if FOCAL:
        source, lf = t.capture(obj, ViewsPerRing=480, **capture)
        parts = lfd.vtkPartCageSource()
        parts.SetInputConnection(source.GetOutputPort())
        parts.Update()
        camera = camera_of(lf.GetRig())
        rows["rest 4x views"] = evaluate(source, lf, parts.GetOutput(), camera)
        rows["k=1 4x views"] = evaluate(source, lf, pose(parts.GetOutputPort()), camera)
    print(f"\n{name}: PSNR dB (object / interior / edge band)")
    for row, (whole, inside, edge) in rows.items():
        print(f"  {row:16s} {whole:6.2f} {inside:6.2f} {edge:6.2f}")
    print(f"  automatic k: at rest {ks[0]}, posed {ks[1]}")
    return rows, ks


def loss(rows, rest, deformed, region):
    return rows[rest][region] - rows[deformed][region]


def breakdown(name, rows):
    """The loss and its parts, printed as the README's table rows."""
    print(f"\n{name}: deformation loss (k = 1, hard edges) and where it comes from, dB")
    print(f"  loss, object / interior / edge band: {loss(rows, 'rest', 'k=1', 0):.2f} / "
          f"{loss(rows, 'rest', 'k=1', 1):.2f} / {loss(rows, 'rest', 'k=1', 2):.2f}")
    print(f"  (a) warp exactness, interior gain of k = 8: "
          f"{rows['k=8'][1] - rows['k=1'][1]:.2f} (object {rows['k=8'][0] - rows['k=1'][0]:.2f})")
    if FOCAL:
        print(f"  (b) focal surface: interior loss with 4x views "
              f"{loss(rows, 'rest 4x views', 'k=1 4x views', 1):.2f} (1x: "
              f"{loss(rows, 'rest', 'k=1', 1):.2f})")
    print(f"  (c) label edges: object - interior loss {loss(rows, 'rest', 'k=1', 0) - loss(rows, 'rest', 'k=1', 1):.2f};"
          f" anti-aliasing gain, object {rows['k=1 aa'][0] - rows['k=1'][0]:.2f}, edge band "
          f"{rows['k=1 aa'][2] - rows['k=1'][2]:.2f}")
    print(f"  (d) lighting: interior loss lit - unlit "
          f"{loss(rows, 'rest', 'k=1', 1) - loss(rows, 'rest unlit', 'k=1 unlit', 1):.2f}")
    print(f"  fixed: auto subdivision + anti-aliasing, object {rows['auto aa'][0]:.2f} "
          f"(k = 1 hard {rows['k=1'][0]:.2f}, rest {rows['rest'][0]:.2f})")


def figure_camera(rig):
    return t.side_camera(rig, azimuth=0.2, angle=26.0)


figure, figure_k = case("figure twisted 40 degrees", lfd.vtkProceduralObjectSource.FIGURE,
              lambda port: t.pose(port, lfd.vtkCagePoseFilter.TWIST, 40.0).GetOutput(),
              figure_camera)
fish, fish_k = case("fish swim", lfd.vtkProceduralObjectSource.FISH,
            lambda port: t.pose(port, lfd.vtkCagePoseFilter.SWIM, 20.0, (0, 0, 1),
                                1.0).GetOutput(),
            t.side_camera)
breakdown("figure twisted 40 degrees", figure)
breakdown("fish swim", fish)

# Thresholds a little under the measured figures (README, "Where the
# deformation loss comes from").
# (At the default tolerance of half a pixel: the twist's boxes bend by
# several pixels at k = 1.)
t.check(figure_k == (1, 5), "figure: automatic k at rest, twisted 40 degrees", figure_k)
t.check(fish_k == (1, 6), "fish: automatic k at rest, swimming", fish_k)
t.check(figure["k=8"][1] - figure["k=1"][1] > 1.4,
        "figure: (a) the exact warp (k = 8) gains > 1.4 dB in the interior",
        figure["k=8"][1] - figure["k=1"][1])
t.check(fish["k=8"][1] - fish["k=1"][1] > 1.0,
        "fish: (a) the exact warp (k = 8) gains > 1.0 dB in the interior",
        fish["k=8"][1] - fish["k=1"][1])
for name, rows in (("figure", figure), ("fish", fish)):
    lighting = loss(rows, "rest", "k=1", 1) - loss(rows, "rest unlit", "k=1 unlit", 1)
    t.check(abs(lighting) < 0.4, f"{name}: (d) lighting explains < 0.4 dB of the interior loss",
            lighting)
t.check(fish["k=1 aa"][0] - fish["k=1"][0] > 0.6,
        "fish: (c) anti-aliased silhouettes gain > 0.6 dB (object)", fish["k=1 aa"][0] - fish["k=1"][0])
t.check(fish["k=1 aa"][1] == fish["k=1"][1],
        "fish: anti-aliasing leaves the interior as it was", (fish["k=1 aa"][1], fish["k=1"][1]))
t.check(figure["auto aa"][0] > 17.7,
        "figure: automatic subdivision + anti-aliasing > 17.7 dB (object; k = 1 16.93, rest 17.64)",
        figure["auto aa"][0])
t.finish()
