// Binds the constructors of waves and profiles: vibrofric.samples, fourier, profile and wave (from
// arrays, names and files), and fit (a Fourier series through samples).
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common.hpp"
#include "vibrofric/api/fit.hpp"
#include "vibrofric/api/limits.hpp"

namespace vibrofric::python {

namespace {

// A column of decimal texts from an array-like (flattened, C order). Float arrays go through
// decimal_text in C++ (the batch path: no Python object per element).
std::vector<std::string> column_texts(const py::array& a, const std::string& what) {
  const char kind = a.dtype().kind();
  const auto n = static_cast<std::size_t>(a.size());
  std::vector<std::string> out;
  out.reserve(n);
  if (kind == 'f') {
    const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    const double* p = d.data();
    for (std::size_t i = 0; i < n; ++i) out.push_back(decimal_text(p[i]));
    return out;
  }
  if (kind == 'i' || kind == 'u') {
    if (kind == 'u' && a.dtype().itemsize() == 8) {
      const auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
      for (std::size_t i = 0; i < n; ++i) out.push_back(std::to_string(u.data()[i]));
      return out;
    }
    const auto d = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for (std::size_t i = 0; i < n; ++i) out.push_back(std::to_string(d.data()[i]));
    return out;
  }
  if (kind == 'U' || kind == 'S' || kind == 'O') {
    const py::array flat = py::module_::import("numpy").attr("ravel")(a.attr("astype")("object"));
    for (const auto& x : flat) out.push_back(scalar_text(x, what));
    return out;
  }
  throw py::type_error(what + " of dtype " + py::str(a.dtype()).cast<std::string>() +
                       ": expected real numbers or decimal strings");
}

std::vector<std::string> array_texts(const py::object& x, const std::string& what) {
  const py::array a = py::module_::import("numpy").attr("asarray")(x);
  if (a.ndim() > 1)
    throw py::value_error(what + " has " + std::to_string(a.ndim()) + " dimensions: expected a one-dimensional array");
  return column_texts(a, what);
}

// periods= of wave() and samples(): None is 0 (one period, checked), else 1 to max_record_periods.
int record_periods(const py::object& periods) {
  const auto k = optional_int(periods, "periods");
  if (!k) return 0;
  if (*k < 1) throw InputError("periods = " + std::to_string(*k) + ": expected an integer from 1 to " +
                               std::to_string(max_record_periods));
  return *k;
}

// The least-squares Fourier fit (fit.hpp) of samples given as arrays or as a samples Wave.
PyWave fit_wave(const py::object& y, const py::object& harmonics, const py::object& t) {
  WaveSpec samples;
  if (py::isinstance<PyWave>(y)) {
    if (!t.is_none()) throw InputError("t given with a Wave: the wave's own phases are fitted (expected t = None)");
    samples = y.cast<const PyWave&>().spec;
  } else {
    samples = samples_wave(array_texts(y, "y"), t.is_none() ? std::vector<std::string>() : array_texts(t, "t"), "samples");
  }
  const auto k = optional_int(harmonics, "harmonics");
  if (!k) throw py::type_error("harmonics = None: expected an integer K, 1 to " + std::to_string(max_fit_harmonics));
  if (*k < 0)  // 0 and above the limit: fit_fourier's message
    throw InputError("harmonics = " + std::to_string(*k) + ": expected 1 to " + std::to_string(max_fit_harmonics));
  PyWave out;
  {
    py::gil_scoped_release release;
    auto fit = std::make_shared<FourierFit>(fit_fourier(samples, static_cast<unsigned>(*k)));
    out.spec = fitted_wave(*fit, "fit");
    out.fit = std::move(fit);
  }
  out.fitted = samples.name;
  return out;
}

constexpr const char* fit_doc = R"doc(fit(y, harmonics, t=None) -> Wave

The least-squares trigonometric polynomial of degree K = harmonics through a sampled signal, as
the tool's `fit` (model.md, "Waveform catalogue"): y and t as for samples() (or y a samples Wave),
in the signal's units. Uniform phases (no t): the DFT, exact least squares, needs 2K < N. With
time stamps: Householder QR on the phases (t - t0)/T in mpfr, needs N >= 2K + 1 and a condition
number at most 1e12. Coefficients are written to 17 significant digits.

Returns the fitted Fourier wave (normalised like any fourier wave), usable wherever a wave is,
with .harmonics [(k, a_k, b_k)] (floats, k = 0 the mean), .method, .rms_residual and
.max_residual (of y_j - fit(phi_j), in y's units) and .fourier_text(), the fourier file the tool
writes (fourier:FILE reads it back to the same wave).
)doc";

}  // namespace

void bind_waves(py::module_& m) {
  m.def(
      "samples",
      [](const py::object& y, const py::object& t, const py::object& periods) {
        const auto ys = array_texts(y, "y");
        const auto ts = t.is_none() ? std::vector<std::string>() : array_texts(t, "t");
        return PyWave{samples_wave(ys, ts, "samples", record_periods(periods)), nullptr, ""};
      },
      "y"_a, "t"_a = py::none(), py::kw_only(), "periods"_a = py::none(),
      R"doc(samples(y, t=None, *, periods=None) -> Wave

A sampled periodic signal, linear between the samples, normalised to zero mean and
max w - min w = 2 (model.md, "Waveform catalogue"). Without t: y_0 ... y_{N-1} at phi = j/N, one
period without its end point (N >= 2). With t: time stamps t_0 ... t_N, strictly increasing, and
y_N = y_0 (one period with its end point; t_N - t_0 is the period); or, as a DAQ records, no end
point and uniform stamps t_j = t_0 + j dt (then phi = j/N and the period is N dt). Exactly as the same numbers in a
samples:FILE (floats by their shortest decimal text; strings exact); ValueError for what such a
file would be refused for (NaN, ragged t and y, a constant signal, repeated periods). periods (the
tool's --periods): a record of K periods, averaged sample by sample (uniform phases, N a multiple
of K); None: one period, and a record that looks like several noisy periods is a ValueError saying
so; 1: one period, not checked.
)doc");
  m.def(
      "fourier",
      [](const py::object& a, const py::object& b, const py::object& a0) {
        const auto as = array_texts(a, "a");
        const auto bs = array_texts(b, "b");
        const std::string a0s = a0.is_none() ? std::string() : scalar_text(a0, "a0");
        if (!a0.is_none() && a0s.empty()) throw InputError("a0 is empty: expected a decimal number");
        return PyWave{fourier_wave(as, bs, a0s, "fourier"), nullptr, ""};
      },
      "a"_a, "b"_a, "a0"_a = py::none(),
      R"doc(fourier(a, b, a0=None) -> Wave

The finite Fourier series w = a0 + sum_k a_k cos(2 pi k phi) + b_k sin(2 pi k phi) with
a = (a_1 ... a_K), b = (b_1 ... b_K); a0 is the mean and is removed, the series normalised to
max w - min w = 2. Exactly as a fourier:FILE of lines 'k a_k b_k'.
)doc");
  m.def(
      "profile",
      [](const py::object& r, const py::object& f) {
        return PyProfile{profile_arrays(array_texts(r, "r"), array_texts(f, "f"), "profile")};
      },
      "r"_a, "f"_a,
      R"doc(profile(r, f) -> Profile

A measured axisymmetric indenter f(r) (MDR, model.md "Curved contacts"): r from 0, increasing;
f(0) = 0, non-decreasing and convex; heights in units of the amplitude A. Exactly as a
profile:FILE of lines 'r f'.
)doc");

  m.def(
      "wave",
      [](const py::object& text, const py::object& column, const py::object& periods, const py::object& skip_rows) {
        if (!py::isinstance<py::str>(text))
          throw py::type_error("wave = " + py_repr(text) + ": expected a name such as 'sine' or 'samples:FILE'");
        WaveReadOptions options;
        options.periods = record_periods(periods);
        if (const auto k = optional_int(skip_rows, "skip_rows")) {
          if (*k < 0 || static_cast<std::size_t>(*k) > max_table_lines)
            throw InputError("skip_rows = " + std::to_string(*k) + ": expected an integer from 0 to " +
                             std::to_string(max_table_lines));
          options.skip_rows = static_cast<int>(*k);
        }
        if (!column.is_none()) {
          if (py::isinstance<py::str>(column))
            options.column = column.cast<std::string>();
          else if (const auto c = optional_int(column, "column"))
            options.column = std::to_string(*c);
        }
        return PyWave{parse_wave(text.cast<std::string>(), options), nullptr, ""};
      },
      "text"_a, py::kw_only(), "column"_a = py::none(), "periods"_a = py::none(), "skip_rows"_a = py::none(),
      R"doc(wave(text, *, column=None, periods=None, skip_rows=None) -> Wave

A wave by name, as the tool's --wave: 'sine', 'triangle', 'sawtooth-right', 'sawtooth-left',
'square', 'power:P', 'fourier:FILE' or 'samples:FILE'. column (the tool's --column): the value
column of a samples file with a header, by its name or 1-based index (a column named 'time' or 't'
still gives the time stamps); the name becomes 'samples:FILE#COLUMN'. periods (the tool's
--periods): the periods a samples record holds, as in samples(). skip_rows (the tool's
--skip-rows, pandas' skiprows): the lines of a preamble before the header. A missing file raises
FileNotFoundError. The file is read once, here.
)doc");
}

void bind_fit(py::module_& m) {
  m.def("fit", fit_wave, "y"_a, "harmonics"_a, "t"_a = py::none(), fit_doc);
}

}  // namespace vibrofric::python
