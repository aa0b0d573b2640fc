#include "vtkCageTransform.h"

#include "lfdTrilinear.h"
#include "vtkDeformationCage.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkCageTransform);
vtkCxxSetObjectMacro(vtkCageTransform, Cage, vtkDeformationCage);

/// One box of the cage, read on InternalUpdate().
struct vtkCageTransformBox
{
  lfd::Hexahedron Rest;
  lfd::Hexahedron Deformed;
  glm::dvec3 RestMin, RestMax; // rest bounds, widened by the containment slack
  bool Moved;                  // false: the box maps its points to themselves
};

struct vtkCageTransform::Internals
{
  std::vector<vtkCageTransformBox> Boxes;

  /// The box holding rest point `p` and its parametric coordinates, or nullptr.
  const vtkCageTransformBox* Find(const glm::dvec3& p, glm::dvec3& uvw) const
  {
    for (const vtkCageTransformBox& box : this->Boxes)
    {
      if (glm::all(glm::greaterThanEqual(p, box.RestMin)) &&
        glm::all(glm::lessThanEqual(p, box.RestMax)) && lfd::Contains(box.Rest, p, uvw))
      {
        return &box;
      }
    }
    return nullptr;
  }

  void Map(const double in[3], double out[3], double (*derivative)[3]) const
  {
    const glm::dvec3 p(in[0], in[1], in[2]);
    glm::dvec3 uvw;
    const vtkCageTransformBox* box = this->Find(p, uvw);
    glm::dvec3 q = p;
    glm::dmat3 jacobian(1.0);
    if (box && box->Moved)
    {
      q = lfd::TrilinearMap(box->Deformed, uvw);
      if (derivative)
      {
        // Chain rule: d out / d in = d out / d uvw (d in / d uvw)^-1.
        jacobian = lfd::TrilinearJacobian(box->Deformed, uvw) *
          glm::inverse(lfd::TrilinearJacobian(box->Rest, uvw));
      }
    }
    out[0] = q.x;
    out[1] = q.y;
    out[2] = q.z;
    if (derivative)
    {
      // glm is column-major: jacobian[column][row].
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          derivative[i][j] = jacobian[j][i];
        }
      }
    }
  }
};

//------------------------------------------------------------------------------
vtkCageTransform::vtkCageTransform()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkCageTransform::~vtkCageTransform()
{
  this->SetCage(nullptr);
}

//------------------------------------------------------------------------------
void vtkCageTransform::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Cage: " << this->Cage << "\n";
  if (this->Cage)
  {
    this->Cage->PrintSelf(os, indent.GetNextIndent());
  }
}

//------------------------------------------------------------------------------
vtkAbstractTransform* vtkCageTransform::MakeTransform()
{
  return vtkCageTransform::New();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkCageTransform::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Cage)
  {
    mtime = std::max(mtime, this->Cage->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
void vtkCageTransform::InternalDeepCopy(vtkAbstractTransform* transform)
{
  auto* source = static_cast<vtkCageTransform*>(transform);
  this->SetInverseTolerance(source->InverseTolerance);
  this->SetInverseIterations(source->InverseIterations);
  this->SetCage(source->Cage);
  if (this->InverseFlag != source->InverseFlag)
  {
    this->InverseFlag = source->InverseFlag;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCageTransform::InternalUpdate()
{
  std::vector<vtkCageTransformBox>& boxes = this->Internal->Boxes;
  boxes.clear();
  if (!this->Cage)
  {
    return;
  }
  const vtkIdType count = this->Cage->GetNumberOfBoxes();
  boxes.reserve(count);
  for (vtkIdType b = 0; b < count; ++b)
  {
    double rest[24], deformed[24];
    if (!this->Cage->GetRestCorners(b, rest) || !this->Cage->GetDeformedCorners(b, deformed))
    {
      vtkErrorMacro(<< "cage box " << b << " (label " << this->Cage->GetBoxLabel(b)
                    << ") is not a hexahedron of existing points: skipped");
      continue;
    }
    vtkCageTransformBox box;
    box.Rest = lfd::HexahedronFromArray(rest);
    box.Deformed = lfd::HexahedronFromArray(deformed);
    box.Moved = !std::equal(rest, rest + 24, deformed);
    const lfd::AxisBounds bounds = lfd::BoxBounds(box.Rest);
    box.RestMin = bounds.Min;
    box.RestMax = bounds.Max;
    // lfd::Contains accepts points up to 1e-9 (parametric) outside the box.
    const glm::dvec3 slack(1e-8 * lfd::BoxSize(box.Rest));
    box.RestMin -= slack;
    box.RestMax += slack;
    boxes.push_back(box);
  }
}

//------------------------------------------------------------------------------
void vtkCageTransform::ForwardTransformPoint(const double in[3], double out[3])
{
  this->Internal->Map(in, out, nullptr);
}

//------------------------------------------------------------------------------
void vtkCageTransform::ForwardTransformPoint(const float in[3], float out[3])
{
  const double p[3] = { in[0], in[1], in[2] };
  double q[3];
  this->Internal->Map(p, q, nullptr);
  out[0] = static_cast<float>(q[0]);
  out[1] = static_cast<float>(q[1]);
  out[2] = static_cast<float>(q[2]);
}

//------------------------------------------------------------------------------
void vtkCageTransform::ForwardTransformDerivative(const double in[3],
  double out[3],
  double derivative[3][3])
{
  this->Internal->Map(in, out, derivative);
}

//------------------------------------------------------------------------------
void vtkCageTransform::ForwardTransformDerivative(const float in[3],
  float out[3],
  float derivative[3][3])
{
  const double p[3] = { in[0], in[1], in[2] };
  double q[3], jacobian[3][3];
  this->Internal->Map(p, q, jacobian);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = static_cast<float>(q[i]);
    for (int j = 0; j < 3; ++j)
    {
      derivative[i][j] = static_cast<float>(jacobian[i][j]);
    }
  }
}
