#include "vtkLightFieldSceneLogic.h"

#include "lfdProjectorMasks.h"

#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkDeformationCage.h"
#include "vtkGroundTruthEvaluator.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkKeyframeInterpolator.h"
#include "vtkLabelCellsByBoxes.h"
#include "vtkLatticeCageFilter.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldReader.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldScene.h"
#include "vtkObjectFactory.h"
#include "vtkPartCageSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkLightFieldSceneLogic);

// The scene (IO) stores the keyframe interpolation as an int that this
// logic hands to the interpolator (Deformation) unchanged.
static_assert(static_cast<int>(vtkLightFieldScene::INTERPOLATION_LINEAR) ==
      static_cast<int>(vtkKeyframeInterpolator::LINEAR) &&
    static_cast<int>(vtkLightFieldScene::INTERPOLATION_CATMULL_ROM) ==
      static_cast<int>(vtkKeyframeInterpolator::CATMULL_ROM),
  "scene.json's interpolation values are vtkKeyframeInterpolator's");

namespace
{
/// Everything a structural cage edit can change: the boxes and their points
/// (rest and deformed, 3 doubles each) and the keyframes that name those
/// points. Copies of the stored doubles, so a restore is exact.
struct CageState
{
  std::vector<double> Rest;
  std::vector<double> Deformed;
  std::vector<std::array<vtkIdType, 8>> Boxes;
  std::vector<int> Labels;
  std::vector<double> KeyframeTimes;
  std::vector<std::vector<double>> KeyframePoints;

  vtkIdType GetNumberOfPoints() const { return static_cast<vtkIdType>(this->Rest.size() / 3); }

  /// "" when box `box` exists, else why the edit `edit` cannot be made.
  std::string CheckBox(const char* edit, vtkIdType box) const
  {
    return box >= 0 && box < static_cast<vtkIdType>(this->Boxes.size())
      ? std::string()
      : std::string(edit) + ": box " + std::to_string(box) + " does not exist";
  }

  /// Appends a point (rest = deformed = `rest`), also to every keyframe.
  vtkIdType AddPoint(const double rest[3])
  {
    this->Rest.insert(this->Rest.end(), rest, rest + 3);
    this->Deformed.insert(this->Deformed.end(), rest, rest + 3);
    for (std::vector<double>& points : this->KeyframePoints)
    {
      points.insert(points.end(), rest, rest + 3);
    }
    return this->GetNumberOfPoints() - 1;
  }
};

std::vector<double> PointsToVector(vtkPoints* points)
{
  std::vector<double> values(3 * (points ? points->GetNumberOfPoints() : 0));
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
  {
    points->GetPoint(i, values.data() + 3 * i);
  }
  return values;
}

vtkSmartPointer<vtkPoints> VectorToPoints(const std::vector<double>& values)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(values.size() / 3));
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, values.data() + 3 * i);
  }
  return points;
}

/// The boxes and points of `cage`, with the keyframes of `scene` (none when
/// null).
CageState CaptureCage(vtkDeformationCage* cage, vtkLightFieldScene* scene)
{
  CageState state;
  const vtkIdType points = cage->GetNumberOfPoints();
  state.Rest.resize(3 * points);
  state.Deformed.resize(3 * points);
  for (vtkIdType i = 0; i < points; ++i)
  {
    cage->GetRestPoint(i, state.Rest.data() + 3 * i);
    cage->GetDeformedPoint(i, state.Deformed.data() + 3 * i);
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType b = 0; b < cage->GetNumberOfBoxes(); ++b)
  {
    cage->GetCellPoints(b, ids);
    std::array<vtkIdType, 8> corners{};
    std::copy_n(ids->GetPointer(0), std::min<vtkIdType>(8, ids->GetNumberOfIds()), corners.data());
    state.Boxes.push_back(corners);
    state.Labels.push_back(cage->GetBoxLabel(b));
  }
  for (int k = 0; scene && k < scene->GetNumberOfKeyframes(); ++k)
  {
    state.KeyframeTimes.push_back(scene->GetKeyframeTime(k));
    state.KeyframePoints.push_back(PointsToVector(scene->GetKeyframePoints(k)));
  }
  return state;
}

void RestoreCage(const CageState& state, vtkDeformationCage* cage, vtkLightFieldScene* scene)
{
  vtkNew<vtkDeformationCage> rebuilt;
  for (vtkIdType i = 0; i < state.GetNumberOfPoints(); ++i)
  {
    rebuilt->AddPoint(state.Rest.data() + 3 * i, state.Deformed.data() + 3 * i);
  }
  for (size_t b = 0; b < state.Boxes.size(); ++b)
  {
    rebuilt->AddBox(state.Boxes[b].data(), state.Labels[b]);
  }
  cage->InitializeFromGrid(rebuilt);
  scene->RemoveAllKeyframes();
  for (size_t k = 0; k < state.KeyframeTimes.size(); ++k)
  {
    scene->AddKeyframe(state.KeyframeTimes[k], VectorToPoints(state.KeyframePoints[k]));
  }
}

bool SameCage(const CageState& a, const CageState& b)
{
  return a.Rest == b.Rest && a.Deformed == b.Deformed && a.Boxes == b.Boxes && a.Labels == b.Labels;
}

bool SameKeyframes(const CageState& a, const CageState& b)
{
  return a.KeyframeTimes == b.KeyframeTimes && a.KeyframePoints == b.KeyframePoints;
}

/// The view camera and render settings of a scene. The camera is a deep
/// copy: restoring it through vtkCamera's setters would renormalise view up
/// and could change its last bit.
struct SettingsState
{
  int Width = 0;
  int Height = 0;
  double FocalDistance = 0.0;
  int Subdivision = 0;
  int WidenedSearch = 0;
  double ObjectThreshold = 0.0;
  std::array<double, 3> Background{};
  vtkSmartPointer<vtkCamera> Camera;
  int Interpolation = 0;
};

