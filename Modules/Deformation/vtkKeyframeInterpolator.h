/**
 * @class   vtkKeyframeInterpolator
 * @brief   cage point positions over time, from keyframes
 *
 * A keyframe is the set of cage point positions at a time (DESIGN.md
 * section 2). vtkKeyframeInterpolator holds keyframes sorted by time and
 * interpolates the points at any time, per point and per coordinate:
 * linearly, or with a uniform Catmull-Rom spline through the keyframes
 * (C1-continuous motion; the first and last keyframes are repeated at the
 * ends). Times outside the keyframes clamp to the first or last one.
 *
 * @sa vtkDeformationCage vtkLightFieldScene
 */
#ifndef vtkKeyframeInterpolator_h
#define vtkKeyframeInterpolator_h

#include "lfdDeformationModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class vtkPoints;

class LFDDEFORMATION_EXPORT vtkKeyframeInterpolator : public vtkObject
{
public:
  static vtkKeyframeInterpolator* New();
  vtkTypeMacro(vtkKeyframeInterpolator, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Interpolation
  {
    LINEAR = 0,
    CATMULL_ROM = 1
  };

  ///@{
  /**
   * How points move between keyframes. Default CATMULL_ROM.
   */
  vtkSetClampMacro(Interpolation, int, LINEAR, CATMULL_ROM);
  vtkGetMacro(Interpolation, int);
  void SetInterpolationToLinear() { this->SetInterpolation(LINEAR); }
  void SetInterpolationToCatmullRom() { this->SetInterpolation(CATMULL_ROM); }
  ///@}

  /**
   * Adds a keyframe (the points are copied). Returns false, with an error,
   * when its number of points differs from the keyframes already there or
   * its time is already taken.
   */
  bool AddKeyframe(double time, vtkPoints* points);

  /**
   * Removes every keyframe.
   */
  void RemoveAllKeyframes();

  ///@{
  /**
   * Number of keyframes, first and last time (0 without keyframes).
   */
  int GetNumberOfKeyframes() const;
  double GetStartTime() const;
  double GetEndTime() const;
  ///@}

  /**
   * The points at `time` into `points` (resized). Returns false without
   * keyframes.
   */
  bool InterpolatePoints(double time, vtkPoints* points) const;

protected:
  vtkKeyframeInterpolator();
  ~vtkKeyframeInterpolator() override;

  int Interpolation = CATMULL_ROM;

private:
  vtkKeyframeInterpolator(const vtkKeyframeInterpolator&) = delete;
  void operator=(const vtkKeyframeInterpolator&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
