// Designs and their metrics as bytes, for executors that run in other
// processes (MPI ranks). Doubles travel as their 8 bytes (bit for bit, NaN
// and -0 included), counts as 8-byte integers, texts with their length;
// both ends are the same build, so the host byte order is the format.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rackopt/study/study_problem.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace rackopt::study {

std::string encode_designs(const std::vector<std::vector<double>>& xs);
std::vector<std::vector<double>> decode_designs(std::string_view bytes);

std::string encode_metrics(const std::vector<DesignMetrics>& results);
// Throws std::runtime_error for bytes that are not a whole encoding.
std::vector<DesignMetrics> decode_metrics(std::string_view bytes);

// One share of a Monte Carlo's sample lives, or why it could not be
// computed (`failure` not empty; `lives` then unused).
struct SampleLivesMessage {
  std::string failure;
  SampleLives lives;
};
std::string encode_sample_lives(const SampleLivesMessage& message);
SampleLivesMessage decode_sample_lives(std::string_view bytes);

}  // namespace rackopt::study