SettingsState CaptureSettings(vtkLightFieldScene* scene)
{
  SettingsState state;
  state.Width = scene->GetWidth();
  state.Height = scene->GetHeight();
  state.FocalDistance = scene->GetFocalDistance();
  state.Subdivision = scene->GetSubdivision();
  state.WidenedSearch = scene->GetWidenedSearch();
  state.ObjectThreshold = scene->GetObjectThreshold();
  scene->GetBackground(state.Background.data());
  state.Interpolation = scene->GetInterpolation();
  state.Camera = vtkSmartPointer<vtkCamera>::New();
  state.Camera->DeepCopy(scene->GetCamera());
  return state;
}

void RestoreSettings(const SettingsState& state, vtkLightFieldScene* scene)
{
  scene->SetWidth(state.Width);
  scene->SetHeight(state.Height);
  scene->SetFocalDistance(state.FocalDistance);
  scene->SetSubdivision(state.Subdivision);
  scene->SetWidenedSearch(state.WidenedSearch);
  scene->SetObjectThreshold(state.ObjectThreshold);
  scene->SetBackground(state.Background.data());
  scene->SetInterpolation(state.Interpolation);
  scene->GetCamera()->DeepCopy(state.Camera);
}

std::string Plural(std::size_t count, const char* noun)
{
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

/// Where corner k of a box sits in its parameter space: bit a of the
/// result is its coordinate along parametric axis a (VTK hexahedron order).
int CornerBits(int k)
{
  const int u = (k % 4 == 1 || k % 4 == 2) ? 1 : 0;
  const int v = (k % 4 == 2 || k % 4 == 3) ? 1 : 0;
  const int w = k >= 4 ? 1 : 0;
  return u | (v << 1) | (w << 2);
}

int CornerOfBits(int bits)
{
  for (int k = 0; k < 8; ++k)
  {
    if (CornerBits(k) == bits)
    {
      return k;
    }
  }
  return 0;
}

/// Splits box `box` of `state` across parametric axis `axis` (SplitBox()):
/// the 4 edges along the axis get their midpoints, which are the trilinear
/// images (Eq. 2) of the mid-parameter since a box's edges are straight.
void SplitBoxState(CageState& state, vtkIdType box, int axis)
{
  const std::array<vtkIdType, 8> corners = state.Boxes[box];
  std::array<vtkIdType, 8> low = corners, high = corners;
  for (int k = 0; k < 8; ++k)
  {
    const int bits = CornerBits(k);
    if (bits & (1 << axis))
    {
      continue;
    }
    const int partner = CornerOfBits(bits | (1 << axis));
    const vtkIdType p = corners[k], q = corners[partner];
    auto middle = [p, q](const std::vector<double>& xyz)
    {
      return std::array<double, 3>{ 0.5 * (xyz[3 * p] + xyz[3 * q]),
        0.5 * (xyz[3 * p + 1] + xyz[3 * q + 1]),
        0.5 * (xyz[3 * p + 2] + xyz[3 * q + 2]) };
    };
    const std::array<double, 3> rest = middle(state.Rest), deformed = middle(state.Deformed);
    const vtkIdType id = state.GetNumberOfPoints();
    state.Rest.insert(state.Rest.end(), rest.begin(), rest.end());
    state.Deformed.insert(state.Deformed.end(), deformed.begin(), deformed.end());
    for (std::vector<double>& points : state.KeyframePoints)
    {
      const std::array<double, 3> keyed = middle(points);
      points.insert(points.end(), keyed.begin(), keyed.end());
    }
    low[partner] = id;
    high[k] = id;
  }
  state.Boxes[box] = low;
  state.Boxes.push_back(high);
  state.Labels.push_back(state.Labels[box]);
}

/// Removes box `box` of `state` and the points only it used; the ids of the
/// points after them shift down.
void RemoveBoxState(CageState& state, vtkIdType box)
{
  const std::array<vtkIdType, 8> removed = state.Boxes[box];
  state.Boxes.erase(state.Boxes.begin() + box);
  state.Labels.erase(state.Labels.begin() + box);
  std::vector<bool> used(state.GetNumberOfPoints(), true);
  for (vtkIdType id : removed)
  {
    used[id] = false;
  }
  for (const std::array<vtkIdType, 8>& corners : state.Boxes)
  {
    for (vtkIdType id : corners)
    {
      used[id] = true;
    }
  }
  std::vector<vtkIdType> newId(used.size(), -1);
  vtkIdType kept = 0;
  for (size_t i = 0; i < used.size(); ++i)
  {
    newId[i] = used[i] ? kept++ : -1;
  }
  auto compact = [&used](std::vector<double>& xyz)
  {
    size_t out = 0;
    for (size_t i = 0; i < used.size(); ++i)
    {
      if (used[i])
      {
        std::copy_n(xyz.begin() + 3 * i, 3, xyz.begin() + 3 * out++);
      }
    }
    xyz.resize(3 * out);
  };
  compact(state.Rest);
  compact(state.Deformed);
  for (std::vector<double>& points : state.KeyframePoints)
  {
    compact(points);
  }
  for (std::array<vtkIdType, 8>& corners : state.Boxes)
  {
    for (vtkIdType& id : corners)
    {
      id = newId[id];
    }
  }
}

/// One undoable edit: Apply(true) redoes it, Apply(false) undoes it; the
/// edit itself was applied (and validated) before the command was pushed.
class Command
{
public:
  virtual ~Command() = default;
  virtual void Apply(vtkLightFieldSceneLogic* logic, bool redo) = 0;
  /// Absorbs `next`, a later edit of the same drag; false when it cannot.
  virtual bool Merge(const Command&) { return false; }

  std::string Name;
  std::vector<unsigned long> Events;
};

/// Moved points: their positions before and after (3 doubles each).
class MoveCommand : public Command
{
public:
  void Apply(vtkLightFieldSceneLogic* logic, bool redo) override
  {
    const std::vector<double>& positions = redo ? this->To : this->From;
    vtkDeformationCage* cage = logic->GetCage();
    for (size_t i = 0; i < this->Ids.size(); ++i)
    {
      cage->SetDeformedPoint(this->Ids[i], positions.data() + 3 * i);
    }
  }

  bool Merge(const Command& next) override
  {
    const auto* move = dynamic_cast<const MoveCommand*>(&next);
    if (!move || move->Ids != this->Ids)
    {
      return false;
    }
    this->To = move->To;
    return true;
  }

  std::vector<vtkIdType> Ids;
  std::vector<double> From;
  std::vector<double> To;
};

/// An edit stored as the whole state it changes, before and after.
class CageCommand : public Command
{
public:
  void Apply(vtkLightFieldSceneLogic* logic, bool redo) override
  {
    RestoreCage(redo ? this->After : this->Before, logic->GetCage(), logic->GetScene());
  }

  CageState Before;
  CageState After;
};

class SettingsCommand : public Command
{
public:
  void Apply(vtkLightFieldSceneLogic* logic, bool redo) override
  {
    RestoreSettings(redo ? this->After : this->Before, logic->GetScene());
  }

  SettingsState Before;
  SettingsState After;
};

/// A painted projector mask: the slice's bytes before and after, in the
/// masks (of the light field at the time) it painted.
class MaskCommand : public Command
{
public:
  void Apply(vtkLightFieldSceneLogic*, bool redo) override
  {
    const std::vector<unsigned char>& bytes = redo ? this->After : this->Before;
    std::copy(bytes.begin(), bytes.end(), this->Array->GetPointer(this->Offset));
    this->Array->Modified();
    this->Masks->Modified();
  }

  vtkSmartPointer<vtkImageData> Masks;
  vtkSmartPointer<vtkUnsignedCharArray> Array;
  vtkIdType Offset = 0;
  std::vector<unsigned char> Before;
  std::vector<unsigned char> After;
};

/// What a cage edit asks to validate after it is applied.
struct CageCheck
{
  bool Whole = false;           ///< the whole cage (a build)
  std::vector<vtkIdType> Boxes; ///< else these boxes (none: no check)
};
} // namespace

