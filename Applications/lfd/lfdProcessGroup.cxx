#include "lfdProcessGroup.h"

#include "lfdCommandSupport.h"

#include "vtkDataArray.h"
#include "vtkLightField.h"
#include "vtkLightFieldReader.h"
#include "vtkMultiProcessController.h"

#ifdef LFD_USE_MPI
#include "vtkMPI.h"
#include "vtkMPIController.h"
#include "vtkSMPTools.h"

#include <cstdlib>
#include <thread>
#endif

#include <algorithm>
#include <string>

namespace lfd::cli
{
#ifdef LFD_USE_MPI
namespace
{
/// Whether an MPI launcher started this process (OpenMPI, MPICH/Hydra, PMIx):
/// a plain `lfd animate` must not start MPI (slow, and noisy in containers).
bool LaunchedByMpi()
{
  for (const char* name : { "OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK" })
  {
    if (std::getenv(name))
    {
      return true;
    }
  }
  return false;
}

/// The number of the job's processes on this machine.
int ProcessesOnThisMachine()
{
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
  int size = 1;
  MPI_Comm_size(local, &size);
  MPI_Comm_free(&local);
  return size;
}
}

ProcessGroup::ProcessGroup(int* argc, char*** argv)
{
  if (!LaunchedByMpi())
  {
    return;
  }
  // A process waiting for the others (a round's outcomes, process 0's
  // encoding) would spin on a core they need: OpenMPI busy-polls unless it
  // counts more processes than cores, so it is told to yield (a user's
  // setting stands).
  setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
  vtkMPIController* controller = vtkMPIController::New();
  controller->Initialize(argc, argv);
  vtkMultiProcessController::SetGlobalController(controller);
  if (controller->GetNumberOfProcesses() > 1)
  {
    if (controller->GetLocalProcessId() != 0)
    {
      lfd::SetConsoleQuiet(true);
    }
    // Processes sharing a machine share its cores: threads beyond them
    // would only compete.
    if (!std::getenv("VTK_SMP_MAX_THREADS"))
    {
      const int cores = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
      vtkSMPTools::Initialize(std::max(1, cores / ProcessesOnThisMachine()));
    }
  }
}

ProcessGroup::~ProcessGroup()
{
  vtkMultiProcessController* controller = GetController();
  if (controller)
  {
    controller->Finalize();
    vtkMultiProcessController::SetGlobalController(nullptr);
    controller->Delete();
  }
}
#else
ProcessGroup::ProcessGroup(int*, char***) {}

ProcessGroup::~ProcessGroup() = default;
#endif

vtkMultiProcessController* ProcessGroup::GetController()
{
  return vtkMultiProcessController::GetGlobalController();
}

int ProcessGroup::GetRank()
{
  return GetController() ? GetController()->GetLocalProcessId() : 0;
}

int ProcessGroup::GetSize()
{
  return GetController() ? GetController()->GetNumberOfProcesses() : 1;
}

void ProcessGroup::ShareLightField(vtkLightField* lightField)
{
  const int processes = GetSize();
  if (processes < 2)
  {
    return;
  }
  // A broadcast's length is a vtkIdType, but MPI counts in int: sent in
  // pieces of at most 1 GiB.
  const vtkIdType chunk = vtkIdType(1) << 30;
  const int views = lightField->GetNumberOfViews();
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    vtkDataArray* array = lightField->GetPass(pass);
    if (!array)
    {
      continue;
    }
    const vtkIdType viewBytes = static_cast<vtkIdType>(lightField->GetWidth()) *
      lightField->GetHeight() * array->GetNumberOfComponents() * array->GetDataTypeSize();
    auto* bytes = static_cast<unsigned char*>(array->GetVoidPointer(0));
    for (int process = 0; process < processes; ++process)
    {
      int range[2];
      vtkLightFieldReader::GetPieceViews(views, process, processes, range);
      const vtkIdType end = range[1] * viewBytes;
      for (vtkIdType first = range[0] * viewBytes; first < end; first += chunk)
      {
        GetController()->Broadcast(bytes + first, std::min(chunk, end - first), process);
      }
    }
  }
}

void ProcessGroup::Check(const char* command)
{
  if (GetSize() > 1 && std::string(command) != "animate")
  {
    Fail(std::string("lfd ") + command + " runs as one process: only 'lfd animate' splits its " +
      "work across MPI processes (mpirun -np N lfd animate ...)");
  }
}
}
