/**
 * @file   lfdTessellation.h
 * @brief  A trilinear box split into k x k x k sub-boxes (DESIGN.md section 4.4).
 *
 * The straight warped ray of a box (lfdRayWarp.h) only approximates the
 * curved rest-space image of a view ray. Splitting the box along its own
 * parametric grid keeps the deformation exactly the same (the sub-boxes'
 * corners are the box's rest and deformed maps of the grid points) and makes
 * the warped ray piecewise linear, converging to the exact answer as the
 * map's nonlinearity falls like 1 / k^2.
 *
 * The sub-grid of a box split k times along each axis has (k+1)^3 nodes at
 * the parametric points node / k; sub-box `cell` (every coordinate in
 * [0, k)) has the nodes cell + HexCorner[c] as its corners c. Nodes and
 * sub-boxes are visited u fastest, then v, then w (VTK's point order), so
 * every user of the tessellation (the renderer, vtkLatticeCageFilter) lists
 * the sub-boxes of a box in the same order.
 *
 * Plain C++17 + GLM, no VTK.
 */
#ifndef lfdTessellation_h
#define lfdTessellation_h

#include "lfdTrilinear.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lfd
{

/// Parametric point of node `node` of the sub-grid of a box split `k` times per axis.
inline glm::dvec3 SubGridPoint(int k, const glm::ivec3& node)
{
  return glm::dvec3(node) / static_cast<double>(k);
}

/// The node of sub-box `cell` at its corner `c` (VTK corner order).
inline glm::ivec3 SubBoxNode(const glm::ivec3& cell, int c)
{
  return cell + glm::ivec3(HexCorner[c][0], HexCorner[c][1], HexCorner[c][2]);
}

/// Calls visit(node) for the (k+1)^3 nodes of the sub-grid, u fastest.
template<typename Visit>
void ForEachSubGridNode(int k, Visit&& visit)
{
  for (int w = 0; w <= k; ++w)
  {
    for (int v = 0; v <= k; ++v)
    {
      for (int u = 0; u <= k; ++u)
      {
        visit(glm::ivec3(u, v, w));
      }
    }
  }
}

/// Calls visit(cell) for the k^3 sub-boxes, u fastest.
template<typename Visit>
void ForEachSubBox(int k, Visit&& visit)
{
  for (int w = 0; w < k; ++w)
  {
    for (int v = 0; v < k; ++v)
    {
      for (int u = 0; u < k; ++u)
      {
        visit(glm::ivec3(u, v, w));
      }
    }
  }
}

/// Sub-box `cell` of `box` split `k` times per axis: the box's map (Eq. 2)
/// of the cell's parametric corners.
inline Hexahedron SubBox(const Hexahedron& box, int k, const glm::ivec3& cell)
{
  Hexahedron sub;
  for (int c = 0; c < 8; ++c)
  {
    sub.Corners[c] = TrilinearMap(box, SubGridPoint(k, SubBoxNode(cell, c)));
  }
  return sub;
}

/**
 * How far the straight warped rays of the box (rest, deformed) split `k`
 * times per axis stray from the exact, curved rest-space images of view
 * rays (lfdRayWarp.h warps a segment through the rest images of its entry
 * and exit points only). Probed on the chords of every deformed sub-box
 * between opposite corners (its 4 body and 12 face diagonals: view rays
 * through the sub-box in every direction): the distance, in rest space,
 * between the exact rest image of the chord's midpoint (the deformed
 * sub-box's map inverted by Newton's method) and the midpoint of the rest
 * chord, where the warped ray passes. Zero for a box at rest or moved by an
 * affine map; it falls as 1 / k^2.
 */
inline double WarpDeviation(const Hexahedron& rest, const Hexahedron& deformed, int k)
{
  // The opposite corners (VTK order) of the 4 body and 12 face diagonals.
  static constexpr int Chords[16][2] = { { 0, 6 },
    { 1, 7 },
    { 2, 4 },
    { 3, 5 },
    { 0, 2 },
    { 1, 3 },
    { 4, 6 },
    { 5, 7 },
    { 0, 5 },
    { 1, 4 },
    { 3, 6 },
    { 2, 7 },
    { 0, 7 },
    { 3, 4 },
    { 1, 6 },
    { 2, 5 } };
  double deviation = 0.0;
  ForEachSubBox(k,
    [&](const glm::ivec3& cell)
    {
      const Hexahedron subRest = SubBox(rest, k, cell);
      const Hexahedron subDeformed = SubBox(deformed, k, cell);
      for (const auto& chord : Chords)
      {
        const glm::dvec3 middle =
          0.5 * (subDeformed.Corners[chord[0]] + subDeformed.Corners[chord[1]]);
        // Start from the parametric midpoint of the chord's corners.
        glm::dvec3 uvw = 0.5 *
          (glm::dvec3(HexCorner[chord[0]][0], HexCorner[chord[0]][1], HexCorner[chord[0]][2]) +
            glm::dvec3(HexCorner[chord[1]][0], HexCorner[chord[1]][1], HexCorner[chord[1]][2]));
        if (!InvertTrilinear(subDeformed, middle, uvw))
        {
          // No inverse (a degenerate sub-box): as bad as it gets.
          deviation = std::max(deviation, BoxSize(subRest));
          continue;
        }
        const glm::dvec3 chordMiddle =
          0.5 * (subRest.Corners[chord[0]] + subRest.Corners[chord[1]]);
        deviation = std::max(deviation, glm::distance(TrilinearMap(subRest, uvw), chordMiddle));
      }
    });
  return deviation;
}

/// Largest k the automatic rule picks.
constexpr int MaximumAutomaticSubdivision = 8;

/**
 * The automatic k of a box (render.subdivision "auto"): the smallest whose
 * measured WarpDeviation is at most `tolerance` (a length in rest space;
 * the renderer passes a pixel tolerance times the size of a pixel at the
 * box), up to MaximumAutomaticSubdivision. The deviation is measured at
 * each k tried; the next k tried is the one the 1 / k^2 law predicts from
 * the last measurement (at least one more), so a few measurements suffice.
 */
inline int AutomaticSubdivision(const Hexahedron& rest,
  const Hexahedron& deformed,
  double tolerance)
{
  int k = 1;
  for (;;)
  {
    const double deviation = WarpDeviation(rest, deformed, k);
    if (deviation <= tolerance || k == MaximumAutomaticSubdivision)
    {
      return k;
    }
    const double predicted = std::ceil(k * std::sqrt(deviation / std::max(tolerance, 1e-300)));
    k = static_cast<int>(std::clamp(predicted, k + 1.0, double(MaximumAutomaticSubdivision)));
  }
}

/// Sub-boxes of a cage whose box b is split into ks[b]^3.
inline long long CountSubBoxes(const std::vector<int>& ks)
{
  long long count = 0;
  for (int k : ks)
  {
    count += static_cast<long long>(k) * k * k;
  }
  return count;
}

/**
 * Lowers automatic subdivisions until the cage fits `budget` sub-boxes: the
 * largest k goes down first (the budget is spent where the map bends most)
 * and every box keeps at least k = 1, so a cage of more boxes than the
 * budget stays over it.
 */
inline void FitSubdivisionBudget(std::vector<int>& ks, long long budget)
{
  for (int cap = MaximumAutomaticSubdivision; cap > 1 && CountSubBoxes(ks) > budget; --cap)
  {
    for (int& k : ks)
    {
      k = std::min(k, cap - 1);
    }
  }
}

} // namespace lfd

#endif
