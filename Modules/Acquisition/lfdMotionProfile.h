/**
 * @file   lfdMotionProfile.h
 * @brief  Trapezoidal point-to-point motion and stops, as segments of
 *         constant acceleration: the gantry simulator's axis and the client's
 *         move deadlines share this one definition.
 *
 * A trapezoidal move accelerates at a to the velocity limit v, cruises and
 * decelerates at a to rest on the target; when the distance is shorter than
 * v^2/a the cruise vanishes and the peak velocity is sqrt(d a) (a triangle).
 * A stop decelerates from the current velocity to rest. Plain C++17, no VTK.
 */
#ifndef lfdMotionProfile_h
#define lfdMotionProfile_h

#include <cmath>
#include <vector>

namespace lfd
{
/// A stretch of constant acceleration, starting at time Start.
struct MotionSegment
{
  double Start;
  double Position;
  double Velocity;
  double Acceleration;
  double Duration;
};

/**
 * A motion from rest or from a velocity to rest: its segments in time order
 * and the position it ends at (exact, not accumulated).
 */
class MotionProfile
{
public:
  /// At rest at `position` forever.
  static MotionProfile Rest(double position)
  {
    MotionProfile profile;
    profile.Final = position;
    return profile;
  }

  /// From rest at `from` at time `start` to rest at `to`: velocity limit
  /// `velocity`, acceleration and deceleration `acceleration` (both > 0).
  static MotionProfile Trapezoid(double start,
    double from,
    double to,
    double velocity,
    double acceleration)
  {
    MotionProfile profile = Rest(to);
    const double distance = std::fabs(to - from);
    if (distance == 0.0)
    {
      return profile;
    }
    const double sign = to > from ? 1.0 : -1.0;
    // Whether the velocity limit is reached: accelerating to v and back
    // takes v^2/a of the distance.
    const double peak = distance >= velocity * velocity / acceleration
      ? velocity
      : std::sqrt(distance * acceleration);
    const double ramp = peak / acceleration;
    const double rampDistance = 0.5 * peak * ramp;
    const double cruise = (distance - 2.0 * rampDistance) / peak;
    double t = start;
    profile.Segments.push_back({ t, from, 0.0, sign * acceleration, ramp });
    t += ramp;
    if (cruise > 0.0)
    {
      profile.Segments.push_back({ t, from + sign * rampDistance, sign * peak, 0.0, cruise });
      t += cruise;
    }
    profile.Segments.push_back(
      { t, to - sign * rampDistance, sign * peak, -sign * acceleration, ramp });
    return profile;
  }

  /// From `position` moving at `velocity` at time `start` to rest,
  /// decelerating at `deceleration` (> 0).
  static MotionProfile Stop(double start, double position, double velocity, double deceleration)
  {
    MotionProfile profile = Rest(position);
    if (velocity == 0.0)
    {
      return profile;
    }
    const double duration = std::fabs(velocity) / deceleration;
    const double sign = velocity > 0.0 ? 1.0 : -1.0;
    profile.Final = position + 0.5 * velocity * duration;
    profile.Segments.push_back({ start, position, velocity, -sign * deceleration, duration });
    return profile;
  }

  /// Position and velocity at time `t` (before the first segment: its start).
  void Evaluate(double t, double& position, double& velocity) const
  {
    for (const MotionSegment& segment : this->Segments)
    {
      const double dt = t - segment.Start;
      if (dt < segment.Duration)
      {
        const double clamped = dt > 0.0 ? dt : 0.0;
        position =
          segment.Position + clamped * (segment.Velocity + 0.5 * segment.Acceleration * clamped);
        velocity = segment.Velocity + segment.Acceleration * clamped;
        return;
      }
    }
    position = this->Final;
    velocity = 0.0;
  }

  /// When the motion comes to rest (-infinity for a rest).
  double GetEnd() const
  {
    if (this->Segments.empty())
    {
      return -HUGE_VAL;
    }
    const MotionSegment& last = this->Segments.back();
    return last.Start + last.Duration;
  }

  /// The duration from the first segment's start to rest (0 for a rest).
  double GetDuration() const
  {
    return this->Segments.empty() ? 0.0 : this->GetEnd() - this->Segments.front().Start;
  }

  double GetFinal() const { return this->Final; }

private:
  std::vector<MotionSegment> Segments;
  double Final = 0.0;
};
}

#endif
