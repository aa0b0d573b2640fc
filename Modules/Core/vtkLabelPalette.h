/**
 * @class   vtkLabelPalette
 * @brief   chooses label colours as far apart as the camera can tell them
 *
 * Projector segmentation (Chen, Ofek, Shum, Levoy 2005, section 4.1) paints
 * each part of the object with one colour and recognises the colours in the
 * photographs, so the colours must be as far apart as possible *as the camera
 * sees them*. vtkLabelPalette picks NumberOfLabels colours among the
 * projector colours whose channels take Levels evenly spaced values (black
 * excluded: black is "no light", the unlabelled mask), maximising the
 * smallest CIELAB distance (Delta E*ab, see lfdColour.h) between any two of
 * them after the camera's colour response: camera RGB = ColourResponse x
 * projector RGB (a 3 x 3 row-major matrix, identity by default; measure it
 * by projecting pure red, green and blue). The choice is a greedy
 * farthest-point selection from the farthest pair, then single swaps while
 * they raise the smallest distance; it is deterministic.
 *
 * Build() fills a 3-component vtkUnsignedCharArray named "LabelPalette" with
 * NumberOfLabels + 1 tuples: tuple 0 is black (unlabelled), tuple i the
 * projector colour of label i; vtkLightField::SetPalette() stores it with the
 * light field and the dataset writer in lightfield.json.
 *
 * @sa vtkLightField vtkLightFieldCapture vtkProjectorSegmentation
 */
#ifndef vtkLabelPalette_h
#define vtkLabelPalette_h

#include "lfdCoreModule.h" // For export macro
#include "vtkObject.h"

class vtkUnsignedCharArray;

class LFDCORE_EXPORT vtkLabelPalette : public vtkObject
{
public:
  static vtkLabelPalette* New();
  vtkTypeMacro(vtkLabelPalette, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of parts to colour. Default 3.
   */
  vtkSetClampMacro(NumberOfLabels, int, 1, 255);
  vtkGetMacro(NumberOfLabels, int);
  ///@}

  ///@{
  /**
   * Values per channel of the candidate projector colours (Levels^3 - 1
   * candidates). Default 4: 0, 85, 170, 255.
   */
  vtkSetClampMacro(Levels, int, 2, 16);
  vtkGetMacro(Levels, int);
  ///@}

  ///@{
  /**
   * The camera's response to the projector's colours, row-major 3 x 3.
   * Default identity.
   */
  vtkSetVectorMacro(ColourResponse, double, 9);
  vtkGetVectorMacro(ColourResponse, double, 9);
  ///@}

  /**
   * Chooses the colours into `palette` (see the class description). Returns
   * false, with an error, when there are more labels than candidates.
   */
  bool Build(vtkUnsignedCharArray* palette);

  /**
   * The smallest Delta E*ab between two colours of the last Build(), as the
   * camera sees them.
   */
  vtkGetMacro(MinimumDistance, double);

  /**
   * The smallest Delta E*ab between two of the labelled colours (tuples 1..N)
   * of any palette, as given (no colour response); 0 with fewer than 2.
   */
  static double GetSeparation(vtkUnsignedCharArray* palette);

  /**
   * The palette a light field without one of its own (a capture without
   * projectors) is shown with, so that the cage widget, the calibration
   * views and the Studio colour label i alike: Build() of a default
   * vtkLabelPalette for labels 1..`largestLabel` (clamped to 1..255), with
   * more levels than the default when that many labels need them.
   */
  static void BuildDefault(int largestLabel, vtkUnsignedCharArray* palette);

protected:
  vtkLabelPalette();
  ~vtkLabelPalette() override = default;

  int NumberOfLabels = 3;
  int Levels = 4;
  double ColourResponse[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double MinimumDistance = 0.0;

private:
  vtkLabelPalette(const vtkLabelPalette&) = delete;
  void operator=(const vtkLabelPalette&) = delete;
};

#endif
