#include "rackopt/dynamics/spectrum.hpp"

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace rackopt {
namespace {

// FFTW's planner is not thread safe; FFTW_ESTIMATE plans are cheap and a
// spectrum is taken once per response, so each call plans under a lock.
struct PlanDeleter {
  void operator()(fftw_plan_s* p) const { fftw_destroy_plan(p); }
};

}  // namespace

Spectrum amplitude_spectrum(const std::vector<double>& samples, double duration) {
  const std::size_t n = samples.size();
  if (n < 2) throw std::invalid_argument("amplitude_spectrum: needs at least 2 samples");
  if (!(duration > 0) || !std::isfinite(duration)) throw std::invalid_argument("amplitude_spectrum: duration must be > 0");
  for (double s : samples) {
    if (!std::isfinite(s)) throw std::invalid_argument("amplitude_spectrum: a sample is not finite");
  }
  std::vector<double> in(samples);
  std::vector<std::complex<double>> out(n / 2 + 1);
  {
    static std::mutex planner;
    std::lock_guard<std::mutex> lock(planner);
    std::unique_ptr<fftw_plan_s, PlanDeleter> plan(fftw_plan_dft_r2c_1d(
        static_cast<int>(n), in.data(), reinterpret_cast<fftw_complex*>(out.data()), FFTW_ESTIMATE));
    if (!plan) throw std::runtime_error("amplitude_spectrum: FFTW could not plan a transform of this size");
    fftw_execute(plan.get());
  }
  Spectrum s;
  s.frequency_hz.resize(out.size());
  s.amplitude.resize(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    s.frequency_hz[k] = static_cast<double>(k) / duration;
    const double a = std::abs(out[k]) / static_cast<double>(n);
    const bool single = k == 0 || (n % 2 == 0 && k == n / 2);
    s.amplitude[k] = single ? a : 2 * a;
  }
  return s;
}

double amplitude_at(const Spectrum& spectrum, double frequency_hz) {
  if (spectrum.frequency_hz.size() < 2) return 0;
  const double df = spectrum.frequency_hz[1];
  const double k = std::round(frequency_hz / df);
  if (k < 0 || k >= static_cast<double>(spectrum.amplitude.size())) return 0;
  return spectrum.amplitude[static_cast<std::size_t>(k)];
}

}  // namespace rackopt