struct vtkLightFieldSceneLogic::Internals
{
  vtkSmartPointer<vtkLightFieldScene> Scene = vtkSmartPointer<vtkLightFieldScene>::New();
  vtkNew<vtkDeformationCage> Cage;
  vtkSmartPointer<vtkLightField> LightField;
  /// The resolved path LightField was read from; "" for one given in memory.
  std::string LightFieldSource;
  std::vector<std::unique_ptr<Command>> Stack;
  /// Commands [0, Index) are applied; [Index, size) can be redone.
  std::size_t Index = 0;
  int InteractionDepth = 0;
  /// The top command is a move of the current drag, which the next move of
  /// the same points joins.
  bool MergeOpen = false;

  /// The command's events, ModifiedEvent, then UndoStackModifiedEvent when
  /// the stack changed.
  static void Notify(vtkLightFieldSceneLogic* logic,
    const std::vector<unsigned long>& events,
    bool stackChanged)
  {
    for (unsigned long event : events)
    {
      logic->InvokeEvent(event);
    }
    logic->Modified();
    if (stackChanged)
    {
      logic->InvokeEvent(UndoStackModifiedEvent);
    }
  }

  /// Pushes an applied command (or merges it into the drag's move).
  bool Push(vtkLightFieldSceneLogic* logic, std::unique_ptr<Command> command)
  {
    if (this->MergeOpen && this->Index == this->Stack.size() && this->Index > 0 &&
      this->Stack[this->Index - 1]->Merge(*command))
    {
      Notify(logic, command->Events, false);
      return true;
    }
    this->Stack.resize(this->Index);
    this->Stack.push_back(std::move(command));
    this->Index = this->Stack.size();
    this->MergeOpen = this->InteractionDepth > 0;
    Notify(logic, this->Stack.back()->Events, true);
    return true;
  }

  /**
   * Applies `edit` (std::string(CageState&, CageCheck&): the reason it
   * cannot be made, or "") to a copy of the cage state, validates what it
   * asks and pushes it as command `name`; a refused edit is undone.
   */
  template<typename Edit>
  bool EditCage(vtkLightFieldSceneLogic* logic, const std::string& name, Edit&& edit)
  {
    auto command = std::make_unique<CageCommand>();
    command->Before = CaptureCage(this->Cage, this->Scene);
    command->After = command->Before;
    CageCheck check;
    const std::string why = edit(command->After, check);
    if (!why.empty())
    {
      return logic->Refuse(logic->Where() + why);
    }
    command->Apply(logic, true);
    vtkNew<vtkIdList> boxes;
    for (vtkIdType box : check.Boxes)
    {
      boxes->InsertNextId(box);
    }
    if ((check.Whole || !check.Boxes.empty()) &&
      !logic->CheckCage(check.Whole ? nullptr : boxes.Get()))
    {
      command->Apply(logic, false);
      return false;
    }
    command->Name = name;
    if (!SameCage(command->Before, command->After))
    {
      command->Events.push_back(CageModifiedEvent);
    }
    if (!SameKeyframes(command->Before, command->After))
    {
      command->Events.push_back(KeyframesModifiedEvent);
    }
    return this->Push(logic, std::move(command));
  }

