/**
 * @file   lfdProcessGroup.h
 * @brief  The processes of `mpirun -np N lfd animate ...`: MPI started
 *         through VTK's vtkMPIController when lfd was launched by an MPI
 *         launcher (and built with VTK::ParallelMPI), else one process.
 */
#ifndef lfdProcessGroup_h
#define lfdProcessGroup_h

class vtkLightField;
class vtkMultiProcessController;

namespace lfd::cli
{
/**
 * Started first in main(), ended last: with several processes, process 0
 * speaks for the job (errors, warnings and progress are said once, by it:
 * the others' errors reach it through lfd::scene::AgreeOnError and the
 * animation writer's rounds), each process renders with its share of its
 * machine's cores (the cores over the processes on that machine, unless
 * VTK_SMP_MAX_THREADS is set), and only `lfd animate` runs (Check()).
 */
class ProcessGroup
{
public:
  ProcessGroup(int* argc, char*** argv);
  ~ProcessGroup();
  ProcessGroup(const ProcessGroup&) = delete;
  void operator=(const ProcessGroup&) = delete;

  /// The job's processes (VTK's global controller), or nullptr for one process.
  static vtkMultiProcessController* GetController();

  /// This process's index (0 for one process) and the number of processes.
  static int GetRank();
  static int GetSize();

  /// Refuses a command other than `lfd animate` when there are several
  /// processes (each would write the same output).
  static void Check(const char* command);

  /**
   * Completes a light field of which this process read only its piece of
   * the views (ReadLightField() with GetRank() of GetSize() pieces): every
   * process broadcasts its views of every pass, so that each ends with the
   * whole light field. Every process must call it, after all have read
   * their piece (lfd::scene::AgreeOnError). Nothing with one process.
   */
  static void ShareLightField(vtkLightField* lightField);
};
}

#endif
