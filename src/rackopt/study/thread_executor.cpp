#include "rackopt/core/parallel_for.hpp"
#include "rackopt/study/design_executor.hpp"

namespace rackopt::study {

namespace {

class ThreadExecutor final : public DesignExecutor {
 public:
  explicit ThreadExecutor(unsigned threads) : threads_(resolve_threads(threads)) {}

  std::vector<DesignEvaluation> evaluate(const StudyProblem& problem, const std::vector<std::vector<double>>& xs,
                                         unsigned inner_threads) override {
    std::vector<DesignEvaluation> out(xs.size());
    if (xs.size() == 1) {
      out[0] = problem.evaluate_design(xs[0], inner_threads);
      return out;
    }
    // Several designs: one thread each, none inside a design (a design's
    // result does not depend on its inner threads).
    parallel_for(xs.size(), threads_, [&](std::size_t k) { out[k] = problem.evaluate_design(xs[k], 1); });
    return out;
  }
  unsigned workers() const override { return threads_; }
  std::string describe() const override {
    return std::to_string(threads_) + (threads_ == 1 ? " thread" : " threads");
  }

 private:
  unsigned threads_;
};

}  // namespace

std::unique_ptr<DesignExecutor> make_thread_executor(unsigned threads) {
  return std::make_unique<ThreadExecutor>(threads);
}

}  // namespace rackopt::study
