// Waves and profiles from numbers instead of files, for front ends that hold arrays (the Python
// module): the numbers, as decimal text, become the rows a file would give and go through the
// file readers' checks (detail/tables.hpp), so an array is accepted, refused and normalised
// exactly as the same numbers in a samples:FILE, fourier:FILE or profile:FILE (model.md, "Waveform
// catalogue": user waves are normalised to zero mean and unit amplitude).
#pragma once
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/fit.hpp"
#include "vibrofric/api/profile_spec.hpp"

namespace vibrofric {

// The shortest decimal text that reads back to x (std::to_chars), as a person would write x in a
// file: 0.1 is "0.1", not its binary expansion. NaN and infinities give "nan", "inf" and "-inf",
// which check_decimal then refuses with the quantity's name.
std::string decimal_text(double x);

// A sampled wave from decimal texts: y_0 … y_{N−1} at φ = j/N when t is empty (one period without
// its end point), or with time stamps t_0 … t_N and y_N = y_0 (one period with its end point,
// t_N − t_0 the period) — the one-column and the 'time,value' layouts of a samples:FILE. The
// WaveSpec is parse_wave's for a file holding those lines, with `label` as its name; messages
// name `label` and the 0-based index (label[j]) instead of the file and its line. InputError for
// ragged arrays (t and y of different lengths) and for everything a file reader refuses.
// periods: as WaveReadOptions::periods (0: one period, a record of several refused).
WaveSpec samples_wave(const std::vector<std::string>& y, const std::vector<std::string>& t,
                      const std::string& label = "samples", int periods = 0);

// A Fourier wave w = a_0 + Σ_{k=1..K} a_k cos 2πkφ + b_k sin 2πkφ from a = (a_1 … a_K),
// b = (b_1 … b_K) and an optional a_0 ("" for none; it is the mean and removed): parse_wave's
// WaveSpec for a fourier:FILE with lines 'k a_k b_k', named `label`. InputError if a and b differ
// in length, and for everything the file reader refuses.
WaveSpec fourier_wave(const std::vector<std::string>& a, const std::vector<std::string>& b, const std::string& a0 = "",
                      const std::string& label = "fourier");

// The wave of a fit (fit.hpp): the WaveSpec of its coefficients as stated, through the fourier
// reader's checks and normalisation (no file text in between), named `label`; what a front end
// that keeps the fit in memory evaluates, equal to the tool's fit output read back.
WaveSpec fitted_wave(const FourierFit& fit, const std::string& label = "fit");

// A measured axisymmetric profile from samples r_j, f_j: parse_profile's ProfileSpec for a
// profile:FILE with lines 'r f', named `label` (the same conditions: r from 0, increasing, f(0) = 0,
// f non-decreasing and convex).
ProfileSpec profile_arrays(const std::vector<std::string>& r, const std::vector<std::string>& f,
                           const std::string& label = "profile");

}  // namespace vibrofric
