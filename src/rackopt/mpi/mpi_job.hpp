// rackopt under `mpirun -np N rackopt run STUDY ...`: rank 0 runs the study
// as without MPI (store, recorder, progress, report are its alone) and hands
// batches of designs to every rank through an MpiExecutor; ranks 1..N-1
// load the same study, compute the designs they are given and send back
// their metrics (study/design_wire.hpp). Rank 0 maps them with its own
// objective scales, so the results equal a serial run's bit for bit.
//
// Protocol (MPI_COMM_WORLD):
//  * at start every worker sends rank 0 one READY message: "" when it loaded
//    the study, else why not; rank 0 reads them before the first batch and
//    refuses to run (naming the rank) when one could not start;
//  * a batch is a broadcast header {kEvaluate, bytes} and the encoded designs;
//    design k goes to rank k % N (rank 0 computes its share meanwhile); each
//    worker sends its results (kResultTag) in one message;
//  * the Monte Carlo of a reliability study's design is a broadcast header
//    {kReliabilitySamples, bytes}, the design and the sample count; rank r
//    runs the same analysis set-up and its contiguous share of the samples
//    and sends their lives (or why it could not) in one message;
//  * the end is a broadcast header {kStop, 0}, sent once by rank 0 on every
//    path out (the job's destructor), after which every rank finalizes.
// A rank that dies takes the job down (mpirun's default): what rank 0 had
// recorded stays in the store and --resume continues from it.
#pragma once

#include <memory>
#include <string>

#include "rackopt/study/design_executor.hpp"
#include "rackopt/study/study_problem.hpp"

namespace rackopt::mpi {

class MpiJob {
 public:
  // True when this process was started by mpirun (OpenMPI's or a PMI
  // launcher's environment); then a job must be made before anything else.
  static bool launched();

  // MPI_Init_thread (only the main thread calls MPI). Ranks > 0 ignore
  // SIGINT, SIGTERM and SIGUSR1 from here on: rank 0 owns the stop.
  MpiJob(int* argc, char*** argv);
  // Rank 0: stops the workers (if not yet done); every rank: MPI_Finalize.
  ~MpiJob();
  MpiJob(const MpiJob&) = delete;
  MpiJob& operator=(const MpiJob&) = delete;

  // The job of this process, or nullptr (no mpirun, or not made yet).
  static MpiJob* current();

  int rank() const { return rank_; }
  int size() const { return size_; }

  // Rank 0: an executor over every rank (`threads` per rank for its own
  // share). Reads the workers' READY messages first: throws
  // std::runtime_error naming the first rank that could not start.
  std::shared_ptr<study::DesignExecutor> executor(unsigned threads);

  // Ranks > 0: sends READY (`problem` null: `why_not` says why) and serves
  // batches until rank 0 says stop. Returns the exit code (0).
  int serve(const study::StudyProblem* problem, const std::string& why_not, unsigned threads);

  // Rank 0: the stop broadcast (once); called by the destructor too.
  void stop_workers();

 private:
  void collect_ready();
  int rank_ = 0, size_ = 1;
  bool ready_collected_ = false, stopped_ = false;
};

}  // namespace rackopt::mpi
