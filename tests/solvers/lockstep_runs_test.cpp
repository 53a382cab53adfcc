// Runs in lockstep: each round holds the next request of every live run in
// run order, at most `width` runs at once, one thread running at a time,
// and an exception of a run or of the batch ends every run and comes out.
#include "rackopt/solvers/lockstep_runs.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace rackopt::solvers {
namespace {

// Run j asks `j + 1` times for one point (j, k) and checks each answer.
struct CountingJobs {
  std::vector<std::vector<std::pair<std::size_t, double>>> rounds;  // (job, u[1]) per request
  std::atomic<int> running{0};
  int most_running = 0;
  std::size_t wrong_answers = 0;

  void job(std::size_t j, LockstepChannel& channel) {
    for (std::size_t k = 0; k <= j; ++k) {
      most_running = std::max(most_running, ++running);
      --running;
      const auto e = channel.evaluate({{static_cast<double>(j), static_cast<double>(k)}});
      if (e.size() != 1 || e[0].objectives.at(0) != 100.0 * static_cast<double>(j) + static_cast<double>(k))
        ++wrong_answers;
    }
  }
  std::vector<std::vector<Evaluation>> serve(const std::vector<LockstepRequest>& round) {
    rounds.emplace_back();
    std::vector<std::vector<Evaluation>> out;
    for (const LockstepRequest& r : round) {
      const auto& u = r.us->front();
      rounds.back().push_back({r.job, u[1]});
      Evaluation e;
      e.objectives = {100.0 * u[0] + u[1]};
      out.push_back({e});
    }
    return out;
  }
};

TEST(LockstepRuns, EachRoundHoldsTheNextRequestOfEveryLiveRunInOrder) {
  CountingJobs c;
  run_in_lockstep(
      4, 2, [&](std::size_t j, LockstepChannel& ch) { c.job(j, ch); },
      [&](const std::vector<LockstepRequest>& r) { return c.serve(r); });
  EXPECT_EQ(c.wrong_answers, 0u);
  EXPECT_EQ(c.most_running, 1);  // one thread at a time
  // Width 2: runs 0 and 1 start; 0 ends after one request and 2 takes its
  // place; 1 ends after two, 3 takes its place; and so on.
  const std::vector<std::vector<std::pair<std::size_t, double>>> expected = {
      {{0, 0}, {1, 0}}, {{1, 1}, {2, 0}}, {{2, 1}, {3, 0}}, {{2, 2}, {3, 1}}, {{3, 2}}, {{3, 3}}};
  EXPECT_EQ(c.rounds, expected);
}

TEST(LockstepRuns, TheOrderDoesNotDependOnTheWidthBeyondTheRunCount) {
  CountingJobs wide, wider;
  run_in_lockstep(
      3, 3, [&](std::size_t j, LockstepChannel& ch) { wide.job(j, ch); },
      [&](const std::vector<LockstepRequest>& r) { return wide.serve(r); });
  run_in_lockstep(
      3, 16, [&](std::size_t j, LockstepChannel& ch) { wider.job(j, ch); },
      [&](const std::vector<LockstepRequest>& r) { return wider.serve(r); });
  EXPECT_EQ(wide.rounds, wider.rounds);
  ASSERT_EQ(wide.rounds.size(), 3u);
  EXPECT_EQ(wide.rounds[0].size(), 3u);
}

TEST(LockstepRuns, ARunsExceptionEndsEveryRunAndComesOut) {
  std::vector<std::size_t> requests(3, 0);
  std::vector<bool> ended_normally(3, false);
  auto job = [&](std::size_t j, LockstepChannel& ch) {
    for (int k = 0; k < 50; ++k) {
      if (j == 1 && k == 3) throw std::runtime_error("run 1 failed");
      ch.evaluate({{0.0}});
      ++requests[j];
    }
    ended_normally[j] = true;
  };
  auto serve = [](const std::vector<LockstepRequest>& round) {
    return std::vector<std::vector<Evaluation>>(round.size(), std::vector<Evaluation>(1));
  };
  try {
    run_in_lockstep(3, 3, job, serve);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "run 1 failed");
  }
  EXPECT_EQ(requests, (std::vector<std::size_t>{3, 3, 3}));  // nobody got a 4th answer
  EXPECT_EQ(ended_normally, (std::vector<bool>{false, false, false}));
}

TEST(LockstepRuns, ABatchExceptionEndsEveryRunAndComesOut) {
  std::size_t rounds = 0;
  auto job = [](std::size_t, LockstepChannel& ch) {
    while (true) ch.evaluate({{1.0}});
  };
  auto serve = [&](const std::vector<LockstepRequest>& round) {
    if (++rounds == 4) throw std::logic_error("batch failed");
    return std::vector<std::vector<Evaluation>>(round.size(), std::vector<Evaluation>(1));
  };
  EXPECT_THROW(run_in_lockstep(5, 2, job, serve), std::logic_error);
  EXPECT_EQ(rounds, 4u);
}

}  // namespace
}  // namespace rackopt::solvers
