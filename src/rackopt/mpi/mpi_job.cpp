#include "rackopt/mpi/mpi_job.hpp"

#include <mpi.h>

#include <csignal>
#include <cstdint>
#include <exception>
#include <cstdlib>
#include <iterator>
#include <span>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/parallel_for.hpp"
#include "rackopt/study/design_wire.hpp"
#include "rackopt/study/reliability_options.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace rackopt::mpi {

namespace {

constexpr int kReadyTag = 1;
constexpr int kResultTag = 2;
enum Command : std::int64_t { kStop = 0, kEvaluate = 1, kReliabilitySamples = 2 };

void send_bytes(const std::string& bytes, int to, int tag) {
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD);
}

std::string receive_bytes(int from, int tag) {
  MPI_Status status;
  MPI_Probe(from, tag, MPI_COMM_WORLD, &status);
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  std::string bytes(static_cast<std::size_t>(count), '\0');
  MPI_Recv(bytes.data(), count, MPI_BYTE, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return bytes;
}

// The broadcast of one batch's header and designs (rank 0 fills them).
void broadcast(std::int64_t& command, std::string& payload) {
  std::int64_t header[2] = {command, static_cast<std::int64_t>(payload.size())};
  MPI_Bcast(header, 2, MPI_INT64_T, 0, MPI_COMM_WORLD);
  command = header[0];
  payload.resize(static_cast<std::size_t>(header[1]));
  if (header[1] > 0) MPI_Bcast(payload.data(), static_cast<int>(header[1]), MPI_BYTE, 0, MPI_COMM_WORLD);
}

// The designs of `xs` that rank `r` of `size` computes: k % size == r.
std::vector<std::size_t> share_of(std::size_t count, int r, int size) {
  std::vector<std::size_t> k;
  for (std::size_t i = static_cast<std::size_t>(r); i < count; i += static_cast<std::size_t>(size)) k.push_back(i);
  return k;
}

std::vector<study::DesignMetrics> compute_share(const study::StudyProblem& problem,
                                                const std::vector<std::vector<double>>& xs,
                                                const std::vector<std::size_t>& mine, unsigned threads) {
  std::vector<study::DesignMetrics> out(mine.size());
  parallel_for(mine.size(), threads, [&](std::size_t j) { out[j] = problem.compute_metrics(xs[mine[j]], 1); });
  return out;
}

// Rank r's share of n Monte Carlo samples: a contiguous range, so that the
// shares concatenate in rank order.
std::pair<std::size_t, std::size_t> sample_share(std::size_t n, int r, int size) {
  const auto rr = static_cast<std::size_t>(r), ss = static_cast<std::size_t>(size);
  return {n * rr / ss, n * (rr + 1) / ss};
}

// A worker's share of the Monte Carlo of a reliability study's design: the
// same set-up as rank 0's run, then its samples.
study::SampleLivesMessage reliability_share(const study::StudyProblem& problem, const std::vector<double>& x,
                                            std::size_t n, int r, int size, unsigned threads) {
  study::SampleLivesMessage m;
  try {
    const Drive design = problem.drive_at(x);
    WearReliabilityOptions wo = study::study_reliability_options(problem.spec(), design, threads);
    wo.sample_share = sample_share(n, r, size);
    WearReliabilityResult result = run_wear_reliability(design, wo);
    if (!result.share_lives) throw std::runtime_error("the design has no random inputs to sample");
    m.lives = std::move(*result.share_lives);
  } catch (const std::exception& e) {
    m.failure = e.what();
  }
  return m;
}

class MpiExecutor final : public study::DesignExecutor {
 public:
  MpiExecutor(MpiJob& job, unsigned threads) : job_(job), threads_(resolve_threads(threads)) {}

  std::vector<study::DesignEvaluation> evaluate(const study::StudyProblem& problem,
                                                const std::vector<std::vector<double>>& xs,
                                                unsigned inner_threads) override {
    std::vector<study::DesignEvaluation> out(xs.size());
    // One design: here (a local solver's step); the ranks would only wait.
    if (xs.size() <= 1 || job_.size() == 1) {
      for (std::size_t k = 0; k < xs.size(); ++k) out[k] = problem.evaluate_design(xs[k], inner_threads);
      return out;
    }
    std::int64_t command = kEvaluate;
    std::string payload = study::encode_designs(xs);
    broadcast(command, payload);
    const std::vector<std::size_t> mine = share_of(xs.size(), 0, job_.size());
    // Ctrl-C inside rank 0's share (a Monte Carlo that gave up) ends the
    // batch, but only once every worker's results are in: the next command
    // (the stop) must find no message left over.
    std::exception_ptr interrupted;
    try {
      std::vector<study::DesignMetrics> own = compute_share(problem, xs, mine, threads_);
      for (std::size_t j = 0; j < mine.size(); ++j) out[mine[j]] = problem.to_evaluation(std::move(own[j]));
    } catch (const Interrupted&) {
      interrupted = std::current_exception();
    }
    for (int r = 1; r < job_.size(); ++r) {
      const std::vector<std::size_t> theirs = share_of(xs.size(), r, job_.size());
      std::vector<study::DesignMetrics> got = study::decode_metrics(receive_bytes(r, kResultTag));
      if (got.size() != theirs.size())
        throw std::runtime_error("MPI rank " + std::to_string(r) + " returned " + std::to_string(got.size()) +
                                 " designs for " + std::to_string(theirs.size()));
      for (std::size_t j = 0; j < theirs.size(); ++j) out[theirs[j]] = problem.to_evaluation(std::move(got[j]));
    }
    if (interrupted) std::rethrow_exception(interrupted);
    return out;
  }
  // The samples in contiguous shares, rank r the r-th; rank 0 computes its
  // own with the run it is in (`here`), the workers theirs after the same
  // set-up, and the shares are joined in rank order.
  decltype(WearReliabilityOptions::sample_executor) reliability_samples(const study::StudyProblem& problem,
                                                                        std::span<const double> x) override {
    if (job_.size() == 1) return {};
    std::vector<double> design(x.begin(), x.end());
    return [this, &problem, design](std::size_t n, const WearReliabilityOptions::SamplesHere& here) {
      std::int64_t command = kReliabilitySamples;
      std::string payload = study::encode_designs({design, {static_cast<double>(n)}});
      broadcast(command, payload);
      const auto [first, last] = sample_share(n, 0, job_.size());
      // Rank 0's own share stops early on Ctrl-C (its skipped samples are
      // thrown away by the analysis); the workers' shares are read all the same.
      SampleLives all = here(first, last);
      std::string failure;
      for (int r = 1; r < job_.size(); ++r) {
        // Every share is received, also after a failure: the next command
        // must find no message left over.
        study::SampleLivesMessage m = study::decode_sample_lives(receive_bytes(r, kResultTag));
        if (!m.failure.empty() && failure.empty())
          failure = "MPI rank " + std::to_string(r) + " could not compute its Monte Carlo samples: " + m.failure;
        all.lives.insert(all.lives.end(), std::make_move_iterator(m.lives.lives.begin()),
                         std::make_move_iterator(m.lives.lives.end()));
        all.criteria.insert(all.criteria.end(), std::make_move_iterator(m.lives.criteria.begin()),
                            std::make_move_iterator(m.lives.criteria.end()));
        all.interpolated += m.lives.interpolated;
      }
      if (!failure.empty()) throw std::runtime_error(failure);
      all.processes = static_cast<unsigned>(job_.size());
      return all;
    };
  }
  unsigned workers() const override { return static_cast<unsigned>(job_.size()) * threads_; }
  std::string describe() const override {
    return std::to_string(job_.size()) + " MPI ranks x " + std::to_string(threads_) +
           (threads_ == 1 ? " thread" : " threads");
  }

 private:
  MpiJob& job_;
  unsigned threads_;
};

MpiJob* current_job = nullptr;

}  // namespace

