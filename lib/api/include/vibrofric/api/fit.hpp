// A sampled signal as a finite Fourier series (model.md, "Waveform catalogue": users bring Fourier
// series and sampled signals): the least-squares trigonometric polynomial of degree K through a
// samples:FILE wave, in the file's units (before the normalisation, which the fourier wave applies
// itself), written as a fourier:FILE. Why least squares: with uniform phases the DFT is its exact
// solution (the harmonics are orthogonal on the grid for 2K < N); with a time column the harmonics
// are not orthogonal, and QR avoids squaring the condition number as normal equations would.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"

namespace vibrofric {

struct FourierFit {
  std::vector<WaveSpec::Harmonic> harmonics;  // k = 0 (the mean, b_0 = 0), 1 … K; 17 significant digits
  std::string method;                         // how they were computed, for the file's comments
  std::string rms_residual, max_residual;     // of y_j − fit(φ_j) with the coefficients as written, 3 digits
  std::size_t samples = 0;                    // N, the samples fitted (the end point of a time column excluded)
};

// Uniform phases φ_j = j/N: the DFT, needs 2K < N. A time column: φ_j = (t_j − t_0)/(t_N − t_0),
// Householder QR in mpfr, needs N ≥ 2K + 1 and a condition number at most 1e12 (else the 17
// digits written would not be determined by data of double precision). Before rounding to 17
// digits each coefficient is within 1e-40·max|y| of the exact least-squares value (one smaller
// than that is written as 0). 1 ≤ K ≤ 10000.
// Throws InputError otherwise, or for a wave that is not samples:FILE.
FourierFit fit_fourier(const WaveSpec& samples_wave, unsigned harmonics);

// The fit as a fourier:FILE that parse_wave reads back: '#' comment lines (source, method, K, N,
// residuals; control bytes of `source` escaped), a header 'k a_k b_k', then one line per harmonic.
std::string fourier_file_text(const FourierFit& fit, const std::string& source);

}  // namespace vibrofric
