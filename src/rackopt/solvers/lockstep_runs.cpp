#include "rackopt/solvers/lockstep_runs.hpp"

#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace rackopt::solvers {

namespace {

constexpr std::size_t kCoordinator = static_cast<std::size_t>(-1);

// The baton: `turn` names the one thread allowed to run (a job's slot or
// the coordinator); every hand-over goes through the mutex, so whatever one
// thread wrote the next one sees.
struct Baton {
  std::mutex mutex;
  std::condition_variable changed;
  std::size_t turn = kCoordinator;

  void pass_and_wait(std::size_t to, std::size_t self) {
    std::unique_lock lock(mutex);
    turn = to;
    changed.notify_all();
    changed.wait(lock, [&] { return turn == self; });
  }
  void pass(std::size_t to) {
    std::lock_guard lock(mutex);
    turn = to;
    changed.notify_all();
  }
  void wait_for(std::size_t self) {
    std::unique_lock lock(mutex);
    changed.wait(lock, [&] { return turn == self; });
  }
};

struct Slot final : LockstepChannel {
  Baton* baton = nullptr;
  std::size_t index = 0;  // the slot's number (its turn)
  std::size_t job = 0;
  const std::vector<std::vector<double>>* request = nullptr;  // set while waiting for a batch
  std::vector<Evaluation> reply;
  bool abandoned = false;
  bool done = false;
  std::exception_ptr error;
  std::thread thread;

  std::vector<Evaluation> evaluate(const std::vector<std::vector<double>>& us) override {
    if (abandoned) throw LockstepAbandoned{};
    request = &us;
    baton->pass_and_wait(kCoordinator, index);
    if (abandoned) throw LockstepAbandoned{};
    return std::move(reply);
  }
};

}  // namespace

void run_in_lockstep(std::size_t jobs, std::size_t width, const std::function<void(std::size_t, LockstepChannel&)>& job,
                     const std::function<std::vector<std::vector<Evaluation>>(
                         const std::vector<LockstepRequest>&)>& serve) {
  if (width == 0) width = 1;
  Baton baton;
  std::vector<std::unique_ptr<Slot>> slots;  // live and ended, in job order
  std::size_t next_job = 0;
  std::exception_ptr first_error;            // of serve, or the first job's in job order
  bool abandon = false;

  auto start = [&](std::size_t j) {
    auto slot = std::make_unique<Slot>();
    slot->baton = &baton;
    slot->index = slots.size();
    slot->job = j;
    Slot* s = slot.get();
    s->thread = std::thread([s, &job, &baton] {
      baton.wait_for(s->index);
      try {
        job(s->job, *s);
      } catch (const LockstepAbandoned&) {
        // Given up by the coordinator: nothing of this job is kept.
      } catch (...) {
        if (!s->abandoned) s->error = std::current_exception();
      }
      s->done = true;
      baton.pass(kCoordinator);
    });
    slots.push_back(std::move(slot));
  };
  auto live = [&] {
    std::size_t n = 0;
    for (const auto& s : slots) n += s->done ? 0 : 1;
    return n;
  };

  while (true) {
    // Each live job runs until it asks for evaluations or ends; a job that
    // ends frees its place for the next one within the same round.
    for (bool passed = true; passed;) {
      while (!abandon && next_job < jobs && live() < width) start(next_job++);
      passed = false;
      for (auto& s : slots)
        if (!s->done && !s->request) {
          baton.pass_and_wait(s->index, kCoordinator);
          passed = true;
        }
    }
    if (!first_error)
      for (const auto& s : slots)
        if (s->error) {
          first_error = s->error;
          break;
        }
    if (first_error) abandon = true;
    std::vector<LockstepRequest> round;
    std::vector<Slot*> asking;
    for (auto& s : slots)
      if (!s->done && s->request) {
        round.push_back({s->job, s->request});
        asking.push_back(s.get());
      }
    if (round.empty() && (abandon || next_job >= jobs)) break;
    if (round.empty()) continue;
    if (!abandon) {
      try {
        std::vector<std::vector<Evaluation>> replies = serve(round);
        for (std::size_t k = 0; k < asking.size(); ++k) asking[k]->reply = std::move(replies[k]);
      } catch (...) {
        first_error = std::current_exception();
        abandon = true;
      }
    }
    for (Slot* s : asking) {
      s->request = nullptr;
      if (abandon) s->abandoned = true;
    }
  }
  for (auto& s : slots) s->thread.join();
  if (first_error) std::rethrow_exception(first_error);
}

Evaluation LockstepProblem::evaluate(std::span<const double> u) const {
  return channel_.evaluate({std::vector<double>(u.begin(), u.end())}).front();
}

std::vector<Evaluation> LockstepProblem::evaluate_batch(const std::vector<std::vector<double>>& us) const {
  return channel_.evaluate(us);
}

}  // namespace rackopt::solvers
