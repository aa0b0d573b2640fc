/**
 * @class   vtkProjectorSegmentation
 * @brief   labels the rays of a light field from projector colour masks (Eq. 1)
 *
 * Chen, Ofek, Shum and Levoy (I3D 2005, section 4.1) split a photographed
 * object by painting each part with one colour from video projectors: the
 * `Coded` pass photographs the object under the colour masks, the `Flood`
 * pass under the same projectors showing white. For every pixel:
 *
 * 1. **Normalisation** (their Eq. 1): B' = 256 B / W per channel, which
 *    cancels the albedo and the shading and leaves the mask colour. A
 *    channel whose W is below DarkThreshold carries no information (the
 *    surface does not reflect it, or no projector reaches it) and takes, for
 *    each palette colour, that colour's own value, so it neither helps nor
 *    hurts; a pixel with every channel dark is unlabelled (0), not a
 *    division by zero.
 * 2. **Classification** to the nearest palette colour (labels 1..N of the
 *    input's palette, vtkLightField::GetPalette(), or SetPalette()) by CIELAB
 *    distance Delta E*ab (lfdColour.h). The sensor noise sigma (NoiseSigma,
 *    or estimated from the Flood pass by Immerkaer's fast noise variance
 *    estimate, 1996) gives the pixel's colour noise s = 256 sigma / W (the
 *    largest over its bright channels). The nearest colour is accepted when
 *    its distance d1 is within max(RejectionFactor x S / 2, 3 s), S the
 *    smallest distance between two palette colours, and the runner-up is
 *    more than 2 s further (a tie is never accepted) and the confidence
 *    (d2 - d1) / (d2 + d1) is at least MinimumConfidence (a colour between
 *    two palette entries is rejected); otherwise the pixel is unlabelled.
 *    The Confidence pass stores 255 (d2 - d1) / (d2 + d1).
 * 3. **Clean-up** with OpenCV morphology, per label: an opening removes
 *    specks smaller than a disc of MorphologyRadius pixels, a closing fills
 *    unlabelled holes of that size where the Flood pass is lit.
 * 4. **Completion** (CompleteLabels, on by default, when the light field
 *    has a Coaxial pass): a projector labels only what it lights, and an
 *    object pixel left unlabelled renders as background once every label
 *    has a box. With two projectors on a 36-view ring more than half of the
 *    fish's object pixels are in no projector's light (the projectors face
 *    its ends, its flanks are lit at grazing angles or shadowed), so its
 *    own view 3 rendered at 15 dB against the photograph. The decided
 *    pixels of every view are therefore painted onto a proxy of the object
 *    (vtkLabelPropagation: the Depth pass when there is one, else the visual
 *    hull of the Coaxial silhouettes brighter than ObjectThreshold), as the
 *    paper suggests for painted labels (section 4.1), and every object pixel
 *    left undecided takes the label of the proxy voxel it sees. Decided
 *    pixels keep their label; completed ones have Confidence 0. A light
 *    field with no decided pixel is left as it is.
 *
 * The output holds the input's passes plus `Label` and `Confidence`.
 * Bad input (no Coded or Flood pass, no palette or fewer than 2 entries) is
 * one error naming what is missing.
 *
 * @sa vtkLabelPalette vtkLightFieldCapture vtkLightFieldSplitter vtkLabelPropagation
 */
#ifndef vtkProjectorSegmentation_h
#define vtkProjectorSegmentation_h

#include "lfdSegmentationModule.h" // For export macro
#include "vtkLightFieldSplitter.h"

class vtkUnsignedCharArray;

class LFDSEGMENTATION_EXPORT vtkProjectorSegmentation : public vtkLightFieldSplitter
{
public:
  static vtkProjectorSegmentation* New();
  vtkTypeMacro(vtkProjectorSegmentation, vtkLightFieldSplitter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The palette to classify against (3 x uint8 per label, entry 0 =
   * unlabelled). Default nullptr: the input's palette.
   */
  virtual void SetPalette(vtkUnsignedCharArray* palette);
  vtkGetObjectMacro(Palette, vtkUnsignedCharArray);
  ///@}

  ///@{
  /**
   * Sensor noise sigma in 8-bit levels; negative (default) estimates it from
   * the Flood pass. GetEstimatedNoise() returns the value used by the last
   * update.
   */
  vtkSetMacro(NoiseSigma, double);
  vtkGetMacro(NoiseSigma, double);
  vtkGetMacro(EstimatedNoise, double);
  ///@}

  ///@{
  /**
   * Flood level below which a channel is dark; negative (default) is
   * max(8, 5 sigma).
   */
  vtkSetMacro(DarkThreshold, double);
  vtkGetMacro(DarkThreshold, double);
  ///@}

  ///@{
  /**
   * Accepted distance to the nearest palette colour as a fraction of half
   * the palette's smallest separation. Default 1 (anything nearer to one
   * colour than halfway to the next).
   */
  vtkSetClampMacro(RejectionFactor, double, 0.0, 10.0);
  vtkGetMacro(RejectionFactor, double);
  ///@}

  ///@{
  /**
   * Smallest accepted confidence (d2 - d1) / (d2 + d1), in [0, 1]: colours
   * between two palette entries are rejected. Default 0.3 (the nearest
   * colour at most about half as far as the runner-up).
   */
  vtkSetClampMacro(MinimumConfidence, double, 0.0, 1.0);
  vtkGetMacro(MinimumConfidence, double);
  ///@}

  ///@{
  /**
   * Radius in pixels of the opening and closing discs; 0 disables the
   * clean-up. Default 1.
   */
  vtkSetClampMacro(MorphologyRadius, int, 0, 50);
  vtkGetMacro(MorphologyRadius, int);
  ///@}

  ///@{
  /**
   * Completes the object pixels the projectors left undecided through a
   * proxy of the object (step 4 above). Default on.
   */
  vtkSetMacro(CompleteLabels, bool);
  vtkGetMacro(CompleteLabels, bool);
  vtkBooleanMacro(CompleteLabels, bool);
  ///@}

  ///@{
  /**
   * Completion without a Depth pass: the Coaxial level (mean of RGB) above
   * which a pixel is object, for the visual hull. Default 20
   * (vtkLabelPropagation's Threshold).
   */
  vtkSetClampMacro(ObjectThreshold, double, 0.0, 255.0);
  vtkGetMacro(ObjectThreshold, double);
  ///@}

  /**
   * Pixels the last update's completion labelled (0 without completion).
   */
  vtkGetMacro(NumberOfCompletedPixels, vtkIdType);

protected:
  vtkProjectorSegmentation();
  ~vtkProjectorSegmentation() override;

  bool Split(vtkLightField* input, vtkLightField* output, std::string& error) override;

  /**
   * Step 4: the undecided object pixels of `output`'s Label pass take the
   * labels propagated from the decided ones.
   */
  bool Complete(vtkLightField* input, vtkLightField* output, std::string& error);

  vtkUnsignedCharArray* Palette = nullptr;
  double NoiseSigma = -1.0;
  double EstimatedNoise = 0.0;
  double DarkThreshold = -1.0;
  double RejectionFactor = 1.0;
  double MinimumConfidence = 0.3;
  int MorphologyRadius = 1;
  bool CompleteLabels = true;
  double ObjectThreshold = 20.0;
  vtkIdType NumberOfCompletedPixels = 0;

private:
  vtkProjectorSegmentation(const vtkProjectorSegmentation&) = delete;
  void operator=(const vtkProjectorSegmentation&) = delete;
};

#endif