  /**
   * Applies `edit` (std::string(vtkLightFieldScene*): the reason it cannot
   * be made, or "") to the scene's settings, checks them as scene.json
   * does and pushes command `name`; a refused edit is undone.
   */
  template<typename Edit>
  bool EditSettings(vtkLightFieldSceneLogic* logic, const std::string& name, Edit&& edit)
  {
    auto command = std::make_unique<SettingsCommand>();
    command->Before = CaptureSettings(this->Scene);
    std::string why = edit(this->Scene.Get());
    if (why.empty())
    {
      why = this->Scene->CheckSettings();
    }
    if (!why.empty())
    {
      RestoreSettings(command->Before, this->Scene);
      return logic->Refuse(logic->Where() + why);
    }
    command->After = CaptureSettings(this->Scene);
    command->Name = name;
    command->Events = { SettingsModifiedEvent };
    return this->Push(logic, std::move(command));
  }

  /// EditCage() of an edit of box `box`, refused (naming `method`) when
  /// the box does not exist.
  template<typename Edit>
  bool EditBox(vtkLightFieldSceneLogic* logic,
    const char* method,
    const std::string& name,
    vtkIdType box,
    Edit&& edit)
  {
    return this->EditCage(logic,
      name,
      [method, box, &edit](CageState& state, CageCheck& check)
      {
        const std::string missing = state.CheckBox(method, box);
        return missing.empty() ? edit(state, check) : missing;
      });
  }

  /// Replaces the cage by `built` (dropping the keyframes) as command `name`.
  bool ReplaceCage(vtkLightFieldSceneLogic* logic,
    const std::string& name,
    vtkDeformationCage* built)
  {
    return this->EditCage(logic,
      name,
      [built](CageState& state, CageCheck& check)
      {
        state = CaptureCage(built, nullptr);
        check.Whole = true;
        return std::string();
      });
  }
};

//------------------------------------------------------------------------------
vtkLightFieldSceneLogic::vtkLightFieldSceneLogic()
  : Internal(new Internals)
{
  this->Internal->Scene->SetCage(this->Internal->Cage);
}

//------------------------------------------------------------------------------
vtkLightFieldSceneLogic::~vtkLightFieldSceneLogic() = default;

//------------------------------------------------------------------------------
vtkLightFieldScene* vtkLightFieldSceneLogic::GetScene()
{
  return this->Internal->Scene;
}

//------------------------------------------------------------------------------
vtkDeformationCage* vtkLightFieldSceneLogic::GetCage()
{
  return this->Internal->Cage;
}