MpiJob* MpiJob::current() { return current_job; }

bool MpiJob::launched() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr ||
         std::getenv("PMIX_RANK") != nullptr;
}

MpiJob::MpiJob(int* argc, char*** argv) {
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  current_job = this;
  // Rank 0 owns the stop: mpirun sends SIGTERM to every rank when it is
  // interrupted and forwards SIGUSR1 to every rank, and a worker that died
  // of either would take rank 0 down before its stopped report is written.
  // A worker finishes the batch it has and ends on rank 0's stop command;
  // it ignores them from here on, also while it loads the study.
  if (rank_ > 0) {
    ::signal(SIGINT, SIG_IGN);
    ::signal(SIGTERM, SIG_IGN);
    ::signal(SIGUSR1, SIG_IGN);
  }
}

MpiJob::~MpiJob() {
  if (rank_ == 0) {
    try {
      stop_workers();
    } catch (...) {
      // Finalizing anyway: a worker that is gone has taken the job down.
    }
  }
  current_job = nullptr;
  MPI_Finalize();
}

void MpiJob::collect_ready() {
  if (ready_collected_ || rank_ != 0) return;
  ready_collected_ = true;
  std::string first_failure;
  for (int r = 1; r < size_; ++r) {
    const std::string why_not = receive_bytes(r, kReadyTag);
    if (!why_not.empty() && first_failure.empty())
      first_failure = "MPI rank " + std::to_string(r) + " could not start: " + why_not;
  }
  if (!first_failure.empty()) throw std::runtime_error(first_failure);
}

std::shared_ptr<study::DesignExecutor> MpiJob::executor(unsigned threads) {
  collect_ready();
  return std::make_shared<MpiExecutor>(*this, threads);
}

void MpiJob::stop_workers() {
  if (rank_ != 0 || stopped_) return;
  stopped_ = true;
  try {
    collect_ready();  // every READY is read before the end, whatever they say
  } catch (const std::runtime_error&) {
    // Already reported by executor(), or the run never needed the workers.
  }
  std::int64_t command = kStop;
  std::string none;
  broadcast(command, none);
}

int MpiJob::serve(const study::StudyProblem* problem, const std::string& why_not, unsigned threads) {
  send_bytes(problem ? std::string() : (why_not.empty() ? std::string("no study to serve") : why_not), 0, kReadyTag);
  const unsigned pool = resolve_threads(threads);
  for (;;) {
    std::int64_t command = kStop;
    std::string payload;
    broadcast(command, payload);
    if (command == kReliabilitySamples) {
      const std::vector<std::vector<double>> parts = study::decode_designs(payload);
      study::SampleLivesMessage m;
      if (!problem || parts.size() != 2 || parts[1].size() != 1) {
        m.failure = problem ? "a malformed Monte Carlo request" : "no study loaded";
      } else {
        m = reliability_share(*problem, parts[0], static_cast<std::size_t>(parts[1][0]), rank_, size_, pool);
      }
      send_bytes(study::encode_sample_lives(m), 0, kResultTag);
      continue;
    }
    if (command != kEvaluate) return 0;
    const std::vector<std::vector<double>> xs = study::decode_designs(payload);
    const std::vector<std::size_t> mine = share_of(xs.size(), rank_, size_);
    std::vector<study::DesignMetrics> results;
    if (problem) results = compute_share(*problem, xs, mine, pool);
    send_bytes(study::encode_metrics(results), 0, kResultTag);
  }
}

}  // namespace rackopt::mpi
