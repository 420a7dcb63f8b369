// The pointwise product of a half-complex spectrum (FFTW's r2c layout) with a kernel's
// spectrum, in place: the step between the forward and the backward transform of a
// convolution by FFT (elastic_deflection.cpp, far_history.cpp). Written as real products and
// sums: std::complex's operator* checks every product for NaN (C Annex G, a library call on
// that path), which keeps the loop from vectorizing. The same products and sums, so the same
// bits for finite values (docs/performance.md: the FFT convolution 11-17 % faster).
#pragma once

#include <fftw3.h>

#include <complex>

namespace tehl::internal {

inline void MultiplySpectrum(fftw_complex* spectrum,
                             const std::complex<double>* kernel,
                             int count) {
  double* s = &spectrum[0][0];
  const double* k = reinterpret_cast<const double*>(kernel);  // array-compatible layout
  for (int q = 0; q < 2 * count; q += 2) {
    const double sr = s[q], si = s[q + 1], kr = k[q], ki = k[q + 1];
    s[q] = sr * kr - si * ki;
    s[q + 1] = sr * ki + si * kr;
  }
}

}  // namespace tehl::internal
