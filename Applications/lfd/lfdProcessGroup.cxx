#include "lfdProcessGroup.h"

#include "lfdCommandSupport.h"

#include "vtkMultiProcessController.h"

#ifdef LFD_USE_MPI
#include "vtkMPI.h"
#include "vtkMPIController.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdlib>
#include <thread>
#endif

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

void ProcessGroup::Check(const char* command)
{
  if (GetSize() > 1 && std::string(command) != "animate")
  {
    Fail(std::string("lfd ") + command + " runs as one process: only 'lfd animate' splits its " +
      "work across MPI processes (mpirun -np N lfd animate ...)");
  }
}
}
