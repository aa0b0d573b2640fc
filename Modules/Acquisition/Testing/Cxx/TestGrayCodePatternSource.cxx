// Gray-code patterns: decoding every pattern pair at every pixel gives back
// the pixel's column and row exactly (for a size that is not a power of
// two), neighbouring columns differ in exactly one pattern, and an index
// out of range is one error.
#include "vtkGrayCodePatternSource.h"
#include "vtkImageData.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"

#include <iostream>
#include <string>
#include <vector>

int TestGrayCodePatternSource(int, char*[])
{
  int failures = 0;
  auto check = [&](bool ok, const std::string& what, double value, double expected)
  {
    std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << " (expected " << expected
              << ")\n";
    failures += ok ? 0 : 1;
  };
  vtkNew<vtkGrayCodePatternSource> source;
  const int width = 100;
  const int height = 37;
  source->SetWidth(width);
  source->SetHeight(height);
  check(source->GetNumberOfColumnBits() == 7, "column bits", source->GetNumberOfColumnBits(), 7);
  check(source->GetNumberOfRowBits() == 6, "row bits", source->GetNumberOfRowBits(), 6);
  check(source->GetNumberOfPatterns() == 26, "patterns", source->GetNumberOfPatterns(), 26);

  // Decode: bit set where pattern 2m is brighter than its inverse 2m + 1.
  std::vector<int> column(width * height, 0);
  std::vector<int> row(width * height, 0);
  int bothEqual = 0;
  for (int m = 0; m < source->GetNumberOfPatterns() / 2; ++m)
  {
    vtkNew<vtkImageData> pattern;
    vtkNew<vtkImageData> inverse;
    source->SetPatternIndex(2 * m);
    source->Update();
    pattern->DeepCopy(source->GetOutput());
    source->SetPatternIndex(2 * m + 1);
    source->Update();
    inverse->DeepCopy(source->GetOutput());
    const auto* on = static_cast<unsigned char*>(pattern->GetScalarPointer());
    const auto* off = static_cast<unsigned char*>(inverse->GetScalarPointer());
    const bool columns = m < source->GetNumberOfColumnBits();
    for (int j = 0; j < height; ++j)
    {
      for (int x = 0; x < width; ++x)
      {
        const int q = j * width + x;
        bothEqual += on[3 * q] == off[3 * q] || on[3 * q] != on[3 * q + 2] ? 1 : 0;
        std::vector<int>& code = columns ? column : row;
        code[q] = 2 * code[q] + (on[3 * q] > off[3 * q] ? 1 : 0);
      }
    }
  }
  check(bothEqual == 0, "pixels where a pattern equals its inverse or is not grey", bothEqual, 0);
  auto fromGray = [](int g)
  {
    int value = 0;
    for (; g; g >>= 1)
    {
      value ^= g;
    }
    return value;
  };
  int wrong = 0;
  int oneBitSteps = 0;
  for (int j = 0; j < height; ++j)
  {
    for (int x = 0; x < width; ++x)
    {
      const int q = j * width + x;
      // Image row j (VTK, bottom first) is projector row height - 1 - j.
      wrong += fromGray(column[q]) != x || fromGray(row[q]) != height - 1 - j ? 1 : 0;
      if (x > 0)
      {
        const int change = column[q] ^ column[q - 1];
        oneBitSteps += change != 0 && (change & (change - 1)) == 0 ? 1 : 0;
      }
    }
  }
  check(wrong == 0, "pixels decoded to a wrong column or row", wrong, 0);
  check(oneBitSteps == (width - 1) * height,
    "neighbouring columns one bit apart",
    oneBitSteps,
    (width - 1) * height);

  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(source);
  source->SetPatternIndex(26);
  source->Update();
  const std::string expected =
    "PatternIndex 26 is out of range: a 100 x 37 projector has 26 Gray-code patterns.";
  std::cout << "error: " << errors->GetErrorMessage() << "\n";
  check(
    expected == errors->GetErrorMessage(), "exact error", expected == errors->GetErrorMessage(), 1);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
