// The Label pass of the fish: exact label values {0, 1, 2, 3} and parts
// where the mesh puts them (head at +X, tail at -X).
#include "lfdSynthesisTestUtilities.h"

#include <array>
#include <set>

int TestFishLabels(int, char*[])
{
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToFish();
  auto capture = lfdtest::RingCapture(source);
  capture->CaptureCoaxialOff();
  capture->CaptureDepthOff();
  capture->Update();
  vtkLightField* lightField = capture->GetOutput();
  vtkDataArray* label = lightField->GetPass(vtkLightField::LABEL);
  lfdtest::Check(
    lightField->GetPass(vtkLightField::COAXIAL) == nullptr, "no Coaxial pass when it is off", 0, 0);

  // No blending, no anti-aliasing: only the labels of the parts appear.
  std::set<int> values;
  for (vtkIdType p = 0; p < label->GetNumberOfTuples(); ++p)
  {
    values.insert(static_cast<int>(label->GetComponent(p, 0)));
  }
  std::cout << "label values:";
  for (int v : values)
  {
    std::cout << " " << v;
  }
  std::cout << "\n";
  lfdtest::Check(values == std::set<int>{ 0, 1, 2, 3 },
    "label set is {0, 1, 2, 3}",
    static_cast<double>(values.size()),
    4);

  // View 0 looks from +Z (image x along world +X), view 4 from -Z: the
  // head's mean column is right of the body's, the body's right of the
  // tail's, and the other way round from behind.
  for (int view : { 0, 4 })
  {
    std::array<double, 4> sum{};
    std::array<double, 4> count{};
    for (int y = 0; y < 128; ++y)
    {
      for (int x = 0; x < 128; ++x)
      {
        const int l =
          static_cast<int>(label->GetComponent(lightField->GetPointIndex(view, x, y), 0));
        sum[l] += x;
        count[l] += 1;
      }
    }
    const double head = sum[1] / std::max(count[1], 1.0);
    const double body = sum[2] / std::max(count[2], 1.0);
    const double tail = sum[3] / std::max(count[3], 1.0);
    std::cout << "view " << view << ": mean column head " << head << ", body " << body << ", tail "
              << tail << "; pixels " << count[1] << ", " << count[2] << ", " << count[3] << "\n";
    const double sign = view == 0 ? 1.0 : -1.0;
    lfdtest::Check(sign * (head - body) > 10.0,
      "head right of body (signed columns)",
      sign * (head - body),
      10.0);
    lfdtest::Check(sign * (body - tail) > 10.0,
      "body right of tail (signed columns)",
      sign * (body - tail),
      10.0);
    lfdtest::Check(count[2] > count[1] && count[2] > count[3],
      "body is the largest part",
      count[2],
      std::max(count[1], count[3]));
  }
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
