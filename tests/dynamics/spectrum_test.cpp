#include "rackopt/dynamics/spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace rackopt {
namespace {

// A mean, a line at 3 cycles per period and one at 40: the spectrum holds
// exactly those amplitudes at exactly those frequencies, nothing elsewhere.
TEST(AmplitudeSpectrum, RecoversTheLinesOfAKnownSignal) {
  const int n = 256;
  const double duration = 0.5;  // s: lines every 2 Hz
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) {
    const double t = duration * i / n;
    x[i] = 7.0 + 2.5 * std::sin(2 * std::numbers::pi * 6.0 * t + 0.3) + 0.75 * std::cos(2 * std::numbers::pi * 80.0 * t);
  }
  const Spectrum s = amplitude_spectrum(x, duration);
  ASSERT_EQ(s.frequency_hz.size(), static_cast<std::size_t>(n / 2 + 1));
  EXPECT_DOUBLE_EQ(s.frequency_hz[1], 2.0);
  EXPECT_NEAR(s.amplitude[0], 7.0, 1e-12);
  EXPECT_NEAR(amplitude_at(s, 6.0), 2.5, 1e-12);
  EXPECT_NEAR(amplitude_at(s, 80.0), 0.75, 1e-12);
  for (std::size_t k = 1; k < s.amplitude.size(); ++k) {
    if (k == 3 || k == 40) continue;
    EXPECT_LT(s.amplitude[k], 1e-12) << "line " << k;
  }
  EXPECT_EQ(amplitude_at(s, 1e6), 0.0);  // beyond the spectrum
}

// Parseval: the mean square of the signal equals the sum of the squared
// single-sided amplitudes (mean squared, halves above it).
TEST(AmplitudeSpectrum, KeepsTheSignalsPower) {
  const int n = 101;  // odd: no Nyquist line
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = std::sin(0.37 * i * i) + 0.1 * i;
  const Spectrum s = amplitude_spectrum(x, 2.0);
  double power = 0, lines = s.amplitude[0] * s.amplitude[0];
  for (double v : x) power += v * v / n;
  for (std::size_t k = 1; k < s.amplitude.size(); ++k) lines += 0.5 * s.amplitude[k] * s.amplitude[k];
  EXPECT_NEAR(lines, power, 1e-10 * power);
}

TEST(AmplitudeSpectrum, RefusesWhatHasNoSpectrum) {
  EXPECT_THROW(amplitude_spectrum({1.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(amplitude_spectrum({1.0, 2.0}, 0.0), std::invalid_argument);
  EXPECT_THROW(amplitude_spectrum({1.0, NAN}, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace rackopt
