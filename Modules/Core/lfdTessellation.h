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
 * Distance of the box's map from the affine map through corners 0, 1, 3 and
 * 4, at the face centres and the centre: the second-order part of the
 * trilinear map, which bends the true inverse image of a straight ray.
 */
inline double Nonlinearity(const Hexahedron& box)
{
  const glm::dvec3& c0 = box.Corners[0];
  const glm::dmat3 affine(box.Corners[1] - c0, box.Corners[3] - c0, box.Corners[4] - c0);
  const glm::dvec3 probes[7] = { { 0.5, 0.5, 0.5 },
    { 0.0, 0.5, 0.5 },
    { 1.0, 0.5, 0.5 },
    { 0.5, 0.0, 0.5 },
    { 0.5, 1.0, 0.5 },
    { 0.5, 0.5, 0.0 },
    { 0.5, 0.5, 1.0 } };
  double deviation = 0.0;
  for (const glm::dvec3& uvw : probes)
  {
    deviation = std::max(deviation, glm::distance(TrilinearMap(box, uvw), c0 + affine * uvw));
  }
  return deviation;
}

/// Largest k the automatic rule picks.
constexpr int MaximumAutomaticSubdivision = 8;

/// The automatic k of a box (render.subdivision "auto"): the smallest that
/// brings the nonlinearity of its rest and deformed maps under `tolerance` x
/// the deformed box's size (it falls as 1 / k^2), up to
/// MaximumAutomaticSubdivision.
inline int AutomaticSubdivision(const Hexahedron& rest,
  const Hexahedron& deformed,
  double tolerance)
{
  const double error =
    std::max(Nonlinearity(rest), Nonlinearity(deformed)) / std::max(BoxSize(deformed), 1e-300);
  return std::clamp(
    static_cast<int>(std::ceil(std::sqrt(error / tolerance))), 1, MaximumAutomaticSubdivision);
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
