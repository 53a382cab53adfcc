// Amplitude spectrum of one period of a periodic signal (FFTW's real
// transform): what the dynamic mesh force and transmission error hold at the
// mesh order, its harmonics and the span order (docs/models/dynamics.md).
#pragma once

#include <vector>

namespace rackopt {

struct Spectrum {
  std::vector<double> frequency_hz;  // k / duration, k = 0 .. n/2
  std::vector<double> amplitude;     // single-sided: |mean| at k = 0, 2 |X_k| / n above (the Nyquist line |X|/n)
};

// `samples` are n >= 2 equally spaced values over one period of `duration`
// seconds (the period's end not repeated). Throws std::invalid_argument for
// n < 2, a duration <= 0 or a non-finite sample.
Spectrum amplitude_spectrum(const std::vector<double>& samples, double duration);

// The amplitude at the line nearest to `frequency_hz` (0 when it lies beyond the spectrum).
double amplitude_at(const Spectrum& spectrum, double frequency_hz);

}  // namespace rackopt
