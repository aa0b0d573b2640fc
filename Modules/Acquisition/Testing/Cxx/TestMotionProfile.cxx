// lfd::MotionProfile against the closed forms of trapezoidal and triangular
// moves and of a stop: durations, positions, velocities.
#include "lfdGantryTestUtilities.h"
#include "lfdMotionProfile.h"

#include <cmath>

namespace
{
bool Near(double value, double expected, double tolerance = 1e-12)
{
  return std::fabs(value - expected) <= tolerance;
}

bool CheckAt(const lfd::MotionProfile& profile,
  double t,
  double position,
  double velocity,
  const std::string& what)
{
  double p, v;
  profile.Evaluate(t, p, v);
  std::ostringstream value;
  value << "p " << p << " (expected " << position << "), v " << v << " (expected " << velocity
        << ")";
  return lfd::test::Check(Near(p, position) && Near(v, velocity), what, value.str());
}
}

int TestMotionProfile(int, char*[])
{
  using lfd::test::Check;
  bool ok = true;

  // 30 degrees at 60 degree/s, 240 degree/s^2: 0.25 s ramps of 7.5 degrees
  // each side of a 0.25 s cruise; starting at t = 100.
  const lfd::MotionProfile trapezoid = lfd::MotionProfile::Trapezoid(100.0, 0.0, 30.0, 60.0, 240.0);
  ok &= Check(
    Near(trapezoid.GetDuration(), 0.75), "trapezoid duration 0.75 s", trapezoid.GetDuration());
  ok &= Check(Near(trapezoid.GetEnd(), 100.75), "trapezoid end 100.75 s", trapezoid.GetEnd());
  ok &= CheckAt(trapezoid, 99.0, 0.0, 0.0, "before the start: at rest at the start");
  ok &= CheckAt(trapezoid, 100.125, 1.875, 30.0, "half-way up the ramp");
  ok &= CheckAt(trapezoid, 100.375, 15.0, 60.0, "cruising, half-way");
  ok &= CheckAt(trapezoid, 100.625, 28.125, 30.0, "half-way down the ramp");
  ok &= CheckAt(trapezoid, 100.75, 30.0, 0.0, "at the end: exactly on the target");
  ok &= CheckAt(trapezoid, 1000.0, 30.0, 0.0, "long after: still there");

  // 3 degrees backwards is shorter than v^2/a = 15 degrees: a triangle
  // peaking at sqrt(3 * 240) degree/s.
  const lfd::MotionProfile triangle = lfd::MotionProfile::Trapezoid(0.0, 0.0, -3.0, 60.0, 240.0);
  const double peak = std::sqrt(720.0);
  ok &= Check(Near(triangle.GetDuration(), 2.0 * peak / 240.0),
    "triangle duration 2 sqrt(720)/240 s",
    triangle.GetDuration());
  ok &=
    CheckAt(triangle, peak / 240.0, -1.5, -peak, "triangle apex: half-way at the peak velocity");

  // The velocity never exceeds the limit and the position never goes back.
  double previous = 0.0;
  double fastest = 0.0;
  bool monotonic = true;
  for (int i = 0; i <= 1000; ++i)
  {
    double p, v;
    trapezoid.Evaluate(100.0 + 0.00075 * i, p, v);
    monotonic = monotonic && p >= previous;
    previous = p;
    fastest = std::max(fastest, std::fabs(v));
  }
  ok &= Check(monotonic && Near(fastest, 60.0, 1e-9), "monotonic, fastest 60 degree/s", fastest);

  // A stop from -20 degree/s at 80 degree/s^2: 0.25 s, 2.5 degrees further.
  const lfd::MotionProfile stop = lfd::MotionProfile::Stop(2.0, 5.0, -20.0, 80.0);
  ok &= Check(Near(stop.GetDuration(), 0.25) && Near(stop.GetFinal(), 2.5),
    "stop: 0.25 s, ends at 2.5",
    stop.GetFinal());
  ok &= CheckAt(stop, 2.125, 5.0 - 2.5 + 0.625, -10.0, "stop, half-way in time");

  const lfd::MotionProfile rest = lfd::MotionProfile::Trapezoid(0.0, 7.0, 7.0, 60.0, 240.0);
  ok &= Check(rest.GetDuration() == 0.0, "a move of 0 degrees takes no time", rest.GetDuration());
  ok &= CheckAt(rest, 0.0, 7.0, 0.0, "a move of 0 degrees stays");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