//------------------------------------------------------------------------------
std::string vtkLightFieldSceneLogic::Where() const
{
  const char* file = this->Internal->Scene->GetFileName();
  return file ? std::string(file) + ": " : std::string();
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::Refuse(const std::string& reason)
{
  vtkErrorMacro(<< reason);
  return false;
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::Load(const char* fileName)
{
  Internals& internal = *this->Internal;
  // A failed Read() keeps the scene as it was; its error is said once, as
  // the logic's own.
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(internal.Scene);
  const bool read = internal.Scene->Read(fileName);
  errors->StopObserving();
  if (!read)
  {
    return this->Refuse(errors->GetErrorMessage());
  }
  internal.Cage->InitializeFromGrid(internal.Scene->GetCage());
  internal.Scene->SetCage(internal.Cage);
  internal.LightField = nullptr;
  internal.LightFieldSource.clear();
  this->ClearUndo();
  Internals::Notify(
    this, { CageModifiedEvent, KeyframesModifiedEvent, SettingsModifiedEvent }, false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::Save(const char* fileName)
{
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(this->Internal->Scene);
  const bool written = this->Internal->Scene->Write(fileName);
  errors->StopObserving();
  return written || this->Refuse(errors->GetErrorMessage());
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::NewScene()
{
  vtkNew<vtkLightFieldScene> scene;
  this->SetScene(scene);
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::SetScene(vtkLightFieldScene* scene)
{
  if (!scene)
  {
    this->NewScene();
    return;
  }
  Internals& internal = *this->Internal;
  internal.Scene = scene;
  if (scene->GetCage() != internal.Cage.Get())
  {
    internal.Cage->InitializeFromGrid(scene->GetCage());
    scene->SetCage(internal.Cage);
  }
  internal.LightField = nullptr;
  internal.LightFieldSource.clear();
  this->ClearUndo();
  Internals::Notify(
    this, { CageModifiedEvent, KeyframesModifiedEvent, SettingsModifiedEvent }, false);
}

//------------------------------------------------------------------------------
vtkLightField* vtkLightFieldSceneLogic::GetLightField()
{
  Internals& internal = *this->Internal;
  if (internal.LightField && internal.LightFieldSource.empty())
  {
    return internal.LightField; // given in memory
  }
  vtkNew<vtkLightFieldReader> reader;
  vtkNew<vtkLightFieldErrorObserver> errors; // said once, as the logic's own
  errors->Observe(internal.Scene);
  errors->Observe(reader);
  const bool configured = internal.Scene->ConfigureReader(reader);
  errors->StopObserving(internal.Scene);
  if (!configured)
  {
    this->Refuse(errors->GetErrorMessage());
    return nullptr;
  }
  const std::string path = internal.Scene->GetResolvedLightFieldPath();
  if (internal.LightField && internal.LightFieldSource == path)
  {
    return internal.LightField;
  }
  reader->Update();
  if (reader->GetErrorCode() != 0)
  {
    this->Refuse(errors->GetErrorMessage());
    return nullptr;
  }
  internal.LightField = vtkSmartPointer<vtkLightField>::New();
  internal.LightField->ShallowCopy(reader->GetOutput());
  internal.LightFieldSource = path;
  return internal.LightField;
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::SetLightField(vtkLightField* lightField)
{
  this->Internal->LightField = lightField;
  this->Internal->LightFieldSource.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::CheckCage(vtkIdList* boxes)
{
  vtkDeformationCage* cage = this->Internal->Cage;
  // The light field is used when it is at hand: validation never reads one.
  vtkLightField* lightField = this->Internal->LightField;
  std::string why;
  if (boxes)
  {
    this->NumberOfBoxesLastValidated = boxes->GetNumberOfIds();
    why = cage->ValidateBoxes(boxes);
    if (why.empty() && lightField)
    {
      why = cage->ValidateLabels(lightField);
    }
  }
  else
  {
    this->NumberOfBoxesLastValidated = cage->GetNumberOfBoxes();
    why = cage->Validate(lightField);
  }
  return why.empty() || this->Refuse(this->Where() + why);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::Validate()
{
  return this->CheckCage(nullptr);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::HasCage()
{
  return this->Internal->Scene->HasCage();
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::GetCageAtTime(double time,
  vtkLightField* lightField,
  vtkDeformationCage* cage)
{
  return this->FillCage(&time, lightField, cage);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::GetCurrentCage(vtkLightField* lightField, vtkDeformationCage* cage)
{
  return this->FillCage(nullptr, lightField, cage);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::FillCage(const double* time,
  vtkLightField* lightField,
  vtkDeformationCage* cage)
{
  vtkLightFieldScene* scene = this->Internal->Scene;
  if (!cage || !scene->HasCage())
  {
    return false;
  }
  cage->InitializeFromGrid(this->Internal->Cage);
  if (time && scene->GetNumberOfKeyframes() > 0)
  {
    vtkNew<vtkKeyframeInterpolator> keyframes;
    keyframes->SetInterpolation(scene->GetInterpolation());
    for (int k = 0; k < scene->GetNumberOfKeyframes(); ++k)
    {
      if (!keyframes->AddKeyframe(scene->GetKeyframeTime(k), scene->GetKeyframePoints(k)))
      {
        return this->Refuse(this->Where() + "keyframes: keyframe " + std::to_string(k) +
          " is refused by the interpolator");
      }
    }
    // Single precision, as the animation frames of `lfd animate` always
    // were: their measured figures stay as they are.
    vtkNew<vtkPoints> points;
    keyframes->InterpolatePoints(*time, points);
    cage->SetPoints(points);
  }
  const std::string why = cage->Validate(lightField);
  return why.empty() || this->Refuse(this->Where() + why);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetInterpolation(int interpolation)
{
  return this->Internal->EditSettings(this,
    "Set interpolation",
    [interpolation](vtkLightFieldScene* scene)
    {
      scene->SetInterpolation(interpolation);
      return scene->GetInterpolation() == interpolation
        ? std::string()
        : "field \"interpolation\": expected 0 (linear) or 1 (Catmull-Rom), found " +
          std::to_string(interpolation);
    });
}

//------------------------------------------------------------------------------
int vtkLightFieldSceneLogic::GetInterpolation()
{
  return this->Internal->Scene->GetInterpolation();
}

//------------------------------------------------------------------------------
double vtkLightFieldSceneLogic::GetAnimationTime(int frame, int frames)
{
  vtkLightFieldScene* scene = this->Internal->Scene;
  const int keyframes = scene->GetNumberOfKeyframes();
  if (keyframes == 0)
  {
    return 0.0;
  }
  const double t0 = scene->GetKeyframeTime(0);
  const double t1 = scene->GetKeyframeTime(keyframes - 1);
  return t0 + (t1 - t0) * frame / std::max(frames - 1, 1);
}

namespace
{
/// The view settings a renderer and a ground-truth evaluator share.
template<typename Target>
void ApplySceneView(Target* target, vtkLightFieldScene* scene)
{
  target->SetCamera(scene->GetCamera());
  target->SetWidth(scene->GetWidth());
  target->SetHeight(scene->GetHeight());
  target->SetFocalDistance(scene->GetFocalDistance());
  target->SetFocalSurface(scene->GetFocalSurface());
  target->SetSubdivision(scene->GetSubdivision()); // 0 = "auto" in all three
  target->SetWidenedSearch(scene->GetWidenedSearch());
  target->SetObjectThreshold(scene->GetObjectThreshold());
  target->SetAntiAliasing(scene->GetAntiAliasing());
}
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::ApplyView(vtkLightFieldRenderer* renderer)
{
  ApplySceneView(renderer, this->Internal->Scene.Get());
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::ApplyView(vtkGroundTruthEvaluator* evaluator)
{
  ApplySceneView(evaluator, this->Internal->Scene.Get());
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::ConfigureRenderer(vtkLightFieldRenderer* renderer,
  vtkLightField* lightField,
  vtkDeformationCage* cage)
{
  renderer->SetInputData(lightField);
  renderer->SetCageData(cage);
  this->ApplyView(renderer);
  renderer->SetBackground(this->Internal->Scene->GetBackground());
  renderer->SetFocalDepth(this->Internal->Scene->GetFocalDepth());
  renderer->SetAperture(this->Internal->Scene->GetAperture());
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::LabelMesh(vtkPolyData* mesh, vtkPolyData* labelled)
{
  vtkNew<vtkLabelCellsByBoxes> labeler;
  labeler->SetInputData(mesh);
  labeler->SetBoxesData(this->Internal->Cage);
  labeler->Update();
  if (labeler->GetErrorCode() != 0 || !labelled)
  {
    return this->Refuse(this->Where() + "the mesh could not be labelled by the scene's boxes");
  }
  labelled->ShallowCopy(labeler->GetOutput());
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::OrbitCamera(vtkCameraRig* rig,
  double phi,
  double scale,
  double height,
  double viewAngle,
  vtkCamera* camera)
{
  const double* axis = rig->GetAxis();
  const double* center = rig->GetCenter();
  double x[3], y[3];
  rig->GetAzimuthFrame(x, y);
  const double r = scale * rig->GetRadius();
  double position[3];
  for (int c = 0; c < 3; ++c)
  {
    position[c] = center[c] + height * axis[c] + r * (std::cos(phi) * x[c] + std::sin(phi) * y[c]);
  }
  camera->SetPosition(position);
  camera->SetFocalPoint(center[0], center[1], center[2]);
  camera->SetViewUp(axis[0], axis[1], axis[2]);
  camera->SetViewAngle(viewAngle);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::BuildCageFromLabels(vtkDataSet* mesh, int axis)
{
  vtkNew<vtkPartCageSource> source;
  source->SetInputData(mesh);
  source->SetAxis(axis);
  source->Update();
  if (source->GetErrorCode() != 0 || source->GetOutput()->GetNumberOfBoxes() == 0)
  {
    return this->Refuse(this->Where() + "no cage could be built from the mesh's labels");
  }
  return this->Internal->ReplaceCage(this, "Build cage from labels", source->GetOutput());
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::BuildCageFromSlabs(const double bounds[6],
  int count,
  int axis,
  int label)
{
  if (count < 1 || count > 1024)
  {
    return this->Refuse(
      "BuildCageFromSlabs: expected 1 to 1024 slabs, found " + std::to_string(count));
  }
  if (axis < -1 || axis > 2)
  {
    return this->Refuse("BuildCageFromSlabs: the axis is 0, 1, 2 or -1 (the ring axis), found " +
      std::to_string(axis));
  }
  if (axis == -1)
  {
    vtkLightField* lightField = this->GetLightField();
    if (!lightField)
    {
      return false;
    }
    vtkCameraRig* rig = lightField->GetRig();
    if (!rig || !rig->HasCylinder())
    {
      return this->Refuse(
        this->Where() + "the light field's rig has no fitted ring: give the slab axis (0, 1 or 2)");
    }
    const double* ring = rig->GetAxis();
    axis = 0;
    for (int c = 1; c < 3; ++c)
    {
      axis = std::abs(ring[c]) > std::abs(ring[axis]) ? c : axis;
    }
  }
  // (b, c, axis) is right-handed, so corner 1 along +b, 3 along +c and 4
  // along +axis give a positive Jacobian.
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  vtkNew<vtkDeformationCage> cage;
  for (int k = 0; k <= count; ++k)
  {
    const double along = bounds[2 * axis] + (bounds[2 * axis + 1] - bounds[2 * axis]) * k / count;
    for (int corner = 0; corner < 4; ++corner)
    {
      const int bits = CornerBits(corner);
      double point[3];
      point[axis] = along;
      point[b] = bounds[2 * b + (bits & 1)];
      point[c] = bounds[2 * c + ((bits >> 1) & 1)];
      cage->AddPoint(point);
    }
  }
  for (int k = 0; k < count; ++k)
  {
    const vtkIdType corners[8] = {
      4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 3, 4 * k + 4, 4 * k + 5, 4 * k + 6, 4 * k + 7
    };
    cage->AddBox(corners, label);
  }
  return this->Internal->ReplaceCage(this, "Build cage from slabs", cage);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::BuildCageFromLattice(vtkLatticeCageFilter* lattice)
{
  if (!lattice)
  {
    return this->Refuse("BuildCageFromLattice: no lattice given");
  }
  vtkNew<vtkDeformationCage> rest;
  rest->InitializeFromGrid(this->Internal->Cage);
  lattice->SetInputData(rest);
  lattice->Update();
  if (lattice->GetErrorCode() != 0)
  {
    return this->Refuse(this->Where() + "the lattice could not be sampled into boxes");
  }
  return this->Internal->ReplaceCage(this, "Build cage from lattice", lattice->GetOutput());
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::ReplaceCage(vtkDeformationCage* cage)
{
  if (!cage)
  {
    return this->Refuse("ReplaceCage: no cage given");
  }
  return this->Internal->ReplaceCage(this, "Replace cage", cage);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::MovePoint(vtkIdType id, const double position[3])
{
  vtkNew<vtkIdList> ids;
  ids->InsertNextId(id);
  vtkNew<vtkPoints> positions;
  positions->SetDataTypeToDouble();
  positions->InsertNextPoint(position);
  return this->MovePoints(ids, positions);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::MovePoints(vtkIdList* ids, vtkPoints* positions)
{
  vtkDeformationCage* cage = this->Internal->Cage;
  if (!ids || !positions || ids->GetNumberOfIds() != positions->GetNumberOfPoints() ||
    ids->GetNumberOfIds() == 0)
  {
    return this->Refuse("MovePoints: give as many positions as point ids (at least one)");
  }
  auto command = std::make_unique<MoveCommand>();
  std::set<vtkIdType> seen;
  for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
  {
    const vtkIdType id = ids->GetId(i);
    if (id < 0 || id >= cage->GetNumberOfPoints())
    {
      return this->Refuse("MovePoints: point " + std::to_string(id) +
        " does not exist (the cage has " + Plural(cage->GetNumberOfPoints(), "point") + ")");
    }
    double from[3], to[3];
    cage->GetDeformedPoint(id, from);
    positions->GetPoint(i, to);
    if (!seen.insert(id).second || !std::isfinite(to[0] + to[1] + to[2]))
    {
      return this->Refuse("MovePoints: point " + std::to_string(id) +
        " is given twice or moved to a non-finite position");
    }
    command->Ids.push_back(id);
    command->From.insert(command->From.end(), from, from + 3);
    command->To.insert(command->To.end(), to, to + 3);
  }
  // Only the boxes using a moved point change shape; rest boxes do not move.
  std::set<vtkIdType> boxes;
  vtkNew<vtkIdList> pointBoxes;
  for (vtkIdType id : command->Ids)
  {
    cage->GetPointCells(id, pointBoxes);
    boxes.insert(pointBoxes->begin(), pointBoxes->end());
  }
  vtkNew<vtkIdList> touched;
  for (vtkIdType box : boxes)
  {
    touched->InsertNextId(box);
  }
  command->Apply(this, true);
  if (!this->CheckCage(touched))
  {
    command->Apply(this, false);
    return false;
  }
  command->Name = "Move " + Plural(command->Ids.size(), "point");
  command->Events = { CageModifiedEvent };
  return this->Internal->Push(this, std::move(command));
}

//------------------------------------------------------------------------------
vtkIdType vtkLightFieldSceneLogic::AddBox(const double bounds[6], int label)
{
  vtkIdType added = -1;
  const bool done = this->Internal->EditCage(this,
    "Add box",
    [bounds, label, &added](CageState& state, CageCheck& check)
    {
      if (!(bounds[0] < bounds[1] && bounds[2] < bounds[3] && bounds[4] < bounds[5]))
      {
        return std::string("AddBox: the bounds are empty (each minimum must be below its maximum)");
      }
      std::array<vtkIdType, 8> corners{};
      for (int k = 0; k < 8; ++k)
      {
        const int bits = CornerBits(k);
        const double point[3] = {
          bounds[bits & 1], bounds[2 + ((bits >> 1) & 1)], bounds[4 + ((bits >> 2) & 1)]
        };
        corners[k] = state.AddPoint(point);
      }
      added = static_cast<vtkIdType>(state.Boxes.size());
      state.Boxes.push_back(corners);
      state.Labels.push_back(label);
      check.Boxes = { added };
      return std::string();
    });
  return done ? added : -1;
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::RemoveBox(vtkIdType box)
{
  return this->Internal->EditBox(this,
    "RemoveBox",
    "Remove box",
    box,
    [box](CageState& state, CageCheck&)
    {
      RemoveBoxState(state, box);
      return std::string();
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SplitBox(vtkIdType box, int axis)
{
  return this->Internal->EditBox(this,
    "SplitBox",
    "Split box",
    box,
    [box, axis](CageState& state, CageCheck& check)
    {
      if (axis < 0 || axis > 2)
      {
        return "SplitBox: the axis is 0 (u), 1 (v) or 2 (w), found " + std::to_string(axis);
      }
      SplitBoxState(state, box, axis);
      check.Boxes = { box, static_cast<vtkIdType>(state.Boxes.size()) - 1 };
      return std::string();
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetBoxLabel(vtkIdType box, int label)
{
  return this->Internal->EditBox(this,
    "SetBoxLabel",
    "Set box label",
    box,
    [box, label](CageState& state, CageCheck& check)
    {
      state.Labels[box] = label;
      check.Boxes = { box };
      return std::string();
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetKeyframe(double time)
{
  return this->Internal->EditCage(this,
    "Set keyframe",
    [time](CageState& state, CageCheck&)
    {
      if (!std::isfinite(time))
      {
        return std::string("SetKeyframe: the time is not finite");
      }
      if (state.Rest.empty())
      {
        return std::string("SetKeyframe: the scene has no cage to key");
      }
      auto& times = state.KeyframeTimes;
      const auto at = std::lower_bound(times.begin(), times.end(), time);
      const auto k = at - times.begin();
      if (at != times.end() && *at == time)
      {
        state.KeyframePoints[k] = state.Deformed;
      }
      else
      {
        times.insert(at, time);
        state.KeyframePoints.insert(state.KeyframePoints.begin() + k, state.Deformed);
      }
      return std::string();
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::RemoveKeyframe(int index)
{
  return this->Internal->EditCage(this,
    "Remove keyframe",
    [index](CageState& state, CageCheck&)
    {
      if (index < 0 || index >= static_cast<int>(state.KeyframeTimes.size()))
      {
        return "RemoveKeyframe: keyframe " + std::to_string(index) + " does not exist";
      }
      state.KeyframeTimes.erase(state.KeyframeTimes.begin() + index);
      state.KeyframePoints.erase(state.KeyframePoints.begin() + index);
      return std::string();
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetSize(int width, int height)
{
  return this->Internal->EditSettings(this,
    "Set image size",
    [width, height](vtkLightFieldScene* scene)
    {
      scene->SetWidth(width);
      scene->SetHeight(height);
      return scene->GetWidth() == width && scene->GetHeight() == height
        ? std::string()
        : "field \"camera.width\", \"camera.height\": expected positive sizes, found " +
          std::to_string(width) + " x " + std::to_string(height);
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetFocalDistance(double distance)
{
  return this->Internal->EditSettings(this,
    "Set focal distance",
    [distance](vtkLightFieldScene* scene)
    {
      scene->SetFocalDistance(distance);
      return std::isfinite(distance)
        ? std::string()
        : std::string("field \"render.focal_distance\": expected a finite number");
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetSubdivision(int subdivision)
{
  return this->Internal->EditSettings(this,
    "Set subdivision",
    [subdivision](vtkLightFieldScene* scene)
    {
      scene->SetSubdivision(subdivision);
      return scene->GetSubdivision() == subdivision
        ? std::string()
        : "field \"render.subdivision\": expected 0 (auto) or a positive integer, found " +
          std::to_string(subdivision);
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetWidenedSearch(int views)
{
  return this->Internal->EditSettings(this,
    "Set widened search",
    [views](vtkLightFieldScene* scene)
    {
      scene->SetWidenedSearch(views);
      return scene->GetWidenedSearch() == views
        ? std::string()
        : "field \"render.widened_search\": expected an integer in [" +
          std::to_string(scene->GetWidenedSearchMinValue()) + ", " +
          std::to_string(scene->GetWidenedSearchMaxValue()) + "], found " + std::to_string(views);
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetObjectThreshold(double threshold)
{
  return this->Internal->EditSettings(this,
    "Set object threshold",
    [threshold](vtkLightFieldScene* scene)
    {
      scene->SetObjectThreshold(threshold);
      std::ostringstream why;
      if (scene->GetObjectThreshold() != threshold)
      {
        why << "field \"render.object_threshold\": expected a brightness in ["
            << scene->GetObjectThresholdMinValue() << ", " << scene->GetObjectThresholdMaxValue()
            << "], found " << threshold;
      }
      return why.str();
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetBackground(double r, double g, double b)
{
  return this->Internal->EditSettings(this,
    "Set background",
    [r, g, b](vtkLightFieldScene* scene)
    {
      scene->SetBackground(r, g, b);
      std::ostringstream why;
      for (double component : { r, g, b })
      {
        if (!(component >= 0.0 && component <= 1.0) && why.str().empty())
        {
          why << "field \"render.background\": expected colour components in [0, 1], found "
              << component;
        }
      }
      return why.str();
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetCamera(vtkCamera* camera)
{
  if (!camera)
  {
    return this->Refuse("SetCamera: no camera given");
  }
  return this->Internal->EditSettings(this,
    "Set camera",
    [camera](vtkLightFieldScene* scene)
    {
      vtkCamera* view = scene->GetCamera();
      view->SetPosition(camera->GetPosition());
      view->SetFocalPoint(camera->GetFocalPoint());
      view->SetViewUp(camera->GetViewUp());
      view->SetViewAngle(camera->GetViewAngle());
      return std::string();
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::SetProjectorMask(int projector, vtkImageData* mask)
{
  Internals& internal = *this->Internal;
  vtkImageData* masks = internal.LightField ? internal.LightField->GetProjectorMasks() : nullptr;
  vtkUnsignedCharArray* target = masks ? lfd::GetMaskColours(masks) : nullptr;
  if (!target)
  {
    return this->Refuse(
      this->Where() + "SetProjectorMask: the light field has no projector masks to paint");
  }
  const int* dims = masks->GetDimensions();
  if (projector < 0 || projector >= dims[2])
  {
    return this->Refuse(this->Where() + "SetProjectorMask: projector " + std::to_string(projector) +
      " does not exist (the light field has " + std::to_string(dims[2]) + ")");
  }
  vtkUnsignedCharArray* source = mask ? lfd::GetMaskColours(mask) : nullptr;
  const int* size = mask ? mask->GetDimensions() : nullptr;
  if (!source || size[0] != dims[0] || size[1] != dims[1] || size[2] != 1)
  {
    return this->Refuse(this->Where() + "SetProjectorMask: the mask of projector " +
      std::to_string(projector) + " must be an RGB uint8 image of " + std::to_string(dims[0]) +
      " x " + std::to_string(dims[1]) + " pixels");
  }
  const vtkIdType bytes = 3 * static_cast<vtkIdType>(dims[0]) * dims[1];
  auto command = std::make_unique<MaskCommand>();
  command->Masks = masks;
  command->Array = target;
  command->Offset = projector * bytes;
  const unsigned char* before = target->GetPointer(command->Offset);
  command->Before.assign(before, before + bytes);
  command->After.assign(source->GetPointer(0), source->GetPointer(0) + bytes);
  command->Name = "Paint projector mask";
  command->Events = { ProjectorMasksModifiedEvent };
  command->Apply(this, true);
  return internal.Push(this, std::move(command));
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::BeginInteraction()
{
  if (this->Internal->InteractionDepth++ == 0)
  {
    this->Internal->MergeOpen = false;
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::EndInteraction()
{
  Internals& internal = *this->Internal;
  internal.InteractionDepth = std::max(internal.InteractionDepth - 1, 0);
  internal.MergeOpen = internal.MergeOpen && internal.InteractionDepth > 0;
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::Undo()
{
  Internals& internal = *this->Internal;
  if (!this->CanUndo())
  {
    return false;
  }
  internal.MergeOpen = false;
  Command& command = *internal.Stack[--internal.Index];
  command.Apply(this, false);
  Internals::Notify(this, command.Events, true);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::Redo()
{
  Internals& internal = *this->Internal;
  if (!this->CanRedo())
  {
    return false;
  }
  internal.MergeOpen = false;
  Command& command = *internal.Stack[internal.Index++];
  command.Apply(this, true);
  Internals::Notify(this, command.Events, true);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::CanUndo() const
{
  return this->Internal->Index > 0;
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneLogic::CanRedo() const
{
  return this->Internal->Index < this->Internal->Stack.size();
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::ClearUndo()
{
  this->Internal->Stack.clear();
  this->Internal->Index = 0;
  this->Internal->MergeOpen = false;
  this->InvokeEvent(UndoStackModifiedEvent);
}

//------------------------------------------------------------------------------
std::string vtkLightFieldSceneLogic::GetUndoName() const
{
  return this->CanUndo() ? this->Internal->Stack[this->Internal->Index - 1]->Name : std::string();
}

//------------------------------------------------------------------------------
std::string vtkLightFieldSceneLogic::GetRedoName() const
{
  return this->CanRedo() ? this->Internal->Stack[this->Internal->Index]->Name : std::string();
}

//------------------------------------------------------------------------------
int vtkLightFieldSceneLogic::GetNumberOfCommands() const
{
  return static_cast<int>(this->Internal->Stack.size());
}

//------------------------------------------------------------------------------
int vtkLightFieldSceneLogic::GetUndoIndex() const
{
  return static_cast<int>(this->Internal->Index);
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneLogic::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const Internals& internal = *this->Internal;
  os << indent
     << "Scene: " << (internal.Scene->GetFileName() ? internal.Scene->GetFileName() : "(unsaved)")
     << "\n";
  os << indent << "Cage: " << internal.Cage->GetNumberOfBoxes() << " boxes on "
     << internal.Cage->GetNumberOfPoints() << " points\n";
  os << indent << "LightField: "
     << (!internal.LightField                   ? "(not read)"
            : internal.LightFieldSource.empty() ? "(in memory)"
                                                : internal.LightFieldSource.c_str())
     << "\n";
  os << indent << "Commands: " << internal.Stack.size() << " (undo index " << internal.Index
     << ")\n";
  os << indent << "UndoName: " << this->GetUndoName() << "\n";
  os << indent << "RedoName: " << this->GetRedoName() << "\n";
  os << indent << "InteractionDepth: " << internal.InteractionDepth << "\n";
  os << indent << "NumberOfBoxesLastValidated: " << this->NumberOfBoxesLastValidated << "\n";
}
