// The camera's pixel formats: RGB8 is exact; Mono8 is the Rec. 601 luma;
// each Bayer layout samples the colours its name says at the top-left cell
// and demosaics a smooth image back within a few levels, a flat one exactly.
#include "lfdPixelFormat.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

int TestPixelFormat(int, char*[])
{
  int failures = 0;
  auto check = [&](bool ok, const std::string& what, double value, double limit)
  {
    std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << " (limit " << limit << ")\n";
    failures += ok ? 0 : 1;
  };
  const std::size_t w = 16;
  const std::size_t h = 12;
  std::vector<unsigned char> smooth(3 * w * h);
  std::vector<unsigned char> flat(3 * w * h);
  for (std::size_t q = 0; q < w * h; ++q)
  {
    const std::size_t x = q % w;
    const std::size_t y = q / w;
    smooth[3 * q] = static_cast<unsigned char>(40 + 8 * x);
    smooth[3 * q + 1] = static_cast<unsigned char>(200 - 6 * y);
    smooth[3 * q + 2] = static_cast<unsigned char>(90 + 3 * x + 2 * y);
    flat[3 * q] = 200;
    flat[3 * q + 1] = 100;
    flat[3 * q + 2] = 50;
  }
  std::vector<unsigned char> wire(3 * w * h);
  std::vector<unsigned char> back(3 * w * h);
  lfd::EncodePixels(smooth.data(), w, h, lfd::PixelFormat::RGB8, wire.data());
  lfd::DecodePixels(wire.data(), w, h, lfd::PixelFormat::RGB8, back.data());
  check(back == smooth, "RGB8 round trip exact", back == smooth, 1);

  lfd::EncodePixels(flat.data(), w, h, lfd::PixelFormat::Mono8, wire.data());
  // 0.299 x 200 + 0.587 x 100 + 0.114 x 50 = 124.2
  check(wire[0] == 124, "Mono8 luma of (200, 100, 50)", wire[0], 124);

  // Top-left 2 x 2 cell of each layout, as R/G/B of (200, 100, 50).
  const char* names[4] = { "BayerRG8", "BayerBG8", "BayerGB8", "BayerGR8" };
  const unsigned char cells[4][4] = {
    { 200, 100, 100, 50 }, { 50, 100, 100, 200 }, { 100, 50, 200, 100 }, { 100, 200, 50, 100 }
  };
  for (int b = 0; b < 4; ++b)
  {
    const auto format = static_cast<lfd::PixelFormat>(1 + b);
    check(
      std::string(lfd::PixelFormatName(format)) == names[b], std::string("name ") + names[b], 1, 1);
    lfd::EncodePixels(flat.data(), w, h, format, wire.data());
    const bool cell = wire[0] == cells[b][0] && wire[1] == cells[b][1] && wire[w] == cells[b][2] &&
      wire[w + 1] == cells[b][3];
    check(cell, std::string(names[b]) + " top-left cell", cell, 1);
    lfd::DecodePixels(wire.data(), w, h, format, back.data());
    check(back == flat, std::string(names[b]) + " flat image back exactly", back == flat, 1);
    lfd::EncodePixels(smooth.data(), w, h, format, wire.data());
    lfd::DecodePixels(wire.data(), w, h, format, back.data());
    int worst = 0;
    // Interior pixels: a linear ramp is rebuilt exactly up to rounding.
    for (std::size_t y = 1; y + 1 < h; ++y)
    {
      for (std::size_t x = 1; x + 1 < w; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          const std::size_t i = 3 * (y * w + x) + c;
          worst = std::max(worst, std::abs(int(back[i]) - int(smooth[i])));
        }
      }
    }
    check(worst <= 1, std::string(names[b]) + " ramp interior, worst error (levels)", worst, 1);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
